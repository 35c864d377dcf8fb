#include "lpv/bench/ReportPlan.h"

#include "lpv/bench/SavedSweep.h"
#include "lpv/radiosity/PatchMesh.h"
#include "lpv/scene/Project.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace lpv::bench::report {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

// A value of the bounces question's sweep ("lpv.bounces=1,2,3"): whole
// numbers from the question table (Questions.cpp); 1 should one not be.
int bouncesOf(const std::string& value) {
    int bounces = 1;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), bounces);
    return ec == std::errc() && end == value.data() + value.size() ? bounces : 1;
}

} // namespace

// Reference samples per pixel unless --spp says otherwise: enough that the
// reference's own noise stays well under the errors it measures. At 256
// spp (160x90) Sibenik's one-bounce light, which enters through a few
// windows, had a noise MARE of 41% and pixels the tracer had not reached
// yet read as black, so the LPV's MARE came out 1,927% against it and 282%
// against 4096 spp (noise 19%); Sponza 17% -> 6.5% at 2048, the Cornell
// box 11% -> 2.7% at 4096 (issue #24, docs/lpv.md).
// cornell-obj: McGuire's Cornell box as `lpv import` makes it, beside the
// built-in template (issue #43: measured on scenes as users import them).
const std::vector<SceneSpec> kScenes = {{"cornell-box", "", 4096},
                                        {"cornell-obj", "cornell/CornellBox-Original.obj", 4096},
                                        {"sibenik", "sibenik/sibenik.obj", 4096},
                                        {"sponza", "sponza/sponza.obj", 2048}};

bool ReportOptions::wantsScene(const std::string& name) const {
    return scenes.empty() || std::ranges::find(scenes, name) != scenes.end();
}

bool ReportOptions::wantsQuestion(const std::string& name) const {
    return questions.empty() || std::ranges::find(questions, name) != questions.end();
}

int ReportOptions::sppFor(const SceneSpec& spec) const {
    return spp ? *spp : (quick ? 256 : spec.defaultSpp);
}

fs::path projectFileOf(const SceneSpec& spec, const ReportOptions& options) {
    return options.outDir / spec.name / (spec.name + ".lpvproj");
}

scene::Expected<ScenePlan> planScene(const SceneSpec& spec, const ReportOptions& options) {
    ScenePlan plan;
    plan.spec = &spec;
    plan.dir = options.outDir / spec.name;
    plan.project = projectFileOf(spec, options);
    plan.spp = options.sppFor(spec);
    const auto loaded = scene::loadProject(plan.project);
    if (!loaded)
        return std::unexpected(loaded.error());
    plan.current = loaded->parameters;
    plan.projectBounces = plan.current.getInt("lpv.bounces");
    // One reference per bounce count a sweep needs (like for like), the
    // project's own first. `sky`: the effects.skyInjection the sweep renders
    // with (empty: the project's), so that reference.skyLight=auto follows it.
    auto referenceIndex = [&](int bounces, const std::string& sky) {
        for (std::size_t i = 0; i < plan.references.size(); ++i)
            if (plan.references[i].bounces == bounces && plan.references[i].sky == sky)
                return i;
        plan.references.push_back({plan.dir / ("reference-" + std::to_string(bounces) + "-bounce" +
                                               (sky.empty() ? "" : "-sky-" + sky) + ".exr"),
                                   bounces, sky});
        return plan.references.size() - 1;
    };
    referenceIndex(plan.projectBounces, "");
    for (const Question& q : reportQuestions()) {
        const std::string& sweep = options.quick ? q.quickSweep : q.sweep;
        if (sweep.empty() || !options.wantsQuestion(q.name))
            continue;
        // Each sweep against its like-for-like reference: the bounces
        // question runs one sweep per value, each against a reference with
        // as many bounces; the sky question one per value, each against a
        // reference that traces sky light exactly when that LPV injects it.
        if (q.name == "bounces") {
            for (const std::string& k : splitValues(sweep))
                plan.sweeps.push_back(
                    {q.name, "lpv.bounces=" + k, plan.dir / q.name / k, referenceIndex(bouncesOf(k), "")});
        } else if (q.name == "sky") {
            for (const std::string& v : splitValues(sweep))
                plan.sweeps.push_back({q.name, "effects.skyInjection=" + v, plan.dir / q.name / v,
                                       referenceIndex(plan.projectBounces, v)});
        } else {
            plan.sweeps.push_back({q.name, sweep, plan.dir / q.name, 0});
        }
    }
    return plan;
}

std::string reportCommand(const ReportOptions& o) {
    std::string command =
        "lpv bench report --out " + o.outDir.string() + " --scenes " + o.scenesDir.string() + " --width " +
        std::to_string(o.width) + " --height " + std::to_string(o.height) + " --frames " +
        std::to_string(o.frames) + " --warmup " + std::to_string(o.warmup) +
        (o.spp ? " --spp " + std::to_string(*o.spp) : std::string()) + " --radiosity-seconds " +
        std::to_string(o.radiosityCount) + roundOptionsText(o.rounds);
    for (const std::string& s : o.scenes)
        command += " --scene " + s;
    for (const std::string& q : o.questions)
        command += " --question " + q;
    if (o.resume)
        command += " --resume";
    if (o.quick)
        command += " --quick";
    return command;
}

fs::path timingFileOf(const ScenePlan& plan) {
    return plan.dir / "timing.json";
}

std::vector<std::string> splitValues(const std::string& sweep) {
    std::vector<std::string> out;
    std::string values = sweep.substr(sweep.find('=') + 1);
    std::stringstream in(values);
    for (std::string v; std::getline(in, v, ',');)
        out.push_back(v);
    return out;
}

bool referenceMatches(const LoadedReference& ref, int width, int height, int bounces, int spp) {
    if (ref.image.width != width || ref.image.height != height || ref.image.samplesPerPixel < spp)
        return false;
    const auto it = ref.attributes.find("lpv:bounces");
    return bounces == 0 || (it != ref.attributes.end() && it->second == std::to_string(bounces));
}

bool referenceMatches(const fs::path& file, int width, int height, int bounces, int spp) {
    if (!fs::exists(file))
        return false;
    const auto ref = readReferenceExr(file);
    return ref && referenceMatches(*ref, width, height, bounces, spp);
}

bool sweepDoneAlready(const fs::path& file, const ScenePlan& plan, const PlannedSweep& sweep,
                      const ReportOptions& options) {
    const fs::path& reference = plan.references[sweep.reference].file;
    const fs::path timing = timingFileOf(plan);
    std::error_code ec;
    if (!fs::exists(file, ec) || fs::last_write_time(file, ec) < fs::last_write_time(reference, ec) || ec ||
        !fs::exists(timing, ec) || fs::last_write_time(file, ec) < fs::last_write_time(timing, ec) || ec)
        return false;
    std::ifstream in(file);
    const Json j = Json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.contains("runs") || j["runs"].empty())
        return false;
    const std::string command = j.value("command", "") + " ";
    for (const std::string& part :
         {"lpv bench " + plan.project.string() + " ", "--sweep " + sweep.sweep + " ",
          "--reference " + reference.string() + " ", "--width " + std::to_string(options.width) + " ",
          "--height " + std::to_string(options.height) + " ",
          "--frames " + std::to_string(options.frames) + " ",
          "--warmup " + std::to_string(options.warmup) + " ", "--times-from " + timing.string() + " "})
        if (command.find(part) == std::string::npos)
            return false;
    return true;
}

std::vector<std::pair<std::vector<Setting>, scene::ParameterSet>> distinctSettings(const ScenePlan& plan,
                                                                                const scene::ParameterSet& base) {
    std::vector<std::pair<std::vector<Setting>, scene::ParameterSet>> out;
    for (const PlannedSweep& sweep : plan.sweeps) {
        const std::string key = sweep.sweep.substr(0, sweep.sweep.find('='));
        for (const std::string& value : splitValues(sweep.sweep)) {
            scene::ParameterSet p = base;
            (void)p.setFromText(key, value, "report");
            const bool seen = std::ranges::any_of(out, [&](const auto& s) { return sameValues(s.second, p); });
            if (!seen)
                out.emplace_back(std::vector<Setting>{{key, value}}, p);
        }
    }
    return out;
}

// The default 0.05 m^2 makes a million of Sibenik's (radiosity.maxPatches), and
// coarse patches darken it (4 m^2: 0.58x the reference's light at residual
// 0.1%, 1 m^2: 1.06x), so the finest size within the bound (0.8 m^2 on
// Sibenik and Sponza).
float reportPatchArea(const scene::Project& p) {
    float area = p.parameters.getFloat("radiosity.maxPatchArea");
    while (radiosity::countPatches(p.scene, {area}) > 150000 && area < 100.0f)
        area *= 4.0f;
    return area;
}

} // namespace lpv::bench::report
