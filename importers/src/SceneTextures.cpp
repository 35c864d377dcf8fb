#include "lpv/importers/SceneTextures.h"

#include "lpv/importers/ImageBudget.h"
#include "lpv/importers/ImageIO.h"
#include "lpv/importers/TextureBudget.h"
#include "lpv/scene/FileRead.h"
#include "lpv/scene/ProjectTextures.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <vector>

namespace lpv::importers {
namespace fs = std::filesystem;

namespace {

std::uint32_t readLe32(const unsigned char* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
           std::uint32_t(p[3]) << 24;
}
std::uint16_t readLe16(const unsigned char* p) {
    return std::uint16_t(p[0] | p[1] << 8);
}

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
    if (w <= 0 || h <= 0 || c <= 0 || height.pixels.size() < std::size_t(w) * std::size_t(h) * std::size_t(c))
        return out;
    out.pixels.resize(std::size_t(w) * std::size_t(h) * 4);
    auto at = [&](int x, int row) {
        x = (x % w + w) % w;
        row = (row % h + h) % h;
        return float(height.pixels[(std::size_t(row) * std::size_t(w) + std::size_t(x)) * std::size_t(c)]) /
               255.0f;
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

SceneTextures loadSceneTextures(const scene::Scene& scene, const fs::path& projectDir, std::uint64_t budget) {
    SceneTextures result;
    auto resolve = [&](const std::string& path) {
        const fs::path p(path);
        return p.is_absolute() ? p : projectDir / p;
    };
    // Which files are used how: each file is decoded once, whatever the
    // number of materials or slots using it, and each use is one image.
    std::set<std::string> plain, heights, keyed;
    for (const scene::Material& m : scene.materials) {
        for (const std::string* slot : scene::textureSlots(m))
            if (!slot->empty() && slot != &m.heightTexture)
                plain.insert(*slot);
        if (!m.heightTexture.empty())
            heights.insert(m.heightTexture);
        if (m.colorKey && !m.diffuseTexture.empty())
            keyed.insert(m.diffuseTexture);
    }
    std::vector<std::string> files;
    std::set_union(plain.begin(), plain.end(), heights.begin(), heights.end(), std::back_inserter(files));
    files.erase(std::unique(files.begin(), files.end()), files.end());

    // The scene's budget, planned from the headers before anything decodes:
    // an unreadable header costs nothing (it becomes the placeholder).
    std::vector<TextureFootprint> footprints;
    for (const std::string& path : files) {
        TextureFootprint f;
        f.copies = int(plain.contains(path)) + int(heights.contains(path)) + int(keyed.contains(path));
        if (auto header = readImageHeader(resolve(path))) {
            f.width = header->width;
            f.height = header->height;
        }
        footprints.push_back(f);
    }
    const std::vector<int> shrink = planTextureShrink(footprints, budget);

    std::map<std::string, LoadedTexture> decoded;
    for (std::size_t i = 0; i < files.size(); ++i) {
        LoadedTexture t = loadTextureOrPlaceholder(resolve(files[i]), shrink[i]);
        if (t.placeholder)
            result.warnings.push_back(t.warning);
        else if (shrink[i] > 1)
            result.warnings.push_back(
                "texture " + resolve(files[i]).string() + " is " + std::to_string(footprints[i].width) + "x" +
                std::to_string(footprints[i].height) + "; loaded at " + std::to_string(t.image.width) + "x" +
                std::to_string(t.image.height) + " to keep the scene's textures within " +
                scene::formatBytes(budget) + " (RGBA8 with mipmaps)");
        decoded.emplace(files[i], std::move(t));
    }

    for (const std::string& path : heights)
        result.images.emplace(path + kHeightNormalSuffix, heightToNormalMap(decoded.at(path).image));
    for (const std::string& path : keyed) {
        scene::Image8 image = decoded.at(path).image;
        std::array<std::uint8_t, 3> colour{0, 0, 0};
        if (!decoded.at(path).placeholder)
            if (auto first =
                    bmpFirstPaletteColour(resolve(path))) // nothing for non-BMPs and true-colour BMPs
                colour = *first;
        applyColorKey(image, colour);
        result.images.emplace(path + kColorKeySuffix, std::move(image));
    }
    // Last, so the derived images above could read them: moved, not copied.
    for (const std::string& path : plain)
        result.images.emplace(path, std::move(decoded.at(path).image));
    return result;
}

} // namespace lpv::importers
