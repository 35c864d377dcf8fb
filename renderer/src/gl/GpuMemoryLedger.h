#pragma once
// Collects the GL objects a frame holds into a GpuMemory (GpuMemory.h):
// each pass names its own textures and buffers, then the frame graph its
// resources; an object met twice (a graph resource that is also a pass's
// texture) counts once, under the first name it was given.
#include "graph/ResourceDesc.h"
#include "lpv/renderer/GpuMemory.h"

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lpv::renderer {

// The bytes of a texture of that shape with `levels` mip levels (a 3D
// texture's depth halves per level, an array's layers do not); a buffer's
// desc.bytes. 0 when the format is unknown to bytesPerTexel().
std::uint64_t textureBytes(const graph::ResourceDesc& desc, int levels);

class GpuMemoryLedger {
  public:
    // Asks GL for the shape and mip levels; 0 (an empty handle) adds nothing.
    void addTexture(std::string_view name, GLuint texture);
    void addBuffer(std::string_view name, GLuint buffer);
    // A frame-graph resource: its description, its mip levels asked of GL.
    void addResource(std::string_view name, GLuint id, const graph::ResourceDesc& desc);

    // Objects of one name with the same shape share a line ("6 x 3D RGBA32F ...").
    GpuMemory finish() const;

  private:
    void add(std::string_view name, bool buffer, GLuint id, const graph::ResourceDesc& desc, int levels);
    struct Entry {
        std::string what;
        std::uint64_t bytes = 0; // of one object
        int count = 0;
    };
    std::set<std::pair<bool, GLuint>> seen_; // (buffer, GL name)
    std::vector<std::string> order_;         // names as first met
    std::map<std::string, std::vector<Entry>, std::less<>> entries_;
};

} // namespace lpv::renderer
