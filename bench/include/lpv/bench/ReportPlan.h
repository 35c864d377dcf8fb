#pragma once
// What `lpv bench report` does, laid out before it does it: per scene the
// project, the references it needs (one per bounce count and sky setting a
// sweep measures against) and the sweeps (one per question, or per value for
// bounces and sky), and what of it is on disk already (--resume, the shards'
// steps; ReportShards.h). The CLI runs the plan: in one process, or on a
// cluster as shards and a coordinator (docs/cluster.md).
#include "lpv/bench/Questions.h"
#include "lpv/bench/ReferenceFile.h"
#include "lpv/bench/Settings.h"
#include "lpv/bench/Timing.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/ParameterRegistry.h"
#include "lpv/scene/Project.h"

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace lpv::bench::report {

struct SceneSpec {
    std::string name;
    std::string source; // relative to --scenes; empty = the built-in template
    // Reference samples per pixel unless --spp says otherwise (see kScenes).
    int defaultSpp;
};
// cornell-box, cornell-obj, sibenik, sponza, in the report's order.
extern const std::vector<SceneSpec> kScenes;

struct ReportOptions {
    std::filesystem::path outDir = "bench-report";
    std::filesystem::path scenesDir = "../shared/scenes";
    std::vector<std::string> scenes;    // --scene; empty = all
    std::vector<std::string> questions; // --question; empty = all
    bool quick = false;
    bool resume = false;
    int width = 320, height = 180, frames = 10, warmup = 2;
    std::optional<int> spp; // --spp; else per scene
    int radiosityCount = 160;
    RoundPlan rounds; // the timing step's rounds (--rounds, --time-budget, --spread-target), per scene

    bool wantsScene(const std::string& name) const;
    bool wantsQuestion(const std::string& name) const;
    int sppFor(const SceneSpec& spec) const; // --quick is a smoke run: 256 unless --spp
};

// The command line that gives these options (headed in report.md; printed as the next step).
std::string reportCommand(const ReportOptions& options);

struct PlannedReference {
    std::filesystem::path file;
    int bounces = 1;
    std::string sky; // effects.skyInjection it is traced for ("": the project's)
};

struct PlannedSweep {
    std::string question;
    std::string sweep; // "KEY=V1,V2,..."
    std::filesystem::path dir;
    std::size_t reference = 0; // into ScenePlan::references
};

struct ScenePlan {
    const SceneSpec* spec = nullptr;
    std::filesystem::path dir;     // OUT/NAME
    std::filesystem::path project; // OUT/NAME/NAME.lpvproj
    int spp = 0;
    int projectBounces = 1;
    scene::ParameterSet current;              // the project's own parameters
    std::vector<PlannedReference> references; // the project's own first
    std::vector<PlannedSweep> sweeps;
};

std::filesystem::path projectFileOf(const SceneSpec& spec, const ReportOptions& options);
// The plan of one scene; its project must exist (its lpv.bounces decides the references).
scene::Expected<ScenePlan> planScene(const SceneSpec& spec, const ReportOptions& options);
// OUT/NAME/timing.json: every distinct setting of the scene's sweeps timed once, together.
std::filesystem::path timingFileOf(const ScenePlan& plan);

// "lpv.bounces=1,2,3" -> {"1", "2", "3"}.
std::vector<std::string> splitValues(const std::string& sweep);

// Every setting the scene's sweeps render, each once, on top of `base` (the
// project's parameters): the swept value and every override it resolves to.
// The report times these together, once, for all its questions.
std::vector<std::pair<std::vector<Setting>, scene::ParameterSet>> distinctSettings(const ScenePlan& plan,
                                                                                const scene::ParameterSet& base);

// The radiosity patch size the report solves with: the project's
// radiosity.maxPatchArea, coarsened (x4 at a time) until the scene meshes
// into at most 150,000 patches.
float reportPatchArea(const scene::Project& project);

// A reference traced earlier with the same size and bounce count (0: any)
// and at least `spp` samples is reused.
bool referenceMatches(const std::filesystem::path& file, int width, int height, int bounces = 0, int spp = 0);
bool referenceMatches(const LoadedReference& ref, int width, int height, int bounces, int spp);
// --resume: whether `file` was written by the very sweep the report would run
// now (its recorded command holds the project, the swept values, the
// reference, the size, frames and warm-up) after the reference and the
// scene's timing were made.
bool sweepDoneAlready(const std::filesystem::path& file, const ScenePlan& plan, const PlannedSweep& sweep,
                      const ReportOptions& options);

} // namespace lpv::bench::report
