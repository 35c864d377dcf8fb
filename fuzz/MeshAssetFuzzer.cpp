// libFuzzer target fuzz_mesh_asset: decodeMeshAsset (scene/src/MeshAsset.cpp),
// the binary .lpvmesh reader behind loadProject.
//
// Each input is decoded twice:
//  1. as given, which mostly exercises the header, size and checksum checks
//     (a random mutation nearly always breaks the FNV-1a checksum);
//  2. with the header's payload size and checksum (FNV-1a for version 1,
//     XXH3 otherwise: payloadChecksum) rewritten to match the bytes, so
//     mutations of counts, flags, streams, indices, submeshes and the name
//     reach the payload checks behind the checksum.
// A decoded mesh must pass validateMesh and survive encode -> decode unchanged.
#include "SceneChecks.h"

#include "lpv/scene/MeshAsset.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace {

using namespace lpv;

// The Cornell box seeds use materials 0..3.
constexpr std::size_t kMaterialCount = 4;
// Header fields (docs/project-format.md): u32 version at 8, u64 payload size at 32, u64 checksum at 40.
constexpr std::size_t kVersionOffset = 8;
constexpr std::size_t kPayloadSizeOffset = 32;
constexpr std::size_t kChecksumOffset = 40;

void decodeAndCheck(std::string_view bytes) {
    const auto mesh = scene::decodeMeshAsset(bytes, "fuzz.lpvmesh", kMaterialCount);
    if (!mesh)
        return;
    if (auto valid = scene::validateMesh(*mesh, "fuzz.lpvmesh", "mesh", kMaterialCount); !valid)
        fuzz::invariantBroken("decoded mesh fails validateMesh: " + valid.error().describe());
    const std::string encoded = scene::encodeMeshAsset(*mesh);
    const auto again = scene::decodeMeshAsset(encoded, "re-encoded.lpvmesh", kMaterialCount);
    if (!again)
        fuzz::invariantBroken("re-encoded mesh does not decode: " + again.error().describe());
    if (!(*again == *mesh))
        fuzz::invariantBroken("encode -> decode changed the mesh");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view raw(reinterpret_cast<const char*>(data), size);
    decodeAndCheck(raw);
    if (size < scene::kMeshAssetHeaderSize)
        return 0;
    std::string fixed(raw);
    const std::uint64_t payloadSize = size - scene::kMeshAssetHeaderSize;
    std::uint32_t version = 0;
    std::memcpy(&version, fixed.data() + kVersionOffset, sizeof version); // little-endian host
    const std::uint64_t checksum =
        scene::payloadChecksum(version, std::string_view(fixed).substr(scene::kMeshAssetHeaderSize));
    std::memcpy(fixed.data() + kPayloadSizeOffset, &payloadSize, sizeof payloadSize);
    std::memcpy(fixed.data() + kChecksumOffset, &checksum, sizeof checksum);
    if (fixed != raw)
        decodeAndCheck(fixed);
    return 0;
}
