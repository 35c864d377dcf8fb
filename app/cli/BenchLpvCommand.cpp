// `lpv bench lpv`: the thesis' LPV measurements on the same axes. (1) RSM
// rendering and injection time against the RSM tile size; (2) propagation
// time against the number of steps, for each of the four variants, with
// geometry-volume occlusion off and on; then which variant is fastest where.
// Figures are printed and written as Markdown / CSV, never asserted.
#include "BenchReport.h"
#include "Cli.h"
#include "RenderSetup.h"

#include "lpv/scene/Project.h"

#include <charconv>
#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>

namespace lpv::cli {

namespace {

constexpr const char* kVariants[] = {"computeGather", "computeScatter", "rasterGather", "rasterScatter"};

std::optional<std::vector<int>> parseList(const std::string& text, int minimum, int maximum) {
    std::vector<int> values;
    std::istringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        int v = 0;
        auto [ptr, ec] = std::from_chars(item.data(), item.data() + item.size(), v);
        if (ec != std::errc() || ptr != item.data() + item.size() || v < minimum || v > maximum)
            return std::nullopt;
        values.push_back(v);
    }
    if (values.empty())
        return std::nullopt;
    return values;
}


const renderer::PassTiming* findPass(const std::vector<renderer::PassTiming>& table, const std::string& pass) {
    for (const auto& row : table)
        if (row.pass == pass && row.samples > 0)
            return &row;
    return nullptr;
}

std::string cell(const renderer::PassTiming* t) {
    if (!t)
        return "-";
    char text[96];
    std::snprintf(text, sizeof text, "%.2f (%.2f-%.2f)", t->medianMs, t->minMs, t->maxMs);
    return text;
}

struct Measured {
    std::map<std::string, std::string> settings;
    std::vector<renderer::PassTiming> passes;
};

} // namespace

void printBenchLpvHelp() {
    std::cout << R"(bench lpv PROJECT [--width N --height N --frames N --warmup N --camera NAME
                   --tiles LIST --steps LIST --set KEY=VALUE --csv FILE --markdown FILE]

The thesis' LPV measurements, on its axes and by default at its settings
(1024x600, 4 cascades of 32^3, RSM tiles of 128^2, 8 propagation steps):
  1. RSM rendering ("rsm") and injection ("lpvInjection", "geometryVolume") against the
     RSM tile size, --tiles (default 32,64,128,256,512,1024);
  2. propagation ("lpvPropagation") against the step count, --steps (default
     1,2,4,8,16,32,64), for each of the four lpv.variant values, with
     lpv.occlusion off and on; also per step and volume;
  3. the fastest variant for each step count and occlusion setting.
Each setting gets --warmup frames (default 2, not counted) and --frames frames
(default 5): median (min-max) GPU ms from timer queries. --markdown writes the
tables headed by the command and the machine; --csv one row per measurement.
)";
}

int benchLpv(Args args) {
    RenderRequest request;
    request.cameraName = args.option("--camera");
    request.sets = args.options("--set");
    const auto csvFile = args.option("--csv");
    const auto markdownFile = args.option("--markdown");
    const auto width = parseCount(args.option("--width").value_or("1024"), 1);
    const auto height = parseCount(args.option("--height").value_or("600"), 1);
    const auto frames = parseCount(args.option("--frames").value_or("5"), 1);
    const auto warmup = parseCount(args.option("--warmup").value_or("2"), 0);
    const auto tiles = parseList(args.option("--tiles").value_or("32,64,128,256,512,1024"), 32, 1024);
    const auto steps = parseList(args.option("--steps").value_or("1,2,4,8,16,32,64"), 0, 64);
    if (!args.missingValue().empty())
        return usageError(args.missingValue() + " needs a value", "bench");
    if (auto unknown = args.unknownOption())
        return usageError("unknown option '" + *unknown + "'", "bench");
    auto pos = args.positionals();
    pos.erase(pos.begin()); // "lpv"
    if (pos.size() != 1)
        return usageError("bench lpv expects exactly one project file", "bench");
    if (!width || !height || !frames || !warmup)
        return usageError("--width, --height and --frames must be positive integers, --warmup zero or more", "bench");
    if (!tiles || !steps)
        return usageError("--tiles takes sizes 32..1024 and --steps counts 0..64, comma-separated", "bench");
    // A benchmark measures the LPV being computed: no reuse of the last frame's
    // volumes (a later --set lpv.reuse=true wins).
    request.sets.insert(request.sets.begin(), "lpv.reuse=false");
    request.projectFile = pos.front();
    int exitCode = kOk;
    auto setup = prepareRender(request, "bench", exitCode);
    if (!setup)
        return exitCode;
    const scene::ParameterSet base = setup->project.parameters;
    const int cascades = std::min(base.getInt("lpv.cascades"), base.getInt("rsm.cascades"));

    // One measurement: the base settings with `settings` on top.
    auto measure = [&](const std::map<std::string, std::string>& settings) -> std::optional<Measured> {
        setup->project.parameters = base;
        std::string label;
        for (const auto& [key, value] : settings) {
            if (auto ok = setup->project.parameters.setFromText(key, value, "bench lpv"); !ok) {
                std::cerr << "lpv: " << ok.error().describe() << "\n";
                return std::nullopt;
            }
            label += " " + key + "=" + value;
        }
        if (*warmup > 0 && !renderFrames(*setup, *width, *height, *warmup))
            return std::nullopt;
        setup->renderer->timer().clearHistory();
        if (!renderFrames(*setup, *width, *height, *frames))
            return std::nullopt;
        Measured m{settings, setup->renderer->timer().table()};
        std::printf("%-70s rsm %-24s lpvInjection %-24s lpvPropagation %s\n", label.c_str(),
                    cell(findPass(m.passes, "rsm")).c_str(), cell(findPass(m.passes, "lpvInjection")).c_str(),
                    cell(findPass(m.passes, "lpvPropagation")).c_str());
        std::fflush(stdout);
        return m;
    };

    std::printf("%s\n", setup->context->info().renderer.c_str());
    std::vector<Measured> tileRuns, stepRuns;
    std::printf("\n1. RSM and injection against the RSM tile size (%d cascades)\n", cascades);
    for (int tile : *tiles) {
        auto m = measure({{"rsm.tileSize", std::to_string(tile)}});
        if (!m)
            return kFailure;
        tileRuns.push_back(std::move(*m));
    }
    std::printf("\n2. Propagation against the step count, per variant, occlusion off and on\n");
    for (const char* occlusion : {"false", "true"})
        for (const char* variant : kVariants)
            for (int s : *steps) {
                auto m = measure({{"lpv.propagationSteps", std::to_string(s)},
                                  {"lpv.variant", variant},
                                  {"lpv.occlusion", occlusion}});
                if (!m)
                    return kFailure;
                stepRuns.push_back(std::move(*m));
            }

    // The report.
    const renderer::GlInfo& gl = setup->context->info();
    std::string command = "lpv bench lpv " + request.projectFile + " --width " + std::to_string(*width) +
                          " --height " + std::to_string(*height) + " --frames " + std::to_string(*frames) +
                          " --warmup " + std::to_string(*warmup);
    for (const std::string& kv : request.sets)
        command += " --set " + kv;
    std::ostringstream md, csv;
    md << "Command: `" << command << "`\n\nMachine: " << describeMachine(gl.renderer, gl.version) << "\n\n"
       << "GPU ms, median (min-max) over " << *frames << " frames after " << *warmup << " warm-up frames; "
       << cascades << " cascades of " << base.getInt("lpv.gridSize") << "^3.\n\n";
    md << "### RSM and injection against the RSM tile size\n\n| tile | rsm | lpvInjection | geometryVolume |\n|---|---|---|---|\n";
    csv << "table,rsm.tileSize,lpv.variant,lpv.occlusion,lpv.propagationSteps,pass,median_ms,min_ms,max_ms,frames\n";
    auto csvRow = [&](const char* table, const Measured& m, const std::string& tile) {
        auto get = [&](const char* key, const std::string& fallback) {
            auto it = m.settings.find(key);
            return it == m.settings.end() ? fallback : it->second;
        };
        for (const auto& t : m.passes)
            if (t.samples > 0)
                csv << table << "," << tile << "," << get("lpv.variant", base.getEnum("lpv.variant")) << ","
                    << get("lpv.occlusion", base.getBool("lpv.occlusion") ? "true" : "false") << ","
                    << get("lpv.propagationSteps", std::to_string(base.getInt("lpv.propagationSteps"))) << ","
                    << t.pass << "," << t.medianMs << "," << t.minMs << "," << t.maxMs << "," << t.samples << "\n";
    };
    for (const Measured& m : tileRuns) {
        const std::string tile = m.settings.at("rsm.tileSize");
        md << "| " << tile << "^2 | " << cell(findPass(m.passes, "rsm")) << " | "
           << cell(findPass(m.passes, "lpvInjection")) << " | " << cell(findPass(m.passes, "geometryVolume")) << " |\n";
        csvRow("tiles", m, tile);
    }
    md << "\n### Propagation against the step count\n\nPer step and volume: the median divided by steps x "
       << cascades << " cascades.\n\n| occlusion | variant | steps | lpvPropagation | per step and volume |\n"
       << "|---|---|---|---|---|\n";
    // fastest[(occlusion, steps)] = (median, variant)
    std::map<std::pair<std::string, int>, std::pair<double, std::string>> fastest;
    for (const Measured& m : stepRuns) {
        const renderer::PassTiming* t = findPass(m.passes, "lpvPropagation");
        const int s = std::stoi(m.settings.at("lpv.propagationSteps"));
        const std::string& occlusion = m.settings.at("lpv.occlusion");
        const std::string& variant = m.settings.at("lpv.variant");
        char perStep[32] = "-";
        if (t && s > 0)
            std::snprintf(perStep, sizeof perStep, "%.2f", t->medianMs / double(s * cascades));
        md << "| " << (occlusion == "true" ? "on" : "off") << " | " << variant << " | " << s << " | " << cell(t)
           << " | " << perStep << " |\n";
        csvRow("steps", m, std::to_string(base.getInt("rsm.tileSize")));
        if (t) {
            auto& best = fastest[{occlusion, s}];
            if (best.second.empty() || t->medianMs < best.first)
                best = {t->medianMs, variant};
        }
    }
    md << "\n### Fastest variant\n\n| occlusion | steps | fastest | median ms |\n|---|---|---|---|\n";
    std::printf("\nFastest variant:\n");
    for (const auto& [key, best] : fastest) {
        md << "| " << (key.first == "true" ? "on" : "off") << " | " << key.second << " | " << best.second << " | "
           << best.first << " |\n";
        std::printf("  occlusion %-5s %2d steps: %s (%.2f ms)\n", key.first.c_str(), key.second, best.second.c_str(),
                    best.first);
    }
    if (!writeReportFiles({{csvFile, csv.str()}, {markdownFile, md.str()}}))
        return kFailure;
    return kOk;
}

} // namespace lpv::cli
