#pragma once
// Helpers shared by the scene tests: readable gtest output for errors and
// projects, whole-file reads and writes, and a fresh folder for each test.
#include "lpv/scene/Project.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>

#ifndef _WIN32
#include <unistd.h>
#endif

// gtest finds PrintTo by argument-dependent lookup, so these stay in lpv::scene.
namespace lpv::scene {
inline void PrintTo(ErrorCode code, std::ostream* os) { *os << toString(code); }
// Projects are large; gtest would otherwise dump their bytes.
inline void PrintTo(const Project& p, std::ostream* os) { *os << "Project \"" << p.name << "\""; }
} // namespace lpv::scene

namespace lpv::test {

// The whole file, or "" when it cannot be read.
inline std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    if (in)
        bytes << in.rdbuf();
    return bytes.str();
}

inline void writeFile(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << bytes;
}

// A unit square in z = 0 facing +z: four vertices, two triangles, one submesh of material 0.
inline scene::Mesh unitQuadMesh() {
    scene::Mesh quad;
    quad.name = "quad";
    quad.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    quad.normals.assign(4, {0, 0, 1});
    quad.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    quad.indices = {0, 1, 2, 0, 2, 3};
    quad.submeshes = {{0, 6, 0}};
    return quad;
}

// Every file under `root`, relative, sorted.
inline std::set<std::string> listFiles(const std::filesystem::path& root) {
    std::set<std::string> out;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root))
        if (entry.is_regular_file())
            out.insert(entry.path().lexically_relative(root).generic_string());
    return out;
}

// This process's id, so that test runs side by side use different folders.
inline std::string pidText() {
#ifdef _WIN32
    return "0";
#else
    return std::to_string(::getpid());
#endif
}

// A fixture with an empty folder `dir_` of its own, removed after the test.
// The folder, under gtest's TempDir, is named prefix + test name + "-" + pid.
class TempDirTest : public testing::Test {
protected:
    explicit TempDirTest(std::string prefix) : prefix_(std::move(prefix)) {}

    void SetUp() override {
        const auto* info = testing::UnitTest::GetInstance()->current_test_info();
        dir_ = std::filesystem::path(testing::TempDir()) / (prefix_ + info->name() + "-" + pidText());
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ignored;
        std::filesystem::remove_all(dir_, ignored);
    }

    std::filesystem::path dir_;

private:
    std::string prefix_;
};

} // namespace lpv::test
