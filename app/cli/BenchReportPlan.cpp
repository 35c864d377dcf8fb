#include "BenchReportPlan.h"

#include "lpv/bench/ContentHash.h"
#include "lpv/bench/ReferenceFile.h"

#include "lpv/scene/Project.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

namespace lpv::cli::report {

namespace fs = std::filesystem;
using Json = nlohmann::json;

const std::vector<Question>& kQuestions = bench::reportQuestions();

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

std::optional<ScenePlan> planScene(const SceneSpec& spec, const ReportOptions& options) {
    ScenePlan plan;
    plan.spec = &spec;
    plan.dir = options.outDir / spec.name;
    plan.project = projectFileOf(spec, options);
    plan.spp = options.sppFor(spec);
    const auto loaded = scene::loadProject(plan.project);
    if (!loaded) {
        std::cerr << "lpv: " << loaded.error().describe() << "\n";
        return std::nullopt;
    }
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
    for (const Question& q : kQuestions) {
        const std::string& sweep = options.quick ? q.quickSweep : q.sweep;
        if (sweep.empty() || !options.wantsQuestion(q.name))
            continue;
        // Each sweep against its like-for-like reference: the bounces
        // question runs one sweep per value, each against a reference with
        // as many bounces; the sky question one per value, each against a
        // reference that traces sky light exactly when that LPV injects it.
        if (q.name == "bounces") {
            for (const std::string& k : splitValues(sweep))
                plan.sweeps.push_back({q.name, "lpv.bounces=" + k, plan.dir / q.name / k,
                                       referenceIndex(std::atoi(k.c_str()), "")});
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

ReferenceCommand referenceCommandOf(const ScenePlan& plan, const PlannedReference& ref, const fs::path& out,
                                    const ReportOptions& options) {
    ReferenceCommand c;
    c.projectFile = plan.project.string();
    c.output = out.string();
    c.width = options.width;
    c.height = options.height;
    c.spp = std::to_string(plan.spp);
    c.bounces = std::to_string(ref.bounces);
    if (!ref.sky.empty())
        c.sets.push_back("effects.skyInjection=" + ref.sky);
    return c;
}

SweepCommand sweepCommandOf(const ScenePlan& plan, const PlannedSweep& sweep, const ReportOptions& options) {
    SweepCommand c;
    c.projectFile = plan.project.string();
    c.sweeps = {sweep.sweep};
    c.referenceFile = plan.references[sweep.reference].file.string();
    c.outDir = sweep.dir;
    c.width = options.width;
    c.height = options.height;
    c.frames = options.frames;
    c.warmup = options.warmup;
    c.timesFrom = timingFileOf(plan);
    return c;
}

int runEchoed(const ReferenceCommand& c) {
    std::printf("\n$ lpv reference %s -o %s --width %d --height %d --spp %s --bounces %s", c.projectFile.c_str(),
                c.output.c_str(), c.width, c.height, c.spp.value_or("-").c_str(), c.bounces.value_or("-").c_str());
    for (const std::string& set : c.sets)
        std::printf(" --set %s", set.c_str());
    if (!c.shard.whole())
        std::printf(" --shard %s", reference::formatShard(c.shard).c_str());
    std::printf("\n");
    std::fflush(stdout);
    return runReferenceCommand(c);
}

int runEchoed(const SweepCommand& c, std::vector<SweepRun>* runs) {
    std::printf("\n$ lpv bench %s --sweep %s --reference %s --width %d --height %d --frames %d --warmup %d --out %s",
                c.projectFile.c_str(), c.sweeps.front().c_str(), c.referenceFile.value_or("-").c_str(), c.width,
                c.height, c.frames, c.warmup, c.outDir.string().c_str());
    if (c.timesFrom)
        std::printf(" --times-from %s", c.timesFrom->string().c_str());
    if (!c.shard.whole())
        std::printf(" --shard %s", reference::formatShard(c.shard).c_str());
    std::printf("\n");
    std::fflush(stdout);
    return runSweepCommand(c, runs);
}

int call(const char* name, int (*command)(Args), std::vector<std::string> args) {
    std::printf("\n$ lpv %s", name);
    for (const auto& a : args)
        std::printf(" %s", a.c_str());
    std::printf("\n");
    std::fflush(stdout);
    return command(Args(std::move(args)));
}

std::vector<std::string> splitValues(const std::string& sweep) {
    std::vector<std::string> out;
    std::string values = sweep.substr(sweep.find('=') + 1);
    std::stringstream in(values);
    for (std::string v; std::getline(in, v, ',');)
        out.push_back(v);
    return out;
}

bool makeProject(const SceneSpec& spec, const fs::path& scenesDir, const fs::path& project) {
    std::error_code ec;
    fs::remove(project, ec);
    fs::remove_all(fs::path(project).replace_extension(".assets"), ec);
    if (spec.source.empty()) {
        if (call("new", runNew, {project.string(), "--template", "cornell-box"}) != kOk)
            return false;
        // The default project as a user first sees it: lit by its ceiling
        // lamp (an area light), which the LPV injects on auto.
        return true;
    }
    const fs::path source = scenesDir / spec.source;
    if (!fs::exists(source)) {
        std::cerr << "lpv: " << source.string() << ": no such scene file (give --scenes DIR)\n";
        return false;
    }
    return call("import", runImport, {source.string(), "-o", project.string()}) == kOk;
}

bool referenceMatches(const bench::LoadedReference& ref, int width, int height, int bounces, int spp) {
    if (ref.image.width != width || ref.image.height != height || ref.image.samplesPerPixel < spp)
        return false;
    const auto it = ref.attributes.find("lpv:bounces");
    return bounces == 0 || (it != ref.attributes.end() && it->second == std::to_string(bounces));
}

bool referenceMatches(const fs::path& file, int width, int height, int bounces, int spp) {
    if (!fs::exists(file))
        return false;
    const auto ref = bench::readReferenceExr(file);
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

} // namespace lpv::cli::report
