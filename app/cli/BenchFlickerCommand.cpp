// `lpv bench PROJECT --flicker`: temporal stability of the LPV's indirect
// light (issue #11 item 5, docs/flicker.md). Renders N frames along a camera
// path or while the sun turns, and per setting reports the frame-to-frame
// change of indirect irradiance on pixels whose surface stayed the same
// (reference::measureFlicker), beside the GPU time and, with --reference, the
// error of the first frame.
#include "BenchReport.h"
#include "Cli.h"
#include "ReferenceFile.h"
#include "RenderSetup.h"
#include "lpv/bench/Settings.h"

#include "lpv/reference/Flicker.h"
#include "lpv/reference/Metrics.h"
#include "lpv/scene/CameraSpline.h"

#include <glm/gtc/matrix_transform.hpp>

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

namespace {

struct FlickerRun {
    std::vector<Setting> settings;
    double meanFlicker = 0.0;  // mean over pairs of the mean relative change
    double worstFlicker = 0.0; // largest per-pair mean
    double p95Flicker = 0.0;   // mean over pairs of the 95th percentile
    double keptFraction = 0.0; // kept pixels / pixels with geometry, mean over pairs
    double totalMs = 0.0;      // sum of the pass medians
    std::optional<double> mare;
};

std::string label(const std::vector<Setting>& settings) {
    std::string s;
    for (const auto& [key, value] : settings)
        s += (s.empty() ? "" : " ") + key + "=" + value;
    return s.empty() ? "defaults" : s;
}

std::vector<glm::vec3> rgb(const std::vector<float>& rgba) {
    std::vector<glm::vec3> out(rgba.size() / 4);
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = {rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]};
    return out;
}

// Directional lights turned by `degrees` about +y, from their directions in `lights`.
std::vector<scene::Light> turnedSun(const std::vector<scene::Light>& lights, float degrees) {
    std::vector<scene::Light> out = lights;
    const glm::mat4 r = glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0, 1, 0));
    for (scene::Light& l : out)
        if (l.type == scene::LightType::Directional)
            l.direction = glm::vec3(r * glm::vec4(l.direction, 0.0f));
    return out;
}

std::string flickerMarkdown(const std::vector<FlickerRun>& runs, const std::string& command,
                            const std::string& machine, const std::string& motion) {
    std::ostringstream out;
    char buf[512];
    out << "# Flicker of the indirect light\n\n`" << command << "`\n\nMachine: " << machine
        << "\n\nMotion: " << motion
        << "\n\n| settings | flicker mean | worst pair | p95 | pixels kept | total GPU ms | indirect "
        << "MARE |\n|---|---:|---:|---:|---:|---:|---:|\n";
    for (const FlickerRun& r : runs) {
        std::snprintf(buf, sizeof buf, "| %s | %.2f%% | %.2f%% | %.2f%% | %.0f%% | %.3f | %s |\n",
                      label(r.settings).c_str(), 100.0 * r.meanFlicker, 100.0 * r.worstFlicker,
                      100.0 * r.p95Flicker, 100.0 * r.keptFraction, r.totalMs,
                      r.mare ? (std::to_string(100.0 * *r.mare).substr(0, 5) + "%").c_str() : "-");
        out << buf;
    }
    return out.str();
}

std::string flickerCsv(const std::vector<FlickerRun>& runs) {
    std::ostringstream out;
    out << "settings,flicker_mean,flicker_worst_pair,flicker_p95,kept_fraction,total_ms,indirect_mare\n";
    for (const FlickerRun& r : runs)
        out << '"' << label(r.settings) << "\"," << r.meanFlicker << "," << r.worstFlicker << ","
            << r.p95Flicker << "," << r.keptFraction << "," << r.totalMs << ","
            << (r.mare ? std::to_string(*r.mare) : "") << "\n";
    return out.str();
}

} // namespace

int benchFlicker(Args args) {
    RenderRequest request;
    request.cameraName = args.option("--camera");
    const std::vector<std::string> sets = args.options("--set");
    const auto pathName = args.option("--path");
    const auto sunRotate = args.option("--sun-rotate");
    const auto referenceFile = args.option("--reference");
    const auto csv = args.option("--csv");
    const auto md = args.option("--markdown");
    const auto width = parseCount(args.option("--width").value_or("320"), 1);
    const auto height = parseCount(args.option("--height").value_or("180"), 1);
    const auto frames = parseCount(args.option("--frames").value_or("16"), 2);
    const auto fps = parseCount(args.option("--fps").value_or("30"), 1);
    if (!args.missingValue().empty())
        return usageError(args.missingValue() + " needs a value", "bench");
    if (auto unknown = args.unknownOption())
        return usageError("unknown option '" + *unknown + "'", "bench");
    const auto pos = args.positionals();
    if (pos.size() != 1)
        return usageError("bench --flicker expects exactly one project file", "bench");
    if (!width || !height || !frames || !fps)
        return usageError("--width, --height and --fps must be positive integers, --frames at least 2",
                          "bench");
    if (pathName.has_value() == sunRotate.has_value())
        return usageError("bench --flicker needs either --path NAME or --sun-rotate DEG", "bench");
    float degrees = 0.0f;
    if (sunRotate) {
        char* end = nullptr;
        degrees = std::strtof(sunRotate->c_str(), &end);
        if (end == sunRotate->c_str() || *end != '\0' || !std::isfinite(degrees))
            return usageError("--sun-rotate needs a number of degrees, got '" + *sunRotate + "'", "bench");
    }
    std::string planError;
    const SetPlan plan = planSettings(sets, planError);
    if (!planError.empty())
        return usageError(planError, "bench");
    for (const auto& [key, value] : plan.fixed)
        request.sets.push_back(key + "=" + value);
    request.projectFile = pos.front();
    int exitCode = kOk;
    auto setup = prepareRender(request, "bench", exitCode);
    if (!setup)
        return exitCode;
    if (auto error = checkCombinations(plan, setup->project.parameters, "--set"))
        return usageError(*error, "bench");

    std::optional<scene::CameraSpline> spline;
    std::string motion;
    if (pathName) {
        auto it = std::ranges::find(setup->project.scene.cameraPaths, *pathName, &scene::CameraPath::name);
        if (it == setup->project.scene.cameraPaths.end()) {
            std::cerr << "lpv: " << request.projectFile << ": no camera path named '" << *pathName << "'\n";
            return kFailure;
        }
        spline.emplace(*it);
        motion = "camera path '" + *pathName + "', " + std::to_string(*frames) + " frames at " +
                 std::to_string(*fps) + " fps from its start";
    } else {
        if (std::ranges::none_of(setup->project.scene.lights, [](const scene::Light& l) {
                return l.type == scene::LightType::Directional;
            })) {
            std::cerr << "lpv: " << request.projectFile << ": --sun-rotate needs a directional light\n";
            return kFailure;
        }
        char buf[160];
        std::snprintf(buf, sizeof buf,
                      "fixed camera, sun turning %g degrees about the vertical in %d frames (%.3g "
                      "per frame)",
                      double(degrees), *frames, double(degrees) / double(*frames - 1));
        motion = buf;
    }
    std::optional<reference::ReferenceImage> ref;
    if (referenceFile) {
        auto loaded = readReferenceExr(*referenceFile);
        if (!loaded) {
            std::cerr << "lpv: " << loaded.error().describe() << "\n";
            return kFailure;
        }
        if (loaded->image.width != *width || loaded->image.height != *height) {
            std::cerr << "lpv: " << *referenceFile << " is " << loaded->image.width << "x"
                      << loaded->image.height << "; give the same --width and --height\n";
            return kFailure;
        }
        ref = std::move(loaded->image);
    }

    const std::vector<std::vector<Setting>> combinations =
        plan.combinations.empty() ? std::vector<std::vector<Setting>>{{}} : plan.combinations;
    const scene::ParameterSet base = setup->project.parameters;
    const std::vector<scene::Light> lights = setup->project.scene.lights;
    const scene::Camera baseCamera = setup->camera;
    const float aspect = float(*width) / float(*height);
    std::vector<FlickerRun> runs;
    for (const auto& combination : combinations) {
        FlickerRun run;
        // Single values given with --set are part of every row's label too.
        run.settings = plan.fixed;
        run.settings.insert(run.settings.end(), combination.begin(), combination.end());
        setup->project.parameters = base;
        for (const auto& [key, value] : combination)
            (void)setup->project.parameters.setFromText(key, value, "--set");
        (void)setup->project.parameters.setFromText("output.view", "indirect", "bench");
        std::printf("\n== %s\n", label(run.settings).c_str());
        auto placeFrame = [&](int i) {
            if (spline)
                setup->camera = spline->cameraAt(spline->startTime() + float(i) / float(*fps), baseCamera);
            else
                setup->project.scene.lights = turnedSun(lights, degrees * float(i) / float(*frames - 1));
        };
        // Warm-up at the first frame: the geometry volume also reads the previous frame's G-buffer.
        placeFrame(0);
        if (!renderFrames(*setup, *width, *height, 2))
            return kFailure;
        setup->renderer->timer().clearHistory();
        std::vector<glm::vec3> indirect[2], position[2], normal[2];
        reference::FlickerFrame frame[2];
        int pairs = 0;
        for (int i = 0; i < *frames; ++i) {
            placeFrame(i);
            if (!renderFrames(*setup, *width, *height, 1))
                return kFailure;
            const int k = i % 2;
            indirect[k] = rgb(setup->renderer->readHdr());
            normal[k] = rgb(setup->renderer->readGBufferNormal());
            const glm::mat4 viewProjection = setup->camera.projection(aspect) * setup->camera.view();
            position[k] = reference::positionsFromDepth(setup->renderer->readDepth(), *width, *height,
                                                        glm::inverse(viewProjection));
            frame[k] = {*width,     *height,        &indirect[k],          &position[k],
                        &normal[k], viewProjection, setup->camera.position};
            if (i == 0 && ref)
                run.mare = reference::compareImages({*width, *height, &indirect[0]},
                                                    {ref->width, ref->height, &ref->indirectMulti},
                                                    &ref->indirectMultiVariance, &ref->coverage)
                               .mare;
            if (i == 0)
                continue;
            const reference::FlickerResult f = reference::measureFlicker(frame[1 - k], frame[k]);
            run.meanFlicker += f.meanRelativeChange;
            run.worstFlicker = std::max(run.worstFlicker, f.meanRelativeChange);
            run.p95Flicker += f.p95RelativeChange;
            run.keptFraction += f.candidates ? double(f.pixels) / double(f.candidates) : 0.0;
            ++pairs;
        }
        run.meanFlicker /= pairs;
        run.p95Flicker /= pairs;
        run.keptFraction /= pairs;
        auto passes = setup->renderer->timer().table();
        for (const auto& p : passes)
            if (p.samples > 0)
                run.totalMs += p.medianMs;
        std::printf("flicker %.3f%% (worst pair %.3f%%, p95 %.3f%%), %.0f%% of the pixels kept, %.3f ms GPU",
                    100.0 * run.meanFlicker, 100.0 * run.worstFlicker, 100.0 * run.p95Flicker,
                    100.0 * run.keptFraction, run.totalMs);
        if (run.mare)
            std::printf(", indirect MARE %.1f%%", 100.0 * *run.mare);
        std::printf("\n");
        runs.push_back(std::move(run));
    }
    setup->project.scene.lights = lights;

    const renderer::GlInfo& gl = setup->context->info();
    std::string command = "lpv bench " + request.projectFile + " --flicker" +
                          (pathName ? " --path " + *pathName + " --fps " + std::to_string(*fps)
                                    : " --sun-rotate " + *sunRotate) +
                          " --frames " + std::to_string(*frames) + " --width " + std::to_string(*width) +
                          " --height " + std::to_string(*height);
    if (request.cameraName)
        command += " --camera " + *request.cameraName;
    for (const std::string& s : sets)
        command += " --set " + s;
    if (referenceFile)
        command += " --reference " + *referenceFile;
    if (!writeReportFiles(
            {{csv, flickerCsv(runs)},
             {md, flickerMarkdown(runs, command, describeMachine(gl.renderer, gl.version), motion)}}))
        return kFailure;
    return kOk;
}

} // namespace lpv::cli
