// `lpv bench PROJECT --flicker`: temporal stability of the LPV's indirect
// light (issue #11 item 5, docs/flicker.md). Reads the options and the
// project; bench::runFlicker (bench/FlickerSweep.h) renders and measures.
#include "BenchReport.h"
#include "Cli.h"
#include "lpv/bench/ContentHash.h"
#include "lpv/bench/ReferenceFile.h"
#include "RenderSetup.h"
#include "lpv/bench/Settings.h"

#include "lpv/bench/FlickerSweep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace lpv::cli {

void printBenchFlickerHelp() {
    std::cout << R"(
bench PROJECT --flicker (--path NAME | --sun-rotate DEG) [options]:
temporal stability. Renders --frames frames of the LPV's indirect irradiance
(output.view=indirect) either along the camera path NAME (frames 1/--fps
apart from its start) or from the fixed camera while every directional
light turns DEG degrees about the vertical axis over the run, and measures
flicker: per pair of frames, each pixel is reprojected into the previous
frame and kept when that frame saw the same surface (position within 2% of
the distance to the camera, normal within 18 degrees); flicker is the mean
(and the 95th percentile) of |L1 - L0| / mean(L0, L1) over kept pixels, L the
luminance, averaged over the pairs. A --set with a list of values compares
settings (e.g. --set lpv.cellSnapping=true,false --set rsm.tileSize=64,256).

  --frames N            Frames measured (default 16; N - 1 pairs)
  --fps N               Path sampling rate (default 30)
  --width N --height N  Image size (default 320x180)
  --reference REF.exr   Also report the error (indirect MARE) of the first
                        frame against this reference (same size and camera)
  --camera NAME --set KEY=VALUE[,VALUE...] --csv FILE --markdown FILE
)";
}

int benchFlicker(Args args) {
    RenderRequest request;
    request.cameraName = args.option("--camera");
    const std::vector<std::string> sets = args.options("--set");
    const auto pathName = args.option("--path");
    std::string sunRotateText;
    const auto sunRotate = args.optionalReal("--sun-rotate", {}, &sunRotateText);
    const auto referenceFile = args.option("--reference");
    const auto csv = args.option("--csv");
    const auto md = args.option("--markdown");
    const int width = args.integer("--width", 320, {1});
    const int height = args.integer("--height", 180, {1});
    const int frames = args.integer("--frames", 16, {2});
    const int fps = args.integer("--fps", 30, {1});
    const auto pos = args.expectPositionals(1, "bench --flicker expects exactly one project file");
    if (pos.empty())
        return usageError(*args.error(), "bench");
    if (pathName.has_value() == sunRotate.has_value())
        return usageError("bench --flicker needs either --path NAME or --sun-rotate DEG", "bench");
    const float degrees = float(sunRotate.value_or(0.0));
    std::string planError;
    const SetPlan plan = planSettings(sets, planError);
    if (!planError.empty())
        return usageError(planError, "bench");
    for (const auto& [key, value] : plan.fixed)
        request.sets.push_back(key + "=" + value);
    request.projectFile = pos.front();
    int exitCode = kOk;
    auto project = loadProjectWithSets(request.projectFile, request.sets, "bench", exitCode);
    if (!project)
        return exitCode;
    if (auto error = checkCombinations(plan, project->parameters, "--set"))
        return usageError(*error, "bench");
    const auto camera = pickCamera(project->scene, request.cameraName, request.projectFile);
    if (!camera)
        return kFailure;

    bench::FlickerSpec spec;
    if (pathName) {
        auto it = std::ranges::find(project->scene.cameraPaths, *pathName, &scene::CameraPath::name);
        if (it == project->scene.cameraPaths.end()) {
            std::cerr << "lpv: " << request.projectFile << ": no camera path named '" << *pathName << "'\n";
            return kFailure;
        }
        spec.path = *it;
    } else if (std::ranges::none_of(project->scene.lights, [](const scene::Light& l) {
                   return l.type == scene::LightType::Directional;
               })) {
        std::cerr << "lpv: " << request.projectFile << ": --sun-rotate needs a directional light\n";
        return kFailure;
    }
    std::optional<reference::ReferenceImage> ref;
    if (referenceFile) {
        auto loaded = bench::readReferenceExr(*referenceFile);
        if (!loaded) {
            std::cerr << "lpv: " << loaded.error().describe() << "\n";
            return kFailure;
        }
        if (loaded->image.width != width || loaded->image.height != height) {
            std::cerr << "lpv: " << *referenceFile << " is " << loaded->image.width << "x"
                      << loaded->image.height << "; give the same --width and --height\n";
            return kFailure;
        }
        ref = std::move(loaded->image);
    }
    spec.project = std::move(*project);
    spec.projectDir = std::filesystem::absolute(request.projectFile).parent_path();
    spec.camera = *camera;
    spec.width = width;
    spec.height = height;
    spec.frames = frames;
    spec.fps = fps;
    spec.sunDegrees = degrees;
    spec.fixed = plan.fixed;
    spec.combinations = plan.combinations;
    bench::FlickerCallbacks callbacks;
    callbacks.progress = [](int, int, const std::string& label) {
        std::printf("\n== %s\n", label.c_str());
        return true;
    };
    callbacks.runDone = [](const bench::FlickerRun& run) {
        std::printf("flicker %.3f%% (worst pair %.3f%%, p95 %.3f%%), %.0f%% of the pixels kept, %.3f ms GPU",
                    100.0 * run.meanFlicker, 100.0 * run.worstFlicker, 100.0 * run.p95Flicker,
                    100.0 * run.keptFraction, run.totalMs);
        if (run.mare)
            std::printf(", indirect MARE %.1f%%", 100.0 * *run.mare);
        std::printf("\n");
    };
    callbacks.warning = [](const std::string& w) { std::cerr << "lpv: warning: " << w << "\n"; };
    auto result = bench::runFlicker(spec, ref ? &*ref : nullptr, callbacks);
    if (!result) {
        std::cerr << "lpv: " << result.error().describe() << "\n";
        return kFailure;
    }

    const renderer::GlInfo& gl = result->gl;
    std::string command = "lpv bench " + request.projectFile + " --flicker" +
                          (pathName ? " --path " + *pathName + " --fps " + std::to_string(fps)
                                    : " --sun-rotate " + sunRotateText) +
                          " --frames " + std::to_string(frames) + " --width " + std::to_string(width) +
                          " --height " + std::to_string(height);
    if (request.cameraName)
        command += " --camera " + *request.cameraName;
    for (const std::string& s : sets)
        command += " --set " + s;
    if (referenceFile)
        command += " --reference " + *referenceFile;
    if (!writeReportFiles({{csv, bench::flickerCsv(result->runs)},
                           {md, bench::flickerMarkdown(result->runs, command,
                                                       describeMachine(gl.renderer, gl.version),
                                                       bench::describeMotion(spec))}}))
        return kFailure;
    return kOk;
}

} // namespace lpv::cli
