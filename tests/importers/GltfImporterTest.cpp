#include "lpv/importers/Importer.h"
#include "TestPaths.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace lpv;
namespace fs = std::filesystem;

namespace {

fs::path scenes() { return fs::path(test::kSharedScenesDir); }

importers::ImportResult importOk(const fs::path& file) {
    auto r = importers::importScene(file);
    EXPECT_TRUE(r.has_value()) << (r ? "" : r.error().describe());
    return r ? std::move(*r) : importers::ImportResult{};
}

fs::path scratch(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / ("lpv-gltf-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

} // namespace

// Counts verified against ../shared/scenes/README.md.
TEST(GltfImporter, CornellBoxWithInstancesAndDanglingTexture) {
    const auto r = importOk(scenes() / "cornell/gltf/cornellBox.gltf");
    // SOURCE.md: 16,720 triangles, 16,732 counting instances. The spheres' pole
    // triangles are degenerate: 380 with exactly zero area (counted with a
    // double-precision script over the .bin) and 128 whose two pole corners are
    // about 1e-8 apart; cleanupMesh drops them (508 with instances).
    EXPECT_EQ(r.scene.triangleCount(), 16224u);
    EXPECT_EQ(r.stats.degenerateTrianglesDropped, 508u);
    EXPECT_EQ(r.scene.meshes.size(), 9u);
    EXPECT_EQ(r.scene.cameras.size(), 1u);
    bool emissive = false, blend = false;
    for (const auto& m : r.scene.materials) {
        emissive |= m.emissive.r > 0.0f;
        blend |= m.alphaMode == scene::AlphaMode::Blend;
    }
    EXPECT_TRUE(emissive) << "the light box is emissive";
    EXPECT_TRUE(blend) << "the glass sphere is alphaMode BLEND";
}

TEST(GltfImporter, SmallSamples) {
    EXPECT_EQ(importOk(scenes() / "gltf-small/Box/glTF/Box.gltf").scene.triangleCount(), 12u);
    const auto textured = importOk(scenes() / "gltf-small/BoxTextured/glTF/BoxTextured.gltf");
    EXPECT_EQ(textured.scene.triangleCount(), 12u);
    EXPECT_EQ(textured.stats.texturesFound, 1u);
    EXPECT_TRUE(fs::exists(textured.scene.materials.front().diffuseTexture));
    // Given a path relative to the working directory, texture paths still come back absolute
    // (a relative one would later be read against the project file's folder).
    const auto relative = importOk(fs::relative(scenes() / "gltf-small/BoxTextured/glTF/BoxTextured.gltf"));
    EXPECT_TRUE(fs::path(relative.scene.materials.front().diffuseTexture).is_absolute())
        << relative.scene.materials.front().diffuseTexture;
    const auto alpha = importOk(scenes() / "gltf-small/AlphaBlendModeTest/glTF/AlphaBlendModeTest.gltf");
    EXPECT_EQ(alpha.scene.triangleCount(), 61u) << "u8 indices";
    int masks = 0;
    for (const auto& m : alpha.scene.materials)
        masks += m.alphaMode == scene::AlphaMode::Mask;
    EXPECT_GE(masks, 1);
    const auto mirror = importOk(scenes() / "gltf-small/NormalTangentMirrorTest/glTF/NormalTangentMirrorTest.gltf");
    EXPECT_EQ(mirror.scene.triangleCount(), 5240u);
    ASSERT_FALSE(mirror.scene.meshes.empty());
    EXPECT_EQ(mirror.scene.meshes[0].tangents.size(), mirror.scene.meshes[0].positions.size()) << "supplied tangents";
    EXPECT_EQ(mirror.stats.texturesMissing, 0u);
}

TEST(GltfImporter, MissingBinIsAnErrorNamingTheFile) {
    const fs::path dir = scratch("nobin");
    fs::copy_file(scenes() / "gltf-small/Box/glTF/Box.gltf", dir / "Box.gltf");
    auto r = importers::importScene(dir / "Box.gltf");
    ASSERT_FALSE(r.has_value());
    EXPECT_NE(r.error().describe().find("Box.gltf"), std::string::npos) << r.error().describe();
    fs::remove_all(dir);
}

TEST(GltfImporter, AccessorPastTheBufferIsTruncatedNotACrash) {
    const fs::path dir = scratch("short");
    // A 12-byte buffer holding one triangle's worth of positions is declared as 3 vertices: 36 bytes needed.
    std::ofstream(dir / "short.bin", std::ios::binary).write("\0\0\0\0\0\0\0\0\0\0\0\0", 12);
    std::ofstream(dir / "short.gltf") << R"({"asset":{"version":"2.0"},"buffers":[{"uri":"short.bin","byteLength":12}],
      "bufferViews":[{"buffer":0,"byteLength":12}],
      "accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[0,0,0]}],
      "meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],"nodes":[{"mesh":0}],"scenes":[{"nodes":[0]}]})";
    auto r = importers::importScene(dir / "short.gltf");
    ASSERT_FALSE(r.has_value());
    EXPECT_EQ(r.error().code, scene::ErrorCode::Truncated) << r.error().describe();
    EXPECT_NE(r.error().location.find("POSITION"), std::string::npos);
    fs::remove_all(dir);
}

TEST(Importer, UnknownFormatAndMissingFile) {
    EXPECT_EQ(importers::importScene("/nonexistent/scene.gltf").error().code, scene::ErrorCode::FileNotFound);
    const fs::path dir = scratch("unknown");
    std::ofstream(dir / "notes.txt") << "hello";
    EXPECT_EQ(importers::importScene(dir / "notes.txt").error().code, scene::ErrorCode::UnknownFormat);
    fs::remove_all(dir);
}

namespace {

std::string readBytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

std::string base64(const std::string& in) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
        const unsigned v = unsigned(std::uint8_t(in[i])) << 16 | unsigned(std::uint8_t(in[i + 1])) << 8 |
                           unsigned(std::uint8_t(in[i + 2]));
        out += {table[v >> 18], table[(v >> 12) & 63], table[(v >> 6) & 63], table[v & 63]};
    }
    if (i + 1 == in.size()) {
        const unsigned v = unsigned(std::uint8_t(in[i])) << 16;
        out += {table[v >> 18], table[(v >> 12) & 63], '=', '='};
    } else if (i + 2 == in.size()) {
        const unsigned v = unsigned(std::uint8_t(in[i])) << 16 | unsigned(std::uint8_t(in[i + 1])) << 8;
        out += {table[v >> 18], table[(v >> 12) & 63], table[(v >> 6) & 63], '='};
    }
    return out;
}

void appendU32(std::string& out, std::uint32_t v) {
    for (int k = 0; k < 4; ++k)
        out += char((v >> (8 * k)) & 0xff);
}

// Keeps the embedded-image cache of these tests out of the user's home.
struct CacheDir {
    fs::path path = scratch("cache");
    CacheDir() { ::setenv("LPV_CACHE_DIR", path.c_str(), 1); }
    ~CacheDir() {
        ::unsetenv("LPV_CACHE_DIR");
        fs::remove_all(path);
    }
};

} // namespace

TEST(GltfImporter, ImageInADataUriIsStoredAndFound) {
    CacheDir cache;
    const fs::path source = scenes() / "gltf-small/BoxTextured/glTF";
    const fs::path dir = scratch("datauri");
    nlohmann::json j = nlohmann::json::parse(readBytes(source / "BoxTextured.gltf"));
    const std::string png = readBytes(source / "CesiumLogoFlat.png");
    j["images"][0] = {{"uri", "data:image/png;base64," + base64(png)}};
    j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(readBytes(source / "BoxTextured0.bin"));
    std::ofstream(dir / "embedded.gltf") << j.dump();
    const auto r = importOk(dir / "embedded.gltf");
    EXPECT_EQ(r.scene.triangleCount(), 12u);
    EXPECT_EQ(r.stats.texturesFound, 1u);
    EXPECT_EQ(r.stats.texturesMissing, 0u);
    const fs::path texture = r.scene.materials.front().diffuseTexture;
    EXPECT_EQ(texture.parent_path(), cache.path / "embedded-images");
    EXPECT_EQ(texture.extension(), ".png");
    EXPECT_EQ(readBytes(texture), png) << "the image's bytes, unchanged";
    fs::remove_all(dir);
}

TEST(GltfImporter, GlbWithItsImageInTheBinaryChunk) {
    CacheDir cache;
    const fs::path source = scenes() / "gltf-small/BoxTextured/glTF";
    std::string bin = readBytes(source / "BoxTextured0.bin");
    const std::string png = readBytes(source / "CesiumLogoFlat.png");
    while (bin.size() % 4)
        bin += '\0';
    nlohmann::json j = nlohmann::json::parse(readBytes(source / "BoxTextured.gltf"));
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", png.size()}});
    j["images"][0] = {{"bufferView", j["bufferViews"].size() - 1}, {"mimeType", "image/png"}};
    bin += png;
    while (bin.size() % 4)
        bin += '\0';
    j["buffers"][0] = {{"byteLength", bin.size()}};
    std::string json = j.dump();
    while (json.size() % 4)
        json += ' ';
    std::string glb = "glTF";
    appendU32(glb, 2);
    appendU32(glb, std::uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    appendU32(glb, std::uint32_t(json.size()));
    glb += "JSON" + json;
    appendU32(glb, std::uint32_t(bin.size()));
    glb += std::string("BIN\0", 4) + bin;
    const fs::path dir = scratch("glb");
    std::ofstream(dir / "box.glb", std::ios::binary) << glb;
    const auto r = importOk(dir / "box.glb");
    EXPECT_EQ(r.scene.triangleCount(), 12u);
    EXPECT_EQ(r.stats.texturesFound, 1u);
    EXPECT_EQ(readBytes(r.scene.materials.front().diffuseTexture), png);
    // The same file named .gltf is still read as binary: the content decides.
    fs::copy_file(dir / "box.glb", dir / "misnamed.gltf");
    EXPECT_EQ(importOk(dir / "misnamed.gltf").scene.triangleCount(), 12u);
    fs::remove_all(dir);
}

// Issue #29: an image uri naming a folder ("." or the scene's own folder) or a
// name too long to look up is a missing texture with a warning that says why,
// not a std::bad_alloc or an uncaught filesystem_error.
TEST(GltfImporter, ImageUrisThatAreNoFileBecomePlaceholders) {
    const fs::path source = scenes() / "gltf-small/BoxTextured/glTF";
    const fs::path dir = scratch("folderuri");
    nlohmann::json j = nlohmann::json::parse(readBytes(source / "BoxTextured.gltf"));
    j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(readBytes(source / "BoxTextured0.bin"));
    const std::vector<std::pair<std::string, std::string>> cases{
        {".", "is a folder, not a file (placeholder used)"},
        {std::string(300, 'n') + ".png", "cannot look it up: File name too long (placeholder used)"}};
    for (const auto& [uri, why] : cases) {
        j["images"][0] = {{"uri", uri}};
        std::ofstream(dir / "odd.gltf") << j.dump();
        const auto r = importOk(dir / "odd.gltf");
        EXPECT_EQ(r.stats.texturesMissing, 1u) << uri.substr(0, 20);
        EXPECT_EQ(r.stats.texturesFound, 0u);
        bool warned = false;
        for (const std::string& w : r.warnings)
            warned |= w.find(why) != std::string::npos;
        EXPECT_TRUE(warned) << uri.substr(0, 20) << ": no warning ending in '" << why << "'";
    }
    fs::remove_all(dir);
}

// fuzz_gltf (a mutated Box.glb): a triangle that OpenMesh's halfedge mesh
// refuses (here: the edge 0-1 again in the same direction, a complex edge)
// left a vertex without a halfedge at its corner that no other triangle uses,
// and the normal generation's counter-clockwise walk around it asserted in
// OpenMesh 9. Both triangles are kept; the lone corner gets its face's normal.
TEST(GltfImporter, TriangleOnAComplexEdgeWithALoneCornerGetsNormals) {
    const float tilt = std::tan(20.0f * 3.14159265358979f / 180.0f);
    const float positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.5f, 1, tilt};
    const std::uint16_t indices[] = {0, 1, 2, 0, 1, 3};
    std::string bin(reinterpret_cast<const char*>(positions), sizeof positions);
    bin.append(reinterpret_cast<const char*>(indices), sizeof indices);
    const nlohmann::json j = {
        {"asset", {{"version", "2.0"}}},
        {"buffers", {{{"uri", "data:application/octet-stream;base64," + base64(bin)}, {"byteLength", bin.size()}}}},
        {"bufferViews",
         {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", sizeof positions}},
          {{"buffer", 0}, {"byteOffset", sizeof positions}, {"byteLength", sizeof indices}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}, {"min", {0, 0, 0}},
           {"max", {1, 1, tilt}}},
          {{"bufferView", 1}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"scenes", {{{"nodes", {0}}}}}};
    const fs::path dir = scratch("complexedge");
    std::ofstream(dir / "fold.gltf") << j.dump();
    const auto r = importOk(dir / "fold.gltf");
    EXPECT_EQ(r.stats.degenerateTrianglesDropped, 0u);
    ASSERT_EQ(r.scene.meshes.size(), 1u);
    const scene::Mesh& m = r.scene.meshes[0];
    ASSERT_EQ(m.triangleCount(), 2u);
    ASSERT_EQ(m.normals.size(), m.positions.size());
    const glm::vec3 up(0, 0, 1);
    const glm::vec3 tilted = glm::normalize(glm::vec3(0, -tilt, 1)); // the second triangle's face normal
    for (std::size_t k = 0; k < 3; ++k)
        EXPECT_LT(glm::distance(m.normals[m.indices[k]], up), 1e-6f) << "first triangle, corner " << k;
    EXPECT_LT(glm::distance(m.normals[m.indices[5]], tilted), 1e-6f) << "the lone corner: its own face's normal";
    for (std::size_t k = 3; k < 5; ++k) { // on the shared edge: smoothed with the first triangle (20 < 60 degrees)
        const glm::vec3 n = m.normals[m.indices[k]];
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
        EXPECT_GT(glm::dot(n, up), glm::dot(tilted, up)) << "corner " << k;
        EXPECT_GT(glm::dot(n, tilted), glm::dot(up, tilted)) << "corner " << k;
    }
    fs::remove_all(dir);
}
