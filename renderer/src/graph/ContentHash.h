#pragma once
// A 64-bit FNV-1a hash of what a pass's output is computed from (the frame
// graph's reuse keys). Floats hash by their bits: a value that changed at all
// is a different key, so a reused output is exactly what a rerun would give.
#include "lpv/scene/ParameterRegistry.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace lpv::renderer::graph {

class ContentHash {
  public:
    ContentHash& bytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < size; ++i) {
            value_ ^= p[i];
            value_ *= 0x100000001b3ull;
        }
        return *this;
    }
    // Plain values (ints, floats, enums, glm vectors and matrices): their bytes.
    template <class T>
        requires std::is_trivially_copyable_v<T>
    ContentHash& add(const T& v) {
        return bytes(&v, sizeof(T));
    }
    ContentHash& add(std::string_view s) {
        add(s.size());
        return bytes(s.data(), s.size());
    }
    ContentHash& add(const scene::ParameterValue& v) {
        add(v.index());
        std::visit(
            [this](const auto& x) {
                if constexpr (std::is_same_v<std::decay_t<decltype(x)>, std::string>)
                    add(std::string_view(x));
                else
                    add(x);
            },
            v);
        return *this;
    }
    template <class T>
    ContentHash& add(const std::vector<T>& values) {
        add(values.size());
        for (const T& v : values)
            add(v);
        return *this;
    }
    std::uint64_t value() const { return value_; }

  private:
    std::uint64_t value_ = 0xcbf29ce484222325ull;
};

} // namespace lpv::renderer::graph
