// `lpv reference PROJECT -o ref.exr`: the path-traced reference of a camera
// view (reference/PathTracer.h) written as a multi-layer EXR.
#include "BenchReport.h"
#include "Cli.h"
#include "lpv/bench/ContentHash.h"
#include "lpv/bench/ReferenceFile.h"
#include "ReferenceTrace.h"
#include "RenderSetup.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/reference/PathTracer.h"
#include "lpv/reference/Preview.h"

#include <cstdio>
#include <iostream>

namespace lpv::cli {

void printReferenceHelp() {
    std::cout << R"(Usage: lpv reference PROJECT.lpvproj -o REF.exr [options]

Path-traces (CPU, Embree, every core) the camera's view through the same
pixel centres the renderer's G-buffer has, progressively, one sample per
pixel per pass, until the sample count or the time budget is reached, and
writes a multi-layer EXR:
  R,G,B                     full image (linear radiance, no exposure or tonemap)
  indirect1.R,G,B           indirect diffuse irradiance at the primary hit, one bounce (W/m^2)
  indirect.R,G,B            the same with up to --bounces bounces
  variance.*, indirect1.variance.*, indirect.variance.*
                            variance of each per-pixel mean (the reference's own noise)
  coverage.Y                1 where the pixel sees geometry, 0 background
The header records the settings (lpv:spp, lpv:seconds, lpv:bounces, ...).
Compare a renderer image with it using `lpv compare`.

  -o, --output FILE     EXR to write, required
  --width N, --height N Image size (default 320x180; use the same for `lpv render`)
  --camera NAME         Named camera of the project (default: the first)
  --spp N               Samples per pixel (reference.samplesPerPixel, default 64)
  --max-seconds S       Stop after the pass that reaches S seconds (reference.maxSeconds)
  --bounces N           Diffuse bounces in the multi-bounce layer (reference.bounces, default 4);
                        compare an LPV with lpv.bounces = k against a reference with --bounces k
                        (or its indirect1 layer for k = 1)
  --threads N           Worker threads (default: every hardware thread)
  --set KEY=VALUE       Any other registry parameter, e.g. reference.skyLight=on
  --shard I/N           Trace only shard I of N (0-based): the 16x16-pixel tiles
                        on every N-th diagonal; the other pixels stay 0. Merge the N
                        files with `lpv merge`: the result is bit-identical to one
                        process tracing all (each pixel's samples depend only on the
                        pixel and the sample index). Needs a sample count, not
                        --max-seconds (shards would stop at different counts).
  --preview             Also write REF-image.png and REF-indirect.png to look at
                        (x / (x + mean), gamma 2.2)

Which lights it traces: every light of the project; the sky and emissive
surfaces as reference.skyLight and reference.emissiveLight say, whose `auto`
(the default) follows what the LPV injects, so the two compare like for like.
Both choices and their reasons are printed.
)";
}

std::optional<TracedReference> traceReference(const scene::Project& project, const std::filesystem::path& projectFile,
                                              const scene::Camera& camera, const ReferenceRequest& request) {
    bench::ReferenceCallbacks callbacks;
    callbacks.warning = [](const std::string& w) { std::cerr << "lpv: warning: " << w << "\n"; };
    double lastPrinted = -1.0;
    if (request.printProgress) {
        callbacks.started = [](const bench::ReferencePlan& plan) {
            const reference::PathTracerSettings& s = plan.settings;
            std::printf("reference: %zu triangles, %dx%d%s, up to %d spp, %d bounces%s\n", plan.triangles, s.width,
                        s.height, s.shard.whole() ? "" : (", shard " + reference::formatShard(s.shard)).c_str(),
                        s.samplesPerPixel, s.bounces,
                        s.maxSeconds > 0.0 ? (", at most " + std::to_string(s.maxSeconds) + " s").c_str() : "");
            std::printf("reference: sky light %s (%s)\nreference: emissive surfaces %s (%s)\n",
                        plan.lights.sky ? "on" : "off", plan.lights.skyReason.c_str(),
                        plan.lights.emissive ? "on" : "off", plan.lights.emissiveReason.c_str());
        };
        callbacks.progress = [&lastPrinted](const reference::TraceProgress& p) {
            // About once a second, and the last pass: enough to see it move, not a flood in a log.
            if (p.seconds - lastPrinted >= 1.0 || p.samplesDone == p.samplesTarget) {
                lastPrinted = p.seconds;
                std::printf("reference: %d/%d spp, %.1f s\n", p.samplesDone, p.samplesTarget, p.seconds);
                std::fflush(stdout);
            }
            return true;
        };
    }
    auto traced = bench::traceReference(project, std::filesystem::absolute(projectFile).parent_path(), camera,
                                        {request.width, request.height, request.threads, request.shard}, callbacks);
    if (!traced) {
        std::cerr << "lpv: " << traced.error().describe() << "\n";
        return std::nullopt;
    }
    return std::move(*traced);
}

int runReference(Args args) {
    ReferenceCommand c;
    const auto output = args.option("--output", "-o");
    c.width = args.integer("--width", c.width, {1});
    c.height = args.integer("--height", c.height, {1});
    c.threads = args.integer("--threads", c.threads, {0});
    c.spp = args.option("--spp");
    c.seconds = args.option("--max-seconds");
    c.bounces = args.option("--bounces");
    c.cameraName = args.option("--camera");
    c.shard = args.shard("--shard").value_or(reference::ShardSpec{});
    c.preview = args.flag("--preview");
    c.sets = args.options("--set");
    args.require(output.has_value(), "missing -o REF.exr");
    const auto pos = args.expectPositionals(1, "expected exactly one project file");
    if (pos.empty())
        return usageError(*args.error(), "reference");
    if (std::filesystem::path(*output).extension() != ".exr")
        return usageError("the reference is written as EXR: -o must end in .exr", "reference");
    c.projectFile = pos.front();
    c.output = *output;
    return runReferenceCommand(c);
}

int runReferenceCommand(const ReferenceCommand& c) {
    std::vector<std::string> sets = c.sets;
    const auto& spp = c.spp;
    const auto& seconds = c.seconds;
    const auto& bounces = c.bounces;
    const auto& shard = c.shard;
    const std::vector<std::string> pos{c.projectFile};
    const std::optional<std::string> output = c.output;
    const std::optional<int> width = c.width, height = c.height, threads = c.threads;
    const bool preview = c.preview;
    const auto& cameraName = c.cameraName;
    // The flags are shorthands for registry parameters: one place checks their ranges.
    if (spp)
        sets.push_back("reference.samplesPerPixel=" + *spp);
    if (seconds)
        sets.push_back("reference.maxSeconds=" + *seconds);
    if (bounces)
        sets.push_back("reference.bounces=" + *bounces);

    int exitCode = kFailure;
    auto project = loadProjectWithSets(pos.front(), sets, "reference", exitCode);
    if (!project)
        return exitCode;
    if (!shard.whole() && project->parameters.getFloat("reference.maxSeconds") > 0.0f)
        return usageError("--shard needs a sample count, not a time budget: shards stopped by "
                          "reference.maxSeconds would reach different sample counts and could not be merged",
                          "reference");
    const auto camera = pickCamera(project->scene, cameraName, pos.front());
    if (!camera)
        return kFailure;
    const auto projectHash = bench::fileContentHash(pos.front());
    if (!projectHash) {
        std::cerr << "lpv: " << projectHash.error().describe() << "\n";
        return kFailure;
    }
    const auto traced =
        traceReference(*project, pos.front(), *camera, {*width, *height, *threads, true, shard});
    if (!traced)
        return kFailure;
    const reference::ReferenceImage* image = &traced->image;
    std::map<std::string, std::string> attributes{
        {"lpv:project", pos.front()},
        {"lpv:projectHash", *projectHash},
        {"lpv:parametersHash", bench::parametersHash(project->parameters)},
        {"lpv:camera", camera->name},
        {"lpv:spp", std::to_string(image->samplesPerPixel)},
        {"lpv:seconds", std::to_string(image->seconds)},
        {"lpv:bounces", std::to_string(project->parameters.getInt("reference.bounces"))},
        {"lpv:skyLight", traced->lights.sky ? "true" : "false"},
        {"lpv:emissiveLight", traced->lights.emissive ? "true" : "false"},
    };
    if (!shard.whole()) {
        attributes["lpv:shard"] = reference::formatShard(shard);
        attributes["lpv:shardTile"] = std::to_string(reference::kShardTileSize);
    }
    if (auto ok = bench::writeReferenceExr(*output, *image, attributes); !ok) {
        std::cerr << "lpv: " << ok.error().describe() << "\n";
        return kFailure;
    }
    std::size_t tracedPixels = 0; // of this shard (all of them unsharded)
    for (int y = 0; y < image->height; ++y)
        for (int x = 0; x < image->width; ++x)
            tracedPixels += reference::shardOfPixel(x, y, shard.count) == shard.index;
    std::printf("reference: %d spp in %.2f s (%.0f samples/s)\n", image->samplesPerPixel, image->seconds,
                double(image->samplesPerPixel) * double(tracedPixels) / std::max(image->seconds, 1e-9));
    std::printf("wrote %s\n", output->c_str());
    if (preview) {
        const std::filesystem::path out(*output);
        for (const auto& [suffix, pixels] :
             {std::pair{"-image.png", &image->image}, std::pair{"-indirect.png", &image->indirectMulti}}) {
            std::filesystem::path png = out;
            png.replace_filename(out.stem().string() + suffix);
            const float key = reference::meanLuminance(*pixels, image->coverage);
            if (auto ok = importers::writeImage(
                    png, reference::previewImage(*pixels, image->width, 0, 0, image->width, image->height, key));
                !ok) {
                std::cerr << "lpv: " << ok.error().describe() << "\n";
                return kFailure;
            }
            std::printf("wrote %s\n", png.string().c_str());
        }
    }
    return kOk;
}

} // namespace lpv::cli
