#pragma once
// One time per setting per scene (issue #43): `lpv bench report` times every
// distinct setting of a scene's questions together, in interleaved rounds
// (timeSettings), and keeps them in `timing.json` beside the scene's
// project; each question's sweep then takes its runs' times from there
// (`lpv bench --sweep ... --times-from timing.json`). The project setting
// that every question contains is timed once, not once per question.
#include "lpv/bench/Sweep.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lpv::bench {

struct SharedTiming {
    std::string command;    // what timed them
    std::string machine;    // describeMachine()
    std::string load;       // before -> after
    int rounds = 0;
    std::string stopReason;
    // Each setting: `parameters` holds every override of the project it was
    // timed with (the project's own and the setting's), so a sweep matches it
    // by value, whatever keys it names.
    struct Entry {
        std::vector<Setting> parameters;
        SweepRun run; // settings (as the timing named them), passes, passStats, total, gpuBytes, lpvBytes
    };
    std::vector<Entry> entries;
};

// Atomic, like every bench file.
scene::Expected<void> saveSharedTiming(const SharedTiming& timing, const std::filesystem::path& file);
// Every field checked; the error names the file.
scene::Expected<SharedTiming> loadSharedTiming(const std::filesystem::path& file);

// The entry timed with exactly these parameter values, or null.
const SharedTiming::Entry* findTiming(const SharedTiming& timing, const scene::ParameterSet& parameters);

// Copies into each run the times and memory of the entry whose parameters
// equal `base` with the run's settings applied. Fails, naming the setting,
// when one has no entry.
scene::Expected<void> applySharedTiming(const SharedTiming& timing, const scene::ParameterSet& base,
                                        std::vector<SweepRun>& runs);

// Whether two timings of the same settings (a report run twice) tell the
// same story: the target of issue #43 is a Spearman rank correlation of at
// least 0.95 between the runs' medians, no pair of settings that both runs
// call different costs in opposite order, and each setting's second median
// within its first spread.
struct TimingAgreement {
    int settings = 0;        // in both timings
    double spearman = 0.0;   // rank correlation of all their medians (ties: average ranks)
    // The settings whose times differ by more than the noise: from the
    // cheapest up (in A), each setting that is a different cost (sameCost)
    // from every one kept so far, in both runs; and the rank correlation of
    // their medians. Settings of the same cost may come in either order in
    // another run: their order is noise, and issue #43's target counts only these.
    int distinctSettings = 0;
    double distinctSpearman = 0.0;
    int distinctPairs = 0;   // pairs both runs call different costs
    int discordantPairs = 0; // of those, the pairs the two runs order oppositely
    int sameCostInBoth = 0;  // settings whose two medians are the same cost (sameCost)
    double largestRatio = 1.0; // the largest max/min of one setting's two medians
    std::string largestRatioSetting;
    double medianSpread = 0.0; // the median relative spread (IQR / median) over both runs' settings
};
TimingAgreement compareTimings(const SharedTiming& a, const SharedTiming& b);

// Whether the ranking agrees: distinctSpearman >= 0.95 and no pair ordered oppositely.
bool rankingAgrees(const TimingAgreement& g);

// Spearman's rank correlation of two equally long samples (average ranks for ties).
double spearman(const std::vector<double>& x, const std::vector<double>& y);

} // namespace lpv::bench
