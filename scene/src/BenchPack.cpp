// Bench pack (.lpvpack, issue #45), layout in docs/project-format.md.
//
// The pack reuses the project format's pieces rather than a second copy of
// them: the document is the project file's JSON (projectToJson /
// projectFromJson, with the same validation), each mesh is a mesh asset
// (encodeMeshAsset / decodeMeshAsset, with its own checksum and bounds
// checks), and the checksum over the whole payload is the mesh assets'
// XXH3-64. What is new here is the framing, read through a cursor that
// checks each length against the bytes left before it takes them.
#include "lpv/scene/BenchPack.h"

#include "FileText.h"
#include "LittleEndian.h"
#include "ProjectJson.h"
#include "lpv/scene/MeshAsset.h"
#include "lpv/scene/ProjectLimits.h"

#include <bit>
#include <cstring>
#include <limits>
#include <sstream>

namespace lpv::scene {
namespace {

constexpr std::string_view kMagic{"LPVPACK\0", 8};

// Header field offsets; every field is little-endian.
constexpr std::size_t kVersionOffset = 8;
constexpr std::size_t kFlagsOffset = 12; // no flags yet: written as 0, anything else refused
constexpr std::size_t kMeshCountOffset = 16;
constexpr std::size_t kTextureCountOffset = 20;
constexpr std::size_t kPayloadSizeOffset = 32;
constexpr std::size_t kChecksumOffset = 40;
static_assert(kChecksumOffset + 8 == kBenchPackHeaderSize);

// The smallest a mesh and a texture record can be: a count larger than the
// bytes left could hold is refused before anything is reserved for it.
constexpr std::uint64_t kMinMeshRecord = 8 + kMeshAssetHeaderSize;
constexpr std::uint64_t kMinTextureRecord = 4 + 12;

using binary::append;
using binary::atByte;
using binary::concat;
using binary::loadAt;
using binary::storeAt;

std::string meshLocation(std::size_t i) { return concat("meshes[", i, "]"); }

// Reads the payload front to back; every take names what it reads, so a
// short file says what was cut off and where.
class Cursor {
public:
    Cursor(std::string_view bytes, std::size_t at, std::string file)
        : bytes_(bytes), at_(at), file_(std::move(file)) {}

    std::uint64_t offset() const { return at_; }
    std::uint64_t left() const { return bytes_.size() - at_; }

    Expected<std::string_view> take(std::uint64_t size, const std::string& what) {
        if (size > left())
            return makeError(ErrorCode::CorruptAsset, file_, atByte(at_),
                             concat(what, " needs ", size, " bytes, but only ", left(), " are left in the pack"));
        const std::string_view part = bytes_.substr(at_, std::size_t(size));
        at_ += std::size_t(size);
        return part;
    }

    template <class T>
    Expected<T> number(const std::string& what) {
        auto part = take(sizeof(T), what);
        if (!part)
            return std::unexpected(part.error());
        return loadAt<T>(*part, 0);
    }

    // A u32 or u64 length, then that many bytes.
    template <class Length>
    Expected<std::string_view> sized(const std::string& what) {
        const auto size = number<Length>(what + "'s length");
        if (!size)
            return std::unexpected(size.error());
        return take(*size, what);
    }

private:
    std::string_view bytes_;
    std::size_t at_;
    std::string file_;
};

Expected<void> checkTexture(const std::string& key, const Image8& image, const std::string& file) {
    const auto side = [](int v) { return v > 0 && std::uint32_t(v) <= kBenchPackMaxTextureSide; };
    if (!side(image.width) || !side(image.height) || image.channels < 1 || image.channels > 4)
        return makeError(ErrorCode::OutOfRange, file, "textures[\"" + key + "\"]",
                         concat("a texture of ", image.width, "x", image.height, " with ", image.channels,
                                " channels cannot be packed (sides 1-", kBenchPackMaxTextureSide, ", 1-4 channels)"));
    const std::uint64_t expected = std::uint64_t(image.width) * std::uint64_t(image.height) * std::uint64_t(image.channels);
    if (image.pixels.size() != expected)
        return makeError(ErrorCode::InvalidValue, file, "textures[\"" + key + "\"]",
                         concat(image.pixels.size(), " bytes of pixels for ", image.width, "x", image.height, "x",
                                image.channels));
    return {};
}

Expected<Mesh> readMesh(Cursor& in, const detail::MeshReference& ref, std::size_t i, std::size_t materialCount,
                        const std::string& file) {
    const std::uint64_t start = in.offset();
    const auto bytes = in.sized<std::uint64_t>(meshLocation(i));
    if (!bytes)
        return std::unexpected(bytes.error());
    // Errors inside the asset count from the asset's start; the name says where that is.
    auto mesh = decodeMeshAsset(*bytes, concat(file, " (", meshLocation(i), ", at byte offset ", start + 8, ")"),
                                materialCount);
    if (!mesh)
        return mesh;
    if (mesh->positions.size() != ref.vertices || mesh->triangleCount() != ref.triangles)
        return makeError(ErrorCode::CorruptAsset, file, meshLocation(i),
                         concat("the document records ", ref.vertices, " vertices and ", ref.triangles,
                                " triangles, but the mesh holds ", mesh->positions.size(), " and ",
                                mesh->triangleCount()));
    mesh->name = ref.name;
    return mesh;
}

Expected<std::pair<std::string, Image8>> readTexture(Cursor& in, std::size_t i, const std::string& file) {
    const std::string where = concat("textures[", i, "]");
    const auto key = in.sized<std::uint32_t>(where + ".key");
    if (!key)
        return std::unexpected(key.error());
    const std::uint64_t sizeAt = in.offset();
    std::uint32_t size[3] = {};
    for (std::uint32_t& v : size) {
        const auto n = in.number<std::uint32_t>(where + ".size");
        if (!n)
            return std::unexpected(n.error());
        v = *n;
    }
    const auto [width, height, channels] = size;
    if (width == 0 || height == 0 || width > kBenchPackMaxTextureSide || height > kBenchPackMaxTextureSide ||
        channels == 0 || channels > 4)
        return makeError(ErrorCode::CorruptAsset, file, atByte(sizeAt),
                         concat(where, " (\"", *key, "\") is ", width, "x", height, " with ", channels,
                                " channels; a pack holds sides of 1-", kBenchPackMaxTextureSide, " and 1-4 channels"));
    const auto pixels = in.take(std::uint64_t(width) * height * channels, where + ".pixels");
    if (!pixels)
        return std::unexpected(pixels.error());
    Image8 image;
    image.width = int(width);
    image.height = int(height);
    image.channels = int(channels);
    image.pixels.assign(pixels->begin(), pixels->end());
    return std::pair{std::string(*key), std::move(image)};
}

} // namespace

bool isBenchPackFile(const std::filesystem::path& file) { return file.extension() == ".lpvpack"; }

Expected<std::string> encodeBenchPack(const BenchPack& pack, const std::string& fileName) {
    const Project& project = pack.project;
    const std::size_t materialCount = project.scene.materials.size();
    if (auto fits = checkMaterialCount(materialCount, fileName, "materials"); !fits)
        return std::unexpected(fits.error());
    constexpr std::size_t kMax32 = std::numeric_limits<std::uint32_t>::max();
    if (project.scene.meshes.size() > kMax32 || pack.textures.size() > kMax32 || pack.projectHash.size() > kMax32)
        return makeError(ErrorCode::OutOfRange, fileName, "", "more than 2^32-1 meshes or textures");

    std::vector<std::string> assetPaths;
    for (std::size_t i = 0; i < project.scene.meshes.size(); ++i) {
        if (auto valid = validateMesh(project.scene.meshes[i], fileName, meshLocation(i), materialCount); !valid)
            return std::unexpected(valid.error());
        assetPaths.push_back(concat("pack/meshes/", i, ".lpvmesh"));
    }
    for (const auto& [key, image] : pack.textures) {
        if (key.size() > kMax32)
            return makeError(ErrorCode::OutOfRange, fileName, "textures", "a texture key over 2^32-1 bytes");
        if (auto valid = checkTexture(key, image, fileName); !valid)
            return std::unexpected(valid.error());
    }
    // The document as the loader will read it back: what it would refuse is refused now.
    const detail::Json document = detail::projectToJson(project, assetPaths);
    if (auto valid = detail::projectFromJson(document, fileName); !valid)
        return std::unexpected(valid.error());
    std::string text;
    try {
        text = document.dump(2) + "\n";
    } catch (const detail::Json::exception& e) {
        return makeError(ErrorCode::InvalidValue, fileName, "", std::string("cannot write the project: ") + e.what());
    }
    if (auto fits = checkWriteFits(text.size(), detail::kProjectFileLimit, fileName); !fits)
        return std::unexpected(fits.error());

    std::string out(kBenchPackHeaderSize, '\0');
    append(out, std::uint32_t(pack.projectHash.size()));
    out += pack.projectHash;
    append(out, std::uint64_t(text.size()));
    out += text;
    for (const Mesh& mesh : project.scene.meshes) {
        const std::string asset = encodeMeshAsset(mesh);
        append(out, std::uint64_t(asset.size()));
        out += asset;
    }
    for (const auto& [key, image] : pack.textures) {
        append(out, std::uint32_t(key.size()));
        out += key;
        append(out, std::uint32_t(image.width));
        append(out, std::uint32_t(image.height));
        append(out, std::uint32_t(image.channels));
        out.append(reinterpret_cast<const char*>(image.pixels.data()), image.pixels.size());
    }

    const std::string_view payload = std::string_view(out).substr(kBenchPackHeaderSize);
    std::memcpy(out.data(), kMagic.data(), kMagic.size());
    storeAt(out, kVersionOffset, kBenchPackVersion);
    storeAt(out, kFlagsOffset, std::uint32_t{0});
    storeAt(out, kMeshCountOffset, std::uint32_t(project.scene.meshes.size()));
    storeAt(out, kTextureCountOffset, std::uint32_t(pack.textures.size()));
    storeAt(out, kPayloadSizeOffset, std::uint64_t(payload.size()));
    storeAt(out, kChecksumOffset, contentHash64(payload));
    return out;
}

Expected<BenchPack> decodeBenchPack(std::string_view bytes, const std::string& file) {
    // Magic, size, version and flags: is this a pack this build can read at all?
    const std::size_t magicBytes = std::min(bytes.size(), kMagic.size());
    if (bytes.substr(0, magicBytes) != kMagic.substr(0, magicBytes))
        return makeError(ErrorCode::UnknownFormat, file, atByte(0), "not an LPV Studio bench pack (wrong magic bytes)");
    if (bytes.size() < kBenchPackHeaderSize)
        return makeError(ErrorCode::Truncated, file, atByte(bytes.size()),
                         concat("the file is ", bytes.size(), " bytes long, but a bench pack header needs ",
                                kBenchPackHeaderSize));
    const auto version = loadAt<std::uint32_t>(bytes, kVersionOffset);
    if (version > kBenchPackVersion)
        return makeError(ErrorCode::NewerVersion, file, atByte(kVersionOffset),
                         concat("bench pack version ", version, " is newer than this build reads (version ",
                                kBenchPackVersion, ")"));
    if (version == 0)
        return makeError(ErrorCode::CorruptAsset, file, atByte(kVersionOffset), "bench pack version 0 does not exist");
    if (const auto flags = loadAt<std::uint32_t>(bytes, kFlagsOffset); flags != 0)
        return makeError(ErrorCode::CorruptAsset, file, atByte(kFlagsOffset), concat("unknown flags ", flags));

    // The payload must be exactly as long as the header says; then its checksum.
    const std::uint64_t payloadSize = loadAt<std::uint64_t>(bytes, kPayloadSizeOffset);
    const std::uint64_t present = bytes.size() - kBenchPackHeaderSize;
    if (payloadSize > present)
        return makeError(ErrorCode::Truncated, file, atByte(bytes.size()),
                         concat("the header announces a payload of ", payloadSize, " bytes, but only ", present,
                                " follow; the file was cut off"));
    if (payloadSize < present)
        return makeError(ErrorCode::CorruptAsset, file, atByte(kBenchPackHeaderSize + payloadSize),
                         concat(present - payloadSize, " unexpected bytes after the payload"));
    const std::uint64_t recorded = loadAt<std::uint64_t>(bytes, kChecksumOffset);
    if (const std::uint64_t actual = contentHash64(bytes.substr(kBenchPackHeaderSize)); actual != recorded)
        return makeError(ErrorCode::ChecksumMismatch, file, atByte(kChecksumOffset),
                         concat("the payload's XXH3 checksum is ", detail::hex16(actual), ", but the header records ",
                                detail::hex16(recorded), "; the file is damaged"));

    // Counts bound what is reserved: each record takes at least a few bytes.
    const std::uint32_t meshCount = loadAt<std::uint32_t>(bytes, kMeshCountOffset);
    const std::uint32_t textureCount = loadAt<std::uint32_t>(bytes, kTextureCountOffset);
    if (meshCount * kMinMeshRecord + textureCount * kMinTextureRecord > payloadSize)
        return makeError(ErrorCode::CorruptAsset, file, atByte(kMeshCountOffset),
                         concat(meshCount, " meshes and ", textureCount, " textures cannot fit a payload of ",
                                payloadSize, " bytes"));

    Cursor in(bytes, kBenchPackHeaderSize, file);
    BenchPack pack;
    const auto hash = in.sized<std::uint32_t>("the project hash");
    if (!hash)
        return std::unexpected(hash.error());
    pack.projectHash = std::string(*hash);
    const std::uint64_t documentAt = in.offset() + 8;
    const auto text = in.sized<std::uint64_t>("the project document");
    if (!text)
        return std::unexpected(text.error());
    if (text->size() > detail::kProjectFileLimit.maxBytes)
        return makeError(ErrorCode::CorruptAsset, file, atByte(documentAt),
                         concat("a project document of ", text->size(), " bytes is over the project file's limit"));
    // Locations inside the document are JSON paths; the name says where it starts.
    const std::string documentName = concat(file, " (project document at byte offset ", documentAt, ")");
    const auto json = detail::parseProjectText(std::string(*text), documentName);
    if (!json)
        return std::unexpected(json.error());
    auto document = detail::projectFromJson(*json, documentName);
    if (!document)
        return std::unexpected(document.error());
    if (document->meshes.size() != meshCount)
        return makeError(ErrorCode::CorruptAsset, file, atByte(kMeshCountOffset),
                         concat("the header counts ", meshCount, " meshes, but the document names ",
                                document->meshes.size()));

    pack.project = std::move(document->project);
    const std::size_t materialCount = pack.project.scene.materials.size();
    if (auto fits = checkMaterialCount(materialCount, file, "materials"); !fits)
        return std::unexpected(fits.error());
    pack.project.scene.meshes.reserve(meshCount);
    for (std::size_t i = 0; i < meshCount; ++i) {
        auto mesh = readMesh(in, document->meshes[i], i, materialCount, file);
        if (!mesh)
            return std::unexpected(mesh.error());
        pack.project.scene.meshes.push_back(std::move(*mesh));
    }
    for (std::size_t i = 0; i < textureCount; ++i) {
        auto texture = readTexture(in, i, file);
        if (!texture)
            return std::unexpected(texture.error());
        if (!pack.textures.emplace(std::move(texture->first), std::move(texture->second)).second)
            return makeError(ErrorCode::CorruptAsset, file, concat("textures[", i, "]"), "a texture key seen twice");
    }
    if (in.left() != 0)
        return makeError(ErrorCode::CorruptAsset, file, atByte(in.offset()),
                         concat(in.left(), " bytes after the last texture"));
    return pack;
}

Expected<void> saveBenchPack(const BenchPack& pack, const std::filesystem::path& file) {
    auto bytes = encodeBenchPack(pack, file.string());
    if (!bytes)
        return std::unexpected(bytes.error());
    return writeFileAtomically(file, *bytes);
}

Expected<BenchPack> loadBenchPack(const std::filesystem::path& file) {
    const auto bytes = readFileBytes(file, {kBenchPackMaxBytes, "bench pack"});
    if (!bytes)
        return std::unexpected(bytes.error());
    return decodeBenchPack(*bytes, file.string());
}

} // namespace lpv::scene
