#include "lpv/bench/MeasuredSweep.h"

#include "lpv/bench/Reference.h"
#include "lpv/renderer/ReferenceLights.h"
#include "lpv/renderer/SceneAnalysis.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <tuple>

namespace lpv::bench {

namespace {

using Clock = std::chrono::steady_clock;

std::string timeLeft(double seconds) {
    char buf[64];
    if (seconds < 60.0)
        std::snprintf(buf, sizeof buf, "about %d s left", int(seconds + 0.5));
    else
        std::snprintf(buf, sizeof buf, "about %d min left", int(seconds / 60.0 + 0.5));
    return buf;
}

scene::ParameterSet parametersOf(const MeasuredSweepSpec& spec, int index) {
    scene::ParameterSet p = spec.project.parameters;
    for (const auto& [key, value] : spec.combinations[std::size_t(index)])
        (void)p.setFromText(key, value, "sweep");
    return p;
}

// A radiosity solution holds every bounce and no sky light: its reference
// traces 8 bounces without the sky (as `lpv bench report` measures it).
constexpr int kRadiosityReferenceBounces = 8;

int referenceBouncesOf(const scene::ParameterSet& p) {
    return renderer::showsBakedRadiosity(p) ? kRadiosityReferenceBounces : p.getInt("lpv.bounces");
}

} // namespace

std::vector<std::vector<int>> groupByReference(const MeasuredSweepSpec& spec) {
    const renderer::SceneTraits traits = renderer::analyseSceneTraits(spec.project.scene);
    std::map<std::tuple<int, bool, bool>, std::size_t> index;
    std::vector<std::vector<int>> groups;
    for (int i = 0; i < int(spec.combinations.size()); ++i) {
        const scene::ParameterSet p = parametersOf(spec, i);
        const renderer::ReferenceLights lights = renderer::decideReferenceLights(spec.project.scene, traits, p);
        const bool sky = lights.sky && !renderer::showsBakedRadiosity(p);
        auto [it, added] = index.emplace(std::make_tuple(referenceBouncesOf(p), sky, lights.emissive),
                                         groups.size());
        if (added)
            groups.emplace_back();
        groups[it->second].push_back(i);
    }
    return groups;
}

scene::Expected<MeasuredSweep> measureSweep(const MeasuredSweepSpec& spec, const MeasuredSweepCallbacks& callbacks) {
    const std::vector<std::vector<int>> groups = groupByReference(spec);
    const int runCount = int(spec.combinations.size());
    // The bar gives each reference the weight of one setting: neither cost is known beforehand.
    const double units = double(groups.size() + spec.combinations.size());
    double unitsDone = 0.0;
    auto report = [&](double fraction, const std::string& text) {
        return !callbacks.progress || callbacks.progress(std::clamp(fraction, 0.0, 1.0), text);
    };
    MeasuredSweep result;
    result.runs.resize(std::size_t(runCount));
    int runsDone = 0;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        const std::vector<int>& group = groups[g];
        const scene::ParameterSet groupParameters = parametersOf(spec, group.front());
        const int bounces = referenceBouncesOf(groupParameters);
        scene::Project traced = spec.project;
        traced.parameters = groupParameters;
        (void)traced.parameters.setFromText("reference.samplesPerPixel", std::to_string(spec.referenceSpp), "sweep");
        (void)traced.parameters.setFromText("reference.bounces", std::to_string(bounces), "sweep");
        (void)traced.parameters.setFromText("reference.maxSeconds", "0", "sweep");
        if (renderer::showsBakedRadiosity(groupParameters))
            (void)traced.parameters.setFromText("reference.skyLight", "off", "sweep");
        bool stopped = false;
        ReferenceCallbacks referenceCallbacks;
        referenceCallbacks.warning = callbacks.warning;
        referenceCallbacks.progress = [&](const reference::TraceProgress& p) {
            char text[160];
            std::snprintf(text, sizeof text, "Reference %zu of %zu: %d/%d spp, %.1f s", g + 1, groups.size(),
                          p.samplesDone, p.samplesTarget, p.seconds);
            stopped = !report((unitsDone + double(p.samplesDone) / std::max(p.samplesTarget, 1)) / units, text);
            return !stopped;
        };
        auto reference = traceReference(traced, spec.projectDir, spec.camera, {spec.width, spec.height, 0, {}},
                                        referenceCallbacks);
        if (!reference)
            return std::unexpected(reference.error());
        if (stopped)
            return scene::makeError(scene::ErrorCode::Cancelled, "", "", "stopped while tracing the reference");
        ++result.references;
        unitsDone += 1.0;
        const reference::ReferenceImage& ref = reference->image;
        const std::vector<glm::vec3>& layer = bounces == 1 ? ref.indirectOne : ref.indirectMulti;

        SweepSpec sweep;
        sweep.project = spec.project;
        sweep.projectDir = spec.projectDir;
        sweep.projectFile = spec.projectFile;
        sweep.camera = spec.camera;
        sweep.width = spec.width;
        sweep.height = spec.height;
        sweep.frames = spec.frames;
        sweep.warmup = spec.warmup;
        sweep.rounds = spec.rounds;
        sweep.referenceBounces = bounces;
        for (int i : group)
            sweep.combinations.push_back(spec.combinations[std::size_t(i)]);
        if (auto problem = checkSweep(sweep, "the reference"))
            return scene::makeError(scene::ErrorCode::InvalidValue, "", "sweep", *problem);
        SweepCallbacks sweepCallbacks;
        sweepCallbacks.warning = callbacks.warning;
        const double groupStart = unitsDone;
        const Clock::time_point groupClock = Clock::now();
        sweepCallbacks.progress = [&](const SweepProgress& p) {
            if (p.fraction >= 1.0)
                return true;
            const double done = groupStart + p.fraction * double(group.size());
            std::string text = p.round < 0 ? "Setting " + std::to_string(runsDone + p.done + 1) + " of " +
                                                 std::to_string(runCount) + ": "
                                           : "Timing round " + std::to_string(p.round + 1) + ": ";
            text += p.label == "defaults" ? std::string("current settings") : p.label;
            // Time left in this group's sweep, from its own pace so far.
            const double elapsed = std::chrono::duration<double>(Clock::now() - groupClock).count();
            if (p.fraction > 0.05)
                text += " (" + timeLeft(elapsed / p.fraction * (1.0 - p.fraction)) + ")";
            return report(done / units, text);
        };
        std::size_t inGroup = 0;
        sweepCallbacks.runDone = [&](const SweepRun& run) {
            const int index = group[inGroup++];
            if (callbacks.runDone)
                callbacks.runDone(index, run, layer, ref.coverage);
            result.runs[std::size_t(index)] = run;
        };
        auto swept = runSweep(sweep, ref, sweepCallbacks);
        if (!swept)
            return std::unexpected(swept.error());
        unitsDone += double(group.size());
        runsDone += int(group.size());
        result.rounds = std::max(result.rounds, swept->rounds);
        result.stopReason = swept->stopReason;
        result.load = swept->load;
        if (g == 0) {
            result.gl = swept->gl;
            result.referenceBounces = bounces;
            result.reference = std::move(reference->image);
        }
    }
    report(1.0, "Done: " + std::to_string(runCount) + " settings");
    return result;
}

} // namespace lpv::bench
