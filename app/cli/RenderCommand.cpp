#include "Cli.h"

#include "lpv/importers/ImageIO.h"
#include "DebugDump.h"
#include "RenderSetup.h"
#include "lpv/bench/Settings.h"

#include <filesystem>

#include "lpv/renderer/SceneAnalysis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

namespace lpv::cli {

using bench::Setting;

void printRenderHelp() {
    std::cout << R"(Usage: lpv render PROJECT.lpvproj -o OUT.png [options]

Renders the project headless (EGL: the GPU where present, Mesa llvmpipe
otherwise), writes the image and prints per-pass GPU times (timer queries):
one row per frame, then median/min/max over the frames rendered.

  -o, --output FILE     Image to write (.png, .jpg, .exr, ...), required; .png
                        and .jpg are exposed (output.exposureMode: auto
                        meters each frame's lit pixels) and tonemapped; .exr
                        holds the linear HDR image before exposure and
                        tonemapping (with --set output.view=indirect: the LPV's
                        indirect irradiance, for `lpv compare`)
  --width N             Image width in pixels (default 1280)
  --height N            Image height in pixels (default 720)
  --camera NAME         Named camera of the project (default: the first)
  --set KEY=VALUE       Override a registry parameter for this run; repeatable
                        (see `lpv params` for keys, types and ranges).
                        KEY=V1,V2,... renders one image per value, named
                        OUT-KEY-V.png, and compares their GPU times; several
                        such keys render every combination.
                        gi.method=radiosity shows the project's radiosity
                        solution (lpv radiosity) as the indirect light; it
                        fails when none matches the scene
  --frames N            Frames to render for the timing table (default 5)
  --explain             Before rendering, print the scene analysis: for each
                        effect whether its passes run and why, e.g. that sky
                        light injection is skipped in a closed scene, from
                        the scene and the --set values
  --dump LIST           Also write the frame's internal images beside OUT,
                        comma-separated frame-graph names (--graph lists
                        them): an output such as rsm.flux, camera.depth,
                        lpv.accumulator (per cascade the accumulated light,
                        DC per colour channel, z slices side by side),
                        lpv.geometry, shadowMaps, skyHeight; or a pass such
                        as rsm or localRsm (everything it wrote). Each as
                        OUT-<name>.exr (exact) and .png (scaled)
  --graph               After the frames, print the last frame's graph: its
                        passes in order, what each read and wrote, and
                        whether it ran, was reused (and why) or was culled
  --markdown            With --graph: print it as the Markdown table of
                        docs/renderer.md (pass, reads, writes) instead
)";
}

namespace {

std::vector<std::string> splitCommas(const std::string& s) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start <= s.size()) {
        const std::size_t comma = std::min(s.find(',', start), s.size());
        if (comma > start)
            out.push_back(s.substr(start, comma - start));
        start = comma + 1;
    }
    return out;
}

scene::Expected<void> writeHdrExr(const std::filesystem::path& out, RenderSetup& setup, int width, int height) {
    const std::vector<float> rgba = setup.renderer->readHdr();
    importers::FloatChannels image{width, height, {"R", "G", "B"}, {}, {}};
    image.pixels.reserve(std::size_t(width) * std::size_t(height) * 3);
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4)
        image.pixels.insert(image.pixels.end(), {rgba[i], rgba[i + 1], rgba[i + 2]});
    return importers::writeImageChannels(out, image,
                                         {{"lpv:outputView", setup.project.parameters.getEnum("output.view")}});
}

} // namespace

int runRender(Args args) {
    const auto output = args.option("--output", "-o");
    const int width = args.integer("--width", 1280, {1});
    const int height = args.integer("--height", 720, {1});
    const int frames = args.integer("--frames", 5, {1});
    const auto dumpText = args.option("--dump");
    const bool explain = args.flag("--explain");
    const bool printGraph = args.flag("--graph");
    const bool graphAsMarkdown = args.flag("--markdown");
    args.require(!graphAsMarkdown || printGraph, "--markdown goes with --graph");
    RenderRequest request = renderRequestOptions(args);
    args.require(output.has_value(), "missing -o OUT.png");
    const auto pos = args.expectPositionals(1, "expected exactly one project file");
    if (pos.empty())
        return usageError(*args.error(), "render");
    const std::vector<std::string> dumps = dumpText ? splitCommas(*dumpText) : std::vector<std::string>{};
    const std::vector<std::string>& known = renderer::frameGraphNames();
    for (const std::string& d : dumps)
        if (std::find(known.begin(), known.end(), d) == known.end()) {
            std::string list;
            for (const std::string& k : known)
                list += (list.empty() ? "" : ", ") + k;
            return usageError("--dump: '" + d + "' is no pass or output of the frame graph (" + list + ")", "render");
        }
    if (dumpText && dumps.empty())
        return usageError("--dump needs a list such as rsm,shadowMaps", "render");

    std::string planError;
    const bench::SetPlan plan = bench::planSettings(request.sets, planError);
    if (!planError.empty())
        return usageError(planError, "render");
    request.sets.clear();
    for (const auto& [key, value] : plan.fixed)
        request.sets.push_back(key + "=" + value);
    request.projectFile = pos.front();
    request.bakedRadiosity = sweepShowsBakedRadiosity(plan.combinations);
    int exitCode = kOk;
    auto setup = prepareRender(request, "render", exitCode);
    if (!setup)
        return exitCode;
    // Every swept value is checked against the registry before anything renders.
    if (auto error = bench::checkCombinations(plan, setup->project.parameters, "--set"))
        return usageError(*error, "render");

    const std::vector<std::vector<Setting>> runs =
        plan.combinations.empty() ? std::vector<std::vector<Setting>>{{}} : plan.combinations;
    const scene::ParameterSet base = setup->project.parameters;
    std::vector<std::pair<std::string, double>> totals;
    const renderer::SceneTraits traits =
        explain ? renderer::analyseSceneTraits(setup->project.scene) : renderer::SceneTraits{};
    for (const auto& combination : runs) {
        setup->project.parameters = base;
        for (const auto& [key, value] : combination)
            (void)setup->project.parameters.setFromText(key, value, "--set");
        std::filesystem::path out = *output;
        if (!combination.empty()) {
            out.replace_filename(out.stem().string() + bench::combinationSuffix(combination) + out.extension().string());
            std::printf("\n== %s\n", bench::combinationSuffix(combination).substr(1).c_str());
        }
        if (explain) {
            std::printf("scene analysis (%d%% of %d sky probes open):\n",
                        int(std::lround(100.0f * traits.openSkyFraction)), traits.skyProbes);
            for (const renderer::EffectDecision& e :
                 renderer::decideEffects(setup->project.scene, traits, setup->project.parameters, &setup->camera,
                                         float(width) / float(height)))
                std::printf("  %-26s %-4s %s = %s: %s\n", e.effect.c_str(), e.runs() ? "run" : "skip",
                            e.parameter.c_str(), e.setting.c_str(), e.reason.c_str());
        }
        setup->renderer->timer().clearHistory();
        if (!renderFrames(*setup, width, height, frames))
            return kFailure;
        // EXR keeps the linear HDR radiance (or the view output.view picks), before exposure and tonemapping,
        // so `lpv compare` can measure it against the path-traced reference.
        const bool hdr = out.extension() == ".exr";
        const auto written = hdr ? writeHdrExr(out, *setup, width, height)
                                 : importers::writeImage(out, {width, height, 4, setup->renderer->readDisplay()});
        if (!written) {
            std::cerr << "lpv: " << written.error().describe() << "\n";
            return kFailure;
        }
        const renderer::DrawListStats draws = setup->renderer->cameraDrawStats();
        std::printf("%s: %zu triangles, %zu draw items (%zu culled), %dx%d, %d frames\n", pos.front().c_str(),
                    setup->project.scene.triangleCount(), draws.total, draws.culled, width, height, frames);
        std::printf("%s\n", setup->renderer->lpvNote().c_str());
        if (setup->project.parameters.getEnum("gi.method") == "reference")
            std::printf("note: gi.method = reference is the editor's live path-traced view; this image has direct "
                        "light only. The path-traced image of a view: lpv reference PROJECT -o REF.exr --preview\n");
        {
            const auto& p = setup->project.parameters;
            const double scale = setup->renderer->displayExposure(p);
            std::printf("exposure: %s, x%.4g (%+.2f EV)%s\n", p.getEnum("output.exposureMode").c_str(), scale,
                        std::log2(scale), p.getEnum("output.exposureMode") == "auto" ? ", metered on the last frame" : "");
        }
        for (const renderer::EffectDecision& e : setup->renderer->frameEffects())
            std::printf("%s: %s (%s)\n", e.effect.c_str(), e.runs() ? "on" : "off", e.reason.c_str());
        std::printf("%s", formatPerFrameTimes(setup->renderer->timer()).c_str());
        const auto table = setup->renderer->timer().table();
        std::printf("%s", renderer::formatTimingTable(table).c_str());
        {
            // Memory beside time (issue #43): what the last frame's resources hold.
            const renderer::GpuMemory memory = setup->renderer->gpuMemory();
            const std::uint64_t lpv = memory.bytesOf("lpv.");
            std::printf("GPU memory: %s (LPV %s, rest of the frame graph %s)\n",
                        renderer::formatBytes(memory.totalBytes).c_str(), renderer::formatBytes(lpv).c_str(),
                        renderer::formatBytes(memory.totalBytes - lpv).c_str());
        }
        double total = 0.0;
        for (const auto& row : table)
            total += row.medianMs;
        totals.emplace_back(out.filename().string(), total);
        std::printf("wrote %s\n", out.string().c_str());
        const renderer::FrameGraphReport& graph = setup->renderer->graphReport();
        if (printGraph && graphAsMarkdown)
            std::printf("%s", renderer::formatGraphMarkdown(graph).c_str());
        else if (printGraph)
            std::printf("frame graph of the last frame:\n%s", renderer::formatGraph(graph).c_str());
        for (const std::string& what : dumps) {
            const auto images = setup->renderer->debugImages(what);
            if (images.empty()) {
                std::string why = "the scene has no light this pass renders for";
                for (const auto& pass : graph.passes) {
                    const bool wrote = std::any_of(pass.writes.begin(), pass.writes.end(), [&](const auto& w) {
                        return w.name.substr(0, w.name.find(' ')) == what;
                    });
                    if ((pass.name == what || wrote) && pass.status == renderer::PassStatus::Culled)
                        why = pass.name + " did not run: " + pass.reason;
                }
                std::printf("--dump %s: nothing to write (%s)\n", what.c_str(), why.c_str());
            }
            bool ok = true;
            for (const auto& file : writeDebugImages(images, out, ok))
                std::printf("wrote %s\n", file.string().c_str());
            if (!ok)
                return kFailure;
        }
    }
    if (runs.size() > 1) {
        std::printf("\nimage                                                   total GPU ms (sum of pass medians)\n");
        for (const auto& [name, total] : totals)
            std::printf("%-56s %10.3f\n", name.c_str(), total);
    }
    return kOk;
}

} // namespace lpv::cli
