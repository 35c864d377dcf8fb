// Camera path files: the JSON schema round-trips exactly, each kind of bad
// input fails with its own error naming the field, and the CSV has one row
// per frame.
#include "ProjectTestSupport.h"
#include "TestFiles.h"

#include "lpv/scene/CameraPathFile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

using namespace lpv::scene;
using namespace lpv::test;
namespace fs = std::filesystem;

namespace {

CameraPath examplePath() {
    CameraPath p;
    p.name = "orbit \xc3\xa9"; // UTF-8
    p.closed = true;
    p.constantSpeed = true;
    p.keyframes = {
        {0.0f, {0, 1, 5}, glm::quat(1, 0, 0, 0), 0.6859f},
        {1.25f, {3, 1, 2}, glm::angleAxis(0.5f, glm::vec3(0, 1, 0)), glm::radians(39.3f)},
        {1.25f, {4, 1, 1}, glm::quat(0.0f, 0.0f, 0.0f, 1.0f), 1.0f / 3.0f}, // w, x, y, z
        {7.5f, {-5, 2.5f, 0.1f}, glm::angleAxis(2.0f, glm::normalize(glm::vec3(1, 1, 0))), 2.9f},
    };
    return p;
}

// The example written as a file, with `from` replaced by `to` (once).
std::string editedExample(const std::string& from, const std::string& to) {
    auto text = cameraPathToJson(examplePath());
    EXPECT_TRUE(text) << text.error().describe();
    std::string s = text ? *text : std::string();
    const std::size_t at = s.find(from);
    EXPECT_NE(at, std::string::npos) << "\"" << from << "\" is not in\n" << s;
    EXPECT_EQ(s.find(from, at + 1), std::string::npos) << "\"" << from << "\" is not unique in\n" << s;
    if (at != std::string::npos)
        s.replace(at, from.size(), to);
    return s;
}

Error readFails(const std::string& text) {
    const auto path = cameraPathFromJson(text, "path.json");
    if (path) {
        ADD_FAILURE() << "reading succeeded:\n" << text;
        return Error{};
    }
    EXPECT_EQ(path.error().file, "path.json");
    EXPECT_FALSE(path.error().message.empty());
    return path.error();
}

class CameraPathFile : public TempDirTest {
  protected:
    CameraPathFile() : TempDirTest("lpv-path-") {}
};

} // namespace

TEST(CameraPathJson, RoundTripIsExact) {
    const CameraPath original = examplePath();
    const auto text = cameraPathToJson(original);
    ASSERT_TRUE(text) << text.error().describe();
    const auto back = cameraPathFromJson(*text, "mem");
    ASSERT_TRUE(back) << back.error().describe();
    EXPECT_EQ(*back, original);
    // And writing again gives the same bytes.
    EXPECT_EQ(*cameraPathToJson(*back), *text);
}

TEST(CameraPathJson, TheFileLooksAsDocumented) {
    const std::string text = *cameraPathToJson(examplePath());
    EXPECT_EQ(text.rfind("{\n  \"format\": \"lpvstudio-camera-path\",\n  \"version\": 1,\n  \"name\": ", 0),
              0u)
        << text;
    EXPECT_TRUE(contains(text, "\"closed\": true,\n  \"constantSpeed\": true,\n  \"keyframes\": [")) << text;
    // The field of view in degrees, as short as reads back exactly.
    EXPECT_TRUE(contains(text, "\"fovYDegrees\": 39.3\n")) << text;
    EXPECT_TRUE(contains(text, "\"time\": 1.25,")) << text;
    EXPECT_EQ(text.back(), '\n');
}

TEST(CameraPathJson, FlagsAreOptionalOnLoad) {
    const std::string text = editedExample("  \"closed\": true,\n  \"constantSpeed\": true,\n", "");
    const auto path = cameraPathFromJson(text, "p.json");
    ASSERT_TRUE(path) << path.error().describe();
    EXPECT_FALSE(path->closed);
    EXPECT_FALSE(path->constantSpeed);
}

TEST(CameraPathJson, NaNIsNotJson) {
    const Error e = readFails(editedExample("\"time\": 1.25,\n      \"position\": [\n        3.0,",
                                            "\"time\": NaN,\n      \"position\": [\n        3.0,"));
    EXPECT_EQ(e.code, ErrorCode::NotJson);
    EXPECT_TRUE(e.location.starts_with("byte offset ")) << e.location;
}

TEST(CameraPathJson, HugeNumberIsNonFinite) {
    const Error e = readFails(editedExample("\"time\": 7.5", "\"time\": 1e999"));
    EXPECT_EQ(e.code, ErrorCode::NonFinite);
    EXPECT_TRUE(contains(e.message, "1e999")) << e.message;
}

TEST(CameraPathJson, NumberBeyondFloatIsNonFinite) {
    const Error e = readFails(editedExample("\"time\": 7.5", "\"time\": 1e300"));
    EXPECT_EQ(e.code, ErrorCode::NonFinite);
    EXPECT_EQ(e.location, "keyframes[3].time");
}

TEST(CameraPathJson, UnsortedTimesAreInvalidValue) {
    const Error e = readFails(editedExample("\"time\": 7.5", "\"time\": 1"));
    EXPECT_EQ(e.code, ErrorCode::InvalidValue);
    EXPECT_EQ(e.location, "keyframes[3].time");
    EXPECT_TRUE(contains(e.message, "keyframe time 1 is earlier than the previous keyframe's 1.25"))
        << e.message;
}

TEST(CameraPathJson, WrongTypesAreTypeMismatch) {
    {
        const Error e = readFails(editedExample("\"closed\": true", "\"closed\": \"yes\""));
        EXPECT_EQ(e.code, ErrorCode::TypeMismatch);
        EXPECT_EQ(e.location, "closed");
        EXPECT_TRUE(contains(e.message, "expected true or false, got a string")) << e.message;
    }
    {
        const Error e = readFails(editedExample("\"time\": 7.5", "\"time\": \"7.5\""));
        EXPECT_EQ(e.code, ErrorCode::TypeMismatch);
        EXPECT_EQ(e.location, "keyframes[3].time");
    }
    {
        const Error e = readFails(editedExample("\"keyframes\": [", "\"keyframes\": {\"a\": 1}, \"x\": ["));
        EXPECT_EQ(e.code, ErrorCode::TypeMismatch);
        EXPECT_EQ(e.location, "keyframes");
    }
}

TEST(CameraPathJson, OrientationNeedsFourNumbers) {
    const Error e = readFails(
        editedExample("\"orientation\": [\n        0.0,\n        0.0,\n        1.0,\n        0.0\n      ]",
                      "\"orientation\": [0, 0, 1]"));
    EXPECT_EQ(e.code, ErrorCode::TypeMismatch);
    EXPECT_EQ(e.location, "keyframes[2].orientation");
    EXPECT_TRUE(contains(e.message, "expected an array of 4 numbers, got an array of 3")) << e.message;
}

TEST(CameraPathJson, ZeroQuaternionIsInvalidValue) {
    const Error e = readFails(
        editedExample("\"orientation\": [\n        0.0,\n        0.0,\n        1.0,\n        0.0\n      ]",
                      "\"orientation\": [0, 0, 0, 0]"));
    EXPECT_EQ(e.code, ErrorCode::InvalidValue);
    EXPECT_EQ(e.location, "keyframes[2].orientation");
}

TEST(CameraPathJson, FieldOfViewOutsideZeroTo180DegreesIsOutOfRange) {
    const Error e = readFails(editedExample("\"fovYDegrees\": 39.3", "\"fovYDegrees\": 180"));
    EXPECT_EQ(e.code, ErrorCode::OutOfRange);
    EXPECT_EQ(e.location, "keyframes[1].fovYDegrees");
    EXPECT_TRUE(contains(e.message, "180 is outside (0, 180)")) << e.message;
}

TEST(CameraPathJson, MissingFieldIsNamed) {
    const Error e = readFails(editedExample("\"fovYDegrees\": 39.3", "\"fovY\": 39.3"));
    EXPECT_EQ(e.code, ErrorCode::MissingField);
    EXPECT_EQ(e.location, "keyframes[1].fovYDegrees");
}

TEST(CameraPathJson, AProjectFileIsUnknownFormat) {
    const Error e = readFails(editedExample("\"lpvstudio-camera-path\"", "\"lpvstudio-project\""));
    EXPECT_EQ(e.code, ErrorCode::UnknownFormat);
    EXPECT_EQ(e.location, "format");
    EXPECT_TRUE(contains(e.message, "expected \"lpvstudio-camera-path\"")) << e.message;
}

TEST(CameraPathJson, NewerVersionIsNewerVersion) {
    const Error e = readFails(editedExample("\"version\": 1", "\"version\": 2"));
    EXPECT_EQ(e.code, ErrorCode::NewerVersion);
    EXPECT_TRUE(contains(e.message, "camera path format version 2 is newer")) << e.message;
}

TEST(CameraPathJson, CutOffTextIsTruncated) {
    const std::string text = *cameraPathToJson(examplePath());
    EXPECT_EQ(readFails(text.substr(0, text.size() / 2)).code, ErrorCode::Truncated);
    EXPECT_EQ(readFails("").code, ErrorCode::Truncated);
}

TEST(CameraPathJson, WritingRefusesWhatReadingWould) {
    CameraPath nan = examplePath();
    nan.keyframes[2].position.y = std::numeric_limits<float>::quiet_NaN();
    auto e = cameraPathToJson(nan);
    ASSERT_FALSE(e);
    EXPECT_EQ(e.error().code, ErrorCode::NonFinite);
    EXPECT_EQ(e.error().location, "keyframes[2].position[1]");

    CameraPath unsorted = examplePath();
    std::swap(unsorted.keyframes[0], unsorted.keyframes[3]);
    e = cameraPathToJson(unsorted);
    ASSERT_FALSE(e);
    EXPECT_EQ(e.error().code, ErrorCode::InvalidValue);
    EXPECT_EQ(e.error().location, "keyframes[1].time");

    CameraPath latin1 = examplePath();
    latin1.name = "caf\xe9";
    e = cameraPathToJson(latin1);
    ASSERT_FALSE(e);
    EXPECT_EQ(e.error().code, ErrorCode::InvalidValue);
}

TEST_F(CameraPathFile, SaveAndLoadThroughAFile) {
    const fs::path file = dir_ / "orbit.json";
    ASSERT_TRUE(saveCameraPathFile(examplePath(), file));
    const auto back = loadCameraPathFile(file);
    ASSERT_TRUE(back) << back.error().describe();
    EXPECT_EQ(*back, examplePath());
    EXPECT_EQ(listFiles(dir_), std::set<std::string>{"orbit.json"}) << "no temporary file left";

    const auto missing = loadCameraPathFile(dir_ / "none.json");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, ErrorCode::FileNotFound);

    CameraPath bad = examplePath();
    bad.keyframes[0].fovY = 0.0f;
    const auto refused = saveCameraPathFile(bad, dir_ / "bad.json");
    ASSERT_FALSE(refused);
    EXPECT_EQ(refused.error().file, (dir_ / "bad.json").string());
    EXPECT_EQ(refused.error().location, "keyframes[0].fovYDegrees");
    EXPECT_FALSE(fs::exists(dir_ / "bad.json"));
}

TEST(CameraPathCsv, OneRowPerFrameFromStartToEnd) {
    CameraPath path = examplePath();
    path.closed = false;
    path.constantSpeed = false;
    const CameraSpline spline(path); // 7.5 s
    for (const double fps : {30.0, 24.0, 29.97, 1.0, 0.5}) {
        const std::string csv = cameraPathToCsv(spline, fps);
        const auto rows = static_cast<int>(std::count(csv.begin(), csv.end(), '\n')) - 1;
        EXPECT_EQ(rows, static_cast<int>(std::floor(spline.duration() * fps)) + 1) << fps;
        EXPECT_EQ(rows, cameraPathCsvRows(spline.duration(), fps));
    }
    const std::string csv = cameraPathToCsv(spline, 30.0);
    EXPECT_EQ(csv.rfind("time,px,py,pz,qx,qy,qz,qw,fovY_deg\n0,0,1,5,0,0,0,1,", 0), 0u) << csv.substr(0, 200);
    // 7.5 s at 30 fps: the last row is the last key.
    EXPECT_TRUE(contains(csv, "\n7.5,-5,2.5,0.1,")) << csv.substr(csv.size() - 200);
    // Every row has nine columns.
    std::size_t start = 0;
    while (start < csv.size()) {
        const std::size_t end = csv.find('\n', start);
        EXPECT_EQ(std::count(csv.begin() + std::ptrdiff_t(start), csv.begin() + std::ptrdiff_t(end), ','), 8);
        start = end + 1;
    }
}

TEST(CameraPathCsv, FieldOfViewIsInDegrees) {
    CameraPath path;
    path.keyframes = {{0.0f, {0, 0, 0}, glm::quat(1, 0, 0, 0), glm::radians(60.0f)}};
    const std::string csv = cameraPathToCsv(CameraSpline(path), 30.0);
    EXPECT_EQ(csv, "time,px,py,pz,qx,qy,qz,qw,fovY_deg\n0,0,0,0,0,0,0,1,60\n");
    EXPECT_EQ(cameraPathToCsv(CameraSpline(path), 0.0), "time,px,py,pz,qx,qy,qz,qw,fovY_deg\n");
}
