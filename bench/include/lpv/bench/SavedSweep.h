#pragma once
// A sweep kept with its project (the editor's sweep dock, issue #26 item 4):
// what was swept around which settings, the figures of every run and a small
// preview of each run's indirect light, in `<Name>.assets/sweep.json` beside
// the project. Not part of the project file: a project opens without it, and
// a damaged one is reported and ignored, never a reason not to open.
#include "lpv/bench/Sweep.h"

#include "lpv/scene/Image.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lpv::bench {

inline constexpr const char* kSavedSweepFormat = "lpvstudio-sweep";
inline constexpr int kSavedSweepVersion = 1;

// One row of the Sweeps dock's question table: its name, `KEY=V1,V2,...`
// and whether it is checked.
struct SweepQuestionRow {
    std::string name;
    std::string values;
    bool checked = false;
    bool operator==(const SweepQuestionRow&) const = default;
};

struct SavedSweep {
    std::string createdAt; // ISO 8601, UTC
    std::string machine;   // describeMachine() of the run
    int width = 0, height = 0, frames = 0, warmup = 0;
    int referenceSpp = 0;
    double referenceSeconds = 0.0;
    double referenceNoiseMare = 0.0; // of its indirect light: errors below it are noise
    std::vector<Setting> base;       // the overrides every run started from (KEY, value text)
    std::vector<SweepRun> runs;      // indirectPixels are not kept
    std::vector<scene::Image8> previews; // per run: its indirect light, exposed like referencePreview
    scene::Image8 referencePreview;
    // The dock's question rows as they were when the sweep was written, so
    // that reopening the project asks the same questions (issue #46).
    // Optional in the file: empty for a sweep saved before it was kept.
    std::vector<SweepQuestionRow> questions;
};

// `<folder>/<stem>.assets/sweep.json` for `<folder>/<stem>.lpvproj`.
std::filesystem::path savedSweepFileOf(const std::filesystem::path& projectFile);

// Atomic, like a project save.
scene::Expected<void> saveSweep(const SavedSweep& sweep, const std::filesystem::path& file);
// Every field checked; the error names the file and the field.
scene::Expected<SavedSweep> loadSweep(const std::filesystem::path& file);

// The parameters a run was measured with: `base` plus its settings.
scene::ParameterSet runParameters(const std::vector<Setting>& base, const SweepRun& run);
// Whether two sets give every parameter the same value (a key set to its
// default equals a key left unset).
bool sameValues(const scene::ParameterSet& a, const scene::ParameterSet& b);
// The overrides of `parameters` as KEY, value text.
std::vector<Setting> settingsOf(const scene::ParameterSet& parameters);

} // namespace lpv::bench
