#pragma once
// Collects Assimp's warnings and errors during one ReadFile call, so that
// what Assimp repairs silently ("failed to locate material light, creating
// new material") reaches the import summary. Assimp's logger is a process-wide
// singleton, so captures are serialised by a mutex held for their lifetime.
#include <mutex>
#include <string>
#include <vector>

namespace lpv::importers {

class AssimpLogCapture {
  public:
    AssimpLogCapture();
    ~AssimpLogCapture();
    AssimpLogCapture(const AssimpLogCapture&) = delete;
    AssimpLogCapture& operator=(const AssimpLogCapture&) = delete;

    // "OBJ: failed to locate material light, creating new material", in order, without duplicates.
    const std::vector<std::string>& messages() const { return messages_; }

  private:
    std::unique_lock<std::mutex> lock_;
    std::vector<std::string> messages_;
};

} // namespace lpv::importers
