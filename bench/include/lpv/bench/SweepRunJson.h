#pragma once
// A sweep run's figures as JSON (settings, timings, error metrics; not its
// pixels), written so that doubles read back to the same bits: a sweep's
// shards (app/cli/BenchSweepShard.cpp) merge to the figures of one process,
// and the editor's saved sweeps reload as they were measured.
#include "lpv/bench/Sweep.h"

#include <nlohmann/json.hpp>

namespace lpv::bench {

nlohmann::json sweepRunToJson(const SweepRun& run);
// A time over rounds: {"medianMs", "q1Ms", "q3Ms", "minMs", "maxMs", "rounds"},
// as nlohmann::json or, for files whose keys keep their order (sweep.json),
// nlohmann::ordered_json.
template <typename Json = nlohmann::json>
Json timingToJson(const TimingStats& t) {
    return {{"medianMs", t.median}, {"q1Ms", t.q1}, {"q3Ms", t.q3}, {"minMs", t.min}, {"maxMs", t.max},
            {"rounds", t.rounds}};
}
TimingStats timingFromJson(const nlohmann::json& j);
// Throws nlohmann::json::exception on a missing or mistyped field.
SweepRun sweepRunFromJson(const nlohmann::json& j);

} // namespace lpv::bench
