#pragma once
// Binary mesh asset (.lpvmesh): header with magic, version, counts and a
// checksum of the payload, then the vertex streams, indices and submeshes.
#include "lpv/scene/Error.h"
#include "lpv/scene/Mesh.h"

#include <string>
#include <string_view>

namespace lpv::scene {

inline constexpr std::uint32_t kMeshAssetVersion = 1;
// Bytes before the payload: magic, version, flags, four counts, payload size, checksum.
inline constexpr std::size_t kMeshAssetHeaderSize = 48;

std::string encodeMeshAsset(const Mesh& mesh);
// `fileName` is only used in error messages; `materialCount` bounds submesh material indices.
Expected<Mesh> decodeMeshAsset(std::string_view bytes, const std::string& fileName,
                               std::size_t materialCount);

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
