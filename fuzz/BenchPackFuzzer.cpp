// libFuzzer target fuzz_bench_pack: decodeBenchPack (scene/src/BenchPack.cpp),
// the .lpvpack reader of lpv render / bench and lpv-gl-bench (issue #45).
//
// Each input is decoded twice, as fuzz_mesh_asset does:
//  1. as given, which mostly exercises the header, size and checksum checks;
//  2. with the header's payload size and XXH3 checksum rewritten to match
//     the bytes, so mutations of counts, lengths, the document, the mesh
//     assets inside and the texture records reach the checks behind it.
// A decoded pack must have textures whose pixels match their sizes, and
// survive encode -> decode unchanged.
#include "SceneChecks.h"

#include "lpv/scene/BenchPack.h"
#include "lpv/scene/MeshAsset.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace {

using namespace lpv;

// Header fields (docs/project-format.md): u64 payload size at 32, u64 XXH3 checksum at 40.
constexpr std::size_t kPayloadSizeOffset = 32;
constexpr std::size_t kChecksumOffset = 40;

void decodeAndCheck(std::string_view bytes) {
    const auto pack = scene::decodeBenchPack(bytes, "fuzz.lpvpack");
    if (!pack)
        return;
    for (const auto& [key, image] : pack->textures)
        if (image.pixels.size() != std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels))
            fuzz::invariantBroken("decoded texture " + key + " has pixels that do not match its size");
    const auto encoded = scene::encodeBenchPack(*pack, "re-encoded.lpvpack");
    if (!encoded)
        fuzz::invariantBroken("a decoded pack does not encode: " + encoded.error().describe());
    const auto again = scene::decodeBenchPack(*encoded, "re-encoded.lpvpack");
    if (!again)
        fuzz::invariantBroken("re-encoded pack does not decode: " + again.error().describe());
    if (!(again->project == pack->project) || again->projectHash != pack->projectHash ||
        again->textures.size() != pack->textures.size())
        fuzz::invariantBroken("encode -> decode changed the pack");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view raw(reinterpret_cast<const char*>(data), size);
    decodeAndCheck(raw);
    if (size < scene::kBenchPackHeaderSize)
        return 0;
    std::string fixed(raw);
    const std::uint64_t payloadSize = size - scene::kBenchPackHeaderSize;
    const std::uint64_t checksum = scene::contentHash64(std::string_view(fixed).substr(scene::kBenchPackHeaderSize));
    std::memcpy(fixed.data() + kPayloadSizeOffset, &payloadSize, sizeof payloadSize); // little-endian host
    std::memcpy(fixed.data() + kChecksumOffset, &checksum, sizeof checksum);
    if (fixed != raw)
        decodeAndCheck(fixed);
    return 0;
}
