// `lpv bench lpv`: the thesis' LPV measurements on the same axes. (1) RSM
// rendering and injection time against the RSM tile size; (2) propagation
// time against the number of steps, for each of the four variants, with
// geometry-volume occlusion off and on; then which variant is fastest where.
// Every setting of the tables is timed in the same interleaved rounds (issue
// #43): each figure a median with its spread, and settings within each
// other's noise named as the same cost. Figures are printed and written as
// Markdown / CSV, never asserted.
#include "BenchReport.h"
#include "Cli.h"
#include "RenderSetup.h"

#include "lpv/scene/Project.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

namespace lpv::cli {

namespace {

constexpr const char* kVariants[] = {"computeGather", "computeScatter", "rasterGather", "rasterScatter"};

// One setting of the tables, timed over the rounds.
struct Measured {
    std::map<std::string, std::string> settings;
    std::vector<renderer::PassTiming> passes;   // medians over the rounds (bench::SettingTiming)
    std::vector<bench::TimingStats> passStats;  // in the order of `passes`
    std::vector<std::vector<renderer::PassTiming>> rounds; // each round's table
};

const bench::TimingStats* findPass(const Measured& m, const std::string& pass) {
    for (std::size_t i = 0; i < m.passes.size() && i < m.passStats.size(); ++i)
        if (m.passes[i].pass == pass && m.passes[i].samples > 0)
            return &m.passStats[i];
    return nullptr;
}

// "2.31 ±0.05 (2.20-2.45)": the median over the rounds, half the interquartile range, the extremes.
std::string cell(const bench::TimingStats* t) {
    if (!t)
        return "-";
    char text[96];
    std::snprintf(text, sizeof text, "%.2f ±%.2f (%.2f-%.2f)", t->median, 0.5 * t->spread(), t->min, t->max);
    return text;
}

// The passes in `passes` summed per round, over the rounds: what a setting
// costs in a group of passes, with its own spread.
bench::TimingStats sumOfPasses(const Measured& m, const std::set<std::string>& passes) {
    std::vector<double> sums;
    for (const auto& table : m.rounds) {
        double sum = 0.0;
        for (const renderer::PassTiming& t : table)
            if (t.samples > 0 && passes.contains(t.pass))
                sum += t.medianMs;
        sums.push_back(sum);
    }
    return bench::timingStatsOf(std::move(sums));
}

std::string joined(const std::vector<std::string>& items) {
    std::string text;
    for (const std::string& item : items)
        text += (text.empty() ? "" : ", ") + item;
    return text.empty() ? "none" : text;
}

} // namespace

void printBenchLpvHelp() {
    std::cout << R"(bench lpv PROJECT [--width N --height N --frames N --warmup N --camera NAME
                   --tiles LIST --steps LIST --set KEY=VALUE --csv FILE --markdown FILE
                   --rounds N --time-budget S --spread-target P]

The thesis' LPV measurements, on its axes and by default at its settings
(1024x600, 4 cascades of 32^3, RSM tiles of 128^2, 8 propagation steps):
  1. RSM rendering ("rsm") and injection ("lpvInjection", "geometryVolume") against the
     RSM tile size, --tiles (default 32,64,128,256,512,1024);
  2. propagation ("lpvPropagation") against the step count, --steps (default
     1,2,4,8,16,32,64), for each of the four lpv.variant values, with
     lpv.occlusion off and on; also per step and volume;
  3. the fastest variant for each step count and occlusion setting.
Each setting gets --warmup frames first (default 2, not counted); then all
settings of the tables are timed in interleaved rounds (in order, then in
reverse, ...), each round one untimed frame after the switch and --frames
timed frames (default 5). A pass's sample in a round is its median over
that round's frames; each figure is the median over the rounds ±half the
interquartile range (min-max). Settings within each other's noise are
named as the same cost: RSM tile sizes by rsm + injection, variants by
propagation at the same steps and occlusion, beside the fastest variant.
--markdown writes the tables headed by the command, the machine, its load
before -> after and why the rounds stopped; --csv one row per measurement
with median, q1, q3, min, max, rounds and frames. Round options:
)" << kRoundOptionsHelp
              << "  (bench lpv only times: --rounds at least 1)\n\n";
}

int benchLpv(Args args) {
    RenderRequest request = renderRequestOptions(args);
    const auto csvFile = args.option("--csv");
    const auto markdownFile = args.option("--markdown");
    const int width = args.integer("--width", 1024, {1});
    const int height = args.integer("--height", 600, {1});
    const int frames = args.integer("--frames", 5, {1});
    const int warmup = args.integer("--warmup", 2, {0});
    const std::vector<int> tiles = args.integerList("--tiles", {32, 1024}).value_or(std::vector{32, 64, 128, 256, 512, 1024});
    const std::vector<int> steps = args.integerList("--steps", {0, 64}).value_or(std::vector{1, 2, 4, 8, 16, 32, 64});
    bench::RoundPlan roundPlan;
    parseRoundOptions(args, roundPlan);
    const auto pos = args.expectPositionals(1, "bench lpv expects exactly one project file", 1); // after "lpv"
    if (pos.empty())
        return usageError(*args.error(), "bench");
    if (roundPlan.maxRounds < 1)
        return usageError("bench lpv times in rounds: --rounds must be 1 or more", "bench");
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

    // Every setting of both tables, timed against each other in the same rounds.
    std::vector<Measured> measured;
    for (int tile : tiles)
        measured.push_back({{{"rsm.tileSize", std::to_string(tile)}}, {}, {}, {}});
    const std::size_t tileCount = measured.size();
    for (const char* occlusion : {"false", "true"})
        for (const char* variant : kVariants)
            for (int s : steps)
                measured.push_back({{{"lpv.propagationSteps", std::to_string(s)},
                                     {"lpv.variant", variant},
                                     {"lpv.occlusion", occlusion}},
                                    {},
                                    {},
                                    {}});
    auto apply = [&](const Measured& m) {
        setup->project.parameters = base;
        for (const auto& [key, value] : m.settings)
            if (auto ok = setup->project.parameters.setFromText(key, value, "bench lpv"); !ok) {
                std::cerr << "lpv: " << ok.error().describe() << "\n";
                return false;
            }
        return true;
    };
    auto labelOf = [](const Measured& m) {
        std::string label;
        for (const auto& [key, value] : m.settings)
            label += " " + key + "=" + value;
        return label;
    };

    std::printf("%s\n", setup->context->info().renderer.c_str());
    const std::string loadBefore = bench::describeLoad();
    std::printf("warming up %zu settings (%d frames each)\n", measured.size(), std::max(warmup, 1));
    std::fflush(stdout);
    for (const Measured& m : measured)
        if (!apply(m) || !renderFrames(*setup, width, height, std::max(warmup, 1)))
            return kFailure;

    // The rounds (bench/Timing.h): one untimed frame after each switch (the
    // geometry volume reads the previous frame), then --frames timed ones.
    bool failed = false;
    bench::RoundCallbacks callbacks;
    callbacks.progress = [&](int round, int position, int) {
        if (position == 0) {
            std::printf("timing round %d: %zu settings\n", round + 1, measured.size());
            std::fflush(stdout);
        }
        return true;
    };
    callbacks.timeOnce = [&](int index) -> scene::Expected<std::vector<renderer::PassTiming>> {
        Measured& m = measured[std::size_t(index)];
        // apply and renderFrames print why they failed; the error only stops the rounds.
        auto stop = [&] {
            failed = true;
            return scene::makeError(scene::ErrorCode::InvalidValue, request.projectFile, "", "a frame failed");
        };
        if (!apply(m) || !renderFrames(*setup, width, height, 1))
            return stop();
        setup->renderer->timer().clearHistory();
        if (!renderFrames(*setup, width, height, frames))
            return stop();
        m.rounds.push_back(setup->renderer->timer().table());
        return m.rounds.back();
    };
    auto timed = bench::timeInRounds(int(measured.size()), roundPlan, callbacks);
    if (!timed) {
        if (!failed)
            std::cerr << "lpv: " << timed.error().describe() << "\n";
        return kFailure;
    }
    const std::string load = loadBefore + " -> " + bench::describeLoad();
    for (std::size_t i = 0; i < measured.size(); ++i) {
        measured[i].passes = std::move(timed->settings[i].passes);
        measured[i].passStats = std::move(timed->settings[i].passStats);
    }
    std::printf("timed in %d interleaved round%s (%s); %s\n", timed->rounds, timed->rounds == 1 ? "" : "s",
                timed->stopReason.c_str(), load.c_str());
    auto printRow = [&](const Measured& m) {
        std::printf("%-70s rsm %-26s lpvInjection %-26s lpvPropagation %s\n", labelOf(m).c_str(),
                    cell(findPass(m, "rsm")).c_str(), cell(findPass(m, "lpvInjection")).c_str(),
                    cell(findPass(m, "lpvPropagation")).c_str());
    };
    std::printf("\n1. RSM and injection against the RSM tile size (%d cascades)\n", cascades);
    for (std::size_t i = 0; i < tileCount; ++i)
        printRow(measured[i]);
    std::printf("\n2. Propagation against the step count, per variant, occlusion off and on\n");
    for (std::size_t i = tileCount; i < measured.size(); ++i)
        printRow(measured[i]);

    // The report.
    const renderer::GlInfo& gl = setup->context->info();
    std::string command = "lpv bench lpv " + request.projectFile + " --width " + std::to_string(width) +
                          " --height " + std::to_string(height) + " --frames " + std::to_string(frames) +
                          " --warmup " + std::to_string(warmup) + roundOptionsText(roundPlan);
    for (const std::string& kv : request.sets)
        command += " --set " + kv;
    std::ostringstream md, csv;
    md << "Command: `" << command << "`\n\nMachine: " << describeMachine(gl.renderer, gl.version) << "\n\n"
       << "Load: " << load << "\n\n"
       << "Timing: " << timed->rounds << " interleaved round" << (timed->rounds == 1 ? "" : "s")
       << " of all the settings below (in order, then in reverse, ...); stopped: " << timed->stopReason << ".\n\n"
       << "GPU ms from timer queries: each round's median over " << frames << " frames (after one untimed frame; "
       << warmup << " warm-up frames per setting before the rounds), then the median over the rounds ±half the "
       << "interquartile range (min-max); " << cascades << " cascades of " << base.getInt("lpv.gridSize")
       << "^3. Settings whose times differ by less than the noise (quartiles overlapping, or medians closer than "
       << "the larger spread, at least " << int(std::lround(100.0 * bench::kSameCostFraction))
       << "%) are the same cost.\n\n";
    md << "### RSM and injection against the RSM tile size\n\n"
       << "rsm + injection: rsm, lpvInjection and geometryVolume summed in each round.\n\n"
       << "| tile | rsm | lpvInjection | geometryVolume | rsm + injection | same cost as |\n"
       << "|---|---|---|---|---|---|\n";
    csv << "table,rsm.tileSize,lpv.variant,lpv.occlusion,lpv.propagationSteps,pass,median_ms,q1_ms,q3_ms,min_ms,"
           "max_ms,rounds,frames\n";
    auto csvRow = [&](const char* table, const Measured& m, const std::string& tile) {
        auto get = [&](const char* key, const std::string& fallback) {
            auto it = m.settings.find(key);
            return it == m.settings.end() ? fallback : it->second;
        };
        for (std::size_t i = 0; i < m.passes.size() && i < m.passStats.size(); ++i) {
            const renderer::PassTiming& t = m.passes[i];
            const bench::TimingStats& st = m.passStats[i];
            if (t.samples > 0)
                csv << table << "," << tile << "," << get("lpv.variant", base.getEnum("lpv.variant")) << ","
                    << get("lpv.occlusion", base.getBool("lpv.occlusion") ? "true" : "false") << ","
                    << get("lpv.propagationSteps", std::to_string(base.getInt("lpv.propagationSteps"))) << ","
                    << t.pass << "," << st.median << "," << st.q1 << "," << st.q3 << "," << st.min << "," << st.max
                    << "," << st.rounds << "," << t.samples << "\n";
        }
    };
    const std::set<std::string> rsmAndInjection = {"rsm", "lpvInjection", "geometryVolume"};
    std::vector<bench::TimingStats> tileSums;
    for (std::size_t i = 0; i < tileCount; ++i)
        tileSums.push_back(sumOfPasses(measured[i], rsmAndInjection));
    for (std::size_t i = 0; i < tileCount; ++i) {
        const Measured& m = measured[i];
        const std::string tile = m.settings.at("rsm.tileSize");
        std::vector<std::string> same;
        for (std::size_t j = 0; j < tileCount; ++j)
            if (j != i && bench::sameCost(tileSums[i], tileSums[j]))
                same.push_back(measured[j].settings.at("rsm.tileSize") + "^2");
        md << "| " << tile << "^2 | " << cell(findPass(m, "rsm")) << " | " << cell(findPass(m, "lpvInjection"))
           << " | " << cell(findPass(m, "geometryVolume")) << " | " << cell(&tileSums[i]) << " | " << joined(same)
           << " |\n";
        csvRow("tiles", m, tile);
    }
    md << "\n### Propagation against the step count\n\nPer step and volume: the median divided by steps x "
       << cascades << " cascades. Same cost as: the other variants at the same steps and occlusion whose "
       << "lpvPropagation is within the noise.\n\n"
       << "| occlusion | variant | steps | lpvPropagation | per step and volume | same cost as |\n"
       << "|---|---|---|---|---|---|\n";
    // The step table's settings with the same occlusion and steps as `m` (the four variants).
    auto peers = [&](const Measured& m) {
        std::vector<const Measured*> out;
        for (std::size_t j = tileCount; j < measured.size(); ++j)
            if (measured[j].settings.at("lpv.occlusion") == m.settings.at("lpv.occlusion") &&
                measured[j].settings.at("lpv.propagationSteps") == m.settings.at("lpv.propagationSteps"))
                out.push_back(&measured[j]);
        return out;
    };
    // fastest[(occlusion, steps)]: the variant with the lowest median propagation
    std::map<std::pair<std::string, int>, const Measured*> fastest;
    for (std::size_t i = tileCount; i < measured.size(); ++i) {
        const Measured& m = measured[i];
        const bench::TimingStats* t = findPass(m, "lpvPropagation");
        const int s = parseInteger(m.settings.at("lpv.propagationSteps")).value_or(0); // written from --steps
        const std::string& occlusion = m.settings.at("lpv.occlusion");
        const std::string& variant = m.settings.at("lpv.variant");
        char perStep[32] = "-";
        if (t && s > 0)
            std::snprintf(perStep, sizeof perStep, "%.2f", t->median / double(s * cascades));
        std::vector<std::string> same;
        for (const Measured* other : peers(m)) {
            const bench::TimingStats* o = findPass(*other, "lpvPropagation");
            if (other != &m && t && o && bench::sameCost(*t, *o))
                same.push_back(other->settings.at("lpv.variant"));
        }
        md << "| " << (occlusion == "true" ? "on" : "off") << " | " << variant << " | " << s << " | " << cell(t)
           << " | " << perStep << " | " << joined(same) << " |\n";
        csvRow("steps", m, std::to_string(base.getInt("rsm.tileSize")));
        if (t) {
            const Measured*& best = fastest[{occlusion, s}];
            if (!best || t->median < findPass(*best, "lpvPropagation")->median)
                best = &m;
        }
    }
    md << "\n### Fastest variant\n\n| occlusion | steps | fastest | median ms | same cost within the noise |\n"
       << "|---|---|---|---|---|\n";
    std::printf("\nFastest variant (and those of the same cost within the noise):\n");
    for (const auto& [key, best] : fastest) {
        const bench::TimingStats& t = *findPass(*best, "lpvPropagation");
        std::vector<std::string> same;
        for (const Measured* other : peers(*best)) {
            const bench::TimingStats* o = findPass(*other, "lpvPropagation");
            if (other != best && o && bench::sameCost(t, *o))
                same.push_back(other->settings.at("lpv.variant"));
        }
        const std::string& variant = best->settings.at("lpv.variant");
        md << "| " << (key.first == "true" ? "on" : "off") << " | " << key.second << " | " << variant << " | "
           << cell(&t) << " | " << joined(same) << " |\n";
        std::printf("  occlusion %-5s %2d steps: %s (%s ms); same cost: %s\n", key.first.c_str(), key.second,
                    variant.c_str(), cell(&t).c_str(), joined(same).c_str());
    }
    if (!writeReportFiles({{csvFile, csv.str()}, {markdownFile, md.str()}}))
        return kFailure;
    return kOk;
}

} // namespace lpv::cli
