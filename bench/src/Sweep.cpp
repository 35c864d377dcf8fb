#include "lpv/bench/Sweep.h"

#include "Pixels.h"
#include "SceneRenderer.h"

#include "lpv/importers/SceneTextures.h"
#include "lpv/radiosity/BakedSolution.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GpuMemory.h"
#include "lpv/renderer/SceneAnalysis.h"

#include <memory>

#include <algorithm>

namespace lpv::bench {

namespace {

// One sweep's GL state: the context, the renderer with the scene uploaded (SceneRenderer.h).
using SweepRenderer = SceneRenderer;

// `count` frames of the sweep's view with `parameters`, their GPU times resolved.
scene::Expected<void> renderFrames(SweepRenderer& gl, const SweepSpec& spec, const scene::ParameterSet& parameters,
                                   int count) {
    for (int f = 0; f < count; ++f)
        if (auto ok = gl.renderer.render(spec.project.scene, parameters, spec.camera, spec.width, spec.height); !ok)
            return std::unexpected(ok.error());
    gl.renderer.timer().resolveAll();
    return {};
}

} // namespace

int bouncesOf(const scene::ParameterSet& base, const std::vector<Setting>& combination) {
    scene::ParameterSet p = base;
    for (const auto& [key, value] : combination)
        (void)p.setFromText(key, value, "--sweep");
    return p.getInt("lpv.bounces");
}

std::optional<std::string> checkSweep(const SweepSpec& spec, const std::string& referenceName) {
    SetPlan plan;
    plan.combinations = spec.combinations;
    if (auto error = checkCombinations(plan, spec.project.parameters, "--sweep"))
        return error;
    const std::vector<std::vector<Setting>> all =
        spec.combinations.empty() ? std::vector<std::vector<Setting>>{{}} : spec.combinations;
    for (const auto& c : all)
        if (const int k = bouncesOf(spec.project.parameters, c); k > 1 && k != spec.referenceBounces)
            return "lpv.bounces=" + std::to_string(k) + " is measured against a reference with " +
                   std::to_string(k) + " bounces, and " + referenceName + " has " +
                   (spec.referenceBounces > 0 ? std::to_string(spec.referenceBounces) : "an unrecorded number of") +
                   " (trace one with `lpv reference --bounces " + std::to_string(k) +
                   "`, one reference per lpv.bounces value, as `lpv bench report` does)";
    return std::nullopt;
}

namespace {

std::vector<std::vector<Setting>> combinationsOf(const SweepSpec& spec) {
    return spec.combinations.empty() ? std::vector<std::vector<Setting>>{{}} : spec.combinations;
}

scene::ParameterSet finalParameters(const SweepSpec& spec, const std::vector<Setting>& combination) {
    scene::ParameterSet parameters = spec.project.parameters;
    for (const auto& [key, value] : combination)
        (void)parameters.setFromText(key, value, "--sweep");
    (void)parameters.setFromText("output.view", "final", "sweep");
    return parameters;
}

// The context, the renderer with the scene and its textures, and a baked
// radiosity solution where a combination shows one.
scene::Expected<std::unique_ptr<SweepRenderer>> openSweep(const SweepSpec& spec, const SweepCallbacks& callbacks,
                                                          std::shared_ptr<const radiosity::BakedSolution>& baked) {
    auto opened = openSceneRenderer(spec.project.scene, spec.projectDir, callbacks.warning);
    if (!opened)
        return std::unexpected(opened.error());
    std::unique_ptr<SweepRenderer> gl = std::move(*opened);
    const importers::SceneTextures& textures = gl->textures;
    // Radiosity is a GI method beside the LPV settings (issue #27 item 5):
    // its solution is read once, before any run, and must fit the scene.
    for (const auto& combination : combinationsOf(spec)) {
        if (!renderer::showsBakedRadiosity(finalParameters(spec, combination)) || baked)
            continue;
        auto solution = radiosity::loadBakedSolution(spec.project.scene, textures.images, spec.projectFile);
        if (!solution)
            return std::unexpected(solution.error());
        baked = std::make_shared<const radiosity::BakedSolution>(std::move(*solution));
        gl->renderer.setBakedRadiosity(baked);
    }
    return gl;
}

// Every combination timed in interleaved rounds (Timing.h): each in turn,
// one untimed frame after the switch, then spec.frames timed ones. Its
// figures go into result.runs (which has one run per combination).
scene::Expected<void> timeRounds(SweepRenderer& gl, const SweepSpec& spec, const SweepCallbacks& callbacks,
                                 double unitsBefore, double units, SweepResult& result) {
    const std::vector<std::vector<Setting>> combinations = combinationsOf(spec);
    const int total = int(combinations.size());
    RoundCallbacks rounds;
    rounds.timeOnce = [&](int index) -> scene::Expected<std::vector<renderer::PassTiming>> {
        const scene::ParameterSet parameters = finalParameters(spec, combinations[std::size_t(index)]);
        if (auto ok = renderFrames(gl, spec, parameters, 1); !ok)
            return std::unexpected(ok.error());
        gl.renderer.timer().clearHistory();
        if (auto ok = renderFrames(gl, spec, parameters, spec.frames); !ok)
            return std::unexpected(ok.error());
        return gl.renderer.timer().table();
    };
    rounds.progress = [&](int round, int position, int index) {
        if (!callbacks.progress)
            return true;
        const double done = unitsBefore + double(total) * double(round) + double(position);
        return callbacks.progress({total, total, sweepLabel(combinations[std::size_t(index)]), round,
                                   std::min(done / units, 0.99)});
    };
    auto timing = timeInRounds(total, spec.rounds, rounds);
    if (!timing)
        return std::unexpected(timing.error());
    result.rounds = timing->rounds;
    result.stopReason = timing->stopReason;
    for (int index = 0; index < total; ++index) {
        SweepRun& run = result.runs[std::size_t(index)];
        SettingTiming& t = timing->settings[std::size_t(index)];
        run.passes = std::move(t.passes);
        run.passStats = std::move(t.passStats);
        run.total = t.total;
        run.totalMs = t.total.median;
    }
    return {};
}

} // namespace

scene::Expected<SweepResult> timeSettings(const SweepSpec& spec, const SweepCallbacks& callbacks) {
    std::shared_ptr<const radiosity::BakedSolution> baked;
    auto gl = openSweep(spec, callbacks, baked);
    if (!gl)
        return std::unexpected(gl.error());
    const std::vector<std::vector<Setting>> combinations = combinationsOf(spec);
    SweepResult result;
    result.gl = (*gl)->context.info();
    result.load = describeLoad();
    // Each combination warmed once (shaders compiled, volumes allocated) before the rounds.
    for (const auto& combination : combinations) {
        SweepRun run;
        run.settings = combination;
        if (auto ok = renderFrames(**gl, spec, finalParameters(spec, combination), std::max(spec.warmup, 1)); !ok)
            return std::unexpected(ok.error());
        const renderer::GpuMemory memory = (*gl)->renderer.gpuMemory();
        run.gpuBytes = memory.totalBytes;
        run.lpvBytes = memory.bytesOf("lpv.");
        result.runs.push_back(std::move(run));
    }
    const double units = double(combinations.size()) * double(std::max(1, spec.rounds.minRounds));
    if (auto ok = timeRounds(**gl, spec, callbacks, 0.0, units, result); !ok)
        return std::unexpected(ok.error());
    result.load += " -> " + describeLoad();
    for (const SweepRun& run : result.runs)
        if (callbacks.runDone)
            callbacks.runDone(run);
    return result;
}

scene::Expected<SweepResult> runSweep(const SweepSpec& spec, const reference::ReferenceImage& ref,
                                      const SweepCallbacks& callbacks) {
    if (ref.width != spec.width || ref.height != spec.height)
        return scene::makeError(scene::ErrorCode::InvalidValue, "", "reference",
                                "the reference is " + std::to_string(ref.width) + "x" + std::to_string(ref.height) +
                                    " and the sweep renders " + std::to_string(spec.width) + "x" +
                                    std::to_string(spec.height) + ": give the same size");
    std::shared_ptr<const radiosity::BakedSolution> baked;
    auto opened = openSweep(spec, callbacks, baked);
    if (!opened)
        return std::unexpected(opened.error());
    SweepRenderer& gl = **opened;
    const std::vector<std::vector<Setting>> combinations = combinationsOf(spec);
    SweepResult result;
    result.gl = gl.context.info();
    result.load = describeLoad();
    const int total = int(combinations.size());
    const bool timed = spec.rounds.maxRounds > 0;
    // Accuracy takes one unit per combination, each timing round about as many.
    const double units = double(total) * (1.0 + (timed ? double(std::max(1, spec.rounds.minRounds)) : 0.0));
    for (int index = 0; index < total; ++index) {
        const auto& combination = combinations[std::size_t(index)];
        if (callbacks.progress &&
            !callbacks.progress({index, total, sweepLabel(combination), -1, double(index) / units}))
            return scene::makeError(scene::ErrorCode::Cancelled, "", "",
                                    "stopped after " + std::to_string(index) + " of " + std::to_string(total) +
                                        " settings");
        SweepRun run;
        run.settings = combination;
        scene::ParameterSet parameters = finalParameters(spec, combination);
        // The measured frame must follow a frame of the same settings: the
        // camera's geometry volume reads the previous frame's G-buffer, so
        // the first frame of a combination depends on what ran before it
        // (in a shard, another combination than in one process).
        if (auto ok = renderFrames(gl, spec, parameters, std::max(spec.warmup, 1)); !ok)
            return std::unexpected(ok.error());
        const auto image = rgbOf(gl.renderer.readHdr());
        const renderer::GpuMemory memory = gl.renderer.gpuMemory();
        run.gpuBytes = memory.totalBytes;
        run.lpvBytes = memory.bytesOf("lpv.");
        // The indirect view: the LPV irradiance at the same pixels, no albedo, no tonemap.
        (void)parameters.setFromText("output.view", "indirect", "sweep");
        if (auto ok = renderFrames(gl, spec, parameters, 1); !ok)
            return std::unexpected(ok.error());
        run.indirectPixels = rgbOf(gl.renderer.readHdr());
        auto measure = [&](const std::vector<glm::vec3>& test, const std::vector<glm::vec3>& r,
                           const std::vector<glm::vec3>& var) {
            return reference::compareImages({spec.width, spec.height, &test}, {ref.width, ref.height, &r}, &var,
                                            &ref.coverage);
        };
        run.bounces = parameters.getInt("lpv.bounces");
        const bool radiosity = renderer::showsBakedRadiosity(parameters);
        if (radiosity) {
            // A solution holds every bounce: it is measured against the
            // reference's multi-bounce layer, whatever lpv.bounces says.
            run.bounces = spec.referenceBounces;
            run.solveSeconds = baked->seconds;
            run.solveResidual = baked->residual;
        }
        run.indirect = run.bounces == 1 && !radiosity ? measure(run.indirectPixels, ref.indirectOne, ref.indirectOneVariance)
                                        : measure(run.indirectPixels, ref.indirectMulti, ref.indirectMultiVariance);
        run.indirectOne = measure(run.indirectPixels, ref.indirectOne, ref.indirectOneVariance);
        run.image = measure(image, ref.image, ref.imageVariance);
        run.imagePixels = image;
        if (callbacks.runMeasured)
            callbacks.runMeasured(run);
        result.runs.push_back(std::move(run));
    }
    if (timed)
        if (auto ok = timeRounds(gl, spec, callbacks, double(total), units, result); !ok)
            return std::unexpected(ok.error());
    result.load += " -> " + describeLoad();
    for (const SweepRun& run : result.runs)
        if (callbacks.runDone)
            callbacks.runDone(run);
    if (callbacks.progress)
        (void)callbacks.progress({total, total, "", -1, 1.0});
    return result;
}

} // namespace lpv::bench
