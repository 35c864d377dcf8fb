#pragma once
// Binary mesh asset (.lpvmesh): header with magic, version, counts and a
// checksum of the payload, then the vertex streams, indices and submeshes.
#include "lpv/scene/Error.h"
#include "lpv/scene/Mesh.h"

#include <string>
#include <string_view>

namespace lpv::scene {

// Version 2 checksums the payload with XXH3-64 (xxHash), which reads memory
// about 10x faster than version 1's byte-wise FNV-1a 64; version 1 assets
// still load.
inline constexpr std::uint32_t kMeshAssetVersion = 2;
// Bytes before the payload: magic, version, flags, four counts, payload size, checksum.
inline constexpr std::size_t kMeshAssetHeaderSize = 48;

std::string encodeMeshAsset(const Mesh& mesh);
// `fileName` is only used in error messages; `materialCount` bounds submesh material indices.
Expected<Mesh> decodeMeshAsset(std::string_view bytes, const std::string& fileName,
                               std::size_t materialCount);

// XXH3-64: the asset checksum (version 2) and the content hash in asset and
// texture file names.
std::uint64_t contentHash64(std::string_view bytes);
// The checksum an asset of `version` records for its payload.
std::uint64_t payloadChecksum(std::uint32_t version, std::string_view payload);
// Version 1's checksum.
std::uint64_t fnv1a64(std::string_view bytes);

// The checks decodeMeshAsset makes, on a mesh in memory: vertex streams empty
// or as long as positions, counts that fit 32 bits, finite floats, whole
// triangles, indices below the vertex count, submeshes inside the index buffer
// with material indices below `materialCount`. saveProject calls it so it
// never writes an asset that loadProject would reject. Error locations start
// with `location` (e.g. "meshes[2]" gives "meshes[2].indices[7]").
Expected<void> validateMesh(const Mesh& mesh, const std::string& fileName, const std::string& location,
                            std::size_t materialCount);

} // namespace lpv::scene
