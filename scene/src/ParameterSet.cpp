#include "lpv/scene/ParameterRegistry.h"

#include <algorithm>
#include <stdexcept>

namespace lpv::scene {
namespace {

// A key the code reads but the registry lacks is a bug in the program, not
// bad input: it fails loudly in every build type (an assert would vanish
// under NDEBUG and leave a null dereference). The renderer turns it into an
// error value for its frame; ParameterRegistryCode's test finds it first.
const ParameterInfo& infoOf(std::string_view key) {
    const ParameterInfo* info = ParameterRegistry::instance().find(key);
    if (!info)
        throw std::logic_error("parameter '" + std::string(key) +
                               "' is read by the code but not declared in ParameterDeclarations.cpp");
    return *info;
}

} // namespace

Expected<void> ParameterSet::set(std::string_view key, const ParameterValue& value, const std::string& where) {
    auto checked = ParameterRegistry::instance().validate(key, value, where);
    if (!checked)
        return std::unexpected(checked.error());
    auto it = std::lower_bound(values_.begin(), values_.end(), key,
                               [](const auto& kv, std::string_view k) { return kv.first < k; });
    if (it != values_.end() && it->first == key)
        it->second = *checked;
    else
        values_.insert(it, {std::string(key), *checked});
    return {};
}

Expected<void> ParameterSet::setFromText(std::string_view key, std::string_view text, const std::string& where) {
    auto parsed = ParameterRegistry::instance().parse(key, text, where);
    if (!parsed)
        return std::unexpected(parsed.error());
    return set(key, *parsed, where);
}

void ParameterSet::reset(std::string_view key) {
    std::erase_if(values_, [&](const auto& kv) { return kv.first == key; });
}

bool ParameterSet::isSet(std::string_view key) const {
    return std::any_of(values_.begin(), values_.end(), [&](const auto& kv) { return kv.first == key; });
}

bool ParameterSet::isWord(std::string_view key, std::string_view word) const {
    const ParameterValue v = get(key);
    return std::holds_alternative<std::string>(v) && std::get<std::string>(v) == word;
}

ParameterValue ParameterSet::get(std::string_view key) const {
    for (const auto& [k, v] : values_)
        if (k == key)
            return v;
    return infoOf(key).defaultValue;
}

bool ParameterSet::getBool(std::string_view key) const { return std::get<bool>(get(key)); }
int ParameterSet::getInt(std::string_view key) const { return std::get<int>(get(key)); }
float ParameterSet::getFloat(std::string_view key) const { return static_cast<float>(std::get<double>(get(key))); }
std::string ParameterSet::getEnum(std::string_view key) const { return std::get<std::string>(get(key)); }

} // namespace lpv::scene
