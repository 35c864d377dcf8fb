#pragma once
// Runs a solver until the residual target, a time budget or a cancel request,
// reporting progress as it goes. Calling it again continues (pause/resume).
#include "lpv/radiosity/ProgressiveSolver.h"

#include <atomic>
#include <functional>

namespace lpv::radiosity {

struct SolveProgress {
    std::uint64_t shots = 0; // over all sessions
    std::uint64_t batches = 0;
    double residual = 1.0;          // unshot / emitted power
    double seconds = 0.0;           // over all sessions
    double shootersPerSecond = 0.0; // in this session
    std::size_t patches = 0;
};

enum class StopReason { Converged, TimeBudget, Cancelled, NothingToShoot };
const char* toString(StopReason reason);

// `lpv radiosity`'s time limit when none is given: a solve that has not
// converged in an hour is resumable (run again), but never runs unattended
// for ever.
inline constexpr double kDefaultMaxSeconds = 3600.0;

// Stops with an error (NonFinite) as soon as the residual is not finite.
struct SolveOptions {
    double residualTarget = 0.01;  // radiosity.convergenceThreshold
    double maxSeconds = 0.0;       // this session's budget; 0 = none (lpv radiosity: kDefaultMaxSeconds)
    int shootersPerBatch = 16;     // radiosity.shootersPerBatch
    double progressInterval = 1.0; // seconds between progress reports
    std::function<void(const SolveProgress&)> progress;
    const std::atomic<bool>* cancel = nullptr; // set from another thread to pause
};

scene::Expected<StopReason> solve(ProgressiveSolver& solver, FormFactorSource& formFactors,
                                  const SolveOptions& options);

SolveProgress progressOf(const ProgressiveSolver& solver, double sessionSeconds, std::uint64_t sessionShots);

} // namespace lpv::radiosity
