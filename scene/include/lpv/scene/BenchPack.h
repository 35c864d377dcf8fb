#pragma once
// Bench pack (.lpvpack, issue #45): one file with what a frame needs, so the
// GPU bench (lpv-gl-bench) runs where no image or scene library is
// installed. It holds the project document (materials, lights, cameras,
// camera paths, parameters, presets, the project's name), every mesh as a
// mesh asset (MeshAsset.h, each with its own checksum), the textures
// decoded as the renderer gets them (RGBA8 at the size the texture budget
// chose, derived images under their own keys) and the content hash of the
// project file it was made from. Layout in docs/project-format.md.
//
// Like the mesh assets it is versioned and checksummed (XXH3-64 of the
// payload), and reading trusts nothing: every count and length is checked
// against the bytes that are there before anything is allocated, so a
// damaged or hostile pack yields an Error, never a crash.
#include "lpv/scene/Error.h"
#include "lpv/scene/Image.h"
#include "lpv/scene/Project.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace lpv::scene {

inline constexpr std::uint32_t kBenchPackVersion = 1;
// Bytes before the payload: magic, version, flags, mesh and texture counts, two reserved words, payload size, checksum.
inline constexpr std::size_t kBenchPackHeaderSize = 48;
// Packs larger than this are refused before reading (Sponza's is about 30 MiB).
inline constexpr std::uint64_t kBenchPackMaxBytes = std::uint64_t{4} << 30;
// A texture side longer than this is refused (the renderer's own limit is lower).
inline constexpr std::uint32_t kBenchPackMaxTextureSide = 32768;

struct BenchPack {
    // The project as loaded: its scene (meshes included), parameters, presets
    // and editor view. Texture paths stay as the project names them; they are
    // the keys of `textures`. loadWarnings are not stored.
    Project project;
    TextureImages textures;
    // 16 hex digits of XXH3 of the project file's bytes (bench::fileContentHash):
    // which project, saved when, the pack was made from.
    std::string projectHash;
};

// The pack's bytes. Refuses (InvalidValue / OutOfRange) what a read would
// refuse: a mesh that fails validateMesh, a texture whose pixels do not
// match its size, counts over 32 bits. `fileName` names the pack in errors.
Expected<std::string> encodeBenchPack(const BenchPack& pack, const std::string& fileName);

// `fileName` is only used in error messages. Errors: UnknownFormat (not a
// pack), NewerVersion, Truncated, ChecksumMismatch, CorruptAsset (a count or
// length that does not fit the bytes there, bytes left over), and whatever
// the project document and mesh assets inside give.
Expected<BenchPack> decodeBenchPack(std::string_view bytes, const std::string& fileName);

// encodeBenchPack, then an atomic write (writeFileAtomically).
Expected<void> saveBenchPack(const BenchPack& pack, const std::filesystem::path& file);
// readFileBytes (at most kBenchPackMaxBytes), then decodeBenchPack.
Expected<BenchPack> loadBenchPack(const std::filesystem::path& file);

// Whether `file` names a bench pack by its extension (".lpvpack"), for the
// programs that take either a project or a pack.
bool isBenchPackFile(const std::filesystem::path& file);

} // namespace lpv::scene
