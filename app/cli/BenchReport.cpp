#include "BenchReport.h"


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
                     const std::string& note) {
    auto written = bench::writeSweepOutputs(outDir, runs, width, height, command, machine, ref, note);
    if (!written) {
        std::cerr << "lpv: " << written.error().describe() << "\n";
        return false;
    }
    for (const auto& file : *written)
        std::printf("wrote %s\n", file.string().c_str());
    return true;
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
