// What a scene may read (issue #29, docs/importers.md "What a scene may
// read"): references that lead out of the import's folders become missing
// textures (or a glTF buffer error) with a warning naming them, and never a
// stored path that a later copy into the project would follow; glTF node
// graphs are imported as trees.
#include "lpv/importers/Importer.h"
#include "lpv/scene/Project.h"
#include "lpv/scene/ProjectTextures.h"
#include "lpv/scene/ReadRoots.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

using namespace lpv;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// A private system file every Debian machine has; never an image.
const fs::path kSystemFile = "/etc/passwd";

class ReadPolicy : public ::testing::Test {
  protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("lpv-readpolicy-" + std::to_string(::getpid()));
        fs::remove_all(root_);
        dir_ = root_ / "scenes" / "model";
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(root_); }

    // One textured triangle; the buffer is embedded unless `bufferUri` is given.
    fs::path writeGltf(const std::string& name, const std::string& imageUri, json nodes = json(),
                       const std::string& bufferUri = "") {
        static const char* kTriangle = "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA/";
        if (nodes.is_null())
            nodes = json::array({{{"mesh", 0}}});
        json g = {
            {"asset", {{"version", "2.0"}}},
            {"scene", 0},
            {"scenes", json::array({{{"nodes", json::array({0})}}})},
            {"nodes", nodes},
            {"meshes", json::array({{{"primitives", json::array({{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}},
                                                                  {"material", 0}}})}}})},
            {"materials", json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}})},
            {"textures", json::array({{{"source", 0}}})},
            {"images", json::array({{{"uri", imageUri}}})},
            {"buffers", json::array({{{"byteLength", 60},
                                      {"uri", bufferUri.empty()
                                                  ? std::string("data:application/octet-stream;base64,") + kTriangle
                                                  : bufferUri}}})},
            {"bufferViews", json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
                                         {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 24}}})},
            {"accessors", json::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
                                        {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
                                       {{"bufferView", 1}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}}})},
        };
        const fs::path file = dir_ / name;
        std::ofstream(file) << g.dump();
        return file;
    }

    fs::path writeObj(const std::string& mapKd) {
        std::ofstream(dir_ / "m.mtl") << "newmtl a\nKd 1 1 1\nmap_Kd " << mapKd << "\n";
        std::ofstream(dir_ / "o.obj") << "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n"
                                         "usemtl a\nf 1/1 2/2 3/3\n";
        return dir_ / "o.obj";
    }

    static std::string allWarnings(const importers::ImportResult& r) {
        std::string out;
        for (const std::string& w : r.warnings)
            out += w + "\n";
        return out;
    }

    static const scene::Material& texturedMaterial(const importers::ImportResult& r) {
        for (const scene::Material& m : r.scene.materials)
            if (!m.diffuseTexture.empty())
                return m;
        ADD_FAILURE() << "no material with a diffuse texture";
        return r.scene.materials.front();
    }

    fs::path root_, dir_;
};

} // namespace

TEST_F(ReadPolicy, AbsoluteGltfImageUriIsAMissingTextureNotTheSystemFile) {
    auto r = importers::importScene(writeGltf("abs.gltf", kSystemFile.string()));
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    EXPECT_EQ(r->stats.texturesMissing, 1u);
    EXPECT_EQ(r->stats.texturesFound, 0u);
    EXPECT_EQ(texturedMaterial(*r).diffuseTexture, "passwd") << "only the last component is kept";
    EXPECT_NE(allWarnings(*r).find("texture '/etc/passwd' lies outside the folders it may be read from (" +
                                   dir_.string()),
              std::string::npos)
        << allWarnings(*r);
}

TEST_F(ReadPolicy, EscapesAndPercentEncodedEscapesAreRefused) {
    for (const std::string uri : {"../../../../../../../../etc/passwd", "%2e%2e/%2e%2e/%2e%2e/%2e%2e/%2e%2e/%2e%2e/%2e%2e/etc/passwd"}) {
        auto r = importers::importScene(writeGltf("esc.gltf", uri));
        ASSERT_TRUE(r.has_value()) << r.error().describe();
        EXPECT_EQ(r->stats.texturesMissing, 1u) << uri;
        EXPECT_EQ(texturedMaterial(*r).diffuseTexture, "passwd") << uri;
        EXPECT_NE(allWarnings(*r).find("lies outside the folders it may be read from"), std::string::npos)
            << allWarnings(*r);
    }
}

TEST_F(ReadPolicy, ASymbolicLinkOutOfTheSceneFolderIsRefused) {
    fs::create_symlink(kSystemFile, dir_ / "wall.png");
    auto r = importers::importScene(writeObj("wall.png"));
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    EXPECT_EQ(r->stats.texturesFound, 0u);
    EXPECT_EQ(texturedMaterial(*r).diffuseTexture, "wall.png");
    EXPECT_NE(allWarnings(*r).find("texture 'wall.png' of material 'a' was found as " + (dir_ / "wall.png").string() +
                                   ", which lies outside the folders it may be read from"),
              std::string::npos)
        << allWarnings(*r);
}

TEST_F(ReadPolicy, AnAbsoluteObjMapIsNeverStoredAsIs) {
    auto r = importers::importScene(writeObj(kSystemFile.string()));
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    EXPECT_EQ(texturedMaterial(*r).diffuseTexture, "passwd");
    // So the copy into a project finds nothing to copy.
    scene::Scene s = r->scene;
    auto copied = scene::copyTexturesIntoProject(s, root_ / "out" / "p.lpvproj");
    ASSERT_TRUE(copied.has_value()) << copied.error().describe();
    EXPECT_EQ(copied->copied, 0u);
    EXPECT_FALSE(fs::exists(root_ / "out" / "p.assets" / "textures"));
}

TEST_F(ReadPolicy, AssimpReadsNoMaterialLibraryFromOutside) {
    // A red material library outside the scene's folders: not read.
    const fs::path outside = root_ / "elsewhere";
    fs::create_directories(outside);
    std::ofstream(outside / "red.mtl") << "newmtl a\nKd 1 0 0\n";
    std::ofstream(dir_ / "o.obj") << "mtllib ../../elsewhere/red.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n";
    auto r = importers::importScene(dir_ / "o.obj");
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    for (const scene::Material& m : r->scene.materials)
        EXPECT_FALSE(m.diffuseColor == glm::vec3(1, 0, 0)) << "material '" << m.name << "' came from outside";
    // With the folder allowed it is.
    importers::ImportOptions options;
    options.allowPaths.push_back(outside);
    auto allowed = importers::importScene(dir_ / "o.obj", options);
    ASSERT_TRUE(allowed.has_value());
    EXPECT_TRUE(std::any_of(allowed->scene.materials.begin(), allowed->scene.materials.end(),
                            [](const scene::Material& m) { return m.diffuseColor == glm::vec3(1, 0, 0); }));
}

TEST_F(ReadPolicy, AFifoMaterialLibraryDoesNotBlockTheImport) {
    ASSERT_EQ(::mkfifo((dir_ / "pipe.mtl").c_str(), 0600), 0);
    std::ofstream(dir_ / "o.obj") << "mtllib pipe.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    auto r = importers::importScene(dir_ / "o.obj"); // would block forever opening the FIFO
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    EXPECT_EQ(r->scene.triangleCount(), 1u);
}

TEST_F(ReadPolicy, AllowPathWidensTheFolders) {
    const fs::path library = root_ / "library";
    fs::create_directories(library);
    std::ofstream(library / "brick.png") << "not really a png";
    importers::ImportOptions options;
    const fs::path file = writeGltf("lib.gltf", "../../library/brick.png");
    auto refused = importers::importScene(file, options);
    ASSERT_TRUE(refused.has_value());
    EXPECT_EQ(refused->stats.texturesFound, 0u);
    options.allowPaths.push_back(library);
    auto allowed = importers::importScene(file, options);
    ASSERT_TRUE(allowed.has_value());
    EXPECT_EQ(allowed->stats.texturesFound, 1u);
    EXPECT_EQ(fs::path(texturedMaterial(*allowed).diffuseTexture), library / "brick.png");
}

TEST_F(ReadPolicy, AGltfBufferOutsideTheFoldersIsAnError) {
    // tinygltf looks an absolute uri up under the scene's folder only.
    auto absolute = importers::importScene(writeGltf("abs.gltf", "x.png", json(), kSystemFile.string()));
    ASSERT_FALSE(absolute.has_value());
    EXPECT_EQ(absolute.error().file, (dir_ / "abs.gltf").string());
    EXPECT_EQ(absolute.error().message, "glTF: File not found : /etc/passwd");
    // An escape is found, and refused with the reason.
    auto escape = importers::importScene(writeGltf("esc.gltf", "x.png", json(), "../../../../../../../../etc/passwd"));
    ASSERT_FALSE(escape.has_value());
    // tinygltf 2.8 reads it ("File read error : PATH : why"), 2.9 asks its size
    // first ("Getting file size failed : PATH, err = why"): the same refusal.
    EXPECT_NE(escape.error().message.find("etc/passwd"), std::string::npos) << escape.error().message;
    EXPECT_NE(escape.error().message.find("lies outside the folders it may be read from (" + dir_.string()),
              std::string::npos)
        << escape.error().message;
}

TEST_F(ReadPolicy, GltfNodesListedTwiceOrSharedAreImportedOnce) {
    const json twice = json::array({{{"children", {1, 1}}}, {{"mesh", 0}}});
    auto r = importers::importScene(writeGltf("twice.gltf", "x.png", twice));
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    EXPECT_EQ(r->scene.objects.size(), 2u);
    EXPECT_NE(allWarnings(*r).find("node 0 lists node 1, which is already in the scene"), std::string::npos)
        << allWarnings(*r);

    // 24 levels, each listing the next twice: 2^24 copies if expanded.
    json dag = json::array();
    for (int i = 0; i < 24; ++i)
        dag.push_back({{"children", {i + 1, i + 1}}});
    dag.push_back({{"mesh", 0}});
    auto d = importers::importScene(writeGltf("dag.gltf", "x.png", dag));
    ASSERT_TRUE(d.has_value()) << d.error().describe();
    EXPECT_EQ(d->scene.objects.size(), 25u);
    EXPECT_NE(allWarnings(*d).find("14 more node links ignored for the same reasons"), std::string::npos)
        << allWarnings(*d);
}

TEST_F(ReadPolicy, AGltfNodeCycleIsCutWithAWarning) {
    const json cycle = json::array({{{"children", {1}}, {"mesh", 0}, {"name", "a"}}, {{"children", {0}}, {"name", "b"}}});
    auto r = importers::importScene(writeGltf("cycle.gltf", "x.png", cycle));
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    EXPECT_EQ(r->scene.objects.size(), 2u);
    EXPECT_EQ(r->scene.objects[1].parent, 0);
    EXPECT_NE(allWarnings(*r).find("node 1 ('b') lists node 0 ('a'), which is already in the scene"), std::string::npos)
        << allWarnings(*r);
}

TEST_F(ReadPolicy, ADeepGltfChainKeepsEveryNodeAndItsMesh) {
    constexpr int kDepth = 100000;
    json chain = json::array();
    for (int i = 0; i < kDepth; ++i)
        chain.push_back({{"children", {i + 1}}, {"translation", {0.0, 0.0, 1.0}}});
    chain.push_back({{"mesh", 0}});
    auto r = importers::importScene(writeGltf("chain.gltf", "x.png", chain));
    ASSERT_TRUE(r.has_value()) << r.error().describe();
    ASSERT_EQ(r->scene.objects.size(), std::size_t(kDepth + 1));
    EXPECT_EQ(r->scene.objects.back().mesh, 0) << "the mesh at the bottom is kept";
    EXPECT_EQ(r->scene.objects.back().parent, kDepth - 1);
}

TEST_F(ReadPolicy, ANumberInfiniteAsAFloatNamesTheInputFileAndField) {
    const json nodes = json::array({{{"mesh", 0}, {"translation", {1e39, 0.0, 0.0}}}});
    auto r = importers::importScene(writeGltf("big.gltf", "x.png", nodes));
    ASSERT_FALSE(r.has_value());
    EXPECT_EQ(r.error().file, (dir_ / "big.gltf").string());
    EXPECT_EQ(r.error().location, "nodes[0].translation[0]");
    EXPECT_NE(r.error().message.find("is not a finite 32-bit float"), std::string::npos) << r.error().message;
}

TEST_F(ReadPolicy, AnyValueASaveWouldRefuseIsReportedAgainstTheInputFile) {
    // A light intensity of 1e39 candela is a finite JSON number but infinite
    // as a float: the project the import would write refuses it, so the
    // import says so, naming the input and where the value lands.
    const fs::path file = writeGltf("light.gltf", "x.png");
    json g = json::parse(std::ifstream(file));
    g["extensionsUsed"] = {"KHR_lights_punctual"};
    g["extensions"]["KHR_lights_punctual"]["lights"] = json::array({{{"type", "point"}, {"intensity", 1e39}}});
    g["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    g["scenes"][0]["nodes"].push_back(1);
    std::ofstream(file) << g.dump();
    auto r = importers::importScene(file);
    ASSERT_FALSE(r.has_value());
    EXPECT_EQ(r.error().file, file.string());
    EXPECT_EQ(r.error().location, "as imported: lights[0].intensity");
    EXPECT_EQ(r.error().message, "inf is not a finite number");
}

TEST_F(ReadPolicy, AProjectNamingASystemFileKeepsOnlyTheNameAndCopiesNothing) {
    auto imported = importers::importScene(writeObj("x.png"));
    ASSERT_TRUE(imported.has_value());
    scene::Project p;
    p.name = "evil";
    p.scene = imported->scene;
    for (scene::Material& m : p.scene.materials) {
        m.diffuseTexture = kSystemFile.string();
        m.normalTexture = "../../../../../../etc/hostname";
    }
    const fs::path file = root_ / "proj" / "evil.lpvproj";
    fs::create_directories(file.parent_path());
    ASSERT_TRUE(scene::saveProject(p, file).has_value());

    auto loaded = scene::loadProject(file);
    ASSERT_TRUE(loaded.has_value()) << loaded.error().describe();
    ASSERT_EQ(loaded->loadWarnings.size(), 2 * p.scene.materials.size());
    EXPECT_NE(loaded->loadWarnings.front().find("texture '/etc/passwd' lies outside the folders the project may read "
                                                "from (" + file.parent_path().string()),
              std::string::npos)
        << loaded->loadWarnings.front();
    for (const scene::Material& m : loaded->scene.materials) {
        EXPECT_EQ(m.diffuseTexture, "passwd");
        EXPECT_EQ(m.normalTexture, "hostname");
    }
    // Saved elsewhere (lpv import X -o P, lpv radiosity P -o Q): nothing from /etc travels.
    auto copied = scene::copyTexturesIntoProject(loaded->scene, root_ / "proj2" / "q.lpvproj");
    ASSERT_TRUE(copied.has_value()) << copied.error().describe();
    EXPECT_EQ(copied->copied, 0u);

    // With the folder allowed, the reference stays.
    auto allowed = scene::loadProject(file, {"/etc"});
    ASSERT_TRUE(allowed.has_value());
    EXPECT_TRUE(allowed->loadWarnings.empty());
    EXPECT_EQ(allowed->scene.materials.front().diffuseTexture, kSystemFile.string());
}

TEST_F(ReadPolicy, ARelativeEscapeIsNotCopiedIntoTheProject) {
    scene::Scene s;
    scene::Material m;
    m.diffuseTexture = "../../../../../../../../etc/passwd";
    s.materials.push_back(m);
    auto copied = scene::copyTexturesIntoProject(s, root_ / "p" / "p.lpvproj");
    ASSERT_TRUE(copied.has_value()) << copied.error().describe();
    EXPECT_EQ(copied->copied, 0u);
    EXPECT_EQ(copied->missing, 1u);
}

TEST_F(ReadPolicy, CopiesAreNeverMoreWidelyReadableThanTheSourceOr644) {
    const fs::path privateFile = dir_ / "private.png", openFile = dir_ / "open.png";
    std::ofstream(privateFile) << "private bytes";
    std::ofstream(openFile) << "open bytes";
    ::chmod(privateFile.c_str(), 0640);
    ::chmod(openFile.c_str(), 0777);
    scene::Scene s;
    scene::Material a, b;
    a.diffuseTexture = privateFile.string();
    b.diffuseTexture = openFile.string();
    s.materials = {a, b};
    auto copied = scene::copyTexturesIntoProject(s, root_ / "p" / "p.lpvproj");
    ASSERT_TRUE(copied.has_value()) << copied.error().describe();
    ASSERT_EQ(copied->copied, 2u);
    auto mode = [&](const std::string& relative) {
        struct stat st {};
        ::stat((root_ / "p" / relative).c_str(), &st);
        return st.st_mode & 0777;
    };
    EXPECT_EQ(mode(s.materials[0].diffuseTexture), 0640u);
    EXPECT_EQ(mode(s.materials[1].diffuseTexture), 0644u);
}

TEST_F(ReadPolicy, LongTextureNamesAreShortenedWhenCopied) {
    // 150 'é' is 300 bytes: no file system holds that with our hash prefix.
    std::string longName;
    for (int i = 0; i < 150; ++i)
        longName += "\xC3\xA9";
    const std::string name = scene::textureCopyName(0x0123456789abcdefull, longName + ".png");
    EXPECT_LE(name.size(), 200u);
    EXPECT_TRUE(name.starts_with("0123456789abcdef-\xC3\xA9"));
    EXPECT_TRUE(name.ends_with(".png"));
    // Cut on a character boundary: the bytes before ".png" end a 2-byte character.
    const std::string stem = name.substr(17, name.size() - 17 - 4);
    EXPECT_EQ(stem.size() % 2, 0u);
    EXPECT_EQ(scene::textureCopyName(1, "short.png"), "0000000000000001-short.png");

    // A real copy of a 250-byte name works.
    const fs::path source = dir_ / (std::string(246, 'a') + ".png");
    std::ofstream(source) << "pixels";
    scene::Scene s;
    scene::Material m;
    m.diffuseTexture = source.string();
    s.materials.push_back(m);
    auto copied = scene::copyTexturesIntoProject(s, root_ / "p" / "p.lpvproj");
    ASSERT_TRUE(copied.has_value()) << copied.error().describe();
    EXPECT_EQ(copied->copied, 1u);
    EXPECT_TRUE(fs::is_regular_file(root_ / "p" / s.materials[0].diffuseTexture));
}

TEST(ReadRoots, FoldersFifosAndOutsidePathsAreRefused) {
    const fs::path dir = fs::temp_directory_path() / ("lpv-readroots-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "sub");
    std::ofstream(dir / "file.png") << "x";
    ASSERT_EQ(::mkfifo((dir / "pipe.png").c_str(), 0600), 0);
    const scene::ReadRoots roots({dir});
    EXPECT_FALSE(roots.refusal(dir / "file.png").has_value());
    EXPECT_FALSE(roots.refusal(dir / "sub" / ".." / "file.png").has_value());
    EXPECT_EQ(roots.refusal(dir / "sub").value_or(""), "is a folder, not a file");
    EXPECT_NE(roots.refusal(dir / "pipe.png").value_or("").find("FIFO"), std::string::npos);
    EXPECT_NE(roots.refusal(dir / ".." / "x.png").value_or("").find("lies outside"), std::string::npos);
    // A sibling whose name starts like the root is not inside it.
    EXPECT_FALSE(roots.contains(fs::path(dir.string() + "-other") / "x.png"));
    EXPECT_TRUE(roots.contains(dir / "not-yet.png"));
    fs::remove_all(dir);
}
