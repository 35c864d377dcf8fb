#include "BenchReport.h"
#include "Cli.h"


#include "lpv/bench/SweepOutput.h"
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

std::string csvField(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos)
        return s;
    std::string out = "\"";
    for (char c : s)
        out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

} // namespace

std::string benchCsv(const std::vector<BenchRun>& runs) {
    std::ostringstream out;
    const std::vector<Setting> keys = runs.empty() ? std::vector<Setting>{} : runs.front().settings;
    for (const auto& [key, value] : keys)
        out << csvField(key) << ",";
    out << "pass,median_ms,min_ms,max_ms,frames\n";
    for (const BenchRun& run : runs)
        for (const auto& p : run.passes) {
            for (const auto& [key, value] : run.settings)
                out << csvField(value) << ",";
            out << csvField(p.pass) << "," << ms(p.medianMs) << "," << ms(p.minMs) << "," << ms(p.maxMs) << ","
                << p.samples << "\n";
        }
    return out.str();
}

std::string benchMarkdown(const std::vector<BenchRun>& runs, const std::string& command, const std::string& machine) {
    std::ostringstream out;
    out << "# lpv bench render\n\n";
    out << "Command: `" << command << "`\n\n";
    out << "Machine: " << machine << "\n\n";
    out << "GPU time per pass from timer queries, median (min-max) in ms over the measured frames.\n\n";
    const std::vector<std::string> passes = passNames(runs);
    const std::vector<Setting> keys = runs.empty() ? std::vector<Setting>{} : runs.front().settings;
    out << "|";
    for (const auto& [key, value] : keys)
        out << " " << key << " |";
    for (const std::string& p : passes)
        out << " " << p << " |";
    out << " total |\n|";
    for (std::size_t i = 0; i < keys.size(); ++i)
        out << "---|";
    for (std::size_t i = 0; i <= passes.size(); ++i)
        out << "---:|";
    out << "\n";
    for (const BenchRun& run : runs) {
        out << "|";
        for (const auto& [key, value] : run.settings)
            out << " " << value << " |";
        double total = 0.0;
        for (const std::string& name : passes) {
            const auto it = std::find_if(run.passes.begin(), run.passes.end(),
                                         [&](const renderer::PassTiming& t) { return t.pass == name; });
            if (it == run.passes.end()) {
                out << " - |";
                continue;
            }
            total += it->medianMs;
            out << " " << ms(it->medianMs) << " (" << ms(it->minMs) << "-" << ms(it->maxMs) << ") |";
        }
        out << " " << ms(total) << " |\n";
    }
    return out.str();
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

bool writeSweepFiles(const std::filesystem::path& outDir, const std::vector<SweepRun>& runs, int width, int height,
                     const std::string& command, const std::string& machine, const reference::ReferenceImage& ref,
                     const std::string& note, const bench::SweepTimingInfo& timing) {
    auto written = bench::writeSweepOutputs(outDir, runs, width, height, command, machine, ref, note, timing);
    if (!written) {
        std::cerr << "lpv: " << written.error().describe() << "\n";
        return false;
    }
    for (const auto& file : *written)
        std::printf("wrote %s\n", file.string().c_str());
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

std::string parseRoundOptions(Args& args, bench::RoundPlan& plan) {
    const auto rounds = args.option("--rounds");
    const auto budget = args.option("--time-budget");
    const auto target = args.option("--spread-target");
    if (rounds) {
        const auto n = parseCount(*rounds, 0);
        if (!n)
            return "--rounds must be a whole number, 0 or more";
        plan.maxRounds = *n;
        plan.minRounds = std::min(plan.minRounds, *n);
    }
    auto positive = [](const std::string& text) -> std::optional<double> {
        double v = 0.0;
        auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v) || v <= 0.0)
            return std::nullopt;
        return v;
    };
    if (budget) {
        const auto v = positive(*budget);
        if (!v)
            return "--time-budget must be a positive number of seconds";
        plan.timeBudgetSeconds = *v;
    }
    if (target) {
        const auto v = positive(*target);
        if (!v)
            return "--spread-target must be a positive percentage";
        plan.spreadTarget = *v / 100.0;
    }
    return {};
}

std::string roundOptionsText(const bench::RoundPlan& plan) {
    char buf[128];
    std::snprintf(buf, sizeof buf, " --rounds %d --spread-target %g", plan.maxRounds, 100.0 * plan.spreadTarget);
    std::string text = buf;
    if (plan.timeBudgetSeconds > 0.0) {
        std::snprintf(buf, sizeof buf, " --time-budget %g", plan.timeBudgetSeconds);
        text += buf;
    }
    return text;
}

std::optional<int> parseCount(const std::string& text, int minimum) {
    int v = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || ptr != text.data() + text.size() || v < minimum)
        return std::nullopt;
    return v;
}

double median(std::vector<double> values) {
    if (values.empty())
        return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::optional<float> parseDegrees(const std::string& text) {
    float v = 0.0f;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v))
        return std::nullopt;
    return v;
}

} // namespace lpv::cli
