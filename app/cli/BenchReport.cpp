#include "BenchReport.h"
#include "Cli.h"


#include "lpv/bench/SweepOutput.h" // bench::SweepTimingInfo
#include "lpv/scene/Project.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iostream>
#include <cstdio>
#include <sstream>

namespace lpv::cli {

namespace {

std::string ms(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    return buf;
}

// Pass names in the order they first appear over all runs.
std::vector<std::string> passNames(const std::vector<BenchRun>& runs) {
    std::vector<std::string> names;
    for (const BenchRun& run : runs)
        for (const auto& p : run.passes)
            if (std::find(names.begin(), names.end(), p.pass) == names.end())
                names.push_back(p.pass);
    return names;
}

// A run's pass as TimingStats: from the rounds, or its one table when it had none.
bench::TimingStats passStatsOf(const BenchRun& run, std::size_t pass) {
    if (pass < run.passStats.size())
        return run.passStats[pass];
    const renderer::PassTiming& t = run.passes[pass];
    return {t.medianMs, t.medianMs, t.medianMs, t.minMs, t.maxMs, 1};
}

bench::TimingStats totalOf(const BenchRun& run) {
    if (run.total.rounds > 0)
        return run.total;
    double total = 0.0;
    for (const renderer::PassTiming& t : run.passes)
        total += t.medianMs;
    return {total, total, total, total, total, run.passes.empty() ? 0 : 1};
}

// "1.234 ±0.012": the median and half the interquartile range.
std::string withSpread(const bench::TimingStats& t) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.3f ±%.3f", t.median, 0.5 * t.spread());
    return buf;
}

std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos)
        return s;
    std::string out = "\"";
    for (char c : s)
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

} // namespace

std::string benchRunLabel(const std::vector<Setting>& settings) {
    if (settings.empty())
        return "project settings";
    std::string label;
    for (const auto& [key, value] : settings)
        label += (label.empty() ? "" : " ") + key + "=" + value;
    return label;
}

std::vector<std::size_t> benchSameCostAs(const std::vector<BenchRun>& runs, std::size_t index) {
    std::vector<std::size_t> same;
    const bench::TimingStats a = totalOf(runs[index]);
    for (std::size_t j = 0; j < runs.size(); ++j) {
        const bench::TimingStats b = totalOf(runs[j]);
        if (j != index && a.rounds > 0 && b.rounds > 0 && bench::sameCost(a, b))
            same.push_back(j);
    }
    return same;
}

std::string benchCsv(const std::vector<BenchRun>& runs) {
    std::ostringstream out;
    const std::vector<Setting> keys = runs.empty() ? std::vector<Setting>{} : runs.front().settings;
    for (const auto& [key, value] : keys)
        out << csvField(key) << ",";
    out << "pass,median_ms,q1_ms,q3_ms,min_ms,max_ms,rounds,frames,same_cost_as\n";
    auto row = [&](const BenchRun& run, const std::string& pass, const bench::TimingStats& t, std::size_t frames,
                   const std::string& same) {
        for (const auto& [key, value] : run.settings)
            out << csvField(value) << ",";
        out << csvField(pass) << "," << ms(t.median) << "," << ms(t.q1) << "," << ms(t.q3) << "," << ms(t.min) << ","
            << ms(t.max) << "," << t.rounds << "," << frames << "," << csvField(same) << "\n";
    };
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const BenchRun& run = runs[i];
        std::size_t frames = 0;
        for (std::size_t p = 0; p < run.passes.size(); ++p) {
            row(run, run.passes[p].pass, passStatsOf(run, p), run.passes[p].samples, "");
            frames = std::max(frames, run.passes[p].samples);
        }
        std::string same;
        for (std::size_t j : benchSameCostAs(runs, i))
            same += (same.empty() ? "" : ";") + benchRunLabel(runs[j].settings);
        row(run, "total", totalOf(run), frames, same);
    }
    return out.str();
}

std::string benchMarkdown(const std::vector<BenchRun>& runs, const std::string& command, const std::string& machine,
                          const bench::SweepTimingInfo& timing) {
    std::ostringstream out;
    out << "# lpv bench render\n\n";
    out << "Command: `" << command << "`\n\n";
    out << "Machine: " << machine << "\n\n";
    if (!timing.load.empty())
        out << "Load: " << timing.load << "\n\n";
    if (timing.rounds > 0)
        out << "Timing: " << timing.rounds << (runs.size() > 1 ? " interleaved" : "") << " round"
            << (timing.rounds == 1 ? "" : "s") << (runs.size() > 1 ? " (the settings in order, then in reverse, ...)" : "")
            << "; stopped: " << timing.stopReason << ".\n\n";
    out << "GPU time per pass from timer queries, in ms: each round's median over its frames, then the median over "
           "the rounds ±half their interquartile range. The total is each round's sum of pass medians, with its "
           "quartiles q1-q3 over the rounds.";
    if (runs.size() > 1)
        out << " Settings whose totals differ by less than the noise (their quartiles overlap, or their medians "
               "differ by less than the larger spread, at least "
            << int(std::lround(100.0 * bench::kSameCostFraction)) << "%) are the same cost.";
    out << "\n\n";
    const std::vector<std::string> passes = passNames(runs);
    const std::vector<Setting> keys = runs.empty() ? std::vector<Setting>{} : runs.front().settings;
    const bool compare = runs.size() > 1;
    out << "|";
    for (const auto& [key, value] : keys)
        out << " " << key << " |";
    for (const std::string& p : passes)
        out << " " << p << " |";
    out << " total | q1-q3 | rounds |" << (compare ? " same cost as |" : "") << "\n|";
    for (std::size_t i = 0; i < keys.size(); ++i)
        out << "---|";
    for (std::size_t i = 0; i < passes.size() + 3; ++i)
        out << "---:|";
    out << (compare ? "---|" : "") << "\n";
    for (std::size_t r = 0; r < runs.size(); ++r) {
        const BenchRun& run = runs[r];
        out << "|";
        for (const auto& [key, value] : run.settings)
            out << " " << value << " |";
        for (const std::string& name : passes) {
            const auto it = std::find_if(run.passes.begin(), run.passes.end(),
                                         [&](const renderer::PassTiming& t) { return t.pass == name; });
            if (it == run.passes.end()) {
                out << " - |";
                continue;
            }
            out << " " << withSpread(passStatsOf(run, std::size_t(it - run.passes.begin()))) << " |";
        }
        const bench::TimingStats total = totalOf(run);
        out << " " << withSpread(total) << " | " << ms(total.q1) << "-" << ms(total.q3) << " | " << total.rounds
            << " |";
        if (compare) {
            std::string same;
            for (std::size_t j : benchSameCostAs(runs, r))
                same += (same.empty() ? "" : ", ") + benchRunLabel(runs[j].settings);
            out << " " << (same.empty() ? "none" : same) << " |";
        }
        out << "\n";
    }
    return out.str();
}

std::string benchTable(const BenchRun& run) {
    std::string text;
    char line[256];
    std::snprintf(line, sizeof line, "%-24s %10s %17s %5s %17s %6s %6s\n", "pass", "median ms", "q1-q3", "IQR",
                  "min-max", "rounds", "frames");
    text += line;
    auto row = [&](const std::string& name, const bench::TimingStats& t, std::size_t frames) {
        char iqr[16], quartiles[48], extremes[48];
        std::snprintf(iqr, sizeof iqr, "%.0f%%", 100.0 * t.relativeSpread());
        std::snprintf(quartiles, sizeof quartiles, "%.3f-%.3f", t.q1, t.q3);
        std::snprintf(extremes, sizeof extremes, "%.3f-%.3f", t.min, t.max);
        std::snprintf(line, sizeof line, "%-24s %10.3f %17s %5s %17s %6d %6zu\n", name.c_str(), t.median, quartiles,
                      iqr, extremes, t.rounds, frames);
        text += line;
    };
    std::size_t frames = 0;
    for (std::size_t p = 0; p < run.passes.size(); ++p) {
        row(run.passes[p].pass, passStatsOf(run, p), run.passes[p].samples);
        frames = std::max(frames, run.passes[p].samples);
    }
    row("total", totalOf(run), frames);
    return text;
}

std::string benchComparison(const std::vector<BenchRun>& runs) {
    if (runs.size() < 2)
        return {};
    std::size_t width = 8;
    for (const BenchRun& run : runs)
        width = std::max(width, benchRunLabel(run.settings).size());
    std::string text;
    char line[512];
    std::snprintf(line, sizeof line, "%-*s %18s %5s  %s\n", int(width), "settings", "total ms", "IQR",
                  "same cost within the noise as");
    text += line;
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const bench::TimingStats total = totalOf(runs[i]);
        std::string same;
        for (std::size_t j : benchSameCostAs(runs, i))
            same += (same.empty() ? "" : ", ") + benchRunLabel(runs[j].settings);
        char iqr[16];
        std::snprintf(iqr, sizeof iqr, "%.0f%%", 100.0 * total.relativeSpread());
        // 19 bytes: the "±" takes two.
        std::snprintf(line, sizeof line, "%-*s %19s %5s  %s\n", int(width), benchRunLabel(runs[i].settings).c_str(),
                      withSpread(total).c_str(), iqr, same.empty() ? "none" : same.c_str());
        text += line;
    }
    return text;
}

bool writeReportFiles(const std::vector<std::pair<std::optional<std::string>, std::string>>& reports) {
    for (const auto& [file, text] : reports) {
        if (!file)
            continue;
        if (auto ok = scene::writeFileAtomically(*file, text); !ok) {
            std::cerr << "lpv: " << ok.error().describe() << "\n";
            return false;
        }
        std::printf("wrote %s\n", file->c_str());
    }
    return true;
}

const char* const kRoundOptionsHelp = R"(  --rounds N            Timing rounds at most (default 9; 0: no timing). The
                        settings are timed in interleaved rounds (A B C, then
                        C B A, ...), --frames frames each after one untimed
                        frame; every time is the median over the rounds with
                        its interquartile range, and settings whose times lie
                        within each other's noise are called the same cost
  --time-budget S       Seconds of timing: no round starts that would end
                        past it (default: no budget)
  --spread-target P     Stop after 3 rounds once every setting's interquartile
                        range is within P% of its median (default 10)
)";

void parseRoundOptions(Args& args, bench::RoundPlan& plan) {
    if (const auto rounds = args.optionalInteger("--rounds", {0})) {
        plan.maxRounds = *rounds;
        plan.minRounds = std::min(plan.minRounds, *rounds);
    }
    if (const auto budget = args.optionalReal("--time-budget", RealRange::above(0.0)))
        plan.timeBudgetSeconds = *budget;
    if (const auto target = args.optionalReal("--spread-target", RealRange::above(0.0)))
        plan.spreadTarget = *target / 100.0;
}

double median(std::vector<double> values) {
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

} // namespace lpv::cli
