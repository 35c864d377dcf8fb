#include "lpv/bench/Settings.h"

namespace lpv::bench {

namespace {

std::vector<std::string> splitValues(const std::string& s) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = s.find(',', start);
        out.push_back(s.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
        if (comma == std::string::npos)
            return out;
        start = comma + 1;
    }
}

} // namespace

SetPlan planSettings(const std::vector<std::string>& sets, std::string& error) {
    SetPlan plan;
    std::vector<std::pair<std::string, std::vector<std::string>>> swept;
    for (const std::string& kv : sets) {
        const auto eq = kv.find('=');
        if (eq == std::string::npos || eq == 0) {
            error = "--set expects KEY=VALUE, got '" + kv + "'";
            return {};
        }
        const std::string key = kv.substr(0, eq);
        const std::vector<std::string> values = splitValues(kv.substr(eq + 1));
        for (const std::string& v : values)
            if (v.empty()) {
                error = "--set " + key + ": empty value in '" + kv + "'";
                return {};
            }
        if (values.size() == 1)
            plan.fixed.emplace_back(key, values.front());
        else
            swept.emplace_back(key, values);
    }
    if (swept.empty())
        return plan;
    // Cartesian product, the first swept key varying slowest.
    plan.combinations = {{}};
    for (const auto& [key, values] : swept) {
        std::vector<std::vector<Setting>> next;
        for (const auto& combination : plan.combinations)
            for (const std::string& v : values) {
                auto c = combination;
                c.emplace_back(key, v);
                next.push_back(std::move(c));
            }
        plan.combinations = std::move(next);
    }
    return plan;
}

std::string combinationSuffix(const std::vector<Setting>& combination) {
    std::string suffix;
    for (const auto& [key, value] : combination)
        suffix += "-" + key + "-" + value;
    return suffix;
}

std::optional<std::string> checkCombinations(const SetPlan& plan, const scene::ParameterSet& base,
                                             const std::string& option) {
    for (const auto& combination : plan.combinations)
        for (const auto& [key, value] : combination) {
            scene::ParameterSet probe = base;
            if (auto ok = probe.setFromText(key, value, option); !ok)
                return ok.error().describe();
        }
    return std::nullopt;
}

} // namespace lpv::bench
