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

} // namespace lpv::bench
