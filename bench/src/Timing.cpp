#include "lpv/bench/Timing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>

namespace lpv::bench {

namespace {

// The q-quantile of sorted samples, linearly interpolated between order
// statistics (R's and NumPy's default): a quartile of 3 rounds falls halfway
// between the median and an extreme.
double quantile(const std::vector<double>& sorted, double q) {
    if (sorted.empty())
        return 0.0;
    const double at = q * double(sorted.size() - 1);
    const std::size_t below = std::size_t(std::floor(at));
    const std::size_t above = std::min(below + 1, sorted.size() - 1);
    return sorted[below] + (at - double(below)) * (sorted[above] - sorted[below]);
}

std::string percent(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0f%%", 100.0 * v);
    return buf;
}

} // namespace

TimingStats timingStatsOf(std::vector<double> samples) {
    TimingStats t;
    if (samples.empty())
        return t;
    std::ranges::sort(samples);
    t.rounds = int(samples.size());
    t.median = quantile(samples, 0.5);
    t.q1 = quantile(samples, 0.25);
    t.q3 = quantile(samples, 0.75);
    t.min = samples.front();
    t.max = samples.back();
    return t;
}

bool sameCost(const TimingStats& a, const TimingStats& b) {
    const bool overlap = a.q1 <= b.q3 && b.q1 <= a.q3;
    // The noise is the larger relative spread of the two (a few rounds can
    // show one setting quieter than the machine is), and never under the floor.
    const double noise = std::max({kSameCostFraction, a.relativeSpread(), b.relativeSpread()});
    return overlap || std::abs(a.median - b.median) < noise * std::max(a.median, b.median);
}

std::string formatTiming(const TimingStats& t) {
    char buf[64];
    if (t.rounds > 1)
        std::snprintf(buf, sizeof buf, "%.1f ms ±%.1f", t.median, 0.5 * t.spread());
    else
        std::snprintf(buf, sizeof buf, "%.1f ms", t.median);
    return buf;
}

std::vector<int> roundOrder(int count, int round) {
    std::vector<int> order(std::size_t(std::max(count, 0)));
    for (int i = 0; i < count; ++i)
        order[std::size_t(i)] = round % 2 == 0 ? i : count - 1 - i;
    return order;
}

bool needsAnotherRound(const RoundPlan& plan, const std::vector<TimingStats>& totals, int roundsDone,
                       double secondsSpent, std::string* why) {
    auto stop = [&](std::string reason) {
        if (why)
            *why = std::move(reason);
        return false;
    };
    const std::string after = " after " + std::to_string(roundsDone) + " round" + (roundsDone == 1 ? "" : "s");
    if (roundsDone >= plan.maxRounds)
        return stop("round limit" + after);
    if (plan.timeBudgetSeconds > 0.0 && roundsDone > 0) {
        // A round costs about what the rounds so far cost on average: one
        // that would end past the budget does not start.
        const double perRound = secondsSpent / roundsDone;
        if (secondsSpent + perRound > plan.timeBudgetSeconds) {
            char buf[96];
            std::snprintf(buf, sizeof buf, "time budget of %.0f s reached", plan.timeBudgetSeconds);
            return stop(buf + after);
        }
    }
    if (roundsDone < plan.minRounds)
        return true;
    for (const TimingStats& t : totals)
        if (t.relativeSpread() > plan.spreadTarget)
            return true;
    return stop("every spread within " + percent(plan.spreadTarget) + after);
}

scene::Expected<RoundsResult> timeInRounds(int count, const RoundPlan& plan, const RoundCallbacks& callbacks) {
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    auto now = [&] {
        return callbacks.clock ? callbacks.clock() : std::chrono::duration<double>(Clock::now() - start).count();
    };
    const double begin = now();
    // Per setting: each pass's per-round medians (passes in first-seen order), and the per-round totals.
    struct Samples {
        std::vector<std::string> order;
        std::map<std::string, std::vector<double>> ms;
        std::map<std::string, std::size_t> frames;
        std::vector<double> totals;
    };
    std::vector<Samples> samples(std::size_t(std::max(count, 0)));
    RoundsResult result;
    result.settings.resize(samples.size());
    auto summarise = [&](std::size_t i) {
        SettingTiming& out = result.settings[i];
        out = {};
        for (const std::string& pass : samples[i].order) {
            const TimingStats s = timingStatsOf(samples[i].ms[pass]);
            out.passes.push_back({pass, s.median, s.min, s.max, samples[i].ms[pass].back(), samples[i].frames[pass]});
            out.passStats.push_back(s);
        }
        out.total = timingStatsOf(samples[i].totals);
    };
    std::vector<TimingStats> totals(samples.size());
    int round = 0;
    while (count > 0 && needsAnotherRound(plan, totals, round, now() - begin, &result.stopReason)) {
        const std::vector<int> order = roundOrder(count, round);
        for (int position = 0; position < count; ++position) {
            const int index = order[std::size_t(position)];
            if (callbacks.progress && !callbacks.progress(round, position, index))
                return scene::makeError(scene::ErrorCode::Cancelled, "", "",
                                        "stopped in timing round " + std::to_string(round + 1));
            auto table = callbacks.timeOnce(index);
            if (!table)
                return std::unexpected(table.error());
            Samples& s = samples[std::size_t(index)];
            double total = 0.0;
            for (const renderer::PassTiming& p : *table) {
                if (p.samples == 0)
                    continue;
                if (!s.ms.contains(p.pass))
                    s.order.push_back(p.pass);
                s.ms[p.pass].push_back(p.medianMs);
                s.frames[p.pass] += p.samples;
                total += p.medianMs;
            }
            s.totals.push_back(total);
        }
        ++round;
        for (std::size_t i = 0; i < samples.size(); ++i)
            totals[i] = timingStatsOf(samples[i].totals);
    }
    for (std::size_t i = 0; i < samples.size(); ++i)
        summarise(i);
    result.rounds = round;
    result.seconds = now() - begin;
    if (count <= 0 || plan.maxRounds <= 0)
        result.stopReason = "not timed";
    return result;
}

std::string describeLoad() {
    std::ifstream in("/proc/loadavg");
    double one = 0.0, five = 0.0, fifteen = 0.0;
    if (!(in >> one >> five >> fifteen))
        return "load unknown";
    char buf[64];
    std::snprintf(buf, sizeof buf, "load %.2f %.2f %.2f", one, five, fifteen);
    return buf;
}

std::string roundOptionsText(const RoundPlan& plan) {
    char buf[128];
    std::snprintf(buf, sizeof buf, " --rounds %d --spread-target %g", plan.maxRounds, 100.0 * plan.spreadTarget);
    std::string text = buf;
    if (plan.timeBudgetSeconds > 0.0) {
        std::snprintf(buf, sizeof buf, " --time-budget %g", plan.timeBudgetSeconds);
        text += buf;
    }
    return text;
}

} // namespace lpv::bench
