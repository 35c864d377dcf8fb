#include "lpv/radiosity/SolveLoop.h"

#include <chrono>
#include <cmath>
#include <string>

namespace lpv::radiosity {

const char* toString(StopReason reason) {
    switch (reason) {
    case StopReason::Converged:
        return "converged";
    case StopReason::TimeBudget:
        return "time budget reached";
    case StopReason::Cancelled:
        return "paused";
    case StopReason::NothingToShoot:
        return "nothing left to shoot";
    }
    return "?";
}

SolveProgress progressOf(const ProgressiveSolver& solver, double sessionSeconds, std::uint64_t sessionShots) {
    SolveProgress p;
    p.shots = solver.state().shots;
    p.batches = solver.state().batches;
    p.residual = solver.residual();
    p.seconds = solver.state().seconds;
    p.shootersPerSecond = sessionSeconds > 0.0 ? double(sessionShots) / sessionSeconds : 0.0;
    p.patches = solver.mesh().size();
    return p;
}

namespace {

// "-nan" from std::to_string says less than this.
std::string nonFiniteText(double v) {
    if (std::isnan(v))
        return "NaN";
    if (std::isinf(v))
        return v > 0.0 ? "infinite" : "-infinite";
    return std::to_string(v) + " but the emitted energy is not finite";
}

} // namespace

scene::Expected<StopReason> solve(ProgressiveSolver& solver, FormFactorSource& formFactors,
                                  const SolveOptions& options) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    auto lastReport = start;
    auto lastStep = start;
    const std::uint64_t shotsBefore = solver.state().shots;
    auto elapsed = [&](Clock::time_point t) { return std::chrono::duration<double>(t - start).count(); };
    auto report = [&](Clock::time_point now) {
        if (options.progress)
            options.progress(progressOf(solver, elapsed(now), solver.state().shots - shotsBefore));
    };
    for (;;) {
        // NaN compares false with every target: without this a light whose
        // energy overflows (3.4e38 W) solved for ever, or saved NaN.
        const glm::dvec3 emitted = solver.state().balance.emitted;
        if (const double residual = solver.residual();
            !std::isfinite(residual) || !std::isfinite(emitted.x + emitted.y + emitted.z)) {
            report(Clock::now());
            return scene::makeError(scene::ErrorCode::NonFinite, "", "radiosity residual",
                                    "the residual (unshot / emitted energy) is " + nonFiniteText(residual) +
                                        " after " + std::to_string(solver.state().shots) +
                                        " shots: the emitted energy overflowed (a light, emissive surface or "
                                        "reflectance too large); the solution was not kept");
        }
        if (solver.residual() <= options.residualTarget) {
            report(Clock::now());
            return StopReason::Converged;
        }
        if (options.cancel && options.cancel->load()) {
            report(Clock::now());
            return StopReason::Cancelled;
        }
        if (options.maxSeconds > 0.0 && elapsed(Clock::now()) >= options.maxSeconds) {
            report(Clock::now());
            return StopReason::TimeBudget;
        }
        auto shot = solver.step(formFactors, options.shootersPerBatch);
        if (!shot)
            return std::unexpected(shot.error());
        const auto now = Clock::now();
        solver.mutableState().seconds += std::chrono::duration<double>(now - lastStep).count();
        lastStep = now;
        if (*shot == 0) {
            report(now);
            return StopReason::NothingToShoot;
        }
        if (std::chrono::duration<double>(now - lastReport).count() >= options.progressInterval) {
            report(now);
            lastReport = now;
        }
    }
}

} // namespace lpv::radiosity
