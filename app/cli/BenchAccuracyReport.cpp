// `lpv bench report`: the accuracy-against-time report from one command.
// For each scene (the built-in Cornell box, Sibenik and Sponza from
// ../shared/scenes) it makes a project, traces the path-traced reference
// once, runs one `lpv bench --sweep` per question (propagation steps, grid,
// cascades, RSM tile, variant, each extension off/on), each varied alone
// around the project's settings (the full cartesian product would be
// thousands of renders), and, where the scene has emissive surfaces, measures
// radiosity against the same reference as it converges. The summary
// (report.md, report.json) names per scene the cheapest settings that reach
// 10% and 5% indirect error; each sweep keeps its own CSV, JSON and plots.
#include "BenchReport.h"
#include "Cli.h"
#include "ReferenceFile.h"

#include "lpv/reference/Metrics.h"
#include "lpv/scene/Project.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

namespace lpv::cli {

namespace fs = std::filesystem;
using Json = nlohmann::json;

void printBenchAccuracyReportHelp() {
    std::cout << R"(
bench report [--out DIR] [--scenes DIR] [--scene NAME ...] [--quick] [options]:
the README's accuracy-against-time report from one command. For each scene
(cornell-box: the built-in template as `lpv new` makes it, lit by its
ceiling lamp, an area light; sibenik and sponza: imported from --scenes,
default ../shared/scenes, with the sun `lpv import` adds) it creates the
project in DIR/NAME/, traces the reference once (DIR/NAME/reference.exr,
with as many bounces as the project's lpv.bounces, kept for later runs of
the same size), then runs `lpv bench --sweep` once per question, each key
varied alone around the project's settings:
  steps      lpv.propagationSteps=0,1,2,4,8,16,32,64
  grid       lpv.gridSize=16,32,64
  cascades   lpv.cascades=1,2,3,4
  rsm        rsm.tileSize=64,128,256,512,1024
  variant    lpv.variant=computeGather,computeScatter,rasterGather,rasterScatter
  occlusion  lpv.occlusion=false,true
  directed   lpv.directedPropagation=off,on
  sky        effects.skyInjection=off,on (one sweep and one reference per value)
  subsurface effects.subsurface=off,on
  glossy     effects.glossyReflections=off,on
  bounces    lpv.bounces=1,2,3 (one sweep and one reference per value)
  viewShift  lpv.viewShift=0,0.5,0.75,1
  damping    lpv.bleedingDamping=0,1,2,4
  offset     lpv.injectionOffset=0,0.5,1,2
  firstStep  lpv.occlusionFirstStep=true,false
  strength   lpv.occlusionStrength=0.5,1,1.333,2
  lookupOffset lpv.lookupOffset=0,0.5,1
  visibility lpv.visibilityLookup=false,true
Like for like: each LPV is measured against the reference's light reflected
as many times as its lpv.bounces, and the reference traces the sky and
emissive surfaces where the LPV injects them (reference.skyLight and
reference.emissiveLight on auto). The tables give the indirect MARE and the
ratio of the LPV's mean indirect irradiance to the reference's.
Scenes with emissive surfaces (the Cornell box's ceiling light) also get a
radiosity solve measured against a reference of the emissive light alone
(the project's lights removed), at doubling solve times. Writes DIR/report.md
(headline table: the project's settings, and the cheapest settings reaching
10% and 5% indirect MARE per scene) and DIR/report.json; each sweep's CSV,
JSON, Markdown and plots stay in DIR/NAME/QUESTION/.

  --out DIR             Output folder (default bench-report)
  --scenes DIR          Folder with sibenik/sibenik.obj and sponza/sponza.obj
                        (default ../shared/scenes)
  --scene NAME          Only this scene (cornell-box, sibenik, sponza); repeatable
  --question NAME       Only this question (steps, grid, ...); repeatable
  --resume              Reuse each sweep whose sweep.json in DIR was made by
                        the same sweep command after its reference (after an
                        interruption; not after changing the program)
  --quick               Three questions with fewer values, 5 s of radiosity:
                        a smoke run (minutes instead of most of an hour)
  --width N --height N  Image size (default 320x180)
  --frames N --warmup N Timed frames per setting (default 10) after warm-up (default 2)
  --spp N               Reference samples per pixel (default per scene, so that
                        the reference's own noise stays low: Cornell box 4096,
                        Sibenik 4096, Sponza 2048; --quick: 256)
  --radiosity-seconds S Longest radiosity solve (default 160; solve times
                        double from 5 s up to it)
)";
}

namespace {

struct Question {
    std::string name;
    std::string sweep;      // full report
    std::string quickSweep; // --quick; empty = left out
};

const std::vector<Question> kQuestions = {
    {"steps", "lpv.propagationSteps=0,1,2,4,8,16,32,64", "lpv.propagationSteps=0,4,16"},
    {"grid", "lpv.gridSize=16,32,64", "lpv.gridSize=16,32"},
    {"cascades", "lpv.cascades=1,2,3,4", ""},
    {"rsm", "rsm.tileSize=64,128,256,512,1024", ""},
    {"variant", "lpv.variant=computeGather,computeScatter,rasterGather,rasterScatter", ""},
    {"occlusion", "lpv.occlusion=false,true", "lpv.occlusion=false,true"},
    {"directed", "lpv.directedPropagation=off,on", ""},
    {"sky", "effects.skyInjection=off,on", ""},
    {"subsurface", "effects.subsurface=off,on", ""},
    {"glossy", "effects.glossyReflections=off,on", ""},
    {"bounces", "lpv.bounces=1,2,3", ""},
    {"viewShift", "lpv.viewShift=0,0.5,0.75,1", ""},
    {"damping", "lpv.bleedingDamping=0,1,2,4", ""},
    {"offset", "lpv.injectionOffset=0,0.5,1,2", ""},
    {"firstStep", "lpv.occlusionFirstStep=true,false", ""},
    {"strength", "lpv.occlusionStrength=0.5,1,1.333,2", ""},
    {"lookupOffset", "lpv.lookupOffset=0,0.5,1", ""},
    {"visibility", "lpv.visibilityLookup=false,true", ""},
};

struct SceneSpec {
    std::string name;
    std::string source; // relative to --scenes; empty = the built-in template
    // Reference samples per pixel unless --spp says otherwise: enough that the
    // reference's own noise stays well under the errors it measures. At 256
    // spp (160x90) Sibenik's one-bounce light, which enters through a few
    // windows, had a noise MARE of 41% and pixels the tracer had not reached
    // yet read as black, so the LPV's MARE came out 1,927% against it and 282%
    // against 4096 spp (noise 19%); Sponza 17% -> 6.5% at 2048, the Cornell
    // box 11% -> 2.7% at 4096 (issue #24, docs/lpv.md).
    int defaultSpp;
};

const std::vector<SceneSpec> kScenes = {{"cornell-box", "", 4096},
                                        {"sibenik", "sibenik/sibenik.obj", 4096},
                                        {"sponza", "sponza/sponza.obj", 2048}};

// One render of a sweep, as its sweep.json gives it.
struct ReportRun {
    std::string question;
    std::string setting; // "key=value"
    bool projectSettings = false;
    double totalMs = 0.0;
    double indirectMare = 0.0;
    double indirectMeanRatio = 0.0; // the LPV's mean indirect irradiance over the reference's
    double noiseMare = 0.0;
    double imageMare = 0.0;
};

struct RadiosityPoint {
    double seconds = 0.0; // cumulative wall time of the solve runs
    reference::ErrorMetrics image;
};

struct SceneReport {
    std::string name;
    std::string projectFile;
    std::string referenceNote;
    std::vector<ReportRun> runs;
    std::vector<std::string> failures;
    std::vector<RadiosityPoint> radiosity;
    std::string radiosityNote;
};

// Runs one `lpv` command in this process, echoing it as a user would type it.
int call(const char* name, int (*command)(Args), std::vector<std::string> args) {
    std::printf("\n$ lpv %s", name);
    for (const auto& a : args)
        std::printf(" %s", a.c_str());
    std::printf("\n");
    std::fflush(stdout);
    return command(Args(std::move(args)));
}

std::string percent(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.1f%%", 100.0 * v);
    return buf;
}

std::string fixed(double v, int digits) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.*f", digits, v);
    return buf;
}

// "lpv.bounces=1,2,3" -> {"1", "2", "3"}.
std::vector<std::string> splitValues(const std::string& sweep) {
    std::vector<std::string> out;
    std::string values = sweep.substr(sweep.find('=') + 1);
    std::stringstream in(values);
    for (std::string v; std::getline(in, v, ',');)
        out.push_back(v);
    return out;
}

// A fresh project for the scene; false (and a message) when it cannot be made.
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

// A reference traced earlier with the same size and bounce count is reused.
bool referenceMatches(const fs::path& file, int width, int height, int bounces = 0, int spp = 0) {
    if (!fs::exists(file))
        return false;
    auto ref = readReferenceExr(file);
    if (!ref || ref->image.width != width || ref->image.height != height || ref->image.samplesPerPixel < spp)
        return false;
    const auto it = ref->attributes.find("lpv:bounces");
    return bounces == 0 || (it != ref->attributes.end() && it->second == std::to_string(bounces));
}

std::string describeReference(const fs::path& file) {
    auto ref = readReferenceExr(file);
    if (!ref)
        return "unreadable";
    auto attr = [&](const char* k) {
        auto it = ref->attributes.find(k);
        return it == ref->attributes.end() ? std::string("?") : it->second;
    };
    return std::to_string(ref->image.width) + "x" + std::to_string(ref->image.height) + ", " +
           std::to_string(ref->image.samplesPerPixel) + " spp in " +
           fixed(std::atof(attr("lpv:seconds").c_str()), 1) + " s";
}

// The runs of one sweep.json; `current` holds the project's own parameters to
// recognise the run that changes nothing.
std::vector<ReportRun> readSweep(const fs::path& file, const std::string& question,
                                 const scene::ParameterSet& current) {
    std::vector<ReportRun> out;
    std::ifstream in(file);
    const Json j = Json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.contains("runs"))
        return out;
    for (const Json& r : j["runs"]) {
        ReportRun run;
        run.question = question;
        run.projectSettings = true;
        for (const auto& [key, value] : r["settings"].items()) {
            run.setting += (run.setting.empty() ? "" : " ") + key + "=" + value.get<std::string>();
            scene::ParameterSet changed = current;
            if (!changed.setFromText(key, value.get<std::string>()) ||
                !(changed.get(key) == current.get(key)))
                run.projectSettings = false;
        }
        run.totalMs = r.value("totalMs", 0.0);
        run.indirectMare = r["indirect"].value("mare", 0.0);
        const double meanReference = r["indirect"].value("meanReference", 0.0);
        run.indirectMeanRatio = meanReference > 0.0 ? r["indirect"].value("meanTest", 0.0) / meanReference : 0.0;
        run.noiseMare = r["indirect"].value("noiseMare", 0.0);
        run.imageMare = r["image"].value("mare", 0.0);
        out.push_back(run);
    }
    return out;
}

bool hasEmissiveMaterial(const scene::Project& p) {
    return std::ranges::any_of(p.scene.materials, [](const scene::Material& m) {
        return m.emissive != glm::vec3(0.0f) || !m.emissiveTexture.empty();
    });
}

// Radiosity against the reference of the emissive light alone, at doubling solve times.
void measureRadiosity(SceneReport& report, const fs::path& sceneDir, int width, int height, int spp,
                      double maxSeconds) {
    auto project = scene::loadProject(report.projectFile);
    if (!project) {
        report.radiosityNote = project.error().describe();
        return;
    }
    if (!hasEmissiveMaterial(*project)) {
        report.radiosityNote =
            "not measured: no emissive material (radiosity shoots from emissive surfaces only)";
        return;
    }
    const fs::path dir = sceneDir / "radiosity";
    fs::create_directories(dir);
    const fs::path emissiveProject = dir / (report.name + "-emissive.lpvproj");
    project->name += "-emissive";
    project->scene.lights.clear(); // their stand-ins for the emitters would light the scene twice
    if (auto ok = scene::saveProject(*project, emissiveProject); !ok) {
        report.radiosityNote = ok.error().describe();
        return;
    }
    const fs::path ref = dir / "reference-emissive.exr";
    if (!referenceMatches(ref, width, height) &&
        call("reference", runReference,
             {emissiveProject.string(), "-o", ref.string(), "--width", std::to_string(width), "--height",
              std::to_string(height), "--spp", std::to_string(spp), "--set",
              "reference.emissiveLight=true"}) != kOk) {
        report.radiosityNote = "the emissive-light reference failed";
        return;
    }
    auto loadedRef = readReferenceExr(ref);
    if (!loadedRef) {
        report.radiosityNote = loadedRef.error().describe();
        return;
    }
    report.radiosityNote =
        "project lights removed, reference.emissiveLight=true, reference " + describeReference(ref);
    double solved = 0.0;
    bool restart = true;
    for (double target = 5.0; solved < maxSeconds - 1e-6; target = std::min(2.0 * target, maxSeconds)) {
        const fs::path image = dir / ("radiosity-" + fixed(target, 0) + "s.exr");
        std::vector<std::string> args{emissiveProject.string(),
                                      "--max-seconds",
                                      fixed(target - solved, 2),
                                      "--residual",
                                      "0.0001",
                                      "--image",
                                      image.string(),
                                      "--width",
                                      std::to_string(width),
                                      "--height",
                                      std::to_string(height),
                                      "--progress-interval",
                                      "10"};
        if (restart)
            args.push_back("--restart");
        restart = false;
        if (call("radiosity", runRadiosity, args) != kOk) {
            report.failures.push_back("radiosity run to " + fixed(target, 0) + " s");
            return;
        }
        solved = target;
        auto test = readRgbExr(image);
        if (!test) {
            report.failures.push_back(test.error().describe());
            return;
        }
        const auto& r = loadedRef->image;
        report.radiosity.push_back(
            {solved, reference::compareImages({test->width, test->height, &test->pixels},
                                              {r.width, r.height, &r.image}, &r.imageVariance, &r.coverage)});
        std::printf("radiosity after %.0f s of solving: %s\n", solved,
                    reference::describe(report.radiosity.back().image).c_str());
    }
}

// --resume: whether `file` was written by the very sweep the report would run
// now (its recorded command holds the project, the swept values, the
// reference, the size, frames and warm-up) after the reference was traced.
bool sweepDoneAlready(const fs::path& file, const fs::path& project, const std::string& sweep,
                      const fs::path& reference, int width, int height, int frames, int warmup) {
    std::error_code ec;
    if (!fs::exists(file, ec) || fs::last_write_time(file, ec) < fs::last_write_time(reference, ec) || ec)
        return false;
    std::ifstream in(file);
    const Json j = Json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.contains("runs") || j["runs"].empty())
        return false;
    const std::string command = j.value("command", "") + " ";
    for (const std::string& part :
         {"lpv bench " + project.string() + " ", "--sweep " + sweep + " ", "--reference " + reference.string() + " ",
          "--width " + std::to_string(width) + " ", "--height " + std::to_string(height) + " ",
          "--frames " + std::to_string(frames) + " ", "--warmup " + std::to_string(warmup) + " "})
        if (command.find(part) == std::string::npos)
            return false;
    return true;
}

// The lowest error among the settings whose mean is within 0.8-1.25x of the
// reference's (issue #24's band): a setting that shows almost no light can
// have a low MARE where the reference is dark.
const ReportRun* lowestInBand(const std::vector<ReportRun>& runs) {
    const ReportRun* best = nullptr;
    for (const ReportRun& r : runs)
        if (r.indirectMeanRatio >= 0.8 && r.indirectMeanRatio <= 1.25 &&
            (!best || r.indirectMare < best->indirectMare))
            best = &r;
    return best;
}

const ReportRun* cheapestBelow(const std::vector<ReportRun>& runs, double target) {
    const ReportRun* best = nullptr;
    for (const ReportRun& r : runs)
        if (r.indirectMare <= target && (!best || r.totalMs < best->totalMs))
            best = &r;
    return best;
}

std::string runCell(const ReportRun* r) {
    if (!r)
        return "none of the sweeps";
    return "`" + r->setting + "`: " + fixed(r->totalMs, 1) + " ms, " + percent(r->indirectMare) + ", mean " +
           fixed(r->indirectMeanRatio, 2) + "x";
}

std::string reportMarkdown(const std::vector<SceneReport>& scenes, const std::string& command,
                           const std::string& machine) {
    std::ostringstream out;
    out << "# LPV Studio: what accuracy costs in time\n\n`" << command << "`\n\nMachine: " << machine
        << "\n\nTime: the sum of the per-pass GPU medians of a frame (timer queries). Error: mean absolute "
           "relative error (MARE) of the LPV's indirect irradiance against the path-traced indirect "
           "irradiance at the same pixels, background masked, like for like: the reference's light reflected as "
           "many times as the LPV's `lpv.bounces`, from the same lights (the sky and emissive surfaces where the "
           "LPV injects them). Mean: the LPV's mean indirect irradiance over the reference's. Each question "
           "varies one key around the project's settings.\n\n";
    out << "| scene | project settings | cheapest at <= 10% | cheapest at <= 5% | lowest error found | lowest "
           "error with the mean within 0.8-1.25x |\n"
           "|---|---|---|---|---|---|\n";
    for (const SceneReport& s : scenes) {
        const ReportRun* base = nullptr;
        const ReportRun* lowest = nullptr;
        for (const ReportRun& r : s.runs) {
            if (r.projectSettings && !base)
                base = &r;
            if (!lowest || r.indirectMare < lowest->indirectMare)
                lowest = &r;
        }
        out << "| " << s.name << " | "
            << (base ? fixed(base->totalMs, 1) + " ms, " + percent(base->indirectMare) + ", mean " +
                           fixed(base->indirectMeanRatio, 2) + "x"
                     : "-")
            << " | "
            << runCell(cheapestBelow(s.runs, 0.10)) << " | " << runCell(cheapestBelow(s.runs, 0.05)) << " | "
            << runCell(lowest) << " | " << runCell(lowestInBand(s.runs)) << " |\n";
    }
    for (const SceneReport& s : scenes) {
        out << "\n## " << s.name << "\n\nReference: " << s.referenceNote;
        if (!s.runs.empty())
            out << "; its own noise on the indirect light: MARE " << percent(s.runs.front().noiseMare);
        out << ".\n\n| question | setting | GPU ms | indirect MARE | indirect mean (LPV / reference) | image "
               "MARE |\n|---|---|---:|---:|---:|---:|\n";
        for (const ReportRun& r : s.runs)
            out << "| " << r.question << " | `" << r.setting << "`" << (r.projectSettings ? " (project)" : "")
                << " | " << fixed(r.totalMs, 2) << " | " << percent(r.indirectMare) << " | "
                << fixed(r.indirectMeanRatio, 2) << "x | " << percent(r.imageMare) << " |\n";
        std::vector<std::string> questions;
        for (const ReportRun& r : s.runs)
            if (std::ranges::find(questions, r.question) == questions.end())
                questions.push_back(r.question);
        out << "\nPlots:";
        for (const std::string& q : questions)
            if (q == "bounces" || q == "sky") { // one sweep per value, in QUESTION/VALUE/
                for (const ReportRun& r : s.runs)
                    if (r.question == q && r.setting.find('=') != std::string::npos)
                        out << " [" << r.setting << "](" << s.name << "/" << q << "/"
                            << r.setting.substr(r.setting.find('=') + 1) << "/sweep.md)";
            } else {
                out << " [" << q << "](" << s.name << "/" << q << "/sweep.md)";
            }
        out << "\n\n### Radiosity against solve time\n\n" << s.radiosityNote << "\n\n";
        if (!s.radiosity.empty()) {
            out << "| solve wall time | image MARE | image relMSE | image SSIM |\n|---:|---:|---:|---:|\n";
            for (const RadiosityPoint& p : s.radiosity)
                out << "| " << fixed(p.seconds, 0) << " s | " << percent(p.image.mare)
                    << (p.image.mareBelowNoise() ? " (below noise)" : "") << " | " << fixed(p.image.relMse, 4)
                    << " | " << fixed(p.image.ssim, 3) << " |\n";
        }
        for (const std::string& f : s.failures)
            out << "\n**Failed:** " << f << "\n";
    }
    return out.str();
}

std::string reportJson(const std::vector<SceneReport>& scenes, const std::string& command,
                       const std::string& machine) {
    Json j{{"command", command}, {"machine", machine}, {"scenes", Json::array()}};
    for (const SceneReport& s : scenes) {
        Json scene{{"name", s.name},
                   {"reference", s.referenceNote},
                   {"runs", Json::array()},
                   {"radiosity", Json::array()},
                   {"failures", s.failures}};
        for (const ReportRun& r : s.runs)
            scene["runs"].push_back({{"question", r.question},
                                     {"setting", r.setting},
                                     {"projectSettings", r.projectSettings},
                                     {"totalMs", r.totalMs},
                                     {"indirectMare", r.indirectMare},
                                     {"indirectMeanRatio", r.indirectMeanRatio},
                                     {"noiseMare", r.noiseMare},
                                     {"imageMare", r.imageMare}});
        for (const RadiosityPoint& p : s.radiosity)
            scene["radiosity"].push_back(
                {{"seconds", p.seconds}, {"imageMare", p.image.mare}, {"imageRelMse", p.image.relMse}});
        j["scenes"].push_back(scene);
    }
    return j.dump(2) + "\n";
}

} // namespace

int benchAccuracyReport(Args args) {
    const fs::path outDir = args.option("--out").value_or("bench-report");
    const fs::path scenesDir = args.option("--scenes").value_or("../shared/scenes");
    const std::vector<std::string> only = args.options("--scene");
    const std::vector<std::string> onlyQuestions = args.options("--question");
    const bool quick = args.flag("--quick");
    const bool resume = args.flag("--resume");
    const auto width = parseCount(args.option("--width").value_or("320"), 1);
    const auto height = parseCount(args.option("--height").value_or("180"), 1);
    const auto frames = parseCount(args.option("--frames").value_or("10"), 1);
    const auto warmup = parseCount(args.option("--warmup").value_or("2"), 0);
    const auto sppOption = args.option("--spp");
    const auto spp = parseCount(sppOption.value_or("1"), 1);
    const auto radiosityText = args.option("--radiosity-seconds");
    if (!args.missingValue().empty())
        return usageError(args.missingValue() + " needs a value", "bench");
    if (auto unknown = args.unknownOption())
        return usageError("unknown option '" + *unknown + "'", "bench");
    if (args.positionals().size() != 1)
        return usageError("bench report takes no files (scenes come from --scenes)", "bench");
    if (!width || !height || !frames || !warmup || !spp)
        return usageError(
            "--width, --height, --frames and --spp must be positive integers, --warmup zero or more",
            "bench");
    const auto radiosityCount = parseCount(radiosityText.value_or(quick ? "5" : "160"), 5);
    if (!radiosityCount)
        return usageError("--radiosity-seconds must be a whole number of seconds, at least 5", "bench");
    for (const std::string& name : onlyQuestions)
        if (std::ranges::find(kQuestions, name, &Question::name) == kQuestions.end())
            return usageError("unknown question '" + name + "' (see lpv bench --help)", "bench");
    for (const std::string& name : only)
        if (std::ranges::find(kScenes, name, &SceneSpec::name) == kScenes.end())
            return usageError("unknown scene '" + name + "' (cornell-box, sibenik, sponza)", "bench");

    std::vector<SceneReport> reports;
    std::string machine;
    int status = kOk;
    for (const SceneSpec& spec : kScenes) {
        if (!only.empty() && std::ranges::find(only, spec.name) == only.end())
            continue;
        SceneReport report;
        report.name = spec.name;
        const fs::path sceneDir = outDir / spec.name;
        std::error_code ec;
        fs::create_directories(sceneDir, ec);
        if (ec) {
            std::cerr << "lpv: " << sceneDir.string() << ": cannot create the folder: " << ec.message()
                      << "\n";
            return kFailure;
        }
        const fs::path project = sceneDir / (spec.name + ".lpvproj");
        report.projectFile = project.string();
        std::printf("\n=== %s\n", spec.name.c_str());
        if (!makeProject(spec, scenesDir, project)) {
            report.failures.push_back("making the project");
            reports.push_back(report);
            status = kFailure;
            continue;
        }
        // --quick is a smoke run: 256 spp unless --spp says otherwise.
        const int sceneSpp = sppOption ? *spp : (quick ? 256 : spec.defaultSpp);
        const auto loaded = scene::loadProject(project);
        const scene::ParameterSet current = loaded ? loaded->parameters : scene::ParameterSet{};
        // One reference per bounce count a sweep needs (like for like); the
        // project's own lpv.bounces first.
        // `sky`: the value of effects.skyInjection the sweep renders with (empty:
        // the project's), so that reference.skyLight=auto follows it.
        auto referenceFor = [&](int bounces, const std::string& sky = "") -> std::optional<fs::path> {
            const fs::path ref = sceneDir / ("reference-" + std::to_string(bounces) + "-bounce" +
                                             (sky.empty() ? "" : "-sky-" + sky) + ".exr");
            if (referenceMatches(ref, *width, *height, bounces, sceneSpp)) {
                std::printf("reusing %s (delete it to trace again)\n", ref.string().c_str());
                return ref;
            }
            std::vector<std::string> traceArgs{project.string(), "-o", ref.string(), "--width",
                                               std::to_string(*width), "--height", std::to_string(*height),
                                               "--spp", std::to_string(sceneSpp), "--bounces", std::to_string(bounces)};
            if (!sky.empty())
                traceArgs.insert(traceArgs.end(), {"--set", "effects.skyInjection=" + sky});
            if (call("reference", runReference, traceArgs) != kOk)
                return std::nullopt;
            return ref;
        };
        const int projectBounces = current.getInt("lpv.bounces");
        const auto ref = referenceFor(projectBounces);
        if (!ref) {
            report.failures.push_back("tracing the reference");
            reports.push_back(report);
            status = kFailure;
            continue;
        }
        report.referenceNote = describeReference(*ref) + ", " + std::to_string(projectBounces) + " bounce" +
                               (projectBounces == 1 ? "" : "s");
        for (const Question& q : kQuestions) {
            const std::string& sweep = quick ? q.quickSweep : q.sweep;
            if (sweep.empty() ||
                (!onlyQuestions.empty() && std::ranges::find(onlyQuestions, q.name) == onlyQuestions.end()))
                continue;
            // Each sweep against its like-for-like reference: the bounces
            // question runs one sweep per value, each against a reference with
            // as many bounces; the sky question one per value, each against a
            // reference that traces sky light exactly when that LPV injects it.
            struct Part {
                std::string sweep, folder, sky;
                int bounces = 1;
            };
            std::vector<Part> parts;
            if (q.name == "bounces") {
                for (const std::string& k : splitValues(sweep))
                    parts.push_back({"lpv.bounces=" + k, k, "", std::atoi(k.c_str())});
            } else if (q.name == "sky") {
                for (const std::string& v : splitValues(sweep))
                    parts.push_back({"effects.skyInjection=" + v, v, v, projectBounces});
            } else {
                parts.push_back({sweep, "", "", projectBounces});
            }
            for (const Part& p : parts) {
                const std::string& part = p.sweep;
                const auto partRef =
                    p.bounces == projectBounces && p.sky.empty() ? ref : referenceFor(p.bounces, p.sky);
                const fs::path dir = p.folder.empty() ? sceneDir / q.name : sceneDir / q.name / p.folder;
                if (partRef && resume && sweepDoneAlready(dir / "sweep.json", project, part, *partRef, *width, *height,
                                                          *frames, *warmup)) {
                    std::printf("reusing %s (--resume: made by the same sweep command)\n",
                                (dir / "sweep.json").string().c_str());
                } else if (!partRef ||
                    call("bench", benchSweep,
                         {project.string(), "--sweep", part, "--reference", partRef->string(), "--out",
                          dir.string(), "--width", std::to_string(*width), "--height", std::to_string(*height),
                          "--frames", std::to_string(*frames), "--warmup", std::to_string(*warmup)}) != kOk) {
                    report.failures.push_back("sweep " + q.name + " (" + part + ")");
                    status = kFailure;
                    continue;
                }
                auto runs = readSweep(dir / "sweep.json", q.name, current);
                report.runs.insert(report.runs.end(), runs.begin(), runs.end());
                if (machine.empty()) {
                    std::ifstream in(dir / "sweep.json");
                    const Json j = Json::parse(in, nullptr, false);
                    if (!j.is_discarded())
                        machine = j.value("machine", "");
                }
            }
        }
        measureRadiosity(report, sceneDir, *width, *height, sceneSpp, double(*radiosityCount));
        if (!report.failures.empty())
            status = kFailure;
        reports.push_back(std::move(report));
    }

    std::string command = "lpv bench report --out " + outDir.string() + " --scenes " + scenesDir.string() +
                          " --width " + std::to_string(*width) + " --height " + std::to_string(*height) +
                          " --frames " + std::to_string(*frames) + " --warmup " + std::to_string(*warmup) +
                          (sppOption ? " --spp " + std::to_string(*spp) : std::string()) + " --radiosity-seconds " +
                          std::to_string(*radiosityCount);
    for (const std::string& s : only)
        command += " --scene " + s;
    for (const std::string& q : onlyQuestions)
        command += " --question " + q;
    if (resume)
        command += " --resume";
    if (quick)
        command += " --quick";
    const std::optional<std::string> md = (outDir / "report.md").string(),
                                     json = (outDir / "report.json").string();
    if (!writeReportFiles(
            {{md, reportMarkdown(reports, command, machine)}, {json, reportJson(reports, command, machine)}}))
        return kFailure;
    return status;
}

} // namespace lpv::cli
