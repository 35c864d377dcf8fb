#include "lpv/bench/SharedTiming.h"

#include "lpv/bench/SavedSweep.h"
#include "lpv/bench/SweepRunJson.h"
#include "lpv/scene/Project.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace lpv::bench {

using Json = nlohmann::json;

namespace {

scene::ParameterSet parametersOf(const std::vector<Setting>& settings) {
    scene::ParameterSet p;
    for (const auto& [key, value] : settings)
        (void)p.setFromText(key, value, "timing");
    return p;
}

} // namespace

scene::Expected<void> saveSharedTiming(const SharedTiming& t, const std::filesystem::path& file) {
    Json entries = Json::array();
    for (const SharedTiming::Entry& e : t.entries) {
        Json parameters = Json::array();
        for (const auto& [key, value] : e.parameters)
            parameters.push_back({key, value});
        Json run = sweepRunToJson(e.run);
        entries.push_back({{"parameters", parameters}, {"run", run}});
    }
    const Json j{{"format", "lpvstudio-timing"}, {"version", 1},          {"command", t.command},
                 {"machine", t.machine},         {"load", t.load},        {"rounds", t.rounds},
                 {"stopReason", t.stopReason},   {"entries", entries}};
    return scene::writeFileAtomically(file, j.dump(2) + "\n");
}

scene::Expected<SharedTiming> loadSharedTiming(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in)
        return scene::makeError(scene::ErrorCode::FileNotFound, file.string(), "", "cannot open the timing file");
    const Json j = Json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.is_object() || j.value("format", "") != "lpvstudio-timing")
        return scene::makeError(scene::ErrorCode::UnknownFormat, file.string(), "",
                                "not a timing file of `lpv bench report` (format lpvstudio-timing)");
    SharedTiming t;
    try {
        t.command = j.at("command").get<std::string>();
        t.machine = j.at("machine").get<std::string>();
        t.load = j.at("load").get<std::string>();
        t.rounds = j.at("rounds").get<int>();
        t.stopReason = j.at("stopReason").get<std::string>();
        for (const Json& e : j.at("entries")) {
            SharedTiming::Entry entry;
            for (const Json& kv : e.at("parameters"))
                entry.parameters.emplace_back(kv.at(0).get<std::string>(), kv.at(1).get<std::string>());
            entry.run = sweepRunFromJson(e.at("run"));
            t.entries.push_back(std::move(entry));
        }
    } catch (const std::exception& e) {
        return scene::makeError(scene::ErrorCode::MissingField, file.string(), "", e.what());
    }
    return t;
}

const SharedTiming::Entry* findTiming(const SharedTiming& timing, const scene::ParameterSet& parameters) {
    for (const SharedTiming::Entry& e : timing.entries)
        if (sameValues(parametersOf(e.parameters), parameters))
            return &e;
    return nullptr;
}

scene::Expected<void> applySharedTiming(const SharedTiming& timing, const scene::ParameterSet& base,
                                        std::vector<SweepRun>& runs) {
    for (SweepRun& run : runs) {
        scene::ParameterSet p = base;
        for (const auto& [key, value] : run.settings)
            (void)p.setFromText(key, value, "sweep");
        const SharedTiming::Entry* e = findTiming(timing, p);
        if (!e)
            return scene::makeError(scene::ErrorCode::InvalidValue, "", "timing",
                                    "no time was measured for " + sweepLabel(run.settings) +
                                        " (time the scene's settings again: `lpv bench report` without --resume)");
        run.passes = e->run.passes;
        run.passStats = e->run.passStats;
        run.total = e->run.total;
        run.totalMs = e->run.totalMs;
        run.gpuBytes = e->run.gpuBytes;
        run.lpvBytes = e->run.lpvBytes;
    }
    return {};
}

namespace {

std::vector<double> averageRanks(const std::vector<double>& v) {
    std::vector<std::size_t> order(v.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::ranges::sort(order, [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
    std::vector<double> ranks(v.size());
    for (std::size_t i = 0; i < order.size();) {
        std::size_t j = i;
        while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]])
            ++j;
        for (std::size_t k = i; k <= j; ++k)
            ranks[order[k]] = 0.5 * double(i + j) + 1.0;
        i = j + 1;
    }
    return ranks;
}

} // namespace

bool rankingAgrees(const TimingAgreement& g) {
    return g.settings > 0 && g.distinctSpearman >= 0.95 && g.discordantPairs == 0;
}

double spearman(const std::vector<double>& x, const std::vector<double>& y) {
    const std::size_t n = std::min(x.size(), y.size());
    if (n < 2)
        return 1.0;
    const std::vector<double> rx = averageRanks(x), ry = averageRanks(y);
    double mx = 0.0, my = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        mx += rx[i];
        my += ry[i];
    }
    mx /= double(n);
    my /= double(n);
    double sxy = 0.0, sxx = 0.0, syy = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        sxy += (rx[i] - mx) * (ry[i] - my);
        sxx += (rx[i] - mx) * (rx[i] - mx);
        syy += (ry[i] - my) * (ry[i] - my);
    }
    return sxx > 0.0 && syy > 0.0 ? sxy / std::sqrt(sxx * syy) : 1.0;
}

TimingAgreement compareTimings(const SharedTiming& a, const SharedTiming& b) {
    TimingAgreement out;
    std::vector<const SweepRun*> first, second;
    for (const SharedTiming::Entry& e : a.entries)
        if (const SharedTiming::Entry* other = findTiming(b, parametersOf(e.parameters))) {
            first.push_back(&e.run);
            second.push_back(&other->run);
        }
    out.settings = int(first.size());
    std::vector<double> x, y, spreads;
    for (std::size_t i = 0; i < first.size(); ++i) {
        x.push_back(first[i]->total.median);
        y.push_back(second[i]->total.median);
        spreads.push_back(first[i]->total.relativeSpread());
        spreads.push_back(second[i]->total.relativeSpread());
        const double ratio = std::max(x.back(), y.back()) / std::max(std::min(x.back(), y.back()), 1e-12);
        if (ratio > out.largestRatio || out.largestRatioSetting.empty()) {
            out.largestRatio = ratio;
            out.largestRatioSetting = sweepLabel(first[i]->settings);
        }
        if (sameCost(first[i]->total, second[i]->total))
            ++out.sameCostInBoth;
    }
    out.spearman = spearman(x, y);
    std::vector<std::size_t> byTime(first.size());
    for (std::size_t i = 0; i < byTime.size(); ++i)
        byTime[i] = i;
    std::ranges::sort(byTime, [&](std::size_t i, std::size_t j) { return x[i] < x[j]; });
    std::vector<std::size_t> kept;
    for (std::size_t i : byTime)
        if (std::ranges::none_of(kept, [&](std::size_t k) {
                return sameCost(first[i]->total, first[k]->total) || sameCost(second[i]->total, second[k]->total);
            }))
            kept.push_back(i);
    std::vector<double> keptX, keptY;
    for (std::size_t i : kept) {
        keptX.push_back(x[i]);
        keptY.push_back(y[i]);
    }
    out.distinctSettings = int(kept.size());
    out.distinctSpearman = spearman(keptX, keptY);
    for (std::size_t i = 0; i < first.size(); ++i)
        for (std::size_t j = i + 1; j < first.size(); ++j) {
            if (sameCost(first[i]->total, first[j]->total) || sameCost(second[i]->total, second[j]->total))
                continue;
            ++out.distinctPairs;
            if ((x[i] < x[j]) != (y[i] < y[j]))
                ++out.discordantPairs;
        }
    if (!spreads.empty()) {
        std::ranges::sort(spreads);
        out.medianSpread = spreads[spreads.size() / 2];
    }
    return out;
}

} // namespace lpv::bench
