#pragma once
// What one field of a scene struct is, declared once (SceneFields.h holds
// the tables): its JSON name, where it lives in the struct, its range and
// unit, and a sentence for the docs. The project reader and writer, the
// editor's property widgets, the renderer's reuse hash, radiosity's scene
// signature, the fuzz checks and docs/project-format.md all walk these
// tables, so they cannot disagree (issue #44). Modelled on the parameter
// registry (ParameterRegistry.h), and on Godot's ADD_PROPERTY.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace lpv::scene {

// The values a number (or each component of a vector) may take. Bounds are
// rounded to float before comparing: the float nearest pi/2 is slightly
// above pi/2, and a value the program itself produces must pass.
struct FieldRange {
    double min = -std::numeric_limits<double>::infinity();
    double max = std::numeric_limits<double>::infinity();
    bool openMin = false;
    bool openMax = false;

    bool contains(float v) const {
        const float lo = static_cast<float>(min);
        const float hi = static_cast<float>(max);
        return (openMin ? v > lo : v >= lo) && (openMax ? v < hi : v <= hi);
    }
    // The nearest value inside (one float step in from an open end): what an
    // edit becomes when another field's rule bounds it.
    float clamp(float v) const {
        const float lo = static_cast<float>(min);
        const float hi = static_cast<float>(max);
        if (openMin ? !(v > lo) : v < lo)
            v = openMin ? std::nextafter(lo, std::numeric_limits<float>::infinity()) : lo;
        if (openMax ? !(v < hi) : v > hi)
            v = openMax ? std::nextafter(hi, -std::numeric_limits<float>::infinity()) : hi;
        return v;
    }
    bool bounded() const {
        return min > -std::numeric_limits<double>::infinity() ||
               max < std::numeric_limits<double>::infinity();
    }
    // The values both ranges hold (a widget's range narrowed by another field).
    constexpr FieldRange within(const FieldRange& o) const {
        FieldRange r = *this;
        if (o.min > min || (o.min == min && o.openMin))
            r.min = o.min, r.openMin = o.openMin;
        if (o.max < max || (o.max == max && o.openMax))
            r.max = o.max, r.openMax = o.openMax;
        return r;
    }
    // As error messages and the docs show it: "(0, 1.5707963267948966]", ">= 0".
    std::string describe() const;
};

inline constexpr FieldRange kAnyValue{};
inline constexpr FieldRange kNonNegative{0.0, std::numeric_limits<double>::infinity()};
inline constexpr FieldRange kPositive{0.0, std::numeric_limits<double>::infinity(), true, false};
inline constexpr FieldRange kUnitInterval{0.0, 1.0};

// Which list an integer field indexes (-1 = none).
enum class IndexOf { None, Meshes, Objects };

// Everything about a field but its C++ type. Optional fields were added
// after version 1 was published: a file without them means the default;
// they are always written.
template <class S> struct FieldInfo {
    const char* name = "";
    FieldRange range{};
    const char* unit = "";        // "rad", "m", "W/sr"; empty for none
    const char* description = ""; // one line for docs/project-format.md
    bool optional = false;
    // The field exists only when this holds (an area light's shape): not
    // read, not written, not hashed otherwise. Null: always.
    bool (*applies)(const S&) = nullptr;
    // Read only when present in the file unless this holds (a disc's size is
    // kept but not required). Null: required (unless `optional`).
    bool (*required)(const S&) = nullptr;
    // What the editor's widget offers, in the field's unit, where it is
    // narrower than `range`: a spin box needs finite ends, and a product
    // check (ValueChecks.h) may refuse part of `range`. Unbounded: `range`.
    FieldRange editRange{};
    // False for what changes no output (a name); the hashes skip it.
    bool hashed = true;
    // Written only when this holds (an object's empty LOD list is left out,
    // so older files keep their bytes). Null: always written.
    bool (*written)(const S&) = nullptr;
    IndexOf index = IndexOf::None;
    // The JSON shape for the docs when the C++ type says too little ("[r, g, b]").
    const char* shape = nullptr;
};

// A field of S of type T: FieldInfo plus the way to reach it.
template <class S, class T> struct Field : FieldInfo<S> {
    using Struct = S;
    using Type = T;
    T& (*ref)(S&) = nullptr;

    T& of(S& s) const { return ref(s); }
    const T& of(const S& s) const { return ref(const_cast<S&>(s)); }
    bool appliesTo(const S& s) const { return !this->applies || this->applies(s); }
    bool requiredIn(const S& s) const { return !this->optional && (!this->required || this->required(s)); }
    // The range the editor offers: editRange where it was given, else range.
    FieldRange widgetRange() const { return this->editRange.bounded() ? this->editRange : this->range; }
};

namespace detail {
template <class> struct MemberTraits;
template <class S, class T> struct MemberTraits<T S::*> {
    using Struct = S;
    using Type = T;
};
template <auto First, auto... Rest> struct MemberPath {
    using Struct = typename MemberTraits<decltype(First)>::Struct;
    using Last = std::tuple_element_t<sizeof...(Rest) - 1, std::tuple<decltype(Rest)...>>;
    using Type = typename MemberTraits<Last>::Type;
    static Type& get(Struct& s) { return ((s.*First).*....*Rest); }
};
template <auto First> struct MemberPath<First> {
    using Struct = typename MemberTraits<decltype(First)>::Struct;
    using Type = typename MemberTraits<decltype(First)>::Type;
    static Type& get(Struct& s) { return s.*First; }
};
} // namespace detail

// field<&Light::outerConeAngle>({...}); a nested member is a path:
// field<&Object::transform, &Transform::scale>({...}).
template <auto... Members>
constexpr auto field(FieldInfo<typename detail::MemberPath<Members...>::Struct> info) {
    using Path = detail::MemberPath<Members...>;
    Field<typename Path::Struct, typename Path::Type> f{};
    static_cast<FieldInfo<typename Path::Struct>&>(f) = info;
    f.ref = &Path::get;
    return f;
}

// How an enum field is named in files: the names it takes ("a, b, c", as
// error messages list them) and their parser. One specialisation of
// kEnumNames per enum, in SceneFields.h.
template <class E> struct EnumNames {
    const char* allowed = nullptr;
    std::optional<E> (*parse)(std::string_view) = nullptr;
};
template <class E> inline constexpr EnumNames<E> kEnumNames{};

// Each table is a tuple of Fields (SceneFields.h); fieldsOf<S>() returns it.
template <class S> struct FieldTable; // specialised in SceneFields.h: static constexpr auto fields

template <class S, class Visit> constexpr void forEachField(Visit&& visit) {
    std::apply([&](const auto&... f) { (visit(f), ...); }, FieldTable<S>::fields);
}

// The table entry of a member: fieldOf<&Light::outerConeAngle>(), for code
// that edits one field by hand (an editor widget) and wants its range.
template <auto... Members> constexpr const auto& fieldOf() {
    using Path = detail::MemberPath<Members...>;
    using Wanted = Field<typename Path::Struct, typename Path::Type>;
    constexpr std::size_t kNone = ~std::size_t(0);
    constexpr std::size_t index = [] {
        std::size_t i = 0;
        std::size_t found = kNone;
        std::apply(
            [&](const auto&... f) {
                (([&] {
                     if constexpr (std::is_same_v<std::decay_t<decltype(f)>, Wanted>)
                         if (f.ref == &Path::get)
                             found = i;
                     ++i;
                 }()),
                 ...);
            },
            FieldTable<typename Path::Struct>::fields);
        return found;
    }();
    static_assert(index != kNone, "the member has no entry in its struct's field table");
    return std::get<index>(FieldTable<typename Path::Struct>::fields);
}

// The bytes of a value as the hashes see them: floats and vectors by their
// bits, enums as 32 bits, flags as one byte. The same value gives the same
// bytes on every run, so a reuse key or a stored signature stays valid.
// Lists of structs (keyframes, LODs) have no byte form: their tables mark them unhashed.
template <class T>
inline constexpr bool kHasFieldBytes =
    std::is_enum_v<T> || std::is_arithmetic_v<T> || std::is_same_v<T, glm::vec2> ||
    std::is_same_v<T, glm::vec3> || std::is_same_v<T, glm::quat> || std::is_same_v<T, std::string>;

template <class Sink, class T> void fieldBytes(Sink& sink, const T& v) {
    if constexpr (std::is_enum_v<T>) {
        const auto u = static_cast<std::uint32_t>(v);
        sink(&u, sizeof u);
    } else if constexpr (std::is_same_v<T, bool>) {
        const auto b = static_cast<std::uint8_t>(v);
        sink(&b, sizeof b);
    } else if constexpr (std::is_same_v<T, std::string>) {
        const std::uint64_t size = v.size();
        sink(&size, sizeof size);
        sink(v.data(), v.size());
    } else {
        sink(&v, sizeof v);
    }
}

namespace detail {

// Feeds `sink` the bytes of field I of S's table, if it is hashed.
template <class S, std::size_t I, class Sink> void hashFieldAt(const S& s, Sink& sink) {
    const auto& f = std::get<I>(FieldTable<S>::fields);
    using T = typename std::decay_t<decltype(f)>::Type;
    if constexpr (kHasFieldBytes<T>)
        if (f.hashed)
            fieldBytes(sink, f.of(s));
}

// hashFieldAt of every field of S's table in the struct's member order,
// worked out once (member offsets are the same in every S): hashing a
// light for a reuse key every frame allocates nothing.
template <class S, class Sink> const std::vector<void (*)(const S&, Sink&)>& hashStepsInMemberOrder() {
    using Step = void (*)(const S&, Sink&);
    static const std::vector<Step> steps = [] {
        constexpr std::size_t count = std::tuple_size_v<std::decay_t<decltype(FieldTable<S>::fields)>>;
        const S probe{};
        const auto offset = [&](const auto& f) {
            return reinterpret_cast<const char*>(&f.of(probe)) - reinterpret_cast<const char*>(&probe);
        };
        std::vector<std::pair<std::ptrdiff_t, Step>> at;
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (at.emplace_back(offset(std::get<I>(FieldTable<S>::fields)), &hashFieldAt<S, I, Sink>), ...);
        }(std::make_index_sequence<count>{});
        std::stable_sort(at.begin(), at.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        std::vector<Step> ordered;
        for (const auto& [where, step] : at)
            ordered.push_back(step);
        return ordered;
    }();
    return steps;
}

} // namespace detail

// Feeds sink(const void*, std::size_t) every hashed field of `s`, whether it
// applies to this light type or not (a field the editor keeps across a type
// switch still counts): a field added to the table is in every hash without
// anyone remembering it. In the struct's member order, not the file's: the
// order radiosity's stored scene signatures were made in, so solutions baked
// before the tables still match. Every sink is a byte stream (a hash, an
// append), so how the bytes are split between calls does not matter.
template <class S, class Sink> void hashFields(const S& s, Sink&& sink) {
    using Target = std::remove_reference_t<Sink>;
    for (const auto step : detail::hashStepsInMemberOrder<S, Target>())
        step(s, sink);
}

} // namespace lpv::scene
