#include "lpv/bench/SweepRunJson.h"

namespace lpv::bench {

using Json = nlohmann::json;

namespace {

Json metricsToJson(const reference::ErrorMetrics& m) {
    // nlohmann writes doubles so that they read back to the same bits.
    return {{"pixels", m.pixels},
            {"relMse", m.relMse},
            {"mare", m.mare},
            {"ssim", m.ssim},
            {"meanTest", m.meanTest},
            {"meanReference", m.meanReference},
            {"noiseRelMse", m.noiseRelMse},
            {"noiseMare", m.noiseMare},
            {"logError", m.logError},
            {"noiseLogError", m.noiseLogError}};
}

reference::ErrorMetrics metricsFromJson(const Json& j) {
    reference::ErrorMetrics m;
    m.pixels = j.at("pixels").get<std::size_t>();
    m.relMse = j.at("relMse").get<double>();
    m.mare = j.at("mare").get<double>();
    m.ssim = j.at("ssim").get<double>();
    m.meanTest = j.at("meanTest").get<double>();
    m.meanReference = j.at("meanReference").get<double>();
    m.noiseRelMse = j.at("noiseRelMse").get<double>();
    m.noiseMare = j.at("noiseMare").get<double>();
    // Absent in files written before the symmetric error (issue #43).
    m.logError = j.value("logError", 0.0);
    m.noiseLogError = j.value("noiseLogError", 0.0);
    return m;
}

} // namespace

TimingStats timingFromJson(const Json& j) {
    return {j.at("medianMs").get<double>(), j.at("q1Ms").get<double>(), j.at("q3Ms").get<double>(),
            j.at("minMs").get<double>(),    j.at("maxMs").get<double>(), j.at("rounds").get<int>()};
}

Json sweepRunToJson(const SweepRun& r) {
    Json settings = Json::array();
    for (const auto& [key, value] : r.settings)
        settings.push_back({key, value});
    Json passes = Json::array();
    for (std::size_t i = 0; i < r.passes.size(); ++i) {
        const auto& p = r.passes[i];
        Json pass{{"pass", p.pass}, {"medianMs", p.medianMs}, {"minMs", p.minMs},
                  {"maxMs", p.maxMs}, {"lastMs", p.lastMs},   {"frames", p.samples}};
        if (i < r.passStats.size())
            pass["rounds"] = timingToJson(r.passStats[i]);
        passes.push_back(pass);
    }
    return {{"settings", settings},
            {"bounces", r.bounces},
            {"totalMs", r.totalMs},
            {"total", timingToJson(r.total)},
            {"gpuBytes", r.gpuBytes},
            {"lpvBytes", r.lpvBytes},
            {"passes", passes},
            {"indirect", metricsToJson(r.indirect)},
            {"indirectOneBounce", metricsToJson(r.indirectOne)},
            {"image", metricsToJson(r.image)},
            {"solveSeconds", r.solveSeconds},
            {"solveResidual", r.solveResidual}};
}

SweepRun sweepRunFromJson(const Json& r) {
    SweepRun run;
    for (const Json& kv : r.at("settings"))
        run.settings.emplace_back(kv.at(0).get<std::string>(), kv.at(1).get<std::string>());
    run.bounces = r.at("bounces").get<int>();
    run.totalMs = r.at("totalMs").get<double>();
    for (const Json& p : r.at("passes")) {
        run.passes.push_back({p.at("pass").get<std::string>(), p.at("medianMs").get<double>(),
                              p.at("minMs").get<double>(), p.at("maxMs").get<double>(),
                              p.at("lastMs").get<double>(), p.at("frames").get<std::size_t>()});
        if (p.contains("rounds"))
            run.passStats.push_back(timingFromJson(p.at("rounds")));
    }
    if (run.passStats.size() != run.passes.size())
        run.passStats.clear();
    // Absent in files written before timing rounds and memory (issue #43).
    if (r.contains("total"))
        run.total = timingFromJson(r.at("total"));
    run.gpuBytes = r.value("gpuBytes", std::uint64_t(0));
    run.lpvBytes = r.value("lpvBytes", std::uint64_t(0));
    run.indirect = metricsFromJson(r.at("indirect"));
    run.indirectOne = metricsFromJson(r.at("indirectOneBounce"));
    run.image = metricsFromJson(r.at("image"));
    // Absent in sweeps written before radiosity runs were measured.
    run.solveSeconds = r.value("solveSeconds", 0.0);
    run.solveResidual = r.value("solveResidual", 0.0);
    return run;
}

} // namespace lpv::bench
