#pragma once
// For tests that walk the scene field tables (SceneFields.h): a value of a
// field's type that differs from the one given, so a test can change each
// field in turn and see every hash that should notice it notice it.
#include "lpv/scene/SceneFields.h"

#include <string>
#include <type_traits>
#include <vector>

namespace lpv::test {

template <class T> T changed(const T& v) {
    if constexpr (std::is_same_v<T, bool>)
        return !v;
    else if constexpr (std::is_integral_v<T>)
        return v + 1;
    else if constexpr (std::is_enum_v<T>)
        return static_cast<T>(static_cast<int>(v) == 0 ? 1 : 0);
    else if constexpr (std::is_same_v<T, std::string>)
        return v + "x";
    else if constexpr (std::is_same_v<T, glm::quat>)
        return glm::quat(v.w, v.x + 0.25f, v.y, v.z);
    else if constexpr (requires(T t) { t.push_back(typename T::value_type{}); }) {
        T out = v;
        out.push_back(typename T::value_type{});
        return out;
    } else
        return v + T(0.25f);
}

// Every field of S that `affects` says changes when the field is changed
// alone, starting from `base`; the names of those it does not.
template <class S, class Affects>
std::vector<std::string> fieldsNotAffecting(const S& base, Affects affects) {
    std::vector<std::string> missed;
    scene::forEachField<S>([&](const auto& field) {
        S s = base;
        field.of(s) = changed(field.of(s));
        if (!affects(base, s))
            missed.emplace_back(field.name);
    });
    return missed;
}

} // namespace lpv::test
