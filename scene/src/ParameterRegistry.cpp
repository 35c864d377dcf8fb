#include "lpv/scene/ParameterRegistry.h"

#include "ParameterDeclarations.h"

#include <algorithm>
#include <cassert>
#include <charconv>
#include <cmath>
#include <sstream>

namespace lpv::scene {

const char* toString(ParameterType t) {
    switch (t) {
    case ParameterType::Bool: return "bool";
    case ParameterType::Int: return "int";
    case ParameterType::Float: return "float";
    case ParameterType::Enum: return "enum";
    }
    return "?";
}

namespace {

// Frame order; the names are the passes' one name everywhere.
const std::vector<std::pair<Pass, const char*>>& passTable() {
    static const std::vector<std::pair<Pass, const char*>> kNames = {
        {Pass::ShadowMaps, "shadowMaps"},
        {Pass::Rsm, "rsm"},
        {Pass::LocalRsm, "localRsm"},
        {Pass::EmissiveVpls, "emissiveVpls"},
        {Pass::SkyHeight, "skyHeight"},
        {Pass::LpvInjection, "lpvInjection"},
        {Pass::SkyInjection, "skyInjection"},
        {Pass::LpvNormals, "lpvNormals"},
        {Pass::GeometryVolume, "geometryVolume"},
        {Pass::LpvPropagation, "lpvPropagation"},
        {Pass::LpvBounces, "lpvBounces"},
        {Pass::Subsurface, "subsurface"},
        {Pass::DepthPrepass, "depthPrepass"},
        {Pass::LpvLookup, "lpvLookup"},
        {Pass::Shading, "shading"},
        {Pass::GlossyReflections, "glossyReflections"},
        {Pass::SunRays, "sunRays"},
        {Pass::Exposure, "exposure"},
        {Pass::Tonemap, "tonemap"},
        {Pass::Radiosity, "radiosity"},
        {Pass::Reference, "reference"},
    };
    return kNames;
}

} // namespace

std::vector<std::string> passNames(Pass passes) {
    std::vector<std::string> out;
    for (const auto& [pass, name] : passTable())
        if (any(passes, pass))
            out.emplace_back(name);
    return out;
}

std::string passName(Pass pass) {
    for (const auto& [p, name] : passTable())
        if (p == pass)
            return name;
    return {};
}

const std::vector<Pass>& allPasses() {
    static const std::vector<Pass> kAll = [] {
        std::vector<Pass> all;
        for (const auto& [pass, name] : passTable())
            all.push_back(pass);
        return all;
    }();
    return kAll;
}

std::string formatValue(const ParameterValue& v) {
    struct Visitor {
        std::string operator()(bool b) const { return b ? "true" : "false"; }
        std::string operator()(int i) const { return std::to_string(i); }
        std::string operator()(double d) const {
            std::ostringstream s;
            s << d;
            return s.str();
        }
        std::string operator()(const std::string& s) const { return s; }
    };
    return std::visit(Visitor{}, v);
}

ParameterRegistry::ParameterRegistry(std::vector<ParameterInfo> params) : params_(std::move(params)) {
    std::sort(params_.begin(), params_.end(), [](const auto& a, const auto& b) { return a.key < b.key; });
}

const ParameterRegistry& ParameterRegistry::instance() {
    static const ParameterRegistry registry(declareParameters());
    return registry;
}

namespace {
bool isOnOffChoice(const ParameterInfo& info) {
    auto has = [&](const char* v) { return std::find(info.enumValues.begin(), info.enumValues.end(), v) != info.enumValues.end(); };
    return has("on") && has("off");
}
} // namespace

const ParameterInfo* ParameterRegistry::find(std::string_view key) const {
    auto it = std::lower_bound(params_.begin(), params_.end(), key,
                               [](const ParameterInfo& p, std::string_view k) { return p.key < k; });
    return it != params_.end() && it->key == key ? &*it : nullptr;
}

Expected<ParameterValue> ParameterRegistry::validate(std::string_view key, const ParameterValue& value,
                                                     const std::string& where) const {
    const ParameterInfo* info = find(key);
    const std::string loc = "parameters." + std::string(key);
    if (!info)
        return makeError(ErrorCode::UnknownParameter, where, loc,
                         "unknown parameter '" + std::string(key) + "' (see `lpv params`)");
    auto mismatch = [&](const char* got) {
        return makeError(ErrorCode::TypeMismatch, where, loc,
                         std::string("expected ") + toString(info->type) + ", got " + got);
    };
    switch (info->type) {
    case ParameterType::Bool:
        if (!std::holds_alternative<bool>(value))
            return mismatch("another type");
        return value;
    case ParameterType::Enum: {
        // A true/false where the choices include on/off (a parameter that was a
        // boolean before it gained `auto`, as reference.skyLight did in issue #22).
        if (std::holds_alternative<bool>(value) && isOnOffChoice(*info))
            return ParameterValue(std::string(std::get<bool>(value) ? "on" : "off"));
        if (!std::holds_alternative<std::string>(value))
            return mismatch("a non-string");
        const auto& s = std::get<std::string>(value);
        if (std::find(info->enumValues.begin(), info->enumValues.end(), s) == info->enumValues.end()) {
            std::string allowed;
            for (const auto& e : info->enumValues)
                allowed += (allowed.empty() ? "" : ", ") + e;
            return makeError(ErrorCode::OutOfRange, where, loc, "'" + s + "' is not one of: " + allowed);
        }
        return value;
    }
    case ParameterType::Int:
    case ParameterType::Float: {
        double d = 0.0;
        if (info->type == ParameterType::Float && std::holds_alternative<std::string>(value)) {
            // A word the parameter admits besides numbers ("auto").
            const auto& s = std::get<std::string>(value);
            if (std::find(info->enumValues.begin(), info->enumValues.end(), s) != info->enumValues.end())
                return value;
            return mismatch(("'" + s + "'").c_str());
        }
        if (std::holds_alternative<int>(value))
            d = std::get<int>(value);
        else if (std::holds_alternative<double>(value))
            d = std::get<double>(value);
        else
            return mismatch("a non-number");
        if (!std::isfinite(d))
            return makeError(ErrorCode::NonFinite, where, loc, "value is NaN or infinite");
        if (info->type == ParameterType::Int && d != std::floor(d))
            return mismatch("a fractional number");
        if (d < info->minValue || d > info->maxValue) {
            std::ostringstream s;
            s << formatValue(value) << " is outside [" << info->minValue << ", " << info->maxValue << "]";
            return makeError(ErrorCode::OutOfRange, where, loc, s.str());
        }
        if (info->type == ParameterType::Int)
            return ParameterValue(static_cast<int>(d));
        return ParameterValue(d);
    }
    }
    return mismatch("?");
}

Expected<ParameterValue> ParameterRegistry::parse(std::string_view key, std::string_view text,
                                                  const std::string& where) const {
    const ParameterInfo* info = find(key);
    if (!info)
        return validate(key, ParameterValue(false), where); // produces the unknown-key error
    const std::string loc = "parameters." + std::string(key);
    switch (info->type) {
    case ParameterType::Bool:
        if (text == "true" || text == "on" || text == "1")
            return ParameterValue(true);
        if (text == "false" || text == "off" || text == "0")
            return ParameterValue(false);
        return makeError(ErrorCode::TypeMismatch, where, loc, "'" + std::string(text) + "' is not true/false");
    case ParameterType::Enum:
        if (isOnOffChoice(*info) && (text == "true" || text == "false"))
            return ParameterValue(std::string(text == "true" ? "on" : "off"));
        return validate(key, ParameterValue(std::string(text)), where);
    case ParameterType::Int:
    case ParameterType::Float: {
        if (info->type == ParameterType::Float &&
            std::find(info->enumValues.begin(), info->enumValues.end(), text) != info->enumValues.end())
            return ParameterValue(std::string(text));
        double d = 0.0;
        const char* end = text.data() + text.size();
        auto [ptr, ec] = std::from_chars(text.data(), end, d);
        if (ec == std::errc::result_out_of_range)
            return makeError(ErrorCode::NonFinite, where, loc, "'" + std::string(text) + "' overflows");
        if (ec != std::errc() || ptr != end || text.empty())
            return makeError(ErrorCode::TypeMismatch, where, loc, "'" + std::string(text) + "' is not a number");
        return validate(key, ParameterValue(d), where);
    }
    }
    return validate(key, ParameterValue(std::string(text)), where);
}

} // namespace lpv::scene
