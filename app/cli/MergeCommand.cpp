// `lpv merge OUT.exr SHARD.exr...`: joins the shards of one reference
// (`lpv reference --shard I/N`) into the image one process would have traced,
// bit for bit (reference/Shards.h). Refuses a set that is incomplete, has a
// shard twice, or mixes projects, settings or sizes; writes atomically.
#include "Cli.h"
#include "lpv/bench/ContentHash.h"
#include "lpv/bench/ReferenceFile.h"

#include "lpv/reference/Shards.h"

#include <cstdio>
#include <filesystem>
#include <iostream>

namespace lpv::cli {

void printMergeHelp() {
    std::cout << R"(Usage: lpv merge OUT.exr SHARD.exr... 

Joins the shards of one path-traced reference (`lpv reference ... --shard I/N`,
one per process or cluster task, see docs/cluster.md) into OUT.exr, the image
one process tracing every pixel would have written, bit for bit.

The shards must belong together: same project content (the hash of the
project file), same parameters, camera, size, sample count, bounces and
lights, the same shard count, each index exactly once. Otherwise nothing is
written and the error names the file and the difference, or the missing
shards. OUT.exr is written through a temporary file and renamed, so an
interrupted merge leaves no partial image. Its header sums the shards'
tracing seconds (lpv:seconds) and records lpv:shards.
)";
}

int runMerge(Args args) {
    if (auto e = args.error())
        return usageError(*e, "merge");
    const auto pos = args.positionals();
    if (pos.size() < 2)
        return usageError("expected OUT.exr and at least one shard", "merge");
    const std::filesystem::path output = pos.front();
    if (output.extension() != ".exr")
        return usageError("the merged reference is written as EXR: OUT must end in .exr", "merge");
    std::vector<reference::ShardPiece> pieces;
    for (std::size_t i = 1; i < pos.size(); ++i) {
        std::error_code ec;
        if (std::filesystem::equivalent(output, pos[i], ec))
            return usageError(pos[i] + " is both the output and a shard", "merge");
        auto loaded = bench::readReferenceExr(pos[i]);
        if (!loaded) {
            std::cerr << "lpv: " << loaded.error().describe() << "\n";
            return kFailure;
        }
        pieces.push_back({pos[i], std::move(loaded->image), std::move(loaded->attributes)});
    }
    auto merged = reference::mergeShards(pieces);
    if (!merged) {
        std::cerr << "lpv: " << merged.error().describe() << "\n";
        return kFailure;
    }
    if (auto it = pieces.front().attributes.find("lpv:project"); it != pieces.front().attributes.end())
        merged->attributes["lpv:project"] = it->second;
    if (auto ok = bench::writeReferenceExr(output, merged->image, merged->attributes); !ok) {
        std::cerr << "lpv: " << ok.error().describe() << "\n";
        return kFailure;
    }
    std::printf("merged %zu shards: %dx%d, %d spp, %.2f s of tracing in all\nwrote %s\n", pieces.size(),
                merged->image.width, merged->image.height, merged->image.samplesPerPixel,
                merged->image.seconds, output.string().c_str());
    return kOk;
}

} // namespace lpv::cli
