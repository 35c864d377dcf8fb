// OBJ and 3DS through Assimp, on the real scenes in ../shared/scenes and on
// the oddities their SOURCE.md files list. Counts were verified by hand
// against SOURCE.md (see the comments) and by running the importer.
#include "lpv/importers/Importer.h"
#include "TestPaths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace lpv;
namespace fs = std::filesystem;

namespace {

fs::path scenes() { return fs::path(test::kSharedScenesDir); }

importers::ImportResult importOk(const fs::path& file, const importers::ImportOptions& options = {}) {
    auto r = importers::importScene(file, options);
    EXPECT_TRUE(r.has_value()) << (r ? "" : r.error().describe());
    return r ? std::move(*r) : importers::ImportResult{};
}

std::size_t countWarnings(const importers::ImportResult& r, const std::string& text) {
    return std::size_t(std::count_if(r.warnings.begin(), r.warnings.end(),
                                     [&](const std::string& w) { return w.find(text) != std::string::npos; }));
}

const scene::Material* findMaterial(const scene::Scene& s, const std::string& name) {
    for (const auto& m : s.materials)
        if (m.name == name)
            return &m;
    return nullptr;
}

bool allFinite(const scene::Mesh& m) {
    for (const auto& n : m.normals)
        if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z) || std::abs(glm::length(n) - 1.0f) > 1e-3f)
            return false;
    return m.normals.size() == m.positions.size();
}

struct TempDir {
    fs::path path = fs::temp_directory_path() / ("lpv-assimp-test-" + std::to_string(::getpid()));
    TempDir() { fs::create_directories(path); }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

} // namespace

// Triangles per SOURCE.md ("triangles (after fan split)").
struct CornellFile {
    const char* file;
    std::size_t triangles;
};
const CornellFile kCornellFiles[] = {
    {"CornellBox-Empty-CO.obj", 12},   {"CornellBox-Empty-RG.obj", 12},  {"CornellBox-Empty-Squashed.obj", 12},
    {"CornellBox-Empty-White.obj", 12}, {"CornellBox-Glossy-Floor.obj", 1112}, {"CornellBox-Glossy.obj", 1112},
    {"CornellBox-Mirror.obj", 36},     {"CornellBox-Original.obj", 36},  {"CornellBox-Sphere.obj", 2188},
    {"CornellBox-Water.obj", 7088},
};

TEST(AssimpImporter, EveryCornellObjImportsWithItsTriangleCount) {
    for (const auto& c : kCornellFiles) {
        SCOPED_TRACE(c.file);
        const auto r = importOk(scenes() / "cornell" / c.file);
        EXPECT_EQ(r.stats.triangles, c.triangles);
        EXPECT_EQ(r.stats.degenerateTrianglesDropped, 0u);
        for (const auto& m : r.scene.meshes)
            EXPECT_TRUE(allFinite(m)) << m.name;
    }
}

// CRLF, negative indices, quads, no normals: the walls must come out flat.
TEST(AssimpImporter, CornellOriginalQuadsGetFlatNormalsAndTheLightIsEmissive) {
    const auto r = importOk(scenes() / "cornell/CornellBox-Original.obj");
    EXPECT_EQ(r.stats.triangles, 36u);
    for (const auto& mesh : r.scene.meshes) {
        ASSERT_EQ(mesh.normals.size(), mesh.positions.size()) << "normals were generated";
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                            c = mesh.positions[mesh.indices[t + 2]];
            const glm::vec3 face = glm::normalize(glm::cross(b - a, c - a));
            for (int k = 0; k < 3; ++k)
                EXPECT_GT(glm::dot(face, mesh.normals[mesh.indices[t + std::size_t(k)]]), 0.999f)
                    << mesh.name << " triangle " << t / 3 << ": a box has hard edges";
        }
    }
    const scene::Material* light = findMaterial(r.scene, "light");
    ASSERT_NE(light, nullptr);
    EXPECT_EQ(light->emissive, glm::vec3(17.0f, 12.0f, 4.0f)) << "Ke 17 12 4";
    const auto bounds = r.scene.worldBounds();
    EXPECT_NEAR(bounds.min.x, -1.02f, 0.01f);
    EXPECT_NEAR(bounds.max.y, 1.99f, 0.01f);
}

TEST(AssimpImporter, MaterialUsedButNotDefinedIsAWarningNotAFailure) {
    // CornellBox-Glossy.obj says `usemtl light`, which CornellBox-Glossy.mtl does not define.
    const auto r = importOk(scenes() / "cornell/CornellBox-Glossy.obj");
    EXPECT_EQ(r.stats.triangles, 1112u);
    EXPECT_GE(countWarnings(r, "light"), 1u) << "Assimp's 'failed to locate material light' reaches the summary";
}

TEST(AssimpImporter, TrailingSpaceInAMaterialNameStillMatches) {
    // CornellBox-Mirror.mtl: `newmtl tallBox ` (trailing space), the OBJ: `usemtl tallBox`.
    const auto r = importOk(scenes() / "cornell/CornellBox-Mirror.obj");
    const scene::Material* tall = findMaterial(r.scene, "tallBox");
    ASSERT_NE(tall, nullptr);
    EXPECT_NEAR(tall->specularColor.r, 0.95f, 1e-4f) << "the MTL's Ks, not a default material";
    EXPECT_NEAR(tall->diffuseColor.g, 0.01f, 1e-4f);
    const auto tallIndex = std::uint32_t(tall - r.scene.materials.data());
    std::size_t tallTriangles = 0;
    for (const auto& mesh : r.scene.meshes)
        for (const auto& sub : mesh.submeshes)
            if (sub.materialIndex == tallIndex)
                tallTriangles += sub.indexCount / 3;
    EXPECT_EQ(tallTriangles, 12u) << "the 6 quads after `usemtl tallBox` (lines 114-157) use it";
}

TEST(AssimpImporter, ObjectWithVerticesButNoFacesAddsNothing) {
    // CornellBox-Empty-Squashed.obj: `# object water` has 2,550 v and 2,432 vn and no faces.
    const auto r = importOk(scenes() / "cornell/CornellBox-Empty-Squashed.obj");
    EXPECT_EQ(r.stats.triangles, 12u);
    std::size_t vertices = 0;
    for (const auto& m : r.scene.meshes)
        vertices += m.positions.size();
    EXPECT_LT(vertices, 100u) << "the faceless water's 2,550 vertices are not imported";
}

TEST(AssimpImporter, SponzaObj) {
    const auto r = importOk(scenes() / "sponza/sponza.obj");
    // SOURCE.md: 66,450 triangles after triangulation, 6 of them exactly zero-area. A
    // seventh (vertices 13593/13594/13596) has area 6.5e-7 on edges 1.3 long, i.e.
    // area / edge^2 = 3.8e-7, a few float ulps: degenerate too (checked with a
    // double-precision script over the OBJ).
    EXPECT_EQ(r.stats.triangles + r.stats.degenerateTrianglesDropped, 66450u);
    EXPECT_EQ(r.stats.degenerateTrianglesDropped, 7u);
    // 20 MTL materials, all used (Assimp adds its DefaultMaterial).
    for (const char* name : {"sp_00_svod", "sp_01_stub_baza_", "sp_00_vrata_krug"})
        EXPECT_NE(findMaterial(r.scene, name), nullptr) << name;
    // 18 names; KAMEN-stup.JPG and KAMEN-stup.jpg are one file, and 10 match only case-insensitively.
    EXPECT_EQ(r.stats.texturesFound, 17u);
    EXPECT_EQ(r.stats.texturesMissing, 0u);
    const scene::Material* vault = findMaterial(r.scene, "sp_00_svod");
    ASSERT_NE(vault, nullptr);
    EXPECT_EQ(fs::path(vault->diffuseTexture).filename(), "KAMEN-stup.JPG");
    EXPECT_EQ(vault->heightTexture, vault->diffuseTexture) << "its bump map is the same file, spelled .jpg";
    const scene::Material* arch = findMaterial(r.scene, "sp_svod_kapitel");
    ASSERT_NE(arch, nullptr);
    EXPECT_EQ(fs::path(arch->diffuseTexture).filename(), "00_skap.JPG") << "00_SKAP.JPG in the MTL";
    for (const auto& m : r.scene.meshes) {
        EXPECT_TRUE(allFinite(m)) << m.name << ": Sponza has no normals, they are generated";
        EXPECT_EQ(m.tangents.size(), m.positions.size()) << m.name << ": tangents for the bump maps";
    }
    const auto b = r.scene.worldBounds();
    EXPECT_NEAR(b.min.x, -17.40f, 0.01f);
    EXPECT_NEAR(b.max.y, 15.65f, 0.01f);
}

TEST(AssimpImporter, Sponza3dsWithItsCameraAndSun) {
    const auto r = importOk(scenes() / "sponza/sponza.3ds");
    // SOURCE.md: 66,454 triangles in 37 meshes; camera Camera01, light Sun01.
    EXPECT_EQ(r.stats.triangles + r.stats.degenerateTrianglesDropped, 66454u);
    ASSERT_EQ(r.scene.cameras.size(), 1u);
    EXPECT_EQ(r.scene.cameras[0].name, "Camera01");
    ASSERT_EQ(r.scene.lights.size(), 1u);
    EXPECT_EQ(r.scene.lights[0].name, "Sun01");
    // 11 upper-case 8.3 names, 9 of which match only case-insensitively.
    EXPECT_EQ(r.stats.texturesFound, 11u);
    EXPECT_EQ(r.stats.texturesMissing, 0u);
    const auto b = r.scene.worldBounds();
    EXPECT_NEAR(b.min.x, -17.40f, 0.05f);
    EXPECT_NEAR(b.max.x, 17.42f, 0.05f);
}

TEST(AssimpImporter, SibenikObj) {
    const auto r = importOk(scenes() / "sibenik/sibenik.obj");
    // SOURCE.md: 73,564 faces, all triangles.
    EXPECT_EQ(r.stats.triangles + r.stats.degenerateTrianglesDropped, 73564u);
    // kamen, kamen-bump, KAMEN-stup, mramor6x6, mramor6x6-bump.
    EXPECT_EQ(r.stats.texturesFound, 5u);
    EXPECT_EQ(r.stats.texturesMissing, 0u);
    const scene::Material* glass = findMaterial(r.scene, "staklo_crveno");
    ASSERT_NE(glass, nullptr);
    EXPECT_GT(glass->translucency, 0.0f) << "coloured Tf: stained glass";
    EXPECT_EQ(glass->alphaMode, scene::AlphaMode::Blend) << "d 0.8";
    const auto b = r.scene.worldBounds();
    EXPECT_NEAR(b.max.x, 20.14f, 0.01f);
    EXPECT_NEAR(b.min.z, -8.50f, 0.01f);
}

TEST(AssimpImporter, MissingTextureIsAWarningNamingItAndTheImportSucceeds) {
    TempDir dir;
    std::ofstream(dir.path / "tri.obj") << "mtllib tri.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                           "usemtl painted\nf 1/1 2/2 3/3\n";
    std::ofstream(dir.path / "tri.mtl") << "newmtl painted\nKd 1 1 1\nmap_Kd Missing Picture.png\n";
    const auto r = importOk(dir.path / "tri.obj");
    EXPECT_EQ(r.stats.triangles, 1u);
    EXPECT_EQ(r.stats.texturesMissing, 1u);
    EXPECT_EQ(countWarnings(r, "'Missing Picture.png'"), 1u);
    const scene::Material* m = findMaterial(r.scene, "painted");
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->diffuseTexture, "Missing Picture.png") << "the name is kept; the renderer draws a placeholder";
}

TEST(AssimpImporter, TextureSearchPathIsUsed) {
    TempDir dir;
    fs::create_directories(dir.path / "model");
    fs::create_directories(dir.path / "library/maps");
    std::ofstream(dir.path / "model/tri.obj") << "mtllib tri.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl p\nf 1 2 3\n";
    std::ofstream(dir.path / "model/tri.mtl") << "newmtl p\nmap_Kd WALL.PNG\n";
    std::ofstream(dir.path / "library/maps/wall.png") << "not really a png";
    importers::ImportOptions options;
    options.textureSearchPaths.push_back(dir.path / "library");
    const auto r = importOk(dir.path / "model/tri.obj", options);
    EXPECT_EQ(r.stats.texturesFound, 1u);
    EXPECT_EQ(r.stats.texturesMissing, 0u);
}

TEST(AssimpImporter, GarbageWithAnObjExtensionIsAnErrorNotACrash) {
    TempDir dir;
    std::ofstream(dir.path / "bad.obj", std::ios::binary) << std::string("\x01\x02\xff\xfe garbage\nf 9 9 9\n", 22);
    auto r = importers::importScene(dir.path / "bad.obj");
    if (r) // Assimp may accept it as an empty scene; then nothing was made up
        EXPECT_EQ(r->stats.triangles, 0u);
    else
        EXPECT_NE(r.error().describe().find("bad.obj"), std::string::npos);
}

// The Cornell OBJ's lamp is an emissive quad (Ke 17 12 4): it becomes one area light of its
// size and radiance, facing down, and the quad stays as its visible surface (issue #22).
TEST(AssimpImporter, TheCornellLampQuadBecomesAnAreaLight) {
    const auto r = importOk(scenes() / "cornell/CornellBox-Original.obj");
    ASSERT_EQ(r.scene.lights.size(), 1u);
    const scene::Light& lamp = r.scene.lights[0];
    EXPECT_EQ(lamp.type, scene::LightType::Area);
    EXPECT_EQ(lamp.shape, scene::AreaShape::Rectangle);
    EXPECT_EQ(lamp.unit, scene::AreaUnit::Radiance);
    EXPECT_FALSE(lamp.twoSided);
    // The quad spans x -0.24..0.23 and z -0.22..0.16 at y 1.98.
    const float w = std::max(lamp.size.x, lamp.size.y), h = std::min(lamp.size.x, lamp.size.y);
    EXPECT_NEAR(w, 0.47f, 1e-4f);
    EXPECT_NEAR(h, 0.38f, 1e-4f);
    EXPECT_NEAR(lamp.position.x, -0.005f, 1e-4f);
    EXPECT_NEAR(lamp.position.y, 1.98f, 1e-4f);
    EXPECT_NEAR(lamp.position.z, -0.03f, 1e-4f);
    EXPECT_NEAR(lamp.direction.y, -1.0f, 1e-5f) << "it lights the room below";
    EXPECT_NEAR(lamp.color.r * lamp.intensity, 17.0f, 1e-4f);
    EXPECT_NEAR(lamp.color.g * lamp.intensity, 12.0f, 1e-4f);
    EXPECT_NEAR(lamp.color.b * lamp.intensity, 4.0f, 1e-4f);
    ASSERT_EQ(r.notes.size(), 1u);
    EXPECT_NE(r.notes[0].find("became the area light"), std::string::npos) << r.notes[0];
    // The quad is still there, emissive: what a camera sees of the lamp.
    const scene::Material* light = findMaterial(r.scene, "light");
    ASSERT_NE(light, nullptr);
    EXPECT_EQ(light->emissive, glm::vec3(17.0f, 12.0f, 4.0f));
}

// Emitters that are not flat rectangles or discs stay emissive surfaces: a glowing cube.
TEST(AssimpImporter, AnEmissiveCubeStaysAnEmissiveSurface) {
    const fs::path dir = fs::temp_directory_path() / ("lpv-glow-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "glow.mtl") << "newmtl glow\nKd 0.5 0.5 0.5\nKe 5 5 5\n";
    std::ofstream(dir / "glow.obj") << "mtllib glow.mtl\n"
                                       "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                       "usemtl glow\n"
                                       "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    const auto r = importOk(dir / "glow.obj");
    EXPECT_TRUE(r.scene.lights.empty()) << "a cube is no panel";
    EXPECT_TRUE(r.notes.empty());
    fs::remove_all(dir);
}

// ---- material libraries with statements outside any material (fuzz_obj) -----
// Assimp 5.2.5 writes a texture statement before the first `newmtl` into a
// material that does not exist (SEGV), and fails on a library of 1 to 7
// bytes ("File is too small"), leaking its stream. The importer serves the
// library without the statement lines before its first `newmtl`, padded to 8
// bytes, and says what it dropped.

namespace {

std::string droppedWarning(const fs::path& obj, const fs::path& library, int lines) {
    return obj.string() + ": material library '" + library.string() + "': " + std::to_string(lines) +
           (lines == 1 ? " line" : " lines") + " before its first 'newmtl' dropped (statements outside any material)";
}

const char* const kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl painted\nf 1/1 2/2 3/3\n";

} // namespace

TEST(AssimpImporter, TextureBeforeAnyNewmtlIsDroppedWithAWarningNotACrash) {
    TempDir dir;
    std::ofstream(dir.path / "tri.obj") << "mtllib tri.mtl\n" << kTriangle;
    std::ofstream(dir.path / "tri.mtl") << "# by hand\nmap_Kd a.png\n  Ns 10\n\n  newmtl painted\nKd 1 0 0\n"
                                           "map_Kd b.png\n";
    const auto r = importOk(dir.path / "tri.obj");
    EXPECT_EQ(r.stats.triangles, 1u);
    EXPECT_EQ(countWarnings(r, droppedWarning(dir.path / "tri.obj", dir.path / "tri.mtl", 2)), 1u);
    EXPECT_EQ(countWarnings(r, "'a.png'"), 0u) << "the dropped texture is not looked for";
    const scene::Material* m = findMaterial(r.scene, "painted");
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->diffuseColor, glm::vec3(1, 0, 0)) << "the statements after newmtl are read";
    EXPECT_EQ(m->diffuseTexture, "b.png");
}

TEST(AssimpImporter, LibraryOfOnlyATextureStatementImportsWithAWarning) {
    // fuzz_obj's minimal reproducer: the library is the one line `map_Kd a.png`.
    TempDir dir;
    std::ofstream(dir.path / "tri.obj") << "mtllib tri.mtl\n" << kTriangle;
    std::ofstream(dir.path / "tri.mtl") << "map_Kd a.png\n";
    const auto r = importOk(dir.path / "tri.obj");
    EXPECT_EQ(r.stats.triangles, 1u);
    EXPECT_EQ(countWarnings(r, droppedWarning(dir.path / "tri.obj", dir.path / "tri.mtl", 1)), 1u);
    EXPECT_EQ(r.stats.texturesMissing, 0u);
}

TEST(AssimpImporter, LibrariesShorterThanEightBytesAreRead) {
    TempDir dir;
    std::ofstream(dir.path / "tri.obj") << "mtllib tri.mtl\n" << kTriangle;
    std::ofstream(dir.path / "tri.mtl") << "Ns 10\n"; // 6 bytes: Assimp alone fails with "File is too small"
    auto r = importOk(dir.path / "tri.obj");
    EXPECT_EQ(r.stats.triangles, 1u);
    EXPECT_EQ(countWarnings(r, droppedWarning(dir.path / "tri.obj", dir.path / "tri.mtl", 1)), 1u);
    std::ofstream(dir.path / "tri.mtl", std::ios::trunc) << "newmtl\n"; // 7 bytes, nothing to drop
    r = importOk(dir.path / "tri.obj");
    EXPECT_EQ(r.stats.triangles, 1u);
    EXPECT_EQ(countWarnings(r, "dropped"), 0u);
}

TEST(AssimpImporter, LibrariesNotNamedMtlAreRepairedToo) {
    // `mtllib` may name any file, the OBJ itself included: everything Assimp
    // opens while it parses the OBJ is read as a material library.
    TempDir dir;
    std::ofstream(dir.path / "notes.obj") << "mtllib notes.txt\n" << kTriangle;
    std::ofstream(dir.path / "notes.txt") << "map_Kd a.png\nnewmtl painted\nKd 0 1 0\n";
    auto r = importOk(dir.path / "notes.obj");
    EXPECT_EQ(countWarnings(r, droppedWarning(dir.path / "notes.obj", dir.path / "notes.txt", 1)), 1u);
    const scene::Material* m = findMaterial(r.scene, "painted");
    ASSERT_NE(m, nullptr);
    EXPECT_EQ(m->diffuseColor, glm::vec3(0, 1, 0));

    // The OBJ parser skips `map_Kd`; read as its own library, its 10 lines are statements.
    std::ofstream(dir.path / "self.obj") << "mtllib self.obj\nmap_Kd a.png\n" << kTriangle;
    r = importOk(dir.path / "self.obj");
    EXPECT_EQ(r.stats.triangles, 1u);
    EXPECT_EQ(countWarnings(r, droppedWarning(dir.path / "self.obj", dir.path / "self.obj", 10)), 1u);
}

TEST(AssimpImporter, Utf16LibraryIsNotReadButDoesNotCrash) {
    // Assimp 5.2.5 converts UTF-16 text into a buffer it then throws away, so
    // it parses the raw bytes: every character a line, `newmtl` never seen,
    // and the `a` of the material's name an anisotropy statement (SEGV).
    TempDir dir;
    std::ofstream(dir.path / "tri.obj") << "mtllib tri.mtl\n" << kTriangle;
    std::string utf16 = "\xFF\xFE";
    for (char c : std::string("newmtl a\n"))
        utf16 += {c, '\0'};
    std::ofstream(dir.path / "tri.mtl", std::ios::binary) << utf16;
    const auto r = importOk(dir.path / "tri.obj");
    EXPECT_EQ(r.stats.triangles, 1u);
    // "\xFF\xFEn", "e", "w", "m", "t", "l", "a"; the space stays.
    EXPECT_EQ(countWarnings(r, droppedWarning(dir.path / "tri.obj", dir.path / "tri.mtl", 7)), 1u);
}
