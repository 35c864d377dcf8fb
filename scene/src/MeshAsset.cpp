// Binary mesh asset (.lpvmesh), layout in docs/project-format.md.
//
// Decoding trusts nothing: every count is checked against the bytes that are
// actually there before anything is allocated, so a damaged or hostile file
// costs at most a copy of itself and yields an Error, never a crash.
#include "lpv/scene/MeshAsset.h"

#include "LittleEndian.h"

#include <xxhash.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <sstream>
#include <limits>
#include <type_traits>

namespace lpv::scene {
namespace {

constexpr std::string_view kMagic{"LPVMESH\0", 8};

// Header field offsets; every field is little-endian.
constexpr std::size_t kVersionOffset = 8;
constexpr std::size_t kFlagsOffset = 12;
constexpr std::size_t kVertexCountOffset = 16;
constexpr std::size_t kIndexCountOffset = 20;
constexpr std::size_t kSubmeshCountOffset = 24;
constexpr std::size_t kReservedOffset = 28; // written as 0, ignored on read
constexpr std::size_t kPayloadSizeOffset = 32;
constexpr std::size_t kChecksumOffset = 40;
static_assert(kChecksumOffset + 8 == kMeshAssetHeaderSize);

constexpr std::uint32_t kHasNormals = 1u << 0;
constexpr std::uint32_t kHasTangents = 1u << 1;
constexpr std::uint32_t kHasUvs = 1u << 2;
constexpr std::uint32_t kKnownFlags = kHasNormals | kHasTangents | kHasUvs;

// Streams are copied in bulk, which needs them to be packed 32-bit words.
static_assert(sizeof(glm::vec2) == 8 && sizeof(glm::vec3) == 12 && sizeof(glm::vec4) == 16);
static_assert(sizeof(Submesh) == 12 && std::is_trivially_copyable_v<Submesh>);
static_assert(std::is_trivially_copyable_v<glm::vec3> && std::is_trivially_copyable_v<glm::vec4>);

constexpr const char* kComponentNames[] = {"x", "y", "z", "w"};

// GCC 12 has no <format>; messages are built with a stream (binary::concat).
using binary::atByte;
using binary::concat;
using binary::littleEndian;
using binary::loadAt;
using binary::storeAt;

std::string hex64(std::uint64_t v) {
    std::ostringstream out;
    out << "0x" << std::hex;
    out.width(16);
    out.fill('0');
    out << v;
    return out.str();
}

// Every stream is a run of 32-bit words (f32 or u32); on a big-endian host
// each word is reversed after the bulk copy.
void swapWordsOnBigEndian(char* data, std::size_t size) {
    if constexpr (std::endian::native == std::endian::big)
        for (std::size_t i = 0; i + 4 <= size; i += 4)
            std::reverse(data + i, data + i + 4);
    else
        static_cast<void>(data), static_cast<void>(size);
}

template <class T>
void appendWords(std::string& out, const std::vector<T>& values) {
    static_assert(sizeof(T) % 4 == 0 && std::is_trivially_copyable_v<T>);
    const std::size_t start = out.size();
    const std::size_t size = values.size() * sizeof(T);
    out.resize(start + size);
    if (size > 0)
        std::memcpy(out.data() + start, values.data(), size);
    swapWordsOnBigEndian(out.data() + start, size);
}

template <class T>
std::vector<T> readWords(std::string_view bytes, std::uint64_t at, std::uint32_t count) {
    std::vector<T> values(count);
    const std::size_t size = std::size_t{count} * sizeof(T);
    if (size > 0) {
        std::memcpy(values.data(), bytes.data() + at, size);
        swapWordsOnBigEndian(reinterpret_cast<char*>(values.data()), size);
    }
    return values;
}

void appendU32(std::string& out, std::uint32_t v) {
    out.resize(out.size() + 4);
    storeAt(out, out.size() - 4, v);
}

// --- checks shared by decodeMeshAsset (locations are byte offsets) and
// validateMesh (locations are field paths); `where` builds the location. ---

template <glm::length_t L, glm::qualifier Q, class Where>
Expected<void> checkFinite(const std::vector<glm::vec<L, float, Q>>& values, const char* stream,
                           const std::string& file, Where where) {
    for (std::size_t i = 0; i < values.size(); ++i)
        for (glm::length_t c = 0; c < L; ++c)
            if (const float v = values[i][c]; !std::isfinite(v))
                return makeError(ErrorCode::NonFinite, file, where(i, c),
                                 concat(stream, " ", i, " component ", kComponentNames[static_cast<std::size_t>(c)], " is ",
                                        std::isnan(v) ? "NaN" : "infinite"));
    return {};
}

template <class Where>
Expected<void> checkIndices(const std::vector<std::uint32_t>& indices, std::size_t vertexCount,
                            const std::string& file, Where where) {
    for (std::size_t i = 0; i < indices.size(); ++i)
        if (indices[i] >= vertexCount)
            return makeError(ErrorCode::IndexOutOfRange, file, where(i),
                             concat("index ", i, " (triangle ", i / 3, ") is ", indices[i], ", but the mesh has ",
                                    vertexCount, " vertices"));
    return {};
}

template <class Where>
Expected<void> checkSubmeshes(const std::vector<Submesh>& submeshes, std::size_t indexCount,
                              std::size_t materialCount, const std::string& file, Where where) {
    for (std::size_t i = 0; i < submeshes.size(); ++i) {
        const Submesh& s = submeshes[i];
        // 64-bit sum: firstIndex + indexCount may exceed 32 bits in a hostile file.
        const std::uint64_t end = std::uint64_t{s.firstIndex} + s.indexCount;
        if (end > indexCount)
            return makeError(ErrorCode::IndexOutOfRange, file, where(i),
                             concat("submesh ", i, " covers indices [", s.firstIndex, ", ", end, "), but the mesh has ",
                                    indexCount, " indices"));
        if (s.firstIndex % 3 != 0 || s.indexCount % 3 != 0)
            return makeError(ErrorCode::InvalidValue, file, where(i),
                             concat("submesh ", i, " covers indices [", s.firstIndex, ", ", end,
                                    "), which is not a whole number of triangles"));
        if (s.materialIndex >= materialCount)
            return makeError(ErrorCode::IndexOutOfRange, file, where(i),
                             concat("submesh ", i, " uses material ", s.materialIndex, ", but the project has ",
                                    materialCount, " materials"));
    }
    return {};
}

// --- decoding ---

struct Header {
    std::uint32_t version = 0;
    std::uint32_t flags = 0;
    std::uint32_t vertexCount = 0;
    std::uint32_t indexCount = 0;
    std::uint32_t submeshCount = 0;
    std::uint64_t payloadSize = 0;
    std::uint64_t checksum = 0;
};

Header readHeader(std::string_view bytes) {
    Header h;
    h.version = loadAt<std::uint32_t>(bytes, kVersionOffset);
    h.flags = loadAt<std::uint32_t>(bytes, kFlagsOffset);
    h.vertexCount = loadAt<std::uint32_t>(bytes, kVertexCountOffset);
    h.indexCount = loadAt<std::uint32_t>(bytes, kIndexCountOffset);
    h.submeshCount = loadAt<std::uint32_t>(bytes, kSubmeshCountOffset);
    h.payloadSize = loadAt<std::uint64_t>(bytes, kPayloadSizeOffset);
    h.checksum = loadAt<std::uint64_t>(bytes, kChecksumOffset);
    return h;
}

// Absolute file offsets of the payload's parts, from the header's counts.
// The counts are 32-bit, so no product here exceeds 2^38 and no sum can
// overflow 64 bits, whatever the header says.
struct Layout {
    std::uint64_t positions = 0, normals = 0, tangents = 0, uvs = 0, indices = 0, submeshes = 0;
    std::uint64_t nameLength = 0; // the u32 name length; the name follows it
};

Layout layoutOf(const Header& h) {
    const std::uint64_t vertices = h.vertexCount;
    Layout l;
    std::uint64_t at = kMeshAssetHeaderSize;
    l.positions = at;
    at += vertices * sizeof(glm::vec3);
    l.normals = at;
    if (h.flags & kHasNormals)
        at += vertices * sizeof(glm::vec3);
    l.tangents = at;
    if (h.flags & kHasTangents)
        at += vertices * sizeof(glm::vec4);
    l.uvs = at;
    if (h.flags & kHasUvs)
        at += vertices * sizeof(glm::vec2);
    l.indices = at;
    at += std::uint64_t{h.indexCount} * sizeof(std::uint32_t);
    l.submeshes = at;
    at += std::uint64_t{h.submeshCount} * sizeof(Submesh);
    l.nameLength = at;
    return l;
}

// Magic, size and version: is this a mesh asset this build can read at all?
Expected<Header> checkHeader(std::string_view bytes, const std::string& file) {
    const std::size_t magicBytes = std::min(bytes.size(), kMagic.size());
    if (bytes.substr(0, magicBytes) != kMagic.substr(0, magicBytes))
        return makeError(ErrorCode::UnknownFormat, file, atByte(0), "not an LPV Studio mesh asset (wrong magic bytes)");
    if (bytes.size() < kMeshAssetHeaderSize)
        return makeError(ErrorCode::Truncated, file, atByte(bytes.size()),
                         concat("the file is ", bytes.size(), " bytes long, but a mesh asset header needs ",
                                kMeshAssetHeaderSize));
    const Header h = readHeader(bytes);
    if (h.version > kMeshAssetVersion)
        return makeError(ErrorCode::NewerVersion, file, atByte(kVersionOffset),
                         concat("mesh asset version ", h.version, " is newer than this build reads (version ",
                                kMeshAssetVersion, ")"));
    if (h.version == 0)
        return makeError(ErrorCode::CorruptAsset, file, atByte(kVersionOffset), "mesh asset version 0 does not exist");
    if (h.flags & ~kKnownFlags)
        return makeError(ErrorCode::CorruptAsset, file, atByte(kFlagsOffset),
                         concat("unknown flag bits ", hex64(h.flags & ~kKnownFlags)));
    if (h.indexCount % 3 != 0)
        return makeError(ErrorCode::CorruptAsset, file, atByte(kIndexCountOffset),
                         concat("index count ", h.indexCount, " is not a whole number of triangles"));
    return h;
}

// The payload must be exactly as long as the header says, and as the counts
// imply; only then is it safe to size vectors from the counts.
Expected<void> checkPayloadSize(std::string_view bytes, const Header& h, const Layout& l, const std::string& file) {
    const std::uint64_t present = bytes.size() - kMeshAssetHeaderSize;
    if (h.payloadSize > present)
        return makeError(ErrorCode::Truncated, file, atByte(bytes.size()),
                         concat("the header announces a payload of ", h.payloadSize, " bytes, but only ", present,
                                " follow"));
    if (h.payloadSize < present)
        return makeError(ErrorCode::CorruptAsset, file, atByte(kMeshAssetHeaderSize + h.payloadSize),
                         concat(present - h.payloadSize, " unexpected bytes after the payload"));
    const std::uint64_t minimum = l.nameLength + 4 - kMeshAssetHeaderSize;
    if (h.payloadSize < minimum)
        return makeError(ErrorCode::CorruptAsset, file, atByte(kPayloadSizeOffset),
                         concat("a payload of ", h.payloadSize, " bytes cannot hold ", h.vertexCount, " vertices, ",
                                h.indexCount, " indices and ", h.submeshCount, " submeshes (at least ", minimum,
                                " bytes)"));
    return {};
}

template <glm::length_t L, glm::qualifier Q>
Expected<void> readStream(std::string_view bytes, std::uint64_t at, std::uint32_t count, const char* stream,
                          const std::string& file, std::vector<glm::vec<L, float, Q>>& out) {
    out = readWords<glm::vec<L, float, Q>>(bytes, at, count);
    return checkFinite(out, stream, file, [&](std::size_t i, glm::length_t c) {
        return atByte(at + (i * static_cast<std::size_t>(L) + static_cast<std::size_t>(c)) * sizeof(float));
    });
}

Expected<Mesh> decodePayload(std::string_view bytes, const Header& h, const Layout& l, const std::string& file,
                             std::size_t materialCount) {
    Mesh mesh;
    const std::uint32_t vertices = h.vertexCount;
    if (auto r = readStream(bytes, l.positions, vertices, "position", file, mesh.positions); !r)
        return std::unexpected(r.error());
    if (h.flags & kHasNormals)
        if (auto r = readStream(bytes, l.normals, vertices, "normal", file, mesh.normals); !r)
            return std::unexpected(r.error());
    if (h.flags & kHasTangents)
        if (auto r = readStream(bytes, l.tangents, vertices, "tangent", file, mesh.tangents); !r)
            return std::unexpected(r.error());
    if (h.flags & kHasUvs)
        if (auto r = readStream(bytes, l.uvs, vertices, "uv", file, mesh.uvs); !r)
            return std::unexpected(r.error());

    mesh.indices = readWords<std::uint32_t>(bytes, l.indices, h.indexCount);
    if (auto r = checkIndices(mesh.indices, vertices, file,
                              [&](std::size_t i) { return atByte(l.indices + i * sizeof(std::uint32_t)); });
        !r)
        return std::unexpected(r.error());

    mesh.submeshes = readWords<Submesh>(bytes, l.submeshes, h.submeshCount);
    if (auto r = checkSubmeshes(mesh.submeshes, mesh.indices.size(), materialCount, file,
                                [&](std::size_t i) { return atByte(l.submeshes + i * sizeof(Submesh)); });
        !r)
        return std::unexpected(r.error());

    // checkPayloadSize guaranteed the 4 length bytes exist.
    const std::uint32_t nameLength = loadAt<std::uint32_t>(bytes, l.nameLength);
    const std::uint64_t nameStart = l.nameLength + 4;
    if (nameStart + nameLength != bytes.size())
        return makeError(ErrorCode::CorruptAsset, file, atByte(l.nameLength),
                         concat("name length ", nameLength, " does not match the ", bytes.size() - nameStart,
                                " bytes left in the payload"));
    mesh.name.assign(bytes.substr(nameStart, nameLength));
    return mesh;
}

} // namespace

std::uint64_t contentHash64(std::string_view bytes) { return XXH3_64bits(bytes.data(), bytes.size()); }

std::uint64_t payloadChecksum(std::uint32_t version, std::string_view payload) {
    return version == 1 ? fnv1a64(payload) : contentHash64(payload);
}

std::uint64_t fnv1a64(std::string_view bytes) {
    std::uint64_t hash = 0xcbf29ce484222325ull; // FNV-1a 64-bit offset basis
    for (const char c : bytes) {
        hash ^= static_cast<unsigned char>(c);
        hash *= 0x100000001b3ull; // FNV 64-bit prime
    }
    return hash;
}

// Precondition (checked by validateMesh, which saveProject calls): counts fit
// 32 bits. A vertex stream whose length differs from positions is left out
// rather than written inconsistently.
std::string encodeMeshAsset(const Mesh& mesh) {
    const std::size_t vertices = mesh.positions.size();
    auto present = [&](std::size_t size) { return size == vertices && vertices > 0; };
    std::uint32_t flags = 0;
    if (present(mesh.normals.size()))
        flags |= kHasNormals;
    if (present(mesh.tangents.size()))
        flags |= kHasTangents;
    if (present(mesh.uvs.size()))
        flags |= kHasUvs;

    std::string out(kMeshAssetHeaderSize, '\0');
    appendWords(out, mesh.positions);
    if (flags & kHasNormals)
        appendWords(out, mesh.normals);
    if (flags & kHasTangents)
        appendWords(out, mesh.tangents);
    if (flags & kHasUvs)
        appendWords(out, mesh.uvs);
    appendWords(out, mesh.indices);
    appendWords(out, mesh.submeshes);
    appendU32(out, static_cast<std::uint32_t>(mesh.name.size()));
    out += mesh.name;

    const std::string_view payload = std::string_view(out).substr(kMeshAssetHeaderSize);
    std::memcpy(out.data(), kMagic.data(), kMagic.size());
    storeAt(out, kVersionOffset, kMeshAssetVersion);
    storeAt(out, kFlagsOffset, flags);
    storeAt(out, kVertexCountOffset, static_cast<std::uint32_t>(vertices));
    storeAt(out, kIndexCountOffset, static_cast<std::uint32_t>(mesh.indices.size()));
    storeAt(out, kSubmeshCountOffset, static_cast<std::uint32_t>(mesh.submeshes.size()));
    storeAt(out, kReservedOffset, std::uint32_t{0});
    storeAt(out, kPayloadSizeOffset, static_cast<std::uint64_t>(payload.size()));
    storeAt(out, kChecksumOffset, payloadChecksum(kMeshAssetVersion, payload));
    return out;
}

Expected<Mesh> decodeMeshAsset(std::string_view bytes, const std::string& fileName, std::size_t materialCount) {
    const auto header = checkHeader(bytes, fileName);
    if (!header)
        return std::unexpected(header.error());
    const Layout layout = layoutOf(*header);
    if (auto r = checkPayloadSize(bytes, *header, layout, fileName); !r)
        return std::unexpected(r.error());
    // The checksum comes before any structural check of the payload, so
    // damage reads as damage and not as some odd value it happens to produce.
    const std::uint64_t actual = payloadChecksum(header->version, bytes.substr(kMeshAssetHeaderSize));
    if (actual != header->checksum)
        return makeError(ErrorCode::ChecksumMismatch, fileName, atByte(kChecksumOffset),
                         concat("the payload's ", header->version == 1 ? "FNV-1a" : "XXH3", " checksum is ",
                                hex64(actual), ", but the header records ",
                                hex64(header->checksum), "; the file is damaged"));
    return decodePayload(bytes, *header, layout, fileName, materialCount);
}

Expected<void> validateMesh(const Mesh& mesh, const std::string& fileName, const std::string& location,
                            std::size_t materialCount) {
    constexpr std::size_t kMax = std::numeric_limits<std::uint32_t>::max();
    if (mesh.positions.size() > kMax || mesh.indices.size() > kMax || mesh.submeshes.size() > kMax ||
        mesh.name.size() > kMax)
        return makeError(ErrorCode::OutOfRange, fileName, location,
                         "more than 2^32-1 vertices, indices, submeshes or name bytes");

    const std::size_t vertices = mesh.positions.size();
    const auto streamSize = [&](std::size_t size, const char* stream) -> Expected<void> {
        if (size != 0 && size != vertices)
            return makeError(ErrorCode::InvalidValue, fileName, location + "." + stream,
                             concat(size, " ", stream, " for ", vertices, " positions"));
        return {};
    };
    if (auto r = streamSize(mesh.normals.size(), "normals"); !r)
        return r;
    if (auto r = streamSize(mesh.tangents.size(), "tangents"); !r)
        return r;
    if (auto r = streamSize(mesh.uvs.size(), "uvs"); !r)
        return r;

    const auto element = [&](const char* stream) {
        return [&location, stream](std::size_t i, glm::length_t c) {
            return concat(location, ".", stream, "[", i, "].", kComponentNames[static_cast<std::size_t>(c)]);
        };
    };
    if (auto r = checkFinite(mesh.positions, "position", fileName, element("positions")); !r)
        return r;
    if (auto r = checkFinite(mesh.normals, "normal", fileName, element("normals")); !r)
        return r;
    if (auto r = checkFinite(mesh.tangents, "tangent", fileName, element("tangents")); !r)
        return r;
    if (auto r = checkFinite(mesh.uvs, "uv", fileName, element("uvs")); !r)
        return r;

    if (mesh.indices.size() % 3 != 0)
        return makeError(ErrorCode::InvalidValue, fileName, location + ".indices",
                         concat(mesh.indices.size(), " indices are not a whole number of triangles"));
    if (auto r = checkIndices(mesh.indices, vertices, fileName,
                              [&](std::size_t i) { return concat(location, ".indices[", i, "]"); });
        !r)
        return r;
    return checkSubmeshes(mesh.submeshes, mesh.indices.size(), materialCount, fileName,
                          [&](std::size_t i) { return concat(location, ".submeshes[", i, "]"); });
}

} // namespace lpv::scene
