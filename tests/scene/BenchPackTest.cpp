// The bench pack (.lpvpack, issue #45): a lossless round trip of the Cornell
// box template with a texture, and a clear error, never a crash or a huge
// allocation, for a cut-off file, a damaged payload and counts or sizes the
// bytes cannot hold.
#include "TestFiles.h"
#include "TestPaths.h"

#include "lpv/scene/BenchPack.h"
#include "lpv/scene/MeshAsset.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

using namespace lpv::scene;

namespace {

constexpr std::size_t kMeshCountOffset = 16;
constexpr std::size_t kTextureCountOffset = 20;
constexpr std::size_t kChecksumOffset = 40;

void patchU32(std::string& bytes, std::size_t at, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
        bytes[at + std::size_t(i)] = char((v >> (8 * i)) & 0xffu);
}

void patchU64(std::string& bytes, std::size_t at, std::uint64_t v) {
    for (int i = 0; i < 8; ++i)
        bytes[at + std::size_t(i)] = char((v >> (8 * i)) & 0xffu);
}

// After an edit of the payload: the checksum made right again, so what is
// tested is the structural check behind it.
void rechecksum(std::string& bytes) {
    patchU64(bytes, kChecksumOffset, contentHash64(std::string_view(bytes).substr(kBenchPackHeaderSize)));
}

// The built-in Cornell box project, with a 3x2 RGBA texture on its first
// material so the pack carries pixels.
BenchPack cornellPack() {
    const auto project =
        loadProject(std::filesystem::path(lpv::test::kSourceDir) / "projects/cornell-box/cornell-box.lpvproj");
    EXPECT_TRUE(project) << project.error().describe();
    BenchPack pack;
    pack.project = *project;
    pack.project.loadWarnings.clear();
    pack.project.scene.materials.at(0).diffuseTexture = "cornell-box.assets/textures/checker.png";
    Image8 image;
    image.width = 3;
    image.height = 2;
    image.channels = 4;
    for (int i = 0; i < 3 * 2 * 4; ++i)
        image.pixels.push_back(std::uint8_t(i * 11));
    pack.textures["cornell-box.assets/textures/checker.png"] = image;
    pack.projectHash = "0123456789abcdef";
    return pack;
}

std::string encoded(const BenchPack& pack) {
    auto bytes = encodeBenchPack(pack, "test.lpvpack");
    EXPECT_TRUE(bytes) << bytes.error().describe();
    return bytes ? *bytes : std::string();
}

// Where the first texture record starts: the end of the payload minus the
// one texture's key, size and pixels.
std::size_t firstTextureRecord(const std::string& bytes, const BenchPack& pack) {
    const auto& [key, image] = *pack.textures.begin();
    return bytes.size() - (4 + key.size() + 12 + image.pixels.size());
}

} // namespace

TEST(BenchPack, RoundTripKeepsTheProjectTexturesAndHash) {
    const BenchPack pack = cornellPack();
    const std::string bytes = encoded(pack);
    ASSERT_GT(bytes.size(), kBenchPackHeaderSize);
    EXPECT_EQ(bytes.substr(0, 8), std::string("LPVPACK\0", 8));
    const auto back = decodeBenchPack(bytes, "test.lpvpack");
    ASSERT_TRUE(back) << back.error().describe();
    EXPECT_TRUE(back->project == pack.project); // scene (meshes, materials, lights, cameras, paths), parameters, name
    EXPECT_EQ(back->project.name, "cornell-box");
    ASSERT_EQ(back->textures.size(), 1u);
    const Image8& image = back->textures.at("cornell-box.assets/textures/checker.png");
    EXPECT_EQ(image.width, 3);
    EXPECT_EQ(image.height, 2);
    EXPECT_EQ(image.pixels, pack.textures.begin()->second.pixels);
    EXPECT_EQ(back->projectHash, "0123456789abcdef");
    // The same pack encodes to the same bytes: packs of one project compare by their bytes.
    EXPECT_EQ(encoded(*back), bytes);
}

TEST(BenchPack, SavedAndLoadedThroughAFile) {
    const auto dir = lpv::test::freshTempDir("benchpack");
    const BenchPack pack = cornellPack();
    ASSERT_TRUE(saveBenchPack(pack, dir / "cornell.lpvpack"));
    const auto back = loadBenchPack(dir / "cornell.lpvpack");
    ASSERT_TRUE(back) << back.error().describe();
    EXPECT_TRUE(back->project == pack.project);
    EXPECT_TRUE(isBenchPackFile(dir / "cornell.lpvpack"));
    EXPECT_FALSE(isBenchPackFile(dir / "cornell.lpvproj"));
    const auto missing = loadBenchPack(dir / "none.lpvpack");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, ErrorCode::FileNotFound);
    std::filesystem::remove_all(dir);
}

TEST(BenchPack, ATruncatedPackSaysItWasCutOff) {
    const std::string bytes = encoded(cornellPack());
    for (std::size_t keep : {std::size_t{0}, std::size_t{5}, std::size_t{20}, kBenchPackHeaderSize + 10,
                             bytes.size() / 2, bytes.size() - 1}) {
        const auto r = decodeBenchPack(std::string_view(bytes).substr(0, keep), "cut.lpvpack");
        ASSERT_FALSE(r) << keep;
        EXPECT_EQ(r.error().code, ErrorCode::Truncated) << keep << ": " << r.error().describe();
        EXPECT_NE(r.error().describe().find("cut.lpvpack"), std::string::npos);
    }
}

TEST(BenchPack, ADamagedPayloadFailsItsChecksum) {
    std::string bytes = encoded(cornellPack());
    bytes[bytes.size() / 2] ^= 0x40;
    const auto r = decodeBenchPack(bytes, "damaged.lpvpack");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ErrorCode::ChecksumMismatch);
    EXPECT_NE(r.error().message.find("damaged"), std::string::npos) << r.error().describe();
}

TEST(BenchPack, CountsTheBytesCannotHoldAreRefusedBeforeAllocating) {
    const BenchPack pack = cornellPack();
    for (const std::size_t offset : {kMeshCountOffset, kTextureCountOffset}) {
        std::string bytes = encoded(pack);
        patchU32(bytes, offset, 0xffffffffu); // the header's counts are outside the payload's checksum
        const auto r = decodeBenchPack(bytes, "counts.lpvpack");
        ASSERT_FALSE(r);
        EXPECT_EQ(r.error().code, ErrorCode::CorruptAsset);
        EXPECT_NE(r.error().message.find("cannot fit"), std::string::npos) << r.error().describe();
    }
    // One mesh fewer than the document names: counted, named.
    std::string bytes = encoded(pack);
    patchU32(bytes, kMeshCountOffset, std::uint32_t(pack.project.scene.meshes.size() - 1));
    const auto fewer = decodeBenchPack(bytes, "fewer.lpvpack");
    ASSERT_FALSE(fewer);
    EXPECT_EQ(fewer.error().code, ErrorCode::CorruptAsset);
}

TEST(BenchPack, ATextureLargerThanItsBytesIsRefused) {
    const BenchPack pack = cornellPack();
    const std::string good = encoded(pack);
    const std::size_t record = firstTextureRecord(good, pack);
    const std::size_t keyLength = pack.textures.begin()->first.size();
    const std::size_t widthAt = record + 4 + keyLength;

    // A width past the limit: refused with the texture's sizes named.
    std::string huge = good;
    patchU32(huge, widthAt, 1u << 20);
    rechecksum(huge);
    auto r = decodeBenchPack(huge, "huge.lpvpack");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ErrorCode::CorruptAsset);
    EXPECT_NE(r.error().message.find("1048576x2"), std::string::npos) << r.error().describe();

    // Within the limit but more pixels than are left: the cursor says what needs how much.
    std::string longer = good;
    patchU32(longer, widthAt, 4000);
    rechecksum(longer);
    r = decodeBenchPack(longer, "longer.lpvpack");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ErrorCode::CorruptAsset);
    EXPECT_NE(r.error().message.find("textures[0].pixels needs 32000 bytes"), std::string::npos)
        << r.error().describe();

    // A mesh asset inside the pack keeps its own checks (and names where it lies).
    std::string mesh = good;
    const std::size_t docLengthAt = kBenchPackHeaderSize + 4 + pack.projectHash.size();
    std::uint64_t docLength = 0;
    std::memcpy(&docLength, mesh.data() + docLengthAt, 8);
    const std::size_t firstMeshAsset = docLengthAt + 8 + std::size_t(docLength) + 8;
    mesh[firstMeshAsset + kMeshAssetHeaderSize] ^= 0x01; // the mesh's payload: its own checksum fails
    rechecksum(mesh);
    r = decodeBenchPack(mesh, "mesh.lpvpack");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ErrorCode::ChecksumMismatch);
    EXPECT_NE(r.error().file.find("meshes[0]"), std::string::npos) << r.error().describe();
}

TEST(BenchPack, NotAPackOrANewerOneIsNamedSo) {
    const auto notPack = decodeBenchPack(encodeMeshAsset(Mesh{}), "mesh.lpvpack");
    ASSERT_FALSE(notPack);
    EXPECT_EQ(notPack.error().code, ErrorCode::UnknownFormat);
    std::string newer = encoded(cornellPack());
    patchU32(newer, 8, kBenchPackVersion + 1);
    const auto r = decodeBenchPack(newer, "newer.lpvpack");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ErrorCode::NewerVersion);
}

TEST(BenchPack, WhatAReadWouldRefuseIsNotWritten) {
    BenchPack pack = cornellPack();
    pack.textures.begin()->second.pixels.pop_back();
    const auto r = encodeBenchPack(pack, "bad.lpvpack");
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ErrorCode::InvalidValue);
}
