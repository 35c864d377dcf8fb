#pragma once
#include <span>
#include <string_view>

namespace lpv::renderer {

struct EmbeddedShader {
    std::string_view name;
    std::string_view source;
};

// Defined in the generated EmbeddedShaders.cpp (cmake/EmbedShaders.cmake).
std::span<const EmbeddedShader> embeddedShaders();

} // namespace lpv::renderer
