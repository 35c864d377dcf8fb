// `lpv bench render`: per-pass GPU time of a project's frames at a chosen
// size, after warm-up frames that are not counted. Figures are printed,
// never asserted.
#include "Cli.h"
#include "RenderSetup.h"

#include <charconv>
#include <cstdio>

namespace lpv::cli {

namespace {

std::optional<int> parseCount(const std::string& s, int minimum) {
    int v = 0;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size() || v < minimum)
        return std::nullopt;
    return v;
}

} // namespace

int benchRender(Args args) {
    RenderRequest request;
    request.cameraName = args.option("--camera");
    request.sets = args.options("--set");
    const auto width = parseCount(args.option("--width").value_or("1280"), 1);
    const auto height = parseCount(args.option("--height").value_or("720"), 1);
    const auto frames = parseCount(args.option("--frames").value_or("60"), 1);
    const auto warmup = parseCount(args.option("--warmup").value_or("5"), 0);
    const bool perFrame = args.flag("--per-frame");
    if (!args.missingValue().empty())
        return usageError(args.missingValue() + " needs a value", "bench");
    if (auto unknown = args.unknownOption())
        return usageError("unknown option '" + *unknown + "'", "bench");
    auto pos = args.positionals();
    pos.erase(pos.begin()); // "render"
    if (pos.size() != 1)
        return usageError("bench render expects exactly one project file", "bench");
    if (!width || !height || !frames || !warmup)
        return usageError("--width, --height and --frames must be positive integers, --warmup zero or more", "bench");

    request.projectFile = pos.front();
    int exitCode = kOk;
    auto setup = prepareRender(request, "bench", exitCode);
    if (!setup)
        return exitCode;
    if (*warmup > 0 && !renderFrames(*setup, *width, *height, *warmup))
        return kFailure;
    setup->renderer->timer().clearHistory();
    if (!renderFrames(*setup, *width, *height, *frames))
        return kFailure;

    const renderer::DrawListStats draws = setup->renderer->cameraDrawStats();
    std::printf("%s: %zu triangles, %zu draw items (%zu culled in the camera pass), %dx%d, %d frames after %d warm-up\n",
                request.projectFile.c_str(), setup->project.scene.triangleCount(), draws.total, draws.culled, *width,
                *height, *frames, *warmup);
    if (perFrame)
        std::printf("%s", formatPerFrameTimes(setup->renderer->timer()).c_str());
    const auto table = setup->renderer->timer().table();
    std::printf("%s", renderer::formatTimingTable(table).c_str());
    double total = 0.0;
    for (const auto& row : table)
        total += row.medianMs;
    std::printf("GPU frame rate from the total: %.1f frames/s\n", total > 0 ? 1000.0 / total : 0.0);
    return kOk;
}

} // namespace lpv::cli
