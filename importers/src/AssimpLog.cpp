#include "AssimpLog.h"

#include <assimp/DefaultLogger.hpp>
#include <assimp/LogStream.hpp>

#include <algorithm>

namespace lpv::importers {
namespace {

std::mutex& loggerMutex() {
    static std::mutex m;
    return m;
}

// Assimp formats messages as "Warn,  T0: text\n"; keep the text.
class CollectingStream : public Assimp::LogStream {
  public:
    explicit CollectingStream(std::vector<std::string>& out) : out_(out) {}

    void write(const char* message) override {
        std::string text(message);
        if (const auto colon = text.find(": "); colon != std::string::npos && colon < 16)
            text.erase(0, colon + 2);
        while (!text.empty() && (text.back() == '\n' || text.back() == '\r'))
            text.pop_back();
        if (!text.empty() && std::find(out_.begin(), out_.end(), text) == out_.end())
            out_.push_back(std::move(text));
    }

  private:
    std::vector<std::string>& out_;
};

} // namespace

AssimpLogCapture::AssimpLogCapture() : lock_(loggerMutex()) {
    Assimp::DefaultLogger::create("", Assimp::Logger::NORMAL, 0);
    // The logger owns the stream and deletes it in kill().
    Assimp::DefaultLogger::get()->attachStream(new CollectingStream(messages_),
                                               Assimp::Logger::Warn | Assimp::Logger::Err);
}

AssimpLogCapture::~AssimpLogCapture() { Assimp::DefaultLogger::kill(); }

} // namespace lpv::importers
