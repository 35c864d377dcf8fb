#pragma once
// A CLI test with its own copy of the built-in Cornell box: the commands
// under test write beside the project (a radiosity solution, an imported
// path, an edited file) and never into the source tree. Each test gets a
// fresh folder named for it and this process, removed after it.
#include "RunLpv.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace lpv::test {

// A 1-second path that moves into the box (three keyframes), as a path file.
inline constexpr const char* kDollyPathFile = R"({
  "format": "lpvstudio-camera-path",
  "version": 1,
  "name": "dolly",
  "closed": false,
  "constantSpeed": false,
  "keyframes": [
    {"time": 0, "position": [2.78, 2.73, -8.0], "orientation": [0, 1, 0, 0], "fovYDegrees": 39.3},
    {"time": 0.5, "position": [3.2, 2.9, -6.5], "orientation": [0, 0.995, 0, 0.0998], "fovYDegrees": 45},
    {"time": 1, "position": [2.5, 2.8, -5.5], "orientation": [0, 0.995, 0, -0.0998], "fovYDegrees": 50}
  ]
}
)";

class CornellCopyTest : public testing::Test {
  protected:
    // `prefix` names the suite's folders: lpv-PREFIX-TEST-PID.
    explicit CornellCopyTest(std::string prefix) : prefix_(std::move(prefix)) {}

    void SetUp() override {
        const auto* info = testing::UnitTest::GetInstance()->current_test_info();
        dir_ = std::filesystem::temp_directory_path() /
               ("lpv-" + prefix_ + "-" + std::string(info->name()) + "-" + std::to_string(::getpid()));
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
        std::filesystem::copy(std::filesystem::path(cornellProject()).parent_path(), dir_ / "cornell",
                              std::filesystem::copy_options::recursive);
        project_ = (dir_ / "cornell" / "cornell-box.lpvproj").string();
    }
    void TearDown() override {
        std::error_code ignored;
        std::filesystem::remove_all(dir_, ignored);
    }

    std::filesystem::path dir_;
    std::string project_; // DIR/cornell/cornell-box.lpvproj

  private:
    std::string prefix_;
};

} // namespace lpv::test
