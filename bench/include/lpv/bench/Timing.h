#pragma once
// Times a user can trust (issue #43): a figure measured over several rounds
// has a median and a spread, and two figures whose difference is inside the
// noise are the same cost. Settings are timed in interleaved rounds (A B C,
// then C B A, ...), so a machine that slows down for a while slows every
// setting alike instead of the one that happened to run then. Rounds stop
// when every setting's spread is within a target, at a round limit, or when
// a time budget runs out. Qt- and GL-free: the rounds call back to render,
// so tests drive them with synthetic timings.
#include "lpv/renderer/GpuTimer.h"
#include "lpv/scene/Error.h"

#include <functional>
#include <string>
#include <vector>

namespace lpv::bench {

// One figure (ms) over rounds: the median, the interquartile range (linear
// interpolation between order statistics) and the extremes.
struct TimingStats {
    double median = 0.0;
    double q1 = 0.0, q3 = 0.0;
    double min = 0.0, max = 0.0;
    int rounds = 0; // samples

    double spread() const { return q3 - q1; }
    // The interquartile range over the median (0.1 = 10%); 0 for one sample.
    double relativeSpread() const { return median > 0.0 ? spread() / median : 0.0; }
};

TimingStats timingStatsOf(std::vector<double> samples);

// Below this difference of medians two settings are the same cost whatever
// their spread: a timer query on a quiet machine scatters by a few percent
// from run to run, more than three rounds' quartiles show.
inline constexpr double kSameCostFraction = 0.05;

// Whether a and b are the same cost within the noise: their interquartile
// ranges overlap, or their medians differ by less than the larger of the two
// relative spreads (at least kSameCostFraction) of the larger median.
bool sameCost(const TimingStats& a, const TimingStats& b);

// "12.3 ms ±0.4" (half the interquartile range) or "12.3 ms" for one round.
std::string formatTiming(const TimingStats& t);

struct RoundPlan {
    int minRounds = 3;          // at least this many (when the budget allows)
    int maxRounds = 9;          // --rounds: at most this many; 0 = no timing at all
    double spreadTarget = 0.10; // stop once every setting's total has relativeSpread() <= this
    double timeBudgetSeconds = 0.0; // --time-budget: no new round starts past it (0 = none)
};

// The plan as the options that give it (" --rounds 9 --spread-target 10"),
// for the command a report or sweep records, so a rerun times alike.
std::string roundOptionsText(const RoundPlan& plan);

// The settings' order in round `round` (0-based): forward on even rounds, backward on odd.
std::vector<int> roundOrder(int count, int round);

// Whether another round should start after `roundsDone` rounds that took
// `secondsSpent` (its reason in `why` when it does not).
bool needsAnotherRound(const RoundPlan& plan, const std::vector<TimingStats>& totals, int roundsDone,
                       double secondsSpent, std::string* why = nullptr);

// One setting's times over the rounds.
struct SettingTiming {
    // Per pass: medianMs, minMs, maxMs over the rounds of each round's
    // median frame; samples = frames timed in all.
    std::vector<renderer::PassTiming> passes;
    std::vector<TimingStats> passStats; // per pass, in the order of `passes`
    TimingStats total;                  // of each round's sum of pass medians
};

struct RoundsResult {
    std::vector<SettingTiming> settings;
    int rounds = 0;
    double seconds = 0.0;
    std::string stopReason; // "spread within 10% after 3 rounds", "time budget of 60 s spent", ...
};

// Times `count` settings in interleaved rounds. `timeOnce(i)` renders
// setting i's frames of one round and gives its per-pass table (medians over
// that round's frames). `progress(round, position, index)` is asked before
// each setting of each round; false stops with ErrorCode::Cancelled.
// `clock` (seconds, monotonic) is steady_clock unless a test gives one.
struct RoundCallbacks {
    std::function<scene::Expected<std::vector<renderer::PassTiming>>(int index)> timeOnce;
    std::function<bool(int round, int position, int index)> progress;
    std::function<double()> clock;
};
scene::Expected<RoundsResult> timeInRounds(int count, const RoundPlan& plan, const RoundCallbacks& callbacks);

// The machine's load as /proc/loadavg gives it ("load 0.42 0.35 0.30"), or "load unknown".
std::string describeLoad();

} // namespace lpv::bench
