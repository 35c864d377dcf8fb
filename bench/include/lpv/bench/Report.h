#pragma once
// The accuracy-against-time report (`lpv bench report`): per scene, every
// question's runs in one table (time with its spread, GPU memory, symmetric
// error, bias, MARE), the headline (the project's settings, the cheapest
// unbiased settings within 10% and 25% of the lowest unbiased error, the
// lowest error found, marked when biased) and the radiosity solve against
// time; as report.md and report.json.
#include "lpv/bench/Pareto.h"
#include "lpv/bench/Sweep.h"
#include "lpv/bench/Timing.h"

#include "lpv/reference/Metrics.h"
#include "lpv/scene/ParameterRegistry.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace lpv::bench {

// One render of a sweep, as the report tabulates it.
struct ReportRun {
    std::string question;
    std::string setting; // "key=value"
    bool projectSettings = false; // changes nothing of the project's settings
    double totalMs = 0.0;         // time.median
    TimingStats time;             // over the timing rounds (shared by every question with this setting)
    std::uint64_t gpuBytes = 0;   // the frame's GPU memory
    double indirectSymmetric = 0.0; // ErrorMetrics::symmetricError of the indirect light
    double noiseSymmetric = 0.0;
    double indirectMare = 0.0;
    double indirectMeanRatio = 0.0; // the LPV's mean indirect irradiance over the reference's
    double noiseMare = 0.0;
    double imageMare = 0.0;
    bool biased() const { return biasedMean(indirectMeanRatio); }
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
    std::string timingNote;    // "5 interleaved rounds (every spread within 10% after 5 rounds), load ..."
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

// The cheapest unbiased run whose symmetric error is within `fraction` of
// the lowest unbiased one (same cost within the noise: the lower error), or null.
const ReportRun* cheapestWithinBest(const std::vector<ReportRun>& runs, double fraction);
// The lowest symmetric error among the unbiased runs (mean within
// 0.8-1.25x of the reference's), or null when none is.
const ReportRun* lowestInBand(const std::vector<ReportRun>& runs);

std::string reportMarkdown(const std::vector<SceneReport>& scenes, const std::string& command,
                           const std::string& machine);
std::string reportJson(const std::vector<SceneReport>& scenes, const std::string& command, const std::string& machine);

} // namespace lpv::bench
