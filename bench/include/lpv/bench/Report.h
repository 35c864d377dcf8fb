#pragma once
// The accuracy-against-time report (`lpv bench report`): per scene, every
// question's runs in one table, the headline (the project's settings, the
// cheapest settings reaching 10% and 5% indirect MARE, the lowest error, the
// lowest error whose mean is within 0.8-1.25x of the reference's) and the
// radiosity solve against time; as report.md and report.json.
#include "lpv/bench/Sweep.h"

#include "lpv/reference/Metrics.h"
#include "lpv/scene/ParameterRegistry.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lpv::bench {

// One render of a sweep, as the report tabulates it.
struct ReportRun {
    std::string question;
    std::string setting; // "key=value"
    bool projectSettings = false; // changes nothing of the project's settings
    double totalMs = 0.0;
    double indirectMare = 0.0;
    double indirectMeanRatio = 0.0; // the LPV's mean indirect irradiance over the reference's
    double noiseMare = 0.0;
    double imageMare = 0.0;
};

struct RadiosityPoint {
    double seconds = 0.0; // the solver's own time so far (all runs)
    reference::ErrorMetrics image;
    reference::ErrorMetrics indirect; // the frame's indirect light against the reference's multi-bounce layer
    double residual = 0.0;
};

struct SceneReport {
    std::string name;
    std::string projectFile;
    std::string referenceNote; // "160x90, 4096 spp in 10.4 s, 1 bounce"
    std::vector<ReportRun> runs;
    std::vector<std::string> failures;
    std::vector<RadiosityPoint> radiosity;
    std::string radiosityNote;
};

// A question's sweep runs as report rows; `current` (the project's own
// parameters) tells which run changes nothing.
std::vector<ReportRun> reportRunsOf(const std::string& question, const std::vector<SweepRun>& runs,
                                    const scene::ParameterSet& current);
// The same from a sweep.json written earlier (`--resume`); empty when it does not read.
std::vector<ReportRun> reportRunsFromSweepJson(const std::filesystem::path& file, const std::string& question,
                                               const scene::ParameterSet& current);

// The fastest run at or under `target` indirect MARE, or null.
const ReportRun* cheapestBelow(const std::vector<ReportRun>& runs, double target);
// The lowest error among the runs whose mean is within 0.8-1.25x of the
// reference's (issue #24's band): a setting that shows almost no light can
// have a low MARE where the reference is dark. Null when none is.
const ReportRun* lowestInBand(const std::vector<ReportRun>& runs);

std::string reportMarkdown(const std::vector<SceneReport>& scenes, const std::string& command,
                           const std::string& machine);
std::string reportJson(const std::vector<SceneReport>& scenes, const std::string& command, const std::string& machine);

} // namespace lpv::bench
