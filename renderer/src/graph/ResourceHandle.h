#pragma once
// A frame resource's name as a type (Filament's FrameGraphHandle): passes
// declare their reads and writes, and look their GL objects up, with
// handles declared once (frame/FrameResources.h), never with string
// literals that could drift apart. The name is what reports, --dump and
// the GPU memory table print.
#include <string>
#include <string_view>

namespace lpv::renderer::graph {

class ResourceHandle {
  public:
    // Explicit: a string becomes a handle only where a resource is declared.
    constexpr explicit ResourceHandle(std::string_view name) : name_(name) {}
    constexpr std::string_view name() const { return name_; }
    std::string str() const { return std::string(name_); }
    friend constexpr bool operator==(ResourceHandle a, ResourceHandle b) { return a.name_ == b.name_; }

  private:
    std::string_view name_; // a literal's: handles are constants with static storage
};

} // namespace lpv::renderer::graph
