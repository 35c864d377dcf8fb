// Bad input never crashes and never writes: each case below damages a saved
// project in one way and checks the error's code, file and location, and that
// the folder (the damaged project, its assets and a good project beside it)
// is byte-for-byte the same afterwards, with no new files.
#include "ProjectTestSupport.h"

#include "lpv/scene/MeshAsset.h"
#include "lpv/scene/Project.h"

#include <gtest/gtest.h>

#include <bit>
#include <limits>
#include <chrono>
#include <map>
#include <set>
#include <stdexcept>

#ifndef _WIN32
#include <sys/stat.h>
#include <unistd.h>
#endif

using namespace lpv::scene;
using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

void putU32(std::string& bytes, std::size_t at, std::uint32_t v) {
    for (std::size_t i = 0; i < 4; ++i)
        bytes[at + i] = static_cast<char>((v >> (8 * i)) & 0xffu);
}

// After editing an asset's payload: a valid checksum, so only the edit is wrong.
void resealChecksum(std::string& asset) {
    const std::uint64_t sum = contentHash64(std::string_view(asset).substr(kMeshAssetHeaderSize));
    putU32(asset, 40, static_cast<std::uint32_t>(sum));
    putU32(asset, 44, static_cast<std::uint32_t>(sum >> 32));
}

std::string hex16(std::uint64_t v) {
    std::string out(16, '0');
    for (int i = 15; i >= 0; --i, v >>= 4)
        out[static_cast<std::size_t>(i)] = "0123456789abcdef"[v & 0xf];
    return out;
}

// Everything in a folder: relative path -> bytes ("<folder>" for folders).
using Snapshot = std::map<std::string, std::string>;

Snapshot snapshot(const fs::path& root) {
    Snapshot out;
    for (const auto& entry : fs::recursive_directory_iterator(root))
        out[entry.path().lexically_relative(root).generic_string()] =
            entry.is_directory() ? std::string("<folder>") : readFile(entry.path());
    return out;
}

std::string differences(const Snapshot& before, const Snapshot& after) {
    std::string out;
    for (const auto& [path, bytes] : before)
        if (!after.contains(path))
            out += " removed: " + path;
        else if (after.at(path) != bytes)
            out += " changed: " + path;
    for (const auto& [path, bytes] : after)
        if (!before.contains(path))
            out += " added: " + path;
    return out;
}

const ParameterInfo& someIntParameter() {
    for (const ParameterInfo& p : ParameterRegistry::instance().all())
        if (p.type == ParameterType::Int && p.maxValue < 1e6)
            return p;
    throw std::logic_error("the registry has no int parameter");
}

int nonDefaultValue(const ParameterInfo& p) {
    const int low = static_cast<int>(p.minValue);
    return low != std::get<int>(p.defaultValue) ? low : static_cast<int>(p.maxValue);
}

// Small, with values that occur once in the file so a test can edit them.
Project goodProject() {
    Project p;
    p.name = "good";
    Material wall;
    wall.name = "wall";
    wall.diffuseColor = {0.25f, 0.125f, 0.375f};
    p.scene.materials = {wall};

    p.scene.meshes = {unitQuadMesh()};

    p.scene.objects = {Object{"base", 0, -1, {}, true, {}}, Object{"child", -1, 0, {}, true, {}}};
    Light sun;
    sun.name = "sun";
    p.scene.lights = {sun};
    Camera cam;
    cam.name = "cam";
    p.scene.cameras = {cam};
    p.scene.sky.intensity = 0.75f;
    const ParameterInfo& param = someIntParameter();
    EXPECT_TRUE(p.parameters.set(param.key, nonDefaultValue(param)));
    ParameterPreset bright{"bright", {}};
    EXPECT_TRUE(bright.parameters.set("lpv.intensity", 2.5));
    EXPECT_TRUE(bright.parameters.set("output.tonemapper", std::string("reinhard")));
    p.presets = {bright, ParameterPreset{"flat", {}}};
    return p;
}

class ProjectBadInput : public TempDirTest {
protected:
    ProjectBadInput() : TempDirTest("lpv-bad-") {}

    void SetUp() override {
        TempDirTest::SetUp();
        // A good project beside the damaged one must survive every failed load.
        ASSERT_TRUE(saveProject(goodProject(), dir_ / "good.lpvproj"));
        ASSERT_TRUE(saveProject(goodProject(), bad_ = dir_ / "bad.lpvproj"));
    }

    // The damaged project's only mesh asset.
    fs::path badAsset() const {
        std::vector<fs::path> assets;
        for (const auto& entry : fs::directory_iterator(dir_ / "bad.assets" / "meshes"))
            assets.push_back(entry.path());
        EXPECT_EQ(assets.size(), 1u);
        return assets.empty() ? fs::path() : assets.front();
    }

    // Replaces the one occurrence of `from` in the damaged project file.
    void editBad(const std::string& from, const std::string& to) {
        std::string text = readFile(bad_);
        const std::size_t at = text.find(from);
        ASSERT_NE(at, std::string::npos) << "\"" << from << "\" is not in\n" << text;
        ASSERT_EQ(text.find(from, at + 1), std::string::npos) << "\"" << from << "\" is not unique";
        text.replace(at, from.size(), to);
        writeFile(bad_, text);
    }

    // Loads `file` expecting an error, and checks the folder did not change.
    Error loadFails(const fs::path& file) {
        const Snapshot before = snapshot(dir_);
        const auto loaded = loadProject(file);
        const Snapshot after = snapshot(dir_);
        EXPECT_TRUE(before == after) << "a failed load changed the folder:" << differences(before, after);
        if (loaded) {
            ADD_FAILURE() << "loading " << file << " succeeded";
            return Error{};
        }
        EXPECT_FALSE(loaded.error().message.empty());
        return loaded.error();
    }

    fs::path bad_;
};

} // namespace

TEST_F(ProjectBadInput, GoodProjectLoads) {
    // The baseline every other case damages.
    const auto loaded = loadProject(bad_);
    ASSERT_TRUE(loaded) << loaded.error().describe();
    EXPECT_EQ(*loaded, goodProject());
}

TEST_F(ProjectBadInput, MissingFileIsFileNotFound) {
    const Error e = loadFails(dir_ / "absent.lpvproj");
    EXPECT_EQ(e.code, ErrorCode::FileNotFound);
    EXPECT_EQ(e.file, (dir_ / "absent.lpvproj").string());
}

TEST_F(ProjectBadInput, CutOffJsonIsTruncated) {
    const std::string text = readFile(bad_);
    writeFile(bad_, text.substr(0, text.size() / 2));
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::Truncated);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_EQ(e.location, "byte offset " + std::to_string(text.size() / 2));
}

TEST_F(ProjectBadInput, EmptyFileIsTruncated) {
    writeFile(bad_, "");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::Truncated);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_EQ(e.location, "byte offset 0");
    EXPECT_TRUE(contains(e.message, "empty")) << e.message;
}

TEST_F(ProjectBadInput, NonJsonIsNotJsonWithItsOffset) {
    writeFile(bad_, "{\"format\": lpv}");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::NotJson);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_EQ(e.location, "byte offset 11");
    EXPECT_TRUE(contains(e.message, "line 1, column 12")) << e.message;
}

TEST_F(ProjectBadInput, OtherFormatNameIsUnknownFormat) {
    editBad("\"lpvstudio-project\"", "\"blender-scene\"");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::UnknownFormat);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_EQ(e.location, "format");
    EXPECT_TRUE(contains(e.message, "blender-scene")) << e.message;
}

TEST_F(ProjectBadInput, JsonArrayIsUnknownFormat) {
    writeFile(bad_, "[1, 2, 3]");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::UnknownFormat);
    EXPECT_EQ(e.file, bad_.string());
}

// Found while fuzzing the loader (docs/fuzzing.md): copying the document
// recursed once per nesting level, so deeply nested arrays overflowed the stack.
TEST_F(ProjectBadInput, DeeplyNestedJsonIsInvalidValue) {
    const std::string start = "{\"format\": \"lpvstudio-project\", \"version\": 1, \"name\": ";
    writeFile(bad_, start + std::string(200000, '[') + std::string(200000, ']') + "}");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::InvalidValue);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_EQ(e.location, "byte offset " + std::to_string(start.size() + 63)) << "the 65th level";
    EXPECT_TRUE(contains(e.message, "more than 64")) << e.message;
}

TEST_F(ProjectBadInput, BracketsInStringsAreNotNesting) {
    editBad("\"good\"", "\"\\\"" + std::string(100, '[') + "\"");
    const auto loaded = loadProject(bad_);
    ASSERT_TRUE(loaded) << loaded.error().describe();
    EXPECT_EQ(loaded->name, "\"" + std::string(100, '['));
}

TEST_F(ProjectBadInput, NewerVersionSaysWhichVersionsThisBuildReads) {
    editBad("\"version\": 2,", "\"version\": 3,");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::NewerVersion);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_EQ(e.location, "version");
    EXPECT_TRUE(contains(e.message, "version 3")) << e.message;
    EXPECT_TRUE(contains(e.message, "up to version 2")) << e.message;
}

TEST_F(ProjectBadInput, VersionZeroIsOutOfRange) {
    editBad("\"version\": 2,", "\"version\": 0,");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::OutOfRange);
    EXPECT_EQ(e.location, "version");
}

TEST_F(ProjectBadInput, MissingFieldIsNamed) {
    editBad("\"alphaCutoff\"", "\"alphaCutof\"");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::MissingField);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_EQ(e.location, "materials[0].alphaCutoff");
}

TEST_F(ProjectBadInput, WrongTypeIsTypeMismatch) {
    editBad("\"castShadows\": true", "\"castShadows\": \"yes\"");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::TypeMismatch);
    EXPECT_EQ(e.location, "lights[0].castShadows");
    EXPECT_TRUE(contains(e.message, "string")) << e.message;
}

TEST_F(ProjectBadInput, UnknownEnumNameIsInvalidValue) {
    editBad("\"blinnPhong\"", "\"phong\"");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::InvalidValue);
    EXPECT_EQ(e.location, "materials[0].shading");
    EXPECT_TRUE(contains(e.message, "\"phong\" is not one of: blinnPhong, metallicRoughness")) << e.message;
}

TEST_F(ProjectBadInput, HugeNumberIsNonFiniteAtItsOffset) {
    editBad("\"intensity\": 0.75", "\"intensity\": 1e999");
    const std::size_t offset = readFile(bad_).find("1e999");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::NonFinite);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_EQ(e.location, "byte offset " + std::to_string(offset));
    EXPECT_TRUE(contains(e.message, "1e999")) << e.message;
}

TEST_F(ProjectBadInput, NumberBeyondFloatIsNonFinite) {
    editBad("\"intensity\": 0.75", "\"intensity\": 1e300");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::NonFinite);
    EXPECT_EQ(e.location, "sky.intensity");
}

TEST_F(ProjectBadInput, OpacityAboveOneIsOutOfRange) {
    editBad("\"opacity\": 1.0", "\"opacity\": 2");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::OutOfRange);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_EQ(e.location, "materials[0].opacity");
    EXPECT_TRUE(contains(e.message, "2 is outside [0, 1]")) << e.message;
}

TEST_F(ProjectBadInput, NegativeColourComponentIsOutOfRange) {
    editBad("0.125", "-1");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::OutOfRange);
    EXPECT_EQ(e.location, "materials[0].diffuseColor[1]");
}

TEST_F(ProjectBadInput, FieldOfViewBeyondPiIsOutOfRange) {
    editBad("\"fovY\": 0.785398", "\"fovY\": 3.5");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::OutOfRange);
    EXPECT_EQ(e.location, "cameras[0].fovY");
}

TEST_F(ProjectBadInput, UnknownParameterKeyIsNamed) {
    // The top-level object (the presets' sit deeper, see below).
    editBad("\n  \"parameters\": {", "\n  \"parameters\": {\n    \"lpv.noSuchParameter\": 3,");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::UnknownParameter);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_TRUE(contains(e.message, "lpv.noSuchParameter")) << e.message;
    EXPECT_TRUE(contains(e.location, "lpv.noSuchParameter")) << e.location;
}

TEST_F(ProjectBadInput, ParameterOutOfRangeIsOutOfRange) {
    const ParameterInfo& p = someIntParameter();
    const int tooLarge = static_cast<int>(p.maxValue) + 1;
    editBad("\"" + p.key + "\": " + std::to_string(nonDefaultValue(p)),
            "\"" + p.key + "\": " + std::to_string(tooLarge));
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::OutOfRange);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_TRUE(contains(e.location, p.key)) << e.location;
    EXPECT_TRUE(contains(e.message, std::to_string(tooLarge))) << e.message;
}

// --- presets: validated like "parameters", located inside the preset ---

TEST_F(ProjectBadInput, UnknownKeyInAPresetIsNamedWithThePreset) {
    editBad("\"lpv.intensity\": 2.5", "\"lpv.intensity\": 2.5,\n        \"lpv.noSuchParameter\": 3");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::UnknownParameter);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_EQ(e.location, "presets[0].parameters.lpv.noSuchParameter");
    EXPECT_TRUE(contains(e.message, "lpv.noSuchParameter")) << e.message;
}

TEST_F(ProjectBadInput, PresetParameterOfTheWrongTypeIsTypeMismatch) {
    editBad("\"lpv.intensity\": 2.5", "\"lpv.intensity\": \"bright\"");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::TypeMismatch);
    EXPECT_EQ(e.location, "presets[0].parameters.lpv.intensity");
    EXPECT_TRUE(contains(e.message, "expected float")) << e.message;
}

TEST_F(ProjectBadInput, PresetParameterOutOfRangeIsOutOfRange) {
    editBad("\"lpv.intensity\": 2.5", "\"lpv.intensity\": 1000.5");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::OutOfRange);
    EXPECT_EQ(e.location, "presets[0].parameters.lpv.intensity");
    EXPECT_TRUE(contains(e.message, "1000.5 is outside [0, 100]")) << e.message;
}

TEST_F(ProjectBadInput, UnknownEnumValueInAPresetIsOutOfRange) {
    editBad("\"reinhard\"", "\"filmic\"");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::OutOfRange);
    EXPECT_EQ(e.location, "presets[0].parameters.output.tonemapper");
    EXPECT_TRUE(contains(e.message, "'filmic' is not one of: aces, reinhard")) << e.message;
}

// JSON has no NaN; the nearest a file gets is a number too large for a double.
TEST_F(ProjectBadInput, HugePresetValueIsNonFiniteAtItsOffset) {
    editBad("\"lpv.intensity\": 2.5", "\"lpv.intensity\": -1e999");
    const std::size_t offset = readFile(bad_).find("-1e999");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::NonFinite);
    EXPECT_EQ(e.location, "byte offset " + std::to_string(offset));
}

TEST_F(ProjectBadInput, NaNCannotEnterAPreset) {
    ParameterPreset preset;
    const auto set = preset.parameters.set("lpv.intensity", std::numeric_limits<double>::quiet_NaN());
    ASSERT_FALSE(set);
    EXPECT_EQ(set.error().code, ErrorCode::NonFinite);
    EXPECT_TRUE(preset.parameters.overrides().empty());
}

TEST_F(ProjectBadInput, PresetWithoutANameIsMissingField) {
    editBad("\"name\": \"flat\",", "");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::MissingField);
    EXPECT_EQ(e.location, "presets[1].name");
}

TEST_F(ProjectBadInput, PresetWithAnEmptyNameIsInvalidValue) {
    editBad("\"name\": \"flat\"", "\"name\": \"\"");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::InvalidValue);
    EXPECT_EQ(e.location, "presets[1].name");
    EXPECT_TRUE(contains(e.message, "needs a name")) << e.message;
}

TEST_F(ProjectBadInput, TwoPresetsWithOneNameIsInvalidValue) {
    editBad("\"name\": \"flat\"", "\"name\": \"bright\"");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::InvalidValue);
    EXPECT_EQ(e.location, "presets[1].name");
    EXPECT_TRUE(contains(e.message, "\"bright\" is already used by presets[0]")) << e.message;
}

TEST_F(ProjectBadInput, PresetsThatAreNotAnArrayIsTypeMismatch) {
    editBad("\"presets\": [", "\"presets\": 7, \"unused\": [");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::TypeMismatch);
    EXPECT_EQ(e.location, "presets");
}

TEST_F(ProjectBadInput, PresetParametersThatAreNotAnObjectIsTypeMismatch) {
    editBad("\"name\": \"flat\",\n      \"parameters\": {}", "\"name\": \"flat\",\n      \"parameters\": [1]");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::TypeMismatch);
    EXPECT_EQ(e.location, "presets[1].parameters");
    EXPECT_TRUE(contains(e.message, "expected an object")) << e.message;
}

TEST_F(ProjectBadInput, PresetsWrittenBeforePresetsExistedLoad) {
    // Cut the "presets" field (the last one) out of the file.
    std::string text = readFile(bad_);
    const std::size_t at = text.find(",\n  \"presets\": [");
    ASSERT_NE(at, std::string::npos) << text;
    writeFile(bad_, text.substr(0, at) + "\n}\n");
    const auto loaded = loadProject(bad_);
    ASSERT_TRUE(loaded) << loaded.error().describe();
    Project expected = goodProject();
    expected.presets.clear();
    EXPECT_EQ(*loaded, expected);
}

// The damaged project with one camera path, closed and at constant speed.
static Project projectWithAPath() {
    Project p = goodProject();
    CameraPath path{"tour", {{0.0f, {0, 1, 2}, {1, 0, 0, 0}, 0.5f}, {2.5f, {3, 1, 2}, {1, 0, 0, 0}, 0.5f}}};
    path.closed = true;
    path.constantSpeed = true;
    p.scene.cameraPaths = {path};
    return p;
}

TEST_F(ProjectBadInput, PathFlagsOfTheWrongTypeAreTypeMismatch) {
    ASSERT_TRUE(saveProject(projectWithAPath(), bad_));
    editBad("\"closed\": true", "\"closed\": 1");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::TypeMismatch);
    EXPECT_EQ(e.location, "cameraPaths[0].closed");
    EXPECT_TRUE(contains(e.message, "expected true or false")) << e.message;
}

TEST_F(ProjectBadInput, ConstantSpeedOfTheWrongTypeIsTypeMismatch) {
    ASSERT_TRUE(saveProject(projectWithAPath(), bad_));
    editBad("\"constantSpeed\": true", "\"constantSpeed\": null");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::TypeMismatch);
    EXPECT_EQ(e.location, "cameraPaths[0].constantSpeed");
}

TEST_F(ProjectBadInput, UnsortedKeyframesAreInvalidValue) {
    ASSERT_TRUE(saveProject(projectWithAPath(), bad_));
    editBad("\"time\": 2.5", "\"time\": -0.0");
    // -0 == 0: equal times are a cut, allowed; an earlier time is not.
    ASSERT_TRUE(loadProject(bad_));
    ASSERT_TRUE(saveProject(projectWithAPath(), bad_));
    editBad("\"time\": 0.0,", "\"time\": 3,");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::InvalidValue);
    EXPECT_EQ(e.location, "cameraPaths[0].keyframes[1].time");
}

TEST_F(ProjectBadInput, PathsWrittenBeforeTheFlagsExistedLoadOpenAndTimed) {
    ASSERT_TRUE(saveProject(projectWithAPath(), bad_));
    editBad(",\n      \"closed\": true,\n      \"constantSpeed\": true", "");
    const auto loaded = loadProject(bad_);
    ASSERT_TRUE(loaded) << loaded.error().describe();
    ASSERT_EQ(loaded->scene.cameraPaths.size(), 1u);
    EXPECT_FALSE(loaded->scene.cameraPaths[0].closed);
    EXPECT_FALSE(loaded->scene.cameraPaths[0].constantSpeed);
    EXPECT_EQ(loaded->scene.cameraPaths[0].keyframes, projectWithAPath().scene.cameraPaths[0].keyframes);
}

TEST_F(ProjectBadInput, ObjectMeshIndexOutOfRange) {
    editBad("\"mesh\": 0", "\"mesh\": 5");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::IndexOutOfRange);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_EQ(e.location, "objects[0].mesh");
    EXPECT_TRUE(contains(e.message, "mesh 5 does not exist")) << e.message;
}

TEST_F(ProjectBadInput, CyclicParentChainIsInvalidValue) {
    editBad("\"parent\": -1", "\"parent\": 1"); // base <-> child
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::InvalidValue);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_EQ(e.location, "objects[0].parent");
    EXPECT_TRUE(contains(e.message, "own ancestor")) << e.message;
    EXPECT_TRUE(contains(e.message, "0 -> 1 -> 0")) << e.message;
}

TEST_F(ProjectBadInput, AssetPathLeavingTheFolderIsInvalidValue) {
    const std::string asset = "bad.assets/meshes/" + badAsset().filename().string();
    // The file exists out there, so only the path check can stop the load.
    fs::copy_file(badAsset(), dir_.parent_path() / ("outside-" + pidText() + ".lpvmesh"));
    editBad(asset, "../outside-" + pidText() + ".lpvmesh");
    const Error e = loadFails(bad_);
    fs::remove(dir_.parent_path() / ("outside-" + pidText() + ".lpvmesh"));
    EXPECT_EQ(e.code, ErrorCode::InvalidValue);
    EXPECT_EQ(e.location, "meshes[0].asset");
    EXPECT_TRUE(contains(e.message, "\"..\"")) << e.message;
}

TEST_F(ProjectBadInput, AbsoluteAssetPathIsInvalidValue) {
    editBad("bad.assets/meshes/" + badAsset().filename().string(), badAsset().generic_string());
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::InvalidValue);
    EXPECT_EQ(e.location, "meshes[0].asset");
    EXPECT_TRUE(contains(e.message, "absolute")) << e.message;
}

TEST_F(ProjectBadInput, MissingAssetIsNamed) {
    const fs::path asset = badAsset();
    fs::remove(asset);
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::MissingAsset);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_EQ(e.location, "meshes[0].asset");
    EXPECT_TRUE(contains(e.message, "bad.assets/meshes/" + asset.filename().string())) << e.message;
}

TEST_F(ProjectBadInput, FlippedAssetByteIsChecksumMismatch) {
    const fs::path asset = badAsset();
    std::string bytes = readFile(asset);
    bytes[kMeshAssetHeaderSize + 10] = static_cast<char>(bytes[kMeshAssetHeaderSize + 10] ^ 1);
    writeFile(asset, bytes);
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::ChecksumMismatch);
    EXPECT_EQ(e.file, asset.string());
    EXPECT_EQ(e.location, "byte offset 40");
}

TEST_F(ProjectBadInput, CutOffAssetIsTruncated) {
    const fs::path asset = badAsset();
    writeFile(asset, readFile(asset).substr(0, 100));
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::Truncated);
    EXPECT_EQ(e.file, asset.string());
    EXPECT_EQ(e.location, "byte offset 100");
}

TEST_F(ProjectBadInput, NaNPositionInAssetIsNonFinite) {
    const fs::path asset = badAsset();
    std::string bytes = readFile(asset);
    // Vertex 1, component y: the fifth float of the payload.
    putU32(bytes, kMeshAssetHeaderSize + 4 * 4, std::bit_cast<std::uint32_t>(std::numeric_limits<float>::quiet_NaN()));
    resealChecksum(bytes);
    writeFile(asset, bytes);
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::NonFinite);
    EXPECT_EQ(e.file, asset.string());
    EXPECT_EQ(e.location, "byte offset 64");
    EXPECT_TRUE(contains(e.message, "position 1 component y is NaN")) << e.message;
}

TEST_F(ProjectBadInput, TriangleIndexOutOfRangeInAsset) {
    const fs::path asset = badAsset();
    std::string bytes = readFile(asset);
    // Header, 4 positions, 4 normals, 4 uvs, then the indices; change index 4.
    const std::size_t indexStart = kMeshAssetHeaderSize + 4 * 12 + 4 * 12 + 4 * 8;
    putU32(bytes, indexStart + 4 * 4, 99);
    resealChecksum(bytes);
    writeFile(asset, bytes);
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::IndexOutOfRange);
    EXPECT_EQ(e.file, asset.string());
    EXPECT_EQ(e.location, "byte offset " + std::to_string(indexStart + 16));
    EXPECT_TRUE(contains(e.message, "index 4 (triangle 1) is 99")) << e.message;
}

TEST_F(ProjectBadInput, NewerAssetVersionIsNewerVersion) {
    const fs::path asset = badAsset();
    std::string bytes = readFile(asset);
    putU32(bytes, 8, kMeshAssetVersion + 1);
    writeFile(asset, bytes);
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::NewerVersion);
    EXPECT_EQ(e.file, asset.string());
}

TEST_F(ProjectBadInput, AssetThatDisagreesWithTheProjectIsCorrupt) {
    editBad("\"vertices\": 4", "\"vertices\": 5");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::CorruptAsset);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_EQ(e.location, "meshes[0]");
}

// --- failed saves ---

TEST_F(ProjectBadInput, SavingOntoAFolderFailsAndChangesNothing) {
    fs::create_directories(dir_ / "folder.lpvproj" / "inside");
    const Snapshot before = snapshot(dir_);
    const auto saved = saveProject(goodProject(), dir_ / "folder.lpvproj");
    ASSERT_FALSE(saved);
    EXPECT_EQ(saved.error().code, ErrorCode::IoError);
    EXPECT_EQ(saved.error().file, (dir_ / "folder.lpvproj").string());
    const Snapshot after = snapshot(dir_);
    EXPECT_TRUE(before == after) << differences(before, after);
}

TEST_F(ProjectBadInput, FailedSaveLeavesThePreviousProjectIntact) {
    const Project previous = goodProject();
    Project next = previous;
    next.name = "next";
    next.scene.meshes[0].positions[2] = {2, 2, 0};
    next.scene.meshes.push_back(next.scene.meshes[0]);
    next.scene.meshes[1].name = "second";
    // Block the second mesh's asset with a folder, so the save fails after
    // it has written the first one.
    const std::string blocked =
        "1-" + hex16(contentHash64(encodeMeshAsset(next.scene.meshes[1]))) + ".lpvmesh";
    fs::create_directories(dir_ / "good.assets" / "meshes" / blocked / "inside");
    const Snapshot before = snapshot(dir_);

    const auto saved = saveProject(next, dir_ / "good.lpvproj");
    ASSERT_FALSE(saved) << "the blocking folder did not block; did the asset naming change?";
    EXPECT_EQ(saved.error().code, ErrorCode::IoError);
    const Snapshot after = snapshot(dir_);
    EXPECT_TRUE(before == after) << differences(before, after);
    const auto loaded = loadProject(dir_ / "good.lpvproj");
    ASSERT_TRUE(loaded) << loaded.error().describe();
    EXPECT_EQ(*loaded, previous);
}

TEST_F(ProjectBadInput, SavingIntoAReadOnlyFolderFailsAndChangesNothing) {
#ifdef _WIN32
    GTEST_SKIP() << "POSIX permissions";
#else
    if (::geteuid() == 0)
        GTEST_SKIP() << "root ignores folder permissions";
    Project next = goodProject();
    next.scene.meshes[0].positions[0].x = -1.0f;
    const Snapshot before = snapshot(dir_);
    fs::permissions(dir_ / "good.assets" / "meshes", fs::perms::owner_write, fs::perm_options::remove);
    fs::permissions(dir_, fs::perms::owner_write, fs::perm_options::remove);
    const auto saved = saveProject(next, dir_ / "good.lpvproj");
    fs::permissions(dir_, fs::perms::owner_write, fs::perm_options::add);
    fs::permissions(dir_ / "good.assets" / "meshes", fs::perms::owner_write, fs::perm_options::add);
    ASSERT_FALSE(saved);
    EXPECT_EQ(saved.error().code, ErrorCode::IoError);
    const Snapshot after = snapshot(dir_);
    EXPECT_TRUE(before == after) << differences(before, after);
    const auto loaded = loadProject(dir_ / "good.lpvproj");
    ASSERT_TRUE(loaded);
    EXPECT_EQ(*loaded, goodProject());
#endif
}

// Issue #29: the depth is checked on the text before parsing, so deep
// nesting that is also invalid JSON (unterminated) is refused for its depth
// without any parser seeing it; 64 levels are not refused for depth.
TEST_F(ProjectBadInput, UnterminatedDeepNestingIsRefusedBeforeParsing) {
    const std::string head = "{\"format\": \"lpvstudio-project\", \"version\": 2, \"x\": ";
    writeFile(bad_, head + std::string(50000, '['));
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::InvalidValue);
    EXPECT_EQ(e.file, bad_.string());
    EXPECT_EQ(e.location, "byte offset " + std::to_string(head.size() + 63)) << "the 65th level";
    EXPECT_EQ(e.message, "the JSON nests more than 64 arrays and objects inside each other; no project file does");
    writeFile(bad_, head + std::string(63, '[') + std::string(63, ']') + "}");
    const Error shallow = loadFails(bad_);
    EXPECT_FALSE(contains(shallow.message, "nests more than")) << shallow.message;
}

TEST_F(ProjectBadInput, AFractionalVersionSaysItIsAFraction) {
    editBad("\"version\": 2,", "\"version\": 1.0,");
    const Error e = loadFails(bad_);
    EXPECT_EQ(e.code, ErrorCode::TypeMismatch);
    EXPECT_EQ(e.location, "version");
    EXPECT_EQ(e.message, "expected an integer, got the fraction 1.0 (written with a decimal point or exponent; write 1)");
}

TEST_F(ProjectBadInput, Utf16TextIsNamedAsSuch) {
    // The good project re-encoded as UTF-16 (little-endian, with and without a byte-order mark).
    const std::string text = readFile(bad_);
    for (const bool bom : {true, false}) {
        std::string wide = bom ? std::string("\xFF\xFE", 2) : std::string();
        for (char c : text)
            wide += std::string{c, '\0'};
        writeFile(bad_, wide);
        const Error e = loadFails(bad_);
        EXPECT_EQ(e.code, ErrorCode::NotJson);
        EXPECT_EQ(e.location, "byte offset 0");
        EXPECT_EQ(e.message, std::string("the file is UTF-16 (little-endian") + (bom ? "" : ", no byte-order mark") +
                                 ") text; LPV Studio reads UTF-8 JSON (convert it, e.g. `iconv -f UTF-16 -t UTF-8`)");
    }
}

TEST_F(ProjectBadInput, AHugeQuotedValueMakesABoundedMessage) {
    // A 5 MB asset path (the was 200 MB): the error quotes it, capped.
    std::string text = readFile(bad_);
    const std::size_t at = text.find(".assets/meshes/");
    ASSERT_NE(at, std::string::npos);
    text.insert(at, std::string(5'000'000, 'x'));
    writeFile(bad_, text);
    const Error e = loadFails(bad_);
    EXPECT_LE(e.describe().size(), bad_.string().size() + 3 * (kMaxErrorText + 64)) << e.describe().substr(0, 300);
    EXPECT_TRUE(contains(e.describe(), " bytes left out ...] ")) << e.describe().substr(0, 300);
}

TEST(ErrorText, LongTextKeepsItsEndsAndWholeCharacters) {
    const std::string small = "short";
    EXPECT_EQ(capErrorText(small), small);
    std::string longText;
    while (longText.size() < 10 * kMaxErrorText)
        longText += "\xC3\xA9"; // é: two bytes each, never cut in half
    const std::string capped = capErrorText(longText);
    EXPECT_LT(capped.size(), kMaxErrorText + 64);
    const std::size_t cut = capped.find(" [... ");
    ASSERT_NE(cut, std::string::npos);
    EXPECT_EQ(cut % 2, 0u) << "the head ends on a character boundary";
    const std::size_t tail = capped.find(" ...] ") + 6;
    EXPECT_EQ((capped.size() - tail) % 2, 0u) << "the tail starts on a character boundary";
    const std::size_t leftOut = std::stoul(capped.substr(cut + 6));
    EXPECT_EQ(leftOut, longText.size() - cut - (capped.size() - tail));
}

#ifndef _WIN32
// Issue #29: only regular files are read (a FIFO would block the loader until
// a writer came), and a file's size is checked against what it can hold
// before anything is read (a sparse 30 GiB project or 100 GiB mesh asset was
// read whole). In a folder of its own: the other cases' snapshot reads files.
TEST(ProjectSpecialFiles, FifosAndSparseGiantsAreRefusedBeforeReading) {
    const fs::path dir = fs::temp_directory_path() / ("lpv-special-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const fs::path project = dir / "p.lpvproj";
    ASSERT_TRUE(saveProject(goodProject(), project));
    const auto timed = [&](const fs::path& file) {
        const auto start = std::chrono::steady_clock::now();
        auto loaded = loadProject(file);
        EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(1));
        return loaded;
    };

    const fs::path fifo = dir / "fifo.lpvproj";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    auto loaded = timed(fifo);
    ASSERT_FALSE(loaded);
    EXPECT_EQ(loaded.error().code, ErrorCode::IoError);
    EXPECT_EQ(loaded.error().message, "is a FIFO (named pipe), not a regular file: only regular files are read");

    const fs::path giant = dir / "giant.lpvproj";
    writeFile(giant, "{");
    fs::resize_file(giant, std::uintmax_t{30} << 30); // sparse: no disk space used
    loaded = timed(giant);
    ASSERT_FALSE(loaded);
    EXPECT_EQ(loaded.error().message,
              "the file is 30.0 GiB, more than a project file can be (64.0 MiB); refused before reading");

    // The mesh asset: a FIFO, then a sparse 100 GiB file, in the asset's place.
    fs::path asset;
    for (const auto& entry : fs::directory_iterator(dir / "p.assets" / "meshes"))
        asset = entry.path();
    ASSERT_FALSE(asset.empty());
    fs::remove(asset);
    ASSERT_EQ(::mkfifo(asset.c_str(), 0600), 0);
    loaded = timed(project);
    ASSERT_FALSE(loaded);
    EXPECT_EQ(loaded.error().file, asset.string());
    EXPECT_TRUE(contains(loaded.error().message, "is a FIFO")) << loaded.error().message;
    fs::remove(asset);
    writeFile(asset, "x");
    fs::resize_file(asset, std::uintmax_t{100} << 30);
    loaded = timed(project);
    ASSERT_FALSE(loaded);
    EXPECT_EQ(loaded.error().file, asset.string());
    EXPECT_TRUE(contains(loaded.error().message, "the file is 100.0 GiB, more than a mesh asset of 4 vertices and "
                                                 "2 triangles can be"))
        << loaded.error().message;
    fs::remove_all(dir);
}
#endif
