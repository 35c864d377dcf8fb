// The binary mesh asset (.lpvmesh): exact layout, lossless round trips, and
// a precise error (never a crash) for every kind of damage.
#include "ProjectTestSupport.h"

#include "lpv/scene/MeshAsset.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

using namespace lpv::scene;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr std::size_t kHeader = 48;

// --- an independent writer of the documented layout (byte by byte, little-endian) ---

void putU32(std::string& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
}

void putU64(std::string& out, std::uint64_t v) {
    for (int i = 0; i < 8; ++i)
        out.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
}

void putF32(std::string& out, float f) { putU32(out, std::bit_cast<std::uint32_t>(f)); }

void patchU32(std::string& bytes, std::size_t at, std::uint32_t v) {
    std::string le;
    putU32(le, v);
    bytes.replace(at, 4, le);
}

void patchU64(std::string& bytes, std::size_t at, std::uint64_t v) {
    std::string le;
    putU64(le, v);
    bytes.replace(at, 8, le);
}

std::uint32_t readU32(const std::string& bytes, std::size_t at) {
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i)
        v = (v << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
    return v;
}

struct RawAsset {
    std::uint32_t version = kMeshAssetVersion;
    std::uint32_t flags = 0;
    std::uint32_t vertexCount = 0;
    std::uint32_t indexCount = 0;
    std::uint32_t submeshCount = 0;
    std::string payload;

    std::string bytes() const {
        std::string out("LPVMESH\0", 8);
        putU32(out, version);
        putU32(out, flags);
        putU32(out, vertexCount);
        putU32(out, indexCount);
        putU32(out, submeshCount);
        putU32(out, 0); // reserved
        putU64(out, payload.size());
        putU64(out, payloadChecksum(version, payload));
        return out + payload;
    }
};

// One triangle with every stream, built from the documented layout.
RawAsset triangleAsset(std::uint32_t badIndex = 2, float firstY = 0.0f) {
    RawAsset a;
    a.flags = 0b111;
    a.vertexCount = 3;
    a.indexCount = 3;
    a.submeshCount = 1;
    for (float v : {0.0f, firstY, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f}) // positions
        putF32(a.payload, v);
    for (int i = 0; i < 3; ++i) // normals
        for (float v : {0.0f, 0.0f, 1.0f})
            putF32(a.payload, v);
    for (int i = 0; i < 3; ++i) // tangents
        for (float v : {1.0f, 0.0f, 0.0f, -1.0f})
            putF32(a.payload, v);
    for (float v : {0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f}) // uvs
        putF32(a.payload, v);
    for (std::uint32_t i : {0u, 1u, badIndex})
        putU32(a.payload, i);
    for (std::uint32_t v : {0u, 3u, 0u}) // submesh: firstIndex, indexCount, materialIndex
        putU32(a.payload, v);
    putU32(a.payload, 3);
    a.payload += "tri";
    return a;
}

Mesh triangleMesh() {
    Mesh m;
    m.name = "tri";
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.normals.assign(3, {0, 0, 1});
    m.tangents.assign(3, {1, 0, 0, -1});
    m.uvs = {{0, 0}, {1, 0}, {0, 1}};
    m.indices = {0, 1, 2};
    m.submeshes = {{0, 3, 0}};
    return m;
}

// Two quads, two materials, values that would expose any lossy step.
Mesh richMesh() {
    Mesh m;
    m.name = "rich mesh \xc3\xa9"; // UTF-8 "é"
    m.positions = {{-0.0f, 1e-38f, 3.4e38f}, {0.1f, -2.5f, std::numeric_limits<float>::denorm_min()},
                   {1, 1, 1},         {-1, 0.333333f, 7},
                   {5, 6, 7},         {8, 9, 10},
                   {11, 12, 13},      {14, 15, 16}};
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        const float f = static_cast<float>(i);
        m.normals.push_back({f, -f, 0.5f});
        m.tangents.push_back({0.25f * f, 1, 0, i % 2 ? 1.0f : -1.0f});
        m.uvs.push_back({f / 7.0f, 1.0f - f / 3.0f});
    }
    m.indices = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    m.submeshes = {{0, 6, 0}, {6, 6, 1}};
    return m;
}

Error decodeError(const std::string& bytes, std::size_t materialCount = 1) {
    const auto decoded = decodeMeshAsset(bytes, "mesh.lpvmesh", materialCount);
    if (decoded) {
        ADD_FAILURE() << "decoding succeeded";
        return {};
    }
    EXPECT_EQ(decoded.error().file, "mesh.lpvmesh") << "an error names the file";
    EXPECT_FALSE(decoded.error().message.empty());
    return decoded.error();
}

} // namespace

TEST(MeshAsset, Fnv1a64MatchesReferenceVectors) {
    EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ull);
    EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cull);
    EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ull);
}

TEST(MeshAsset, EncoderWritesTheDocumentedLayout) {
    EXPECT_EQ(encodeMeshAsset(triangleMesh()), triangleAsset().bytes());
    const std::string bytes = encodeMeshAsset(triangleMesh());
    ASSERT_EQ(bytes.size(), kMeshAssetHeaderSize + 3 * (12 + 12 + 16 + 8) + 3 * 4 + 12 + 4 + 3);
    EXPECT_EQ(readU32(bytes, 8), kMeshAssetVersion);
}

TEST(MeshAsset, RoundTripsEveryStreamExactly) {
    const Mesh mesh = richMesh();
    const auto decoded = decodeMeshAsset(encodeMeshAsset(mesh), "rich.lpvmesh", 2);
    ASSERT_TRUE(decoded) << decoded.error().describe();
    EXPECT_EQ(*decoded, mesh);
    EXPECT_TRUE(std::signbit(decoded->positions[0].x)) << "-0 stays -0";
}

TEST(MeshAsset, RoundTripsPositionsOnly) {
    Mesh mesh = richMesh();
    mesh.normals.clear();
    mesh.tangents.clear();
    mesh.uvs.clear();
    mesh.submeshes.clear();
    const std::string bytes = encodeMeshAsset(mesh);
    EXPECT_EQ(readU32(bytes, 12), 0u) << "no stream flags";
    const auto decoded = decodeMeshAsset(bytes, "p.lpvmesh", 0);
    ASSERT_TRUE(decoded) << decoded.error().describe();
    EXPECT_EQ(*decoded, mesh);
}

TEST(MeshAsset, RoundTripsAnEmptyMesh) {
    const Mesh empty;
    const auto decoded = decodeMeshAsset(encodeMeshAsset(empty), "e.lpvmesh", 0);
    ASSERT_TRUE(decoded) << decoded.error().describe();
    EXPECT_EQ(*decoded, empty);
}

TEST(MeshAsset, EveryTruncationIsReportedAsTruncated) {
    const std::string bytes = encodeMeshAsset(richMesh());
    for (std::size_t size = 0; size < bytes.size(); ++size) {
        const auto decoded = decodeMeshAsset(std::string_view(bytes).substr(0, size), "cut.lpvmesh", 2);
        ASSERT_FALSE(decoded) << "prefix of " << size << " bytes";
        EXPECT_EQ(decoded.error().code, ErrorCode::Truncated) << "prefix of " << size << " bytes";
    }
}

TEST(MeshAsset, WrongMagicIsUnknownFormat) {
    const Error e = decodeError("\x89PNG\r\n\x1a\n and then some more bytes of a picture, long enough");
    EXPECT_EQ(e.code, ErrorCode::UnknownFormat);
    EXPECT_EQ(e.location, "byte offset 0");
}

TEST(MeshAsset, NewerVersionIsRejectedWithBothVersions) {
    RawAsset a = triangleAsset();
    a.version = kMeshAssetVersion + 1;
    const Error e = decodeError(a.bytes());
    EXPECT_EQ(e.code, ErrorCode::NewerVersion);
    EXPECT_EQ(e.location, "byte offset 8");
    EXPECT_NE(e.message.find("version " + std::to_string(kMeshAssetVersion + 1)), std::string::npos) << e.message;
    EXPECT_NE(e.message.find("version " + std::to_string(kMeshAssetVersion)), std::string::npos) << e.message;
}

TEST(MeshAsset, VersionOneAssetsWithTheirFnvChecksumStillLoad) {
    RawAsset a = triangleAsset();
    a.version = 1;
    ASSERT_EQ(payloadChecksum(1, a.payload), fnv1a64(a.payload));
    const auto decoded = decodeMeshAsset(a.bytes(), "old.lpvmesh", 1);
    ASSERT_TRUE(decoded.has_value()) << decoded.error().describe();
    EXPECT_EQ(*decoded, triangleMesh());
    std::string damaged = a.bytes();
    damaged.back() ^= 1;
    const auto bad = decodeMeshAsset(damaged, "old.lpvmesh", 1);
    ASSERT_FALSE(bad.has_value());
    EXPECT_EQ(bad.error().code, ErrorCode::ChecksumMismatch);
    EXPECT_NE(bad.error().message.find("FNV-1a"), std::string::npos) << bad.error().message;
}

TEST(MeshAsset, ContentHashIsXxh3) {
    // Reference values of XXH3_64bits with seed 0 (xxHash's own test vectors).
    EXPECT_EQ(contentHash64(""), 0x2D06800538D394C2ull);
    EXPECT_NE(contentHash64("a"), contentHash64("b"));
}

TEST(MeshAsset, AnyFlippedPayloadByteIsChecksumMismatch) {
    const std::string good = encodeMeshAsset(richMesh());
    for (std::size_t at = kHeader; at < good.size(); ++at) {
        std::string bad = good;
        bad[at] = static_cast<char>(bad[at] ^ 0x40);
        const auto decoded = decodeMeshAsset(bad, "flip.lpvmesh", 2);
        ASSERT_FALSE(decoded) << "byte " << at;
        EXPECT_EQ(decoded.error().code, ErrorCode::ChecksumMismatch) << "byte " << at;
        EXPECT_EQ(decoded.error().location, "byte offset 40");
    }
}

TEST(MeshAsset, NaNPositionWithValidChecksumIsNonFiniteAtItsOffset) {
    const Error e = decodeError(triangleAsset(2, kNaN).bytes());
    EXPECT_EQ(e.code, ErrorCode::NonFinite);
    // Vertex 0, component y: the second float of the payload.
    EXPECT_EQ(e.location, "byte offset 52");
    EXPECT_NE(e.message.find("position 0 component y is NaN"), std::string::npos) << e.message;
}

TEST(MeshAsset, InfiniteUvIsNonFiniteAtItsOffset) {
    RawAsset a = triangleAsset();
    const std::size_t uvStart = 3 * (12 + 12 + 16);
    std::string inf;
    putF32(inf, kInf);
    a.payload.replace(uvStart + 8 + 4, 4, inf); // uv of vertex 1, component y
    const Error e = decodeError(a.bytes());
    EXPECT_EQ(e.code, ErrorCode::NonFinite);
    EXPECT_EQ(e.location, "byte offset " + std::to_string(kHeader + uvStart + 12));
    EXPECT_NE(e.message.find("uv 1 component y is infinite"), std::string::npos) << e.message;
}

TEST(MeshAsset, TriangleIndexOutOfRangeNamesPositionValueAndOffset) {
    const Error e = decodeError(triangleAsset(7).bytes());
    EXPECT_EQ(e.code, ErrorCode::IndexOutOfRange);
    const std::size_t indexStart = kHeader + 3 * (12 + 12 + 16 + 8);
    EXPECT_EQ(e.location, "byte offset " + std::to_string(indexStart + 2 * 4));
    EXPECT_NE(e.message.find("index 2 (triangle 0) is 7"), std::string::npos) << e.message;
    EXPECT_NE(e.message.find("3 vertices"), std::string::npos) << e.message;
}

TEST(MeshAsset, IndexCountThatIsNotWholeTrianglesIsCorrupt) {
    RawAsset a = triangleAsset();
    a.indexCount = 2;
    a.submeshCount = 0;
    a.payload.erase(3 * (12 + 12 + 16 + 8) + 8, 4 + 12); // drop the last index and the submesh
    const Error e = decodeError(a.bytes());
    EXPECT_EQ(e.code, ErrorCode::CorruptAsset);
    EXPECT_EQ(e.location, "byte offset 20");
}

TEST(MeshAsset, SubmeshBeyondTheIndexBufferIsIndexOutOfRange) {
    RawAsset a = triangleAsset();
    const std::size_t submeshStart = 3 * (12 + 12 + 16 + 8) + 12;
    std::string range;
    putU32(range, 3);
    putU32(range, 3);
    a.payload.replace(submeshStart, 8, range); // indices [3, 6) of 3
    const Error e = decodeError(a.bytes());
    EXPECT_EQ(e.code, ErrorCode::IndexOutOfRange);
    EXPECT_EQ(e.location, "byte offset " + std::to_string(kHeader + submeshStart));
    EXPECT_NE(e.message.find("[3, 6)"), std::string::npos) << e.message;
}

TEST(MeshAsset, SubmeshWithUnknownMaterialIsIndexOutOfRange) {
    const std::string bytes = encodeMeshAsset(richMesh()); // uses materials 0 and 1
    const Error e = decodeError(bytes, 1);
    EXPECT_EQ(e.code, ErrorCode::IndexOutOfRange);
    EXPECT_NE(e.message.find("material 1"), std::string::npos) << e.message;
    EXPECT_TRUE(decodeMeshAsset(bytes, "x", 2)) << "fine with two materials";
}

TEST(MeshAsset, HugeCountsInASmallFileAreCorruptAndAllocateNothing) {
    RawAsset a = triangleAsset();
    a.vertexCount = 0xffffffffu; // would be 206 GB of vertex data
    a.indexCount = 0xfffffffcu; // whole triangles, so the size check is what fails
    const Error e = decodeError(a.bytes());
    EXPECT_EQ(e.code, ErrorCode::CorruptAsset);
    EXPECT_EQ(e.location, "byte offset 32");
}

TEST(MeshAsset, PayloadSizeBeyondTheFileIsTruncated) {
    std::string bytes = triangleAsset().bytes();
    patchU64(bytes, 32, std::numeric_limits<std::uint64_t>::max());
    EXPECT_EQ(decodeError(bytes).code, ErrorCode::Truncated);
}

TEST(MeshAsset, TrailingBytesAreCorrupt) {
    const Error e = decodeError(triangleAsset().bytes() + "xx");
    EXPECT_EQ(e.code, ErrorCode::CorruptAsset);
    EXPECT_NE(e.message.find("2 unexpected bytes"), std::string::npos) << e.message;
}

TEST(MeshAsset, UnknownFlagBitsAreCorrupt) {
    std::string bytes = triangleAsset().bytes();
    patchU32(bytes, 12, 0b1111);
    const Error e = decodeError(bytes);
    EXPECT_EQ(e.code, ErrorCode::CorruptAsset);
    EXPECT_EQ(e.location, "byte offset 12");
}

TEST(MeshAsset, NameLengthThatDisagreesWithThePayloadIsCorrupt) {
    RawAsset a = triangleAsset();
    patchU32(a.payload, a.payload.size() - 7, 2); // "tri" announced as 2 bytes
    const Error e = decodeError(a.bytes());
    EXPECT_EQ(e.code, ErrorCode::CorruptAsset);
    EXPECT_EQ(e.location, "byte offset " + std::to_string(kHeader + a.payload.size() - 7));
}

TEST(MeshAsset, RandomDamageIsAnErrorNeverACrash) {
    const std::string good = encodeMeshAsset(richMesh());
    std::mt19937 random(1234);
    std::uniform_int_distribution<std::size_t> position(0, good.size() - 1);
    std::uniform_int_distribution<int> value(0, 255);
    int failures = 0;
    for (int round = 0; round < 3000; ++round) {
        std::string bad = good;
        for (int k = 0; k < 1 + round % 4; ++k)
            bad[position(random)] = static_cast<char>(value(random));
        // Damage to the checksummed payload must always be caught; only the
        // reserved header field may change without consequence.
        const auto decoded = decodeMeshAsset(bad, "r.lpvmesh", 2);
        if (!decoded)
            ++failures;
        else if (bad.compare(kHeader, std::string::npos, good, kHeader) != 0)
            ADD_FAILURE() << "damaged payload accepted in round " << round;
    }
    EXPECT_GT(failures, 2500);
}

TEST(MeshAsset, ValidateMeshNamesTheField) {
    Mesh m = triangleMesh();
    EXPECT_TRUE(validateMesh(m, "p.lpvproj", "meshes[3]", 1));

    Mesh badNormals = m;
    badNormals.normals.pop_back();
    auto r = validateMesh(badNormals, "p.lpvproj", "meshes[3]", 1);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ErrorCode::InvalidValue);
    EXPECT_EQ(r.error().location, "meshes[3].normals");

    Mesh nan = m;
    nan.positions[1].z = kNaN;
    r = validateMesh(nan, "p.lpvproj", "meshes[3]", 1);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ErrorCode::NonFinite);
    EXPECT_EQ(r.error().location, "meshes[3].positions[1].z");

    Mesh badIndex = m;
    badIndex.indices[1] = 3;
    r = validateMesh(badIndex, "p.lpvproj", "meshes[3]", 1);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ErrorCode::IndexOutOfRange);
    EXPECT_EQ(r.error().location, "meshes[3].indices[1]");

    r = validateMesh(m, "p.lpvproj", "meshes[3]", 0);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, ErrorCode::IndexOutOfRange);
    EXPECT_EQ(r.error().location, "meshes[3].submeshes[0]");
}
