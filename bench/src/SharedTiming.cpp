#include "lpv/bench/SharedTiming.h"

#include "lpv/bench/SavedSweep.h"
#include "lpv/bench/SweepRunJson.h"
#include "lpv/scene/Project.h"

#include <nlohmann/json.hpp>

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

} // namespace lpv::bench
