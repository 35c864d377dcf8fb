// The Mafia .4ds reader: every real file in shared/scenes/4ds with the counts
// measured on it, the coordinate conventions, texture lookup, and one small
// hand-built file per way the input can be broken (each error asserted by
// code and byte offset; none crashes, none allocates for a count the file
// cannot hold).
#include "lpv/importers/FourDsReader.h"
#include "TestFiles.h"

#include "TestPaths.h"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace lpv::scene {
inline void PrintTo(ErrorCode code, std::ostream* os) {
    *os << toString(code);
}
} // namespace lpv::scene

namespace {

using lpv::test::contains;

namespace fs = std::filesystem;
using lpv::importers::ImportOptions;
using lpv::importers::ImportResult;
using lpv::importers::readFourDs;
using lpv::scene::ErrorCode;
using Bytes = std::vector<std::uint8_t>;

const fs::path kModels = fs::path(lpv::test::kSharedScenesDir) / "4ds";

Bytes readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

lpv::scene::Expected<ImportResult> readModel(const std::string& name, const ImportOptions& options = {}) {
    const fs::path file = kModels / name;
    const Bytes bytes = readFile(file);
    EXPECT_FALSE(bytes.empty()) << file;
    return readFourDs(bytes, file, options);
}

std::size_t countWarnings(const ImportResult& r, const std::string& part) {
    std::size_t n = 0;
    for (const std::string& w : r.warnings)
        n += contains(w, part) ? 1 : 0;
    return n;
}

// --- a writer of the documented layout, for the hand-built failure files ---

constexpr std::uint32_t kDiffuseMap = 0x00040000;
constexpr std::uint32_t kEnvMap = 0x00080000;
constexpr std::uint32_t kTwoSided = 0x10000000;
constexpr std::uint32_t kColorKey = 0x20000000;
constexpr std::uint32_t kAlphaMap = 0x40000000;
constexpr std::uint32_t kAdditive = 0x80000000;

struct Writer {
    Bytes b;

    std::size_t size() const { return b.size(); }
    Writer& u8(unsigned v) {
        b.push_back(static_cast<std::uint8_t>(v));
        return *this;
    }
    Writer& u16(unsigned v) { return u8(v & 0xffu).u8((v >> 8) & 0xffu); }
    Writer& u32(std::uint32_t v) { return u16(v & 0xffffu).u16(v >> 16); }
    Writer& u64(std::uint64_t v) {
        return u32(static_cast<std::uint32_t>(v)).u32(static_cast<std::uint32_t>(v >> 32));
    }
    Writer& f32(float v) { return u32(std::bit_cast<std::uint32_t>(v)); }
    Writer& vec3(float x, float y, float z) { return f32(x).f32(y).f32(z); }
    Writer& str(std::string_view s) {
        u8(static_cast<unsigned>(s.size()));
        b.insert(b.end(), s.begin(), s.end());
        return *this;
    }
};

void header(Writer& w, unsigned version = 29) {
    w.u8('4').u8('D').u8('S').u8(0).u16(version).u64(0x01c2d2524a6f0000ull);
}

void material(Writer& w, std::string_view diffuse, std::uint32_t flags = kDiffuseMap, float opacity = 1.0f) {
    w.u32(flags).vec3(0.1f, 0.1f, 0.1f).vec3(0.5f, 0.25f, 0.125f).vec3(0, 0, 0).f32(opacity);
    if (flags & kEnvMap)
        w.f32(0.75f).str("ENV.BMP");
    w.str(diffuse);
}

struct FrameOffsets {
    std::size_t parent = 0;
    std::size_t transform = 0;
};

// Common frame header; returns where its parent index and transform sit.
FrameOffsets frame(Writer& w, unsigned type, unsigned visual, unsigned parent, std::string_view name,
                   glm::vec3 position = glm::vec3(0.0f), glm::vec4 wxyz = {1, 0, 0, 0}) {
    w.u8(type);
    if (type == 1)
        w.u8(visual).u16(0);
    FrameOffsets at;
    at.parent = w.size();
    w.u16(parent);
    at.transform = w.size();
    w.vec3(position.x, position.y, position.z).vec3(1, 1, 1).f32(wxyz.x).f32(wxyz.y).f32(wxyz.z).f32(wxyz.w);
    w.u8(9).str(name).str("");
    return at;
}

// One LOD: a triangle (0,0,0) (1,0,0) (0,1,0) with normals +Z, face (0,1,2).
void triangleLod(Writer& w, unsigned materialIndex = 1, unsigned faceCorner2 = 2) {
    w.f32(0.0f).u16(3);
    w.vec3(0, 0, 0).vec3(0, 0, 1).f32(0.25f).f32(0.75f);
    w.vec3(1, 0, 0).vec3(0, 0, 1).f32(1.0f).f32(0.75f);
    w.vec3(0, 1, 0).vec3(0, 0, 1).f32(0.25f).f32(0.0f);
    w.u8(1).u16(1).u16(0).u16(1).u16(faceCorner2).u16(materialIndex);
}

void standardMesh(Writer& w, unsigned lods = 1, unsigned materialIndex = 1) {
    w.u16(0).u8(lods);
    for (unsigned i = 0; i < lods; ++i)
        triangleLod(w, materialIndex);
}

void dummyBox(Writer& w) {
    w.vec3(-1, -1, -1).vec3(1, 1, 1);
}

// One material and one mesh frame; the caller adds frameCount - 1 frames and
// the final 5ds flag byte.
Writer oneTriangleFile(unsigned frameCount = 1) {
    Writer w;
    header(w);
    w.u16(1);
    material(w, "RED.BMP");
    w.u16(frameCount);
    frame(w, 1, 0, 0, "tri");
    standardMesh(w);
    return w;
}

lpv::scene::Expected<ImportResult> parse(const Bytes& bytes, const fs::path& file = "test.4ds",
                                         const ImportOptions& options = {}) {
    return readFourDs(bytes, file, options);
}

void expectError(const lpv::scene::Expected<ImportResult>& r, ErrorCode code, std::size_t offset,
                 const std::string& messagePart) {
    ASSERT_FALSE(r.has_value()) << "expected " << lpv::scene::toString(code);
    EXPECT_EQ(r.error().code, code) << r.error().describe();
    EXPECT_EQ(r.error().location, "byte offset " + std::to_string(offset)) << r.error().describe();
    EXPECT_TRUE(contains(r.error().message, messagePart)) << r.error().describe();
    EXPECT_EQ(r.error().file, "test.4ds");
}

// ------------------------------------------------------------------ real data

struct RealModel {
    const char* file;
    std::size_t triangles;
    std::size_t materials;
    std::size_t objects;
    std::size_t meshes;
    std::size_t texturesFound; // diffuse/alpha maps plus the _ddn/_spec companions
    std::size_t warnings;
};

// Counts measured with this reader and cross-checked with SOURCE.md.
const RealModel kRealModels[] = {
    {"bunny00.4ds", 2092, 1, 1, 1, 3, 0},       {"cube00.4ds", 12, 1, 1, 1, 3, 0},
    {"denjasno2.4ds", 22, 13, 5, 3, 14, 2}, // 2 glow frames skipped
    {"scene.4ds", 60, 3, 10, 10, 6, 0},         {"sibenik.4ds", 72524, 10, 9, 9, 9, 0},
    {"sphere00.4ds", 256, 1, 1, 1, 1, 0},       {"sphere01.4ds", 256, 1, 1, 1, 1, 0},
    {"test00.4ds", 308, 1, 7, 7, 3, 1},                                                   // 1 trailing byte
    {"tree00.4ds", 1704, 2, 2, 2, 6, 0},        {"white_box.4ds", 1310, 1, 11, 11, 3, 1}, // 1 trailing byte
    {"white_interier.4ds", 612, 1, 1, 1, 1, 0},
};

TEST(FourDsReader, EveryRealModelImportsWithItsCounts) {
    std::set<std::string> seen;
    for (const RealModel& m : kRealModels) {
        SCOPED_TRACE(m.file);
        seen.insert(m.file);
        const auto r = readModel(m.file);
        ASSERT_TRUE(r.has_value()) << r.error().describe();
        EXPECT_EQ(r->scene.triangleCount(), m.triangles);
        EXPECT_EQ(r->stats.triangles, m.triangles);
        EXPECT_EQ(r->scene.materials.size(), m.materials);
        EXPECT_EQ(r->stats.materials, m.materials);
        EXPECT_EQ(r->scene.objects.size(), m.objects);
        EXPECT_EQ(r->stats.objects, m.objects);
        EXPECT_EQ(r->scene.meshes.size(), m.meshes);
        EXPECT_EQ(r->stats.texturesFound, m.texturesFound);
        EXPECT_EQ(r->stats.texturesMissing, 0u);
        EXPECT_EQ(r->warnings.size(), m.warnings);
        for (const auto& w : r->warnings)
            EXPECT_TRUE(contains(w, m.file)) << "a warning names the file: " << w;
        for (const auto& mesh : r->scene.meshes) {
            EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
            EXPECT_EQ(mesh.uvs.size(), mesh.positions.size());
            for (const auto& sub : mesh.submeshes)
                EXPECT_LT(sub.materialIndex, r->scene.materials.size());
        }
    }
    // Every model in the folder is in the table above.
    for (const auto& entry : fs::directory_iterator(kModels)) {
        if (entry.path().extension() == ".4ds") {
            EXPECT_TRUE(seen.count(entry.path().filename().string()))
                << entry.path() << " has no expected counts";
        }
    }
}

TEST(FourDsReader, SibenikFindsEveryTextureAndItsCompanions) {
    const auto r = readModel("sibenik.4ds");
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    EXPECT_EQ(r->stats.texturesMissing, 0u);
    ASSERT_EQ(r->scene.materials.size(), 10u);
    for (const auto& m : r->scene.materials) {
        SCOPED_TRACE(m.name);
        // Stored as SIBENIK_*.BMP, on disk as sibenik_*.bmp.
        for (const std::string* path : {&m.diffuseTexture, &m.normalTexture, &m.specularTexture}) {
            ASSERT_FALSE(path->empty());
            EXPECT_TRUE(fs::path(*path).is_absolute()) << *path;
            EXPECT_TRUE(fs::exists(*path)) << *path;
        }
        EXPECT_TRUE(contains(m.normalTexture, "_ddn.bmp")) << m.normalTexture;
        EXPECT_TRUE(contains(m.specularTexture, "_spec.bmp")) << m.specularTexture;
        EXPECT_EQ(m.diffuseColor, glm::vec3(1.0f)) << "textured and not COLORED: the map gives the colour";
        EXPECT_FALSE(m.twoSided);
        EXPECT_EQ(m.alphaMode, lpv::scene::AlphaMode::Opaque);
    }
    EXPECT_EQ(r->scene.materials[0].name, "SIBENIK_KAMEN");
    EXPECT_EQ(r->scene.materials[1].name, "SIBENIK_KAMEN #2");
    EXPECT_EQ(fs::path(r->scene.materials[3].diffuseTexture).filename(), "sibenik_mramor6x6.bmp");
}

TEST(FourDsReader, SibenikSubmeshesFollowTheFaceGroups) {
    const auto r = readModel("sibenik.4ds");
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    const auto& mesh = r->scene.meshes[0]; // Object00: groups of 4320, 9512, 138, 1162 faces
    EXPECT_EQ(mesh.name, "Object00");
    EXPECT_EQ(mesh.positions.size(), 18005u);
    ASSERT_EQ(mesh.submeshes.size(), 4u);
    const std::uint32_t faces[] = {4320, 9512, 138, 1162};
    const std::uint32_t materials[] = {0, 1, 2, 6};
    std::uint32_t first = 0;
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(mesh.submeshes[i].firstIndex, first);
        EXPECT_EQ(mesh.submeshes[i].indexCount, 3 * faces[i]);
        EXPECT_EQ(mesh.submeshes[i].materialIndex, materials[i]);
        first += 3 * faces[i];
    }
}

// After our conversion the geometric normal (right-handed, counter-clockwise)
// must agree with the stored vertex normals, as it does in the file.
TEST(FourDsReader, SibenikWindingAgreesWithItsNormals) {
    const auto r = readModel("sibenik.4ds");
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    std::size_t agree = 0, total = 0;
    for (const auto& mesh : r->scene.meshes)
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            const auto a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
            const glm::vec3 n =
                glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
            agree += glm::dot(n, mesh.normals[a] + mesh.normals[b] + mesh.normals[c]) > 0.0f ? 1 : 0;
            ++total;
        }
    EXPECT_EQ(total, 72524u);
    EXPECT_GT(double(agree) / double(total), 0.99);
}

// X is mirrored: the 4ds Sibenik then has the orientation of Dabrovic's
// sibenik.obj (x in [-20.14, 20.14], y in [-15.31, 15.30], z in [-8.50, 8.50]),
// shifted by (1.295, 14.364, 0).
TEST(FourDsReader, SibenikLinesUpWithTheObjVersion) {
    const auto r = readModel("sibenik.4ds");
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    const auto b = r->scene.worldBounds();
    EXPECT_NEAR(b.min.x, -20.1411f + 1.2947f, 1e-3f);
    EXPECT_NEAR(b.max.x, 20.1411f + 1.2947f, 1e-3f);
    EXPECT_NEAR(b.min.y, -15.3123f + 14.3641f, 1e-3f);
    EXPECT_NEAR(b.max.y, 15.3f + 14.3641f, 1e-3f);
    EXPECT_NEAR(b.min.z, -8.4968f, 1e-3f);
    EXPECT_NEAR(b.max.z, 8.4968f, 1e-3f);
}

TEST(FourDsReader, OddTextureNamesResolve) {
    // Spaces, upper case on disk, '+', '^'.
    const auto sky = readModel("denjasno2.4ds");
    ASSERT_TRUE(sky.has_value()) << sky.error().describe();
    EXPECT_EQ(fs::path(sky->scene.materials[0].diffuseTexture).filename(), "SKY 3 5.BMP");
    const auto& sun = sky->scene.materials[12];
    EXPECT_EQ(fs::path(sun.diffuseTexture).filename(), "2sun1.bmp");
    EXPECT_EQ(sun.alphaMode, lpv::scene::AlphaMode::Blend) << "it has the alpha map 2SUN1+.BMP";
    EXPECT_EQ(fs::path(sun.alphaTexture).filename(), "2sun1+.bmp");
    EXPECT_EQ(countWarnings(*sky, "2SUN1+.BMP"), 0u) << "found, so nothing to warn about";
    EXPECT_EQ(countWarnings(*sky, "visual type 6 (glow)"), 2u);
    EXPECT_EQ(countWarnings(*sky, "'lensflere'"), 1u);

    const auto scene = readModel("scene.4ds");
    ASSERT_TRUE(scene.has_value()) << scene.error().describe();
    EXPECT_EQ(fs::path(scene->scene.materials[0].diffuseTexture).filename(), "^sl_6m02.bmp");
    EXPECT_EQ(fs::path(scene->scene.materials[0].normalTexture).filename(), "^sl_6m02_ddn.bmp");
    EXPECT_TRUE(scene->scene.materials[0].specularTexture.empty()) << "there is no ^sl_6m02_spec.bmp";
}

TEST(FourDsReader, MaterialFlagsAndColours) {
    const auto tree = readModel("tree00.4ds");
    ASSERT_TRUE(tree.has_value()) << tree.error().describe();
    const auto& leaves = tree->scene.materials[1]; // flags 0x30049001: two-sided, colour key
    EXPECT_TRUE(leaves.twoSided);
    EXPECT_EQ(leaves.alphaMode, lpv::scene::AlphaMode::Mask);
    EXPECT_FALSE(tree->scene.materials[0].twoSided);

    const auto sun = readModel("sphere00.4ds"); // emission 1, opacity 0.5
    ASSERT_TRUE(sun.has_value()) << sun.error().describe();
    EXPECT_EQ(sun->scene.materials[0].emissive, glm::vec3(1.0f));
    EXPECT_FLOAT_EQ(sun->scene.materials[0].opacity, 0.5f);
    EXPECT_EQ(sun->scene.materials[0].alphaMode, lpv::scene::AlphaMode::Blend);
}

TEST(FourDsReader, TrailingBytesAreToleratedWithAWarning) {
    const auto r = readModel("test00.4ds");
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    EXPECT_EQ(countWarnings(*r, "1 byte(s) after the end"), 1u);
}

TEST(FourDsReader, UnnormalisedQuaternionIsNormalised) {
    const auto r = readModel("white_interier.4ds"); // stored as (0.7071, 0, 0, 0)
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    const glm::quat q = r->scene.objects[0].transform.rotation;
    EXPECT_NEAR(q.w, 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(q), 1.0f, 1e-6f);
}

// --------------------------------------------------------- conventions

TEST(FourDsReader, MirrorsXReversesWindingAndFlipsV) {
    Writer w = oneTriangleFile();
    w.u8(0);
    const auto r = parse(w.b);
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    const auto& mesh = r->scene.meshes.at(0);
    EXPECT_EQ(mesh.positions[1], glm::vec3(-1, 0, 0));
    EXPECT_EQ(mesh.normals[0], glm::vec3(0, 0, 1));
    EXPECT_EQ(mesh.uvs[0], glm::vec2(0.25f, 0.25f));
    EXPECT_EQ(mesh.uvs[2], glm::vec2(0.25f, 1.0f));
    EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 2, 1}));
    EXPECT_EQ(r->scene.materials[0].name, "RED");
    EXPECT_EQ(r->scene.materials[0].diffuseColor, glm::vec3(1.0f));
}

TEST(FourDsReader, TransformIsMirroredToo) {
    Writer w;
    header(w);
    w.u16(0).u16(1);
    const float h = std::sqrt(0.5f); // 90 degrees about +Y in the file
    frame(w, 6, 0, 0, "node", {1, 2, 3}, {h, 0, h, 0});
    dummyBox(w);
    w.u8(0);
    const auto r = parse(w.b);
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    const auto& t = r->scene.objects.at(0).transform;
    EXPECT_EQ(t.translation, glm::vec3(-1, 2, 3));
    // File: +X turns to -Z. Mirrored: -X turns to -Z.
    const glm::vec3 turned = t.rotation * glm::vec3(-1, 0, 0);
    EXPECT_NEAR(turned.x, 0.0f, 1e-6f);
    EXPECT_NEAR(turned.z, -1.0f, 1e-6f);
    EXPECT_EQ(r->scene.objects[0].mesh, -1);
    EXPECT_TRUE(r->warnings.empty()) << "a dummy loses nothing";
}

TEST(FourDsReader, HierarchyAndInstances) {
    Writer w;
    header(w);
    w.u16(1);
    material(w, "RED.BMP");
    w.u16(3);
    frame(w, 6, 0, 0, "root");
    dummyBox(w);
    frame(w, 1, 0, 1, "child");
    standardMesh(w);
    frame(w, 1, 0, 1, "copy");
    w.u16(2); // instance of frame #2
    w.u8(0);
    const auto r = parse(w.b);
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    const auto& o = r->scene.objects;
    ASSERT_EQ(o.size(), 3u);
    EXPECT_EQ(o[0].parent, -1);
    EXPECT_EQ(o[1].parent, 0);
    EXPECT_EQ(o[2].parent, 0);
    EXPECT_EQ(o[1].mesh, 0);
    EXPECT_EQ(o[2].mesh, 0);
    EXPECT_EQ(r->scene.meshes.size(), 1u);
    EXPECT_EQ(r->stats.triangles, 2u);
}

TEST(FourDsReader, FurtherLodsAreReadButOnlyLodZeroImported) {
    Writer w;
    header(w);
    w.u16(1);
    material(w, "RED.BMP");
    w.u16(1);
    frame(w, 1, 0, 0, "lods");
    standardMesh(w, 3);
    w.u8(0);
    const auto r = parse(w.b);
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    // LOD 1 and 2 are kept as meshes the object lists; only LOD 0 is drawn.
    ASSERT_EQ(r->scene.meshes.size(), 3u);
    EXPECT_EQ(r->stats.triangles, 1u);
    const auto& lods = r->scene.objects[0].lods;
    ASSERT_EQ(lods.size(), 2u);
    EXPECT_EQ(lods[0].mesh, 1);
    EXPECT_EQ(lods[1].mesh, 2);
    EXPECT_EQ(r->scene.meshes[1].name, "lods LOD 1");
    EXPECT_EQ(r->scene.meshes[2].triangleCount(), 1u);
}

TEST(FourDsReader, FacesWithoutMaterialGetADefault) {
    Writer w;
    header(w);
    w.u16(0).u16(1);
    frame(w, 1, 0, 0, "bare");
    standardMesh(w, 1, 0);
    w.u8(0);
    const auto r = parse(w.b);
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    ASSERT_EQ(r->scene.materials.size(), 1u);
    EXPECT_EQ(r->scene.meshes[0].submeshes[0].materialIndex, 0u);
}

TEST(FourDsReader, MaterialFlagsMapToOurModel) {
    Writer w;
    header(w);
    w.u16(4);
    material(w, "A.BMP", kDiffuseMap | kTwoSided);
    material(w, "B.BMP", kDiffuseMap | kAdditive);
    material(w, "", 0, 0.25f); // untextured: the diffuse colour counts
    material(w, "C.BMP", kDiffuseMap | kEnvMap | kColorKey);
    w.u16(0).u8(0);
    const auto r = parse(w.b);
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    const auto& m = r->scene.materials;
    EXPECT_TRUE(m[0].twoSided);
    EXPECT_EQ(m[1].alphaMode, lpv::scene::AlphaMode::Blend);
    EXPECT_EQ(m[2].name, "material 3");
    EXPECT_EQ(m[2].diffuseColor, glm::vec3(0.5f, 0.25f, 0.125f));
    EXPECT_FLOAT_EQ(m[2].opacity, 0.25f);
    EXPECT_EQ(m[2].alphaMode, lpv::scene::AlphaMode::Blend);
    EXPECT_TRUE(m[1].additive);
    EXPECT_FALSE(m[0].additive);
    EXPECT_FLOAT_EQ(m[3].glossiness, 0.75f);
    EXPECT_FLOAT_EQ(m[3].environmentRatio, 0.75f);
    EXPECT_EQ(m[3].environmentTexture, "ENV.BMP") << "not found: the stored name is kept";
    EXPECT_TRUE(m[3].colorKey);
    EXPECT_FALSE(m[0].colorKey);
    EXPECT_EQ(m[3].alphaMode, lpv::scene::AlphaMode::Mask);
}

// --------------------------------------------------------- texture lookup

struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() / ("lpv-4ds-test-" + std::to_string(std::random_device{}()));
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

TEST(FourDsReader, MissingTextureKeepsItsNameAndWarns) {
    TempDir dir;
    Writer w;
    header(w);
    w.u16(2);
    material(w, "NOPE.BMP");
    material(w, "nope.bmp"); // the same file: counted once
    w.u16(0).u8(0);
    const fs::path file = dir.path / "model.4ds";
    const auto r = readFourDs(w.b, file, {});
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    EXPECT_EQ(r->stats.texturesMissing, 1u);
    EXPECT_EQ(r->stats.texturesFound, 0u);
    EXPECT_EQ(r->scene.materials[0].diffuseTexture, "NOPE.BMP");
    EXPECT_TRUE(r->scene.materials[0].normalTexture.empty());
    ASSERT_EQ(countWarnings(*r, "'NOPE.BMP'"), 1u);
    EXPECT_EQ(countWarnings(*r, file.string()), 1u);
}

TEST(FourDsReader, SearchPathsAreUsedAndPathsCannotEscapeThem) {
    TempDir dir;
    Writer w;
    header(w);
    w.u16(2);
    material(w, "RED.BMP");
    material(w, "..\\..\\maps\\Red.bmp"); // only the file name counts
    w.u16(0).u8(0);
    ImportOptions options;
    options.textureSearchPaths = {kModels}; // its maps/ subfolder is searched too
    const auto r = readFourDs(w.b, dir.path / "model.4ds", options);
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    EXPECT_EQ(r->stats.texturesMissing, 0u);
    for (const auto& m : r->scene.materials) {
        EXPECT_EQ(fs::path(m.diffuseTexture), (kModels / "maps" / "red.bmp").lexically_normal());
        EXPECT_EQ(fs::path(m.normalTexture).filename(), "red_ddn.bmp");
        EXPECT_EQ(fs::path(m.specularTexture).filename(), "red_spec.bmp");
    }
    EXPECT_EQ(r->stats.texturesFound, 3u);
}

// --------------------------------------------------------- names

TEST(FourDsReader, Windows1250NamesBecomeValidUtf8) {
    Writer w;
    header(w);
    w.u16(0).u16(1);
    const std::string raw = {'d', 'v', 'e', char(0xF8), 'e', char(0x9A), char(0x81), char(0x01)};
    frame(w, 6, 0, 0, raw);
    dummyBox(w);
    w.u8(0);
    const auto r = parse(w.b);
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    // ř = U+0159, š = U+0161, undefined 0x81 = U+FFFD, control 0x01 = '?'.
    EXPECT_EQ(r->scene.objects[0].name, "dve\xC5\x99"
                                        "e\xC5\xA1\xEF\xBF\xBD?");
}

// --------------------------------------------------------- skipped types

TEST(FourDsReader, KnownNonMeshTypesAreParsedPastWithWarnings) {
    Writer w;
    header(w);
    w.u16(1);
    material(w, "RED.BMP");
    w.u16(9);
    frame(w, 5, 0, 0, "sector");
    w.u32(2049).u32(0).u32(3).u32(1).vec3(0, 0, 0).vec3(1, 0, 0).vec3(0, 1, 0).u16(0).u16(1).u16(2);
    dummyBox(w);
    w.u8(1).u8(2).u32(4).f32(0).f32(10).vec3(0, 0, 1).f32(0).vec3(0, 0, 0).vec3(1, 1, 1); // one portal
    frame(w, 12, 0, 0, "occluder");
    w.u32(3).u32(1).vec3(0, 0, 0).vec3(1, 0, 0).vec3(0, 1, 0).u16(0).u16(1).u16(2);
    frame(w, 7, 0, 0, "target");
    w.u16(0).u8(2).u16(1).u16(2);
    frame(w, 10, 0, 0, "joint");
    for (int i = 0; i < 16; ++i)
        w.f32(i % 5 == 0 ? 1.0f : 0.0f);
    w.u32(0);
    frame(w, 1, 6, 0, "glow");
    w.u8(2).f32(0).u16(1).f32(0.5f).u16(1);
    frame(w, 1, 8, 0, "mirror");
    for (int i = 0; i < 3 + 3 + 3 + 1 + 16 + 3 + 1; ++i)
        w.f32(0.0f);
    w.u32(3).u32(1).vec3(0, 0, 0).vec3(1, 0, 0).vec3(0, 1, 0).u16(0).u16(1).u16(2);
    frame(w, 1, 4, 0, "billboard");
    standardMesh(w);
    w.u32(1).u8(0);
    frame(w, 1, 5, 0, "morph");
    standardMesh(w);
    w.u8(2).u8(1).u8(1); // 2 targets, 1 region, 1 LOD
    w.u16(1).vec3(0, 0, 0).vec3(0, 0, 1).vec3(0, 0, 1).vec3(0, 0, 1).u8(1).u16(0);
    dummyBox(w);
    w.vec3(0, 0, 0).f32(1.0f);
    frame(w, 1, 2, 0, "skinned");
    standardMesh(w);
    w.u8(1).u32(0);
    dummyBox(w);
    for (int i = 0; i < 16; ++i)
        w.f32(0.0f);
    w.u32(1).u32(2).u32(0);
    dummyBox(w);
    w.f32(0.5f).f32(0.5f);
    w.u8(0);
    const auto r = parse(w.b);
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    EXPECT_EQ(r->scene.objects.size(), 9u);
    EXPECT_EQ(r->scene.meshes.size(), 3u) << "billboard, morph and skinned mesh keep their geometry";
    for (const char* part :
         {"frame type 5 (sector)", "frame type 12 (occluder)", "frame type 7 (target)",
          "frame type 10 (joint)", "visual type 6 (glow)", "visual type 8 (mirror)",
          "visual type 4 (billboard)", "visual type 5 (morph)", "visual type 2 (skinned mesh)"})
        EXPECT_EQ(countWarnings(*r, part), 1u) << part;
    for (const char* name : {"'sector'", "'occluder'", "'target'", "'joint'", "'glow'", "'mirror'",
                             "'billboard'", "'morph'", "'skinned'"})
        EXPECT_EQ(countWarnings(*r, name), 1u) << name;
}

TEST(FourDsReader, UnknownFrameTypeStopsCleanlyKeepingWhatWasRead) {
    Writer w = oneTriangleFile(3);
    frame(w, 2, 0, 0, "lamp"); // a light: layout unknown
    w.u32(0xdeadbeef);
    const auto r = parse(w.b);
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    EXPECT_EQ(r->scene.objects.size(), 2u);
    EXPECT_EQ(r->scene.meshes.size(), 1u);
    EXPECT_EQ(countWarnings(*r, "frame #2 'lamp': frame type 2 (light)"), 1u);
    EXPECT_EQ(countWarnings(*r, "remaining 1 of 3 frames"), 1u);
}

TEST(FourDsReader, UnknownVisualTypeStopsCleanly) {
    Writer w = oneTriangleFile(2);
    frame(w, 1, 7, 0, "projector");
    const auto r = parse(w.b);
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    EXPECT_EQ(countWarnings(*r, "'projector': visual type 7 (projector)"), 1u);
}

// --------------------------------------------------------- failure modes

TEST(FourDsReader, EmptyFileIsTruncated) {
    const auto r = parse({});
    expectError(r, ErrorCode::Truncated, 0, "signature");
}

TEST(FourDsReader, BadMagicIsUnknownFormat) {
    const Bytes bytes = {'O', 'B', 'J', ' ', 29, 0, 0, 0};
    expectError(parse(bytes), ErrorCode::UnknownFormat, 0, "4f 42 4a 20");
    EXPECT_FALSE(lpv::importers::looksLikeFourDs(bytes));
}

TEST(FourDsReader, NewerVersionNamesIt) {
    Writer w;
    header(w, 41);
    expectError(parse(w.b), ErrorCode::NewerVersion, 4, "version 41");
    EXPECT_FALSE(lpv::importers::looksLikeFourDs(w.b));
}

TEST(FourDsReader, OlderVersionIsUnknownFormat) {
    Writer w;
    header(w, 28);
    expectError(parse(w.b), ErrorCode::UnknownFormat, 4, "version 28");
}

TEST(FourDsReader, LooksLikeFourDs) {
    EXPECT_TRUE(lpv::importers::looksLikeFourDs(oneTriangleFile().b));
    EXPECT_TRUE(lpv::importers::looksLikeFourDs(readFile(kModels / "cube00.4ds")));
    EXPECT_FALSE(lpv::importers::looksLikeFourDs(Bytes{'4', 'D', 'S', 0}));
}

TEST(FourDsReader, TruncatedHeaderNamesTheOffset) {
    Writer w;
    header(w);
    w.b.resize(10); // signature, version and half of the timestamp
    expectError(parse(w.b), ErrorCode::Truncated, 6, "timestamp");
}

TEST(FourDsReader, EveryPrefixOfARealModelIsTruncated) {
    for (const char* name : {"cube00.4ds", "denjasno2.4ds"}) {
        const Bytes full = readFile(kModels / name);
        for (std::size_t n = 0; n < full.size(); ++n) {
            const Bytes cut(full.begin(), full.begin() + std::ptrdiff_t(n));
            const auto r = readFourDs(cut, name, {});
            ASSERT_FALSE(r.has_value()) << name << " cut at " << n;
            ASSERT_EQ(r.error().code, ErrorCode::Truncated)
                << name << " cut at " << n << ": " << r.error().describe();
            ASSERT_TRUE(r.error().location.starts_with("byte offset ")) << r.error().describe();
        }
    }
}

TEST(FourDsReader, SibenikCutAtManyOffsetsIsTruncated) {
    const Bytes full = readFile(kModels / "sibenik.4ds");
    std::mt19937 rng(4);
    std::uniform_int_distribution<std::size_t> pick(0, full.size() - 1);
    for (int i = 0; i < 60; ++i) {
        const std::size_t n = pick(rng);
        const Bytes cut(full.begin(), full.begin() + std::ptrdiff_t(n));
        const auto r = readFourDs(cut, "sibenik.4ds", {});
        ASSERT_FALSE(r.has_value()) << "cut at " << n;
        ASSERT_EQ(r.error().code, ErrorCode::Truncated) << "cut at " << n << ": " << r.error().describe();
        // The error points into the part that is there.
        const std::size_t offset = std::stoul(r.error().location.substr(std::strlen("byte offset ")));
        ASSERT_LE(offset, n);
    }
}

TEST(FourDsReader, HugeVertexCountIsTruncatedBeforeAllocating) {
    Writer w;
    header(w);
    w.u16(0).u16(1);
    frame(w, 1, 0, 0, "big");
    w.u16(0).u8(1).f32(0);
    w.u16(0xffff);
    const std::size_t at = w.size();
    w.vec3(0, 0, 0); // far fewer than 65535 x 32 bytes
    expectError(parse(w.b), ErrorCode::Truncated, at, "count of 65535 needs 2097120 bytes");
}

TEST(FourDsReader, HugeSectorCountIsTruncatedBeforeAllocating) {
    Writer w;
    header(w);
    w.u16(0).u16(1);
    frame(w, 5, 0, 0, "sector");
    w.u32(2049).u32(0).u32(0xffffffffu).u32(0xffffffffu);
    const std::size_t at = w.size();
    expectError(parse(w.b), ErrorCode::Truncated, at, "count of 4294967295");
}

TEST(FourDsReader, HugeMaterialCountIsTruncated) {
    Writer w;
    header(w);
    w.u16(0xffff);
    const std::size_t at = w.size();
    material(w, "A.BMP");
    expectError(parse(w.b), ErrorCode::Truncated, at, "materials: a count of 65535");
}

TEST(FourDsReader, ParentOutOfRangeIsAnError) {
    Writer w;
    header(w);
    w.u16(0).u16(1);
    const auto at = frame(w, 6, 0, 5, "orphan");
    dummyBox(w);
    w.u8(0);
    expectError(parse(w.b), ErrorCode::IndexOutOfRange, at.parent, "frame #1 'orphan' names parent #5");
}

TEST(FourDsReader, ParentCycleIsAnError) {
    Writer w;
    header(w);
    w.u16(0).u16(3);
    frame(w, 6, 0, 0, "root");
    dummyBox(w);
    const auto a = frame(w, 6, 0, 3, "a"); // a -> b -> a
    dummyBox(w);
    frame(w, 6, 0, 2, "b");
    dummyBox(w);
    w.u8(0);
    expectError(parse(w.b), ErrorCode::InvalidValue, a.parent, "cycle");
}

TEST(FourDsReader, SelfParentIsAnError) {
    Writer w;
    header(w);
    w.u16(0).u16(1);
    const auto at = frame(w, 6, 0, 1, "self");
    dummyBox(w);
    w.u8(0);
    expectError(parse(w.b), ErrorCode::InvalidValue, at.parent, "'self' is its own ancestor");
}

TEST(FourDsReader, FaceIndexOutOfRangeIsAnError) {
    Writer w;
    header(w);
    w.u16(1);
    material(w, "RED.BMP");
    w.u16(1);
    frame(w, 1, 0, 0, "bad");
    w.u16(0).u8(1);
    const std::size_t lodStart = w.size();
    triangleLod(w, 1, 7);
    const std::size_t faceAt = lodStart + 4 + 2 + 3 * 32 + 1 + 2;
    expectError(parse(w.b), ErrorCode::IndexOutOfRange, faceAt, "uses vertex 7 but the LOD has 3 vertices");
}

TEST(FourDsReader, MaterialIndexOutOfRangeIsAnError) {
    Writer w;
    header(w);
    w.u16(1);
    material(w, "RED.BMP");
    w.u16(1);
    frame(w, 1, 0, 0, "bad");
    w.u16(0).u8(1);
    const std::size_t lodStart = w.size();
    triangleLod(w, 9);
    const std::size_t materialAt = lodStart + 4 + 2 + 3 * 32 + 1 + 2 + 6;
    expectError(parse(w.b), ErrorCode::IndexOutOfRange, materialAt, "uses material 9 but the file has 1");
}

TEST(FourDsReader, InstanceOutOfRangeIsAnError) {
    Writer w;
    header(w);
    w.u16(0).u16(1);
    frame(w, 1, 0, 0, "copy");
    const std::size_t at = w.size();
    w.u16(40);
    w.u8(0);
    expectError(parse(w.b), ErrorCode::IndexOutOfRange, at, "instances frame #40");
}

TEST(FourDsReader, NonFiniteVertexIsAnError) {
    Writer w;
    header(w);
    w.u16(0).u16(1);
    frame(w, 1, 0, 0, "nan");
    w.u16(0).u8(1).f32(0).u16(1);
    const std::size_t at = w.size();
    w.vec3(std::nanf(""), 0, 0).vec3(0, 0, 1).f32(0).f32(0);
    w.u8(0).u8(0);
    expectError(parse(w.b), ErrorCode::NonFinite, at, "vertex 0 of LOD 0 of frame #1 'nan'");
}

TEST(FourDsReader, NonFiniteTransformIsAnError) {
    Writer w;
    header(w);
    w.u16(0).u16(1);
    const auto at = frame(w, 6, 0, 0, "inf", {std::numeric_limits<float>::infinity(), 0, 0});
    dummyBox(w);
    w.u8(0);
    expectError(parse(w.b), ErrorCode::NonFinite, at.transform, "transform");
}

// Found by fuzz_4ds (docs/fuzzing.md): a NaN ratio passed std::clamp into the
// material's glossiness and environment ratio.
TEST(FourDsReader, NonFiniteEnvironmentMapRatioIsAnError) {
    Writer w;
    header(w);
    w.u16(1);
    w.u32(kEnvMap).vec3(0.1f, 0.1f, 0.1f).vec3(0.5f, 0.25f, 0.125f).vec3(0, 0, 0).f32(1.0f);
    const std::size_t at = w.size();
    w.f32(std::nanf("")).str("ENV.BMP").str("");
    w.u16(0).u8(0);
    expectError(parse(w.b), ErrorCode::NonFinite, at, "material 1 has an environment map ratio");
}

// Random damage to small real files: an answer (scene or error) every time.
TEST(FourDsReader, RandomByteDamageNeverThrowsOrCrashes) {
    std::mt19937 rng(29);
    std::size_t errors = 0, scenes = 0;
    for (const char* name : {"cube00.4ds", "denjasno2.4ds", "scene.4ds"}) {
        const Bytes original = readFile(kModels / name);
        std::uniform_int_distribution<std::size_t> pos(0, original.size() - 1);
        std::uniform_int_distribution<int> value(0, 255), howMany(1, 8);
        for (int round = 0; round < 700; ++round) {
            Bytes damaged = original;
            for (int k = howMany(rng); k > 0; --k)
                damaged[pos(rng)] = static_cast<std::uint8_t>(value(rng));
            const auto r = readFourDs(damaged, name, {});
            (r.has_value() ? scenes : errors) += 1;
        }
    }
    EXPECT_GT(errors, 0u);
    EXPECT_GT(scenes, 0u);
}

} // namespace

// A stored colour below zero would make the project unsavable (colours are
// >= 0 there); importScene sets it to 0 and says so.
TEST(FourDsReader, NegativeColourIsClampedByTheImportWithAWarning) {
    Writer w;
    header(w);
    w.u16(1);
    w.u32(0).vec3(0.1f, 0.1f, 0.1f).vec3(-0.5f, 0.25f, 0.125f).vec3(0, -1, 0).f32(1.0f);
    w.str("");
    w.u16(1);
    frame(w, 1, 0, 0, "tri");
    standardMesh(w);
    w.u8(0);
    TempDir dir;
    const fs::path file = dir.path / "negative.4ds";
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(w.b.data()), std::streamsize(w.b.size()));
    const auto r = lpv::importers::importScene(file);
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    ASSERT_FALSE(r->scene.materials.empty());
    EXPECT_EQ(r->scene.materials[0].diffuseColor, glm::vec3(0.0f, 0.25f, 0.125f));
    EXPECT_EQ(r->scene.materials[0].emissive, glm::vec3(0.0f));
    EXPECT_EQ(countWarnings(*r, "negative colour"), 1u);
}

// 4ds materials with an emission colour take the importers' common path
// (EmissiveLamps.h, issue #22): a flat emissive quad becomes one area light
// whose visible surface is the quad, facing the way its normals do. Glow
// visuals are lens-flare sprites without geometry or power: not lights.
TEST(FourDsReader, AnEmissiveQuadBecomesOneAreaLightAGlowDoesNot) {
    Writer w;
    header(w);
    w.u16(1);
    w.u32(0).vec3(0.1f, 0.1f, 0.1f).vec3(1.0f, 1.0f, 1.0f).vec3(4.0f, 3.0f, 2.0f).f32(1.0f);
    w.str("");
    w.u16(2);
    frame(w, 1, 0, 0, "lamp", {0.0f, 3.0f, 0.0f});
    // A 1 x 0.5 m quad in y = 0 (frame space), its normals facing down.
    w.u16(0).u8(1).f32(0.0f).u16(4);
    for (const glm::vec2 xz : {glm::vec2(-0.5f, -0.25f), glm::vec2(0.5f, -0.25f), glm::vec2(0.5f, 0.25f),
                               glm::vec2(-0.5f, 0.25f)})
        w.vec3(xz.x, 0.0f, xz.y).vec3(0, -1, 0).f32(0.0f).f32(0.0f);
    w.u8(1).u16(2).u16(0).u16(1).u16(2).u16(0).u16(2).u16(3).u16(1);
    frame(w, 1, 6, 0, "flare", {0.0f, 2.0f, 0.0f});
    w.u8(1).f32(0.5f).u16(1); // one flare: position, material
    w.u8(0);
    TempDir dir;
    const fs::path file = dir.path / "lamp.4ds";
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(w.b.data()), std::streamsize(w.b.size()));
    const auto r = lpv::importers::importScene(file);
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    ASSERT_EQ(r->scene.lights.size(), 1u) << "the quad alone is a lamp";
    const lpv::scene::Light& lamp = r->scene.lights[0];
    EXPECT_EQ(lamp.type, lpv::scene::LightType::Area);
    EXPECT_NEAR(lamp.position.y, 3.0f, 1e-4f);
    EXPECT_NEAR(lamp.direction.y, -1.0f, 1e-4f) << "it shines the way its normals face";
    EXPECT_NEAR(lamp.size.x * lamp.size.y, 0.5f, 1e-4f);
    EXPECT_NEAR(lamp.intensity * lamp.color.r, 4.0f, 1e-3f);
    EXPECT_NEAR(lamp.intensity * lamp.color.b, 2.0f, 1e-3f);
    EXPECT_EQ(countWarnings(*r, "visual type 6 (glow)"), 1u);
}
