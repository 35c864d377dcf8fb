#include "lpv/scene/ParameterRegistry.h"

#include <nlohmann/json.hpp>

namespace lpv::scene {
namespace {

using nlohmann::json;

json valueToJson(const ParameterValue& v) {
    return std::visit([](const auto& x) { return json(x); }, v);
}

std::optional<ParameterType> parseType(const std::string& s) {
    for (ParameterType t : {ParameterType::Bool, ParameterType::Int, ParameterType::Float, ParameterType::Enum})
        if (s == toString(t))
            return t;
    return std::nullopt;
}

Pass parsePasses(const json& names) {
    Pass out = Pass::None;
    for (std::uint32_t bit = 0; bit < 32; ++bit) {
        const Pass p = Pass(1u << bit);
        const auto n = passNames(p);
        if (!n.empty() && std::find(names.begin(), names.end(), n.front()) != names.end())
            out = out | p;
    }
    return out;
}

} // namespace

std::string ParameterRegistry::toJson() const {
    json out = json::array();
    for (const ParameterInfo& p : params_) {
        json j{{"key", p.key},         {"type", toString(p.type)}, {"default", valueToJson(p.defaultValue)},
               {"unit", p.unit},       {"description", p.description}, {"group", p.group},
               {"invalidates", passNames(p.invalidates)}};
        if (p.type == ParameterType::Int || p.type == ParameterType::Float) {
            j["min"] = p.minValue;
            j["max"] = p.maxValue;
        }
        if (p.type == ParameterType::Enum || (p.type == ParameterType::Float && !p.enumValues.empty()))
            j["values"] = p.enumValues;
        out.push_back(std::move(j));
    }
    return out.dump(2);
}

Expected<ParameterRegistry> ParameterRegistry::fromJson(std::string_view text, const std::string& where) {
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::parse_error& e) {
        return makeError(ErrorCode::NotJson, where, "byte offset " + std::to_string(e.byte), e.what());
    }
    if (!doc.is_array())
        return makeError(ErrorCode::TypeMismatch, where, "", "expected an array of parameters");
    std::vector<ParameterInfo> params;
    for (std::size_t i = 0; i < doc.size(); ++i) {
        const json& j = doc[i];
        const std::string loc = "[" + std::to_string(i) + "]";
        try {
            ParameterInfo p;
            p.key = j.at("key").get<std::string>();
            auto type = parseType(j.at("type").get<std::string>());
            if (!type)
                return makeError(ErrorCode::InvalidValue, where, loc + ".type", "unknown parameter type");
            p.type = *type;
            const json& def = j.at("default");
            switch (p.type) {
            case ParameterType::Bool: p.defaultValue = def.get<bool>(); break;
            case ParameterType::Int: p.defaultValue = def.get<int>(); break;
            case ParameterType::Float:
                if (def.is_string())
                    p.defaultValue = def.get<std::string>(); // a word such as "auto"
                else
                    p.defaultValue = def.get<double>();
                break;
            case ParameterType::Enum: p.defaultValue = def.get<std::string>(); break;
            }
            if (p.type == ParameterType::Int || p.type == ParameterType::Float) {
                p.minValue = j.at("min").get<double>();
                p.maxValue = j.at("max").get<double>();
            } else if (p.type == ParameterType::Bool) {
                p.maxValue = 1.0;
            }
            if (p.type == ParameterType::Enum)
                p.enumValues = j.at("values").get<std::vector<std::string>>();
            else if (p.type == ParameterType::Float && j.contains("values"))
                p.enumValues = j.at("values").get<std::vector<std::string>>();
            p.unit = j.at("unit").get<std::string>();
            p.description = j.at("description").get<std::string>();
            p.group = j.at("group").get<std::string>();
            p.invalidates = parsePasses(j.at("invalidates"));
            params.push_back(std::move(p));
        } catch (const json::exception& e) {
            return makeError(ErrorCode::TypeMismatch, where, loc, e.what());
        }
    }
    return ParameterRegistry(std::move(params));
}

} // namespace lpv::scene
