#include "ImageFiles.h"

#include "lpv/scene/Project.h"

#include <bit>
#include <cstring>
#include <string>

namespace lpv::glbench {

namespace {

scene::Expected<void> checkSize(const std::filesystem::path& file, int width, int height, std::size_t values) {
    if (width < 1 || height < 1 || values != std::size_t(width) * std::size_t(height) * 4)
        return scene::makeError(scene::ErrorCode::InvalidValue, file.string(), "",
                                "the read-back holds " + std::to_string(values) + " values, not " +
                                    std::to_string(width) + "x" + std::to_string(height) + "x4");
    return {};
}

} // namespace

scene::Expected<void> writePpm(const std::filesystem::path& file, int width, int height,
                               const std::vector<std::uint8_t>& rgba) {
    if (auto ok = checkSize(file, width, height, rgba.size()); !ok)
        return ok;
    std::string out = "P6\n" + std::to_string(width) + " " + std::to_string(height) + "\n255\n";
    out.reserve(out.size() + std::size_t(width) * std::size_t(height) * 3);
    for (std::size_t i = 0; i < rgba.size(); i += 4)
        out.append(reinterpret_cast<const char*>(&rgba[i]), 3);
    return scene::writeFileAtomically(file, out);
}

scene::Expected<void> writePfm(const std::filesystem::path& file, int width, int height,
                               const std::vector<float>& rgba) {
    if (auto ok = checkSize(file, width, height, rgba.size()); !ok)
        return ok;
    // "-1.0": little-endian floats. PFM stores the bottom row first.
    std::string out = "PF\n" + std::to_string(width) + " " + std::to_string(height) + "\n-1.0\n";
    out.reserve(out.size() + std::size_t(width) * std::size_t(height) * 12);
    for (int y = height - 1; y >= 0; --y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) {
                std::uint32_t bits = std::bit_cast<std::uint32_t>(rgba[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * 4 + std::size_t(c)]);
                if constexpr (std::endian::native == std::endian::big)
                    bits = std::byteswap(bits);
                out.append(reinterpret_cast<const char*>(&bits), 4);
            }
    return scene::writeFileAtomically(file, out);
}

} // namespace lpv::glbench
