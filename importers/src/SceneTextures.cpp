#include "lpv/importers/SceneTextures.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/scene/ProjectTextures.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <vector>

namespace lpv::importers {
namespace fs = std::filesystem;

namespace {

std::uint32_t readLe32(const unsigned char* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}
std::uint16_t readLe16(const unsigned char* p) { return std::uint16_t(p[0] | p[1] << 8); }

} // namespace

std::optional<std::array<std::uint8_t, 3>> bmpFirstPaletteColour(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    // 14-byte file header, then the info header (12 bytes for OS/2 core
    // headers, 40 or more for Windows ones), then the palette.
    unsigned char header[14 + 40 + 4] = {};
    in.read(reinterpret_cast<char*>(header), sizeof(header));
    if (in.gcount() < 14 + 12 + 3 || header[0] != 'B' || header[1] != 'M')
        return std::nullopt;
    const std::uint32_t infoSize = readLe32(header + 14);
    std::uint16_t bitsPerPixel = 0;
    std::size_t paletteOffset = 14 + infoSize;
    if (infoSize == 12) {
        bitsPerPixel = readLe16(header + 14 + 10);
    } else if (infoSize >= 40) {
        bitsPerPixel = readLe16(header + 14 + 14);
    } else {
        return std::nullopt;
    }
    if (bitsPerPixel == 0 || bitsPerPixel > 8)
        return std::nullopt;
    unsigned char entry[3] = {};
    in.clear();
    in.seekg(std::streamoff(paletteOffset));
    in.read(reinterpret_cast<char*>(entry), 3);
    if (in.gcount() != 3)
        return std::nullopt;
    return std::array<std::uint8_t, 3>{entry[2], entry[1], entry[0]}; // stored as B, G, R
}

namespace {

// Keyed texels keep the key colour (black, magenta...), and bilinear
// filtering and mipmaps blend it into the visible edge: dark fringes around
// leaves. A few passes copy each cut-out texel the mean colour of its visible
// neighbours so the blend picks up the surface colour instead.
void bleedColourIntoCutOuts(scene::Image8& image, int passes) {
    const int w = image.width, h = image.height;
    std::vector<std::uint8_t> filled(std::size_t(w) * std::size_t(h));
    for (std::size_t i = 0; i < filled.size(); ++i)
        filled[i] = image.pixels[i * 4 + 3] != 0;
    for (int pass = 0; pass < passes; ++pass) {
        std::vector<std::uint8_t> next = filled;
        bool changed = false;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                if (filled[i])
                    continue;
                int sum[3] = {0, 0, 0}, n = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        if (nx < 0 || ny < 0 || nx >= w || ny >= h)
                            continue;
                        const std::size_t j = std::size_t(ny) * std::size_t(w) + std::size_t(nx);
                        if (!filled[j])
                            continue;
                        for (int k = 0; k < 3; ++k)
                            sum[k] += image.pixels[j * 4 + std::size_t(k)];
                        ++n;
                    }
                if (n == 0)
                    continue;
                for (int k = 0; k < 3; ++k)
                    image.pixels[i * 4 + std::size_t(k)] = std::uint8_t(sum[k] / n);
                next[i] = 1;
                changed = true;
            }
        filled.swap(next);
        if (!changed)
            break;
    }
}

} // namespace

void applyColorKey(scene::Image8& image, const std::array<std::uint8_t, 3>& key) {
    if (image.channels != 4 || image.pixels.size() < std::size_t(image.width) * std::size_t(image.height) * 4)
        return;
    bool any = false;
    for (std::size_t i = 0; i + 3 < image.pixels.size(); i += 4)
        if (image.pixels[i] == key[0] && image.pixels[i + 1] == key[1] && image.pixels[i + 2] == key[2]) {
            image.pixels[i + 3] = 0;
            any = true;
        }
    // Four texels cover the footprint of trilinear filtering down to mip level 2.
    if (any)
        bleedColourIntoCutOuts(image, 4);
}

scene::Image8 heightToNormalMap(const scene::Image8& height, float strength) {
    scene::Image8 out;
    out.width = height.width;
    out.height = height.height;
    out.channels = 4;
    const int w = height.width, h = height.height, c = height.channels;
    if (w <= 0 || h <= 0 || c <= 0 ||
        height.pixels.size() < std::size_t(w) * std::size_t(h) * std::size_t(c))
        return out;
    out.pixels.resize(std::size_t(w) * std::size_t(h) * 4);
    auto at = [&](int x, int row) {
        x = (x % w + w) % w;
        row = (row % h + h) % h;
        return float(height.pixels[(std::size_t(row) * std::size_t(w) + std::size_t(x)) * std::size_t(c)]) / 255.0f;
    };
    for (int row = 0; row < h; ++row)
        for (int x = 0; x < w; ++x) {
            const float dhdu = 0.5f * (at(x + 1, row) - at(x - 1, row));
            const float dhdv = 0.5f * (at(x, row - 1) - at(x, row + 1)); // the row above is +v
            const glm::vec3 n = glm::normalize(glm::vec3(-strength * dhdu, -strength * dhdv, 1.0f));
            std::uint8_t* p = &out.pixels[(std::size_t(row) * std::size_t(w) + std::size_t(x)) * 4];
            for (int k = 0; k < 3; ++k)
                p[k] = std::uint8_t(std::clamp(std::lround((n[k] * 0.5f + 0.5f) * 255.0f), 0l, 255l));
            p[3] = 255;
        }
    return out;
}

SceneTextures loadSceneTextures(const scene::Scene& scene, const fs::path& projectDir) {
    SceneTextures result;
    // Decoded once per path, whatever the number of materials or slots using it.
    std::map<std::string, LoadedTexture> decoded;
    auto resolve = [&](const std::string& path) {
        const fs::path p(path);
        return p.is_absolute() ? p : projectDir / p;
    };
    auto load = [&](const std::string& path) -> const scene::Image8& {
        auto it = decoded.find(path);
        if (it == decoded.end()) {
            it = decoded.emplace(path, loadTextureOrPlaceholder(resolve(path))).first;
            if (it->second.placeholder)
                result.warnings.push_back(it->second.warning);
        }
        return it->second.image;
    };

    for (const scene::Material& m : scene.materials) {
        for (const std::string* slot : scene::textureSlots(m)) {
            if (slot->empty() || slot == &m.heightTexture)
                continue;
            if (!result.images.contains(*slot))
                result.images.emplace(*slot, load(*slot));
        }
        if (!m.heightTexture.empty()) {
            const std::string key = m.heightTexture + kHeightNormalSuffix;
            if (!result.images.contains(key))
                result.images.emplace(key, heightToNormalMap(load(m.heightTexture)));
        }
        if (m.colorKey && !m.diffuseTexture.empty()) {
            const std::string key = m.diffuseTexture + kColorKeySuffix;
            if (!result.images.contains(key)) {
                scene::Image8 keyed = load(m.diffuseTexture);
                const fs::path file = resolve(m.diffuseTexture);
                std::array<std::uint8_t, 3> colour{0, 0, 0};
                if (!decoded.at(m.diffuseTexture).placeholder)
                    if (auto first = bmpFirstPaletteColour(file)) // nothing for non-BMPs and true-colour BMPs
                        colour = *first;
                applyColorKey(keyed, colour);
                result.images.emplace(key, std::move(keyed));
            }
        }
    }
    return result;
}

} // namespace lpv::importers
