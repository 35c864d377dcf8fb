// Project <-> JSON document, format v1 (docs/project-format.md).
//
// Reading validates everything a renderer would otherwise trip over later:
// types, finiteness, ranges, enum names, parameter keys, indices and parent
// chains. Each check names the JSON path of the offending value, so a user
// editing the file by hand can find it.
#include "ProjectJson.h"

#include "lpv/scene/SceneFields.h"
#include "lpv/scene/ValueChecks.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numbers>
#include <optional>
#include <span>
#include <sstream>
#include <unordered_map>

namespace lpv::scene::detail {
namespace {

template <class... Args>
std::string concat(const Args&... args) {
    std::ostringstream out;
    (out << ... << args);
    return out.str();
}

// Shortest text that reads back as the same value (so messages show what is in the file).
template <class T>
std::string formatNumber(T v) {
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    return ec == std::errc() ? std::string(buffer, end) : std::string("?");
}

std::string atByte(std::size_t offset) { return concat("byte offset ", offset); }

std::string fieldPath(const std::string& path, std::string_view key) {
    return path.empty() ? std::string(key) : concat(path, ".", key);
}

std::string indexPath(const std::string& path, std::size_t i) { return concat(path, "[", i, "]"); }

// --- value ranges -----------------------------------------------------------

// The fields' ranges live in their tables (SceneFields.h); the camera path
// file's degrees below are the one range of this file's own.
using Range = FieldRange;
constexpr double kPi = std::numbers::pi;

// --- reading ----------------------------------------------------------------

// The file being read and the first error found in it. Readers below stop
// doing anything once an error is recorded, so a reading function can read
// all its fields in sequence and the caller checks once.
class Reader {
public:
    explicit Reader(std::string file) : file_(std::move(file)) {}

    bool ok() const { return !error_.has_value(); }
    const std::string& file() const { return file_; }
    const Error& error() const { return *error_; }

    void fail(ErrorCode code, std::string location, std::string message) {
        if (!error_) // capped as makeError does: a name in the message can be megabytes long
            error_ = Error{code, capErrorText(file_), capErrorText(std::move(location)),
                           capErrorText(std::move(message))};
    }
    void fail(Error error) {
        if (!error_)
            error_ = std::move(error);
    }

private:
    std::string file_;
    std::optional<Error> error_;
};

std::string typeOf(const Json& v) {
    if (v.is_number_float()) {
        const double d = v.get<double>();
        // 1.0 is a whole number written as a fraction: say so, instead of "got the number 1".
        if (std::isfinite(d) && std::trunc(d) == d && std::abs(d) < 1e15)
            return concat("the fraction ", formatNumber(d), ".0 (written with a decimal point or exponent; write ",
                          formatNumber(d), ")");
        return "the number " + formatNumber(d);
    }
    return std::string("a ") + v.type_name();
}

std::optional<float> readFloat(Reader& r, const Json& v, const std::string& path, const Range& range) {
    if (!v.is_number()) {
        r.fail(ErrorCode::TypeMismatch, path, "expected a number, got " + typeOf(v));
        return std::nullopt;
    }
    const double d = v.get<double>();
    // JSON has no NaN or infinity literal, but a document built in memory can hold them.
    if (!std::isfinite(d)) {
        r.fail(ErrorCode::NonFinite, path, formatNumber(d) + " is not a finite number");
        return std::nullopt;
    }
    // Halfway between FLT_MAX and 2^128: from here on a double rounds to an
    // infinite float (and converting it would be undefined behaviour).
    constexpr double kFloatOverflow = 0x1.ffffffp+127;
    if (std::abs(d) >= kFloatOverflow) {
        r.fail(ErrorCode::NonFinite, path, formatNumber(d) + " is infinite as a 32-bit float");
        return std::nullopt;
    }
    const float f = static_cast<float>(d);
    if (!range.contains(f)) {
        r.fail(ErrorCode::OutOfRange, path, concat(formatNumber(f), " is outside ", range.describe()));
        return std::nullopt;
    }
    return f;
}

// An array of exactly N numbers, each checked against `range`; locations name the element ("diffuseColor[1]").
template <std::size_t N>
std::optional<std::array<float, N>> readFloats(Reader& r, const Json& v, const std::string& path,
                                               const Range& range) {
    if (!v.is_array() || v.size() != N) {
        r.fail(ErrorCode::TypeMismatch, path,
               concat("expected an array of ", N, " numbers, got ",
                      v.is_array() ? concat("an array of ", v.size()) : typeOf(v)));
        return std::nullopt;
    }
    std::array<float, N> out{};
    for (std::size_t i = 0; i < N; ++i) {
        const auto f = readFloat(r, v[i], indexPath(path, i), range);
        if (!f)
            return std::nullopt;
        out[i] = *f;
    }
    return out;
}

std::optional<std::int64_t> readInteger(Reader& r, const Json& v, const std::string& path) {
    if (v.is_number_unsigned()) {
        const std::uint64_t u = v.get<std::uint64_t>();
        // Too large for any index or count; clamped so the range check reports it.
        return u > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())
                   ? std::numeric_limits<std::int64_t>::max()
                   : static_cast<std::int64_t>(u);
    }
    if (v.is_number_integer())
        return v.get<std::int64_t>();
    r.fail(ErrorCode::TypeMismatch, path, "expected an integer, got " + typeOf(v));
    return std::nullopt;
}

// One JSON object at `path`; every field it is asked for is required.
class Fields {
public:
    Fields(Reader& reader, const Json& json, std::string path) : r_(reader), path_(std::move(path)) {
        if (!r_.ok())
            return;
        if (!json.is_object()) {
            r_.fail(ErrorCode::TypeMismatch, path_.empty() ? "(top level)" : path_,
                    "expected an object, got " + typeOf(json));
            return;
        }
        json_ = &json;
    }

    Reader& reader() { return r_; }
    bool ok() const { return r_.ok(); }
    std::string pathOf(std::string_view key) const { return fieldPath(path_, key); }

    // nullptr when the field is missing (recorded), or reading already failed.
    const Json* get(const char* key) {
        if (!json_ || !r_.ok())
            return nullptr;
        const auto it = json_->find(key);
        if (it == json_->end()) {
            r_.fail(ErrorCode::MissingField, pathOf(key), concat("required field \"", key, "\" is missing"));
            return nullptr;
        }
        return &*it;
    }

    // For fields added after version 1 was published: absent means the default.
    bool has(const char* key) const { return json_ && r_.ok() && json_->contains(key); }

    void text(const char* key, std::string& out) {
        if (const Json* v = get(key)) {
            if (v->is_string())
                out = v->get<std::string>();
            else
                r_.fail(ErrorCode::TypeMismatch, pathOf(key), "expected a string, got " + typeOf(*v));
        }
    }

    void flag(const char* key, bool& out) {
        if (const Json* v = get(key)) {
            if (v->is_boolean())
                out = v->get<bool>();
            else
                r_.fail(ErrorCode::TypeMismatch, pathOf(key), "expected true or false, got " + typeOf(*v));
        }
    }

    void number(const char* key, float& out, const Range& range) {
        if (const Json* v = get(key))
            if (const auto f = readFloat(r_, *v, pathOf(key), range))
                out = *f;
    }

    template <glm::length_t L, glm::qualifier Q>
    void vector(const char* key, glm::vec<L, float, Q>& out, const Range& range) {
        if (const Json* v = get(key))
            if (const auto a = readFloats<static_cast<std::size_t>(L)>(r_, *v, pathOf(key), range))
                for (glm::length_t i = 0; i < L; ++i)
                    out[i] = (*a)[static_cast<std::size_t>(i)];
    }

    // [x, y, z, w]; any non-zero quaternion (the renderer normalises).
    void rotation(const char* key, glm::quat& out) {
        const Json* v = get(key);
        if (!v)
            return;
        const auto a = readFloats<4>(r_, *v, pathOf(key), kAnyValue);
        if (!a)
            return;
        if ((*a)[0] == 0.0f && (*a)[1] == 0.0f && (*a)[2] == 0.0f && (*a)[3] == 0.0f) {
            r_.fail(ErrorCode::InvalidValue, pathOf(key), "a rotation quaternion cannot be all zeros");
            return;
        }
        out.x = (*a)[0];
        out.y = (*a)[1];
        out.z = (*a)[2];
        out.w = (*a)[3];
    }

    // An index into a list of `size` things, or -1 for none.
    void index(const char* key, int& out, std::size_t size, const char* thing, const char* things) {
        const auto i = integerIn(key, -1, static_cast<std::int64_t>(size) - 1, ErrorCode::IndexOutOfRange,
                                 [&](std::int64_t bad) {
                                     return concat(thing, " ", bad, " does not exist (the project has ", size,
                                                   " ", things, "; -1 means none)");
                                 });
        if (i)
            out = static_cast<int>(*i);
    }

    void count(const char* key, std::uint64_t& out) {
        const auto i =
            integerIn(key, 0, std::numeric_limits<std::int64_t>::max(), ErrorCode::OutOfRange,
                      [](std::int64_t bad) { return concat("a count cannot be negative (", bad, ")"); });
        if (i)
            out = static_cast<std::uint64_t>(*i);
    }

    template <class E>
    void enumeration(const char* key, E& out, std::optional<E> (*parse)(std::string_view), const char* allowed) {
        std::string name;
        text(key, name);
        if (!r_.ok())
            return;
        if (const auto e = parse(name))
            out = *e;
        else
            r_.fail(ErrorCode::InvalidValue, pathOf(key), concat("\"", name, "\" is not one of: ", allowed));
    }

    const Json* array(const char* key) {
        const Json* v = get(key);
        if (v && !v->is_array()) {
            r_.fail(ErrorCode::TypeMismatch, pathOf(key), "expected an array, got " + typeOf(*v));
            return nullptr;
        }
        return v;
    }

private:
  // An integer field in [min, max]; `why(value)` says what is wrong with one outside.
  template <class Why>
  std::optional<std::int64_t> integerIn(const char* key, std::int64_t min, std::int64_t max, ErrorCode code,
                                        Why why) {
      const Json* v = get(key);
      if (!v)
          return std::nullopt;
      const auto i = readInteger(r_, *v, pathOf(key));
      if (i && (*i < min || *i > max)) {
          r_.fail(code, pathOf(key), why(*i));
          return std::nullopt;
      }
      return i;
  }

    Reader& r_;
    const Json* json_ = nullptr;
    std::string path_;
};

// The product checks (ValueChecks.h) after a struct's fields are read one by one.
void report(Fields& f, const std::optional<ValueProblem>& problem) {
    if (problem && f.ok())
        f.reader().fail(problem->code, f.pathOf(problem->field), problem->message);
}

template <class T, class ReadElement>
std::vector<T> readArray(Fields& parent, const char* key, ReadElement readElement) {
    std::vector<T> out;
    const Json* a = parent.array(key);
    if (!a)
        return out;
    out.reserve(a->size());
    for (std::size_t i = 0; i < a->size() && parent.ok(); ++i) {
        Fields element(parent.reader(), (*a)[i], indexPath(parent.pathOf(key), i));
        out.push_back(readElement(element));
    }
    return out;
}

// How many meshes and objects the project has: the range of index fields.
struct IndexCounts {
    std::size_t meshes = 0;
    std::size_t objects = 0;
};

template <class S> S readStruct(Fields& f, const IndexCounts& counts);

template <class S> std::vector<S> readStructs(Fields& parent, const char* key, const IndexCounts& counts) {
    return readArray<S>(parent, key, [&](Fields& element) { return readStruct<S>(element, counts); });
}

// One field, read as its table entry says: the JSON form follows the C++ type.
template <class S, class T>
void readField(Fields& f, const Field<S, T>& field, T& out, const IndexCounts& counts) {
    const char* key = field.name;
    if constexpr (std::is_same_v<T, std::string>)
        f.text(key, out);
    else if constexpr (std::is_same_v<T, bool>)
        f.flag(key, out);
    else if constexpr (std::is_same_v<T, float>)
        f.number(key, out, field.range);
    else if constexpr (std::is_same_v<T, glm::quat>)
        f.rotation(key, out);
    else if constexpr (std::is_enum_v<T>) {
        static_assert(kEnumNames<T>.parse != nullptr, "an enum field needs its kEnumNames (SceneFields.h)");
        f.enumeration(key, out, kEnumNames<T>.parse, kEnumNames<T>.allowed);
    } else if constexpr (std::is_same_v<T, int>) {
        if (field.index == IndexOf::Meshes)
            f.index(key, out, counts.meshes, "mesh", "meshes");
        else
            f.index(key, out, counts.objects, "object", "objects");
    } else if constexpr (requires { out.push_back(typename T::value_type{}); })
        out = readStructs<typename T::value_type>(f, key, counts);
    else
        f.vector(key, out, field.range);
}

// Every field of S in table order: one that does not apply (an area light's
// shape on a spot) is skipped, an optional one read only when present. Then
// the rules between fields and the product checks.
template <class S> S readStruct(Fields& f, const IndexCounts& counts) {
    S s;
    forEachField<S>([&](const auto& field) {
        if (!f.ok() || !field.appliesTo(s) || (!field.requiredIn(s) && !f.has(field.name)))
            return;
        readField(f, field, field.of(s), counts);
    });
    if (f.ok())
        report(f, checkFieldRules(s));
    return s;
}

MeshReference readMeshReference(Fields& f) {
    MeshReference m;
    f.text("name", m.name);
    f.text("asset", m.asset);
    if (f.ok())
        if (auto checked = checkAssetPath(m.asset, f.reader().file(), f.pathOf("asset")); !checked)
            f.reader().fail(checked.error());
    f.count("vertices", m.vertices);
    f.count("triangles", m.triangles);
    return m;
}

// --- camera path files// --- camera path files (docs/camera-paths.md): the field of view in degrees ---

const Range kFieldOfViewDegrees{0.0, 180.0, true, true};

double degreesFromRadians(float radians) { return static_cast<double>(radians) * (180.0 / kPi); }
float radiansFromDegrees(double degrees) { return static_cast<float>(degrees * (kPi / 180.0)); }

CameraKeyframe readPathFileKeyframe(Fields& f) {
    CameraKeyframe k;
    f.number("time", k.time, kNonNegative);
    f.vector("position", k.position, kAnyValue);
    f.rotation("orientation", k.orientation);
    float degrees = 0.0f;
    f.number("fovYDegrees", degrees, kFieldOfViewDegrees);
    // From the double in the file, so the shortest decimal written for a
    // float's degrees reads back as exactly that float in radians.
    if (f.ok())
        if (const Json* v = f.get("fovYDegrees"))
            k.fovY = radiansFromDegrees(v->get<double>());
    // The file names the field of view in degrees.
    auto problem = checkKeyframe(k);
    if (problem && problem->field == "fovY")
        problem->field = "fovYDegrees";
    report(f, problem);
    return k;
}

void readSky(Fields& top, Sky& sky) {
    if (const Json* v = top.get("sky")) {
        Fields f(top.reader(), *v, "sky");
        sky = readStruct<Sky>(f, {});
    }
}

std::optional<ParameterValue> toParameterValue(Reader& r, const Json& v, const std::string& path) {
    constexpr std::int64_t kIntMin = std::numeric_limits<int>::min();
    constexpr std::int64_t kIntMax = std::numeric_limits<int>::max();
    if (v.is_boolean())
        return ParameterValue(v.get<bool>());
    if (v.is_string())
        return ParameterValue(v.get<std::string>());
    // Integers beyond int are passed on as doubles so the registry reports them out of range.
    if (v.is_number_unsigned()) {
        const std::uint64_t u = v.get<std::uint64_t>();
        return u <= static_cast<std::uint64_t>(kIntMax) ? ParameterValue(static_cast<int>(u))
                                                          : ParameterValue(static_cast<double>(u));
    }
    if (v.is_number_integer()) {
        const std::int64_t i = v.get<std::int64_t>();
        return i >= kIntMin && i <= kIntMax ? ParameterValue(static_cast<int>(i))
                                            : ParameterValue(static_cast<double>(i));
    }
    if (v.is_number_float()) {
        const double d = v.get<double>();
        if (!std::isfinite(d)) {
            r.fail(ErrorCode::NonFinite, path, formatNumber(d) + " is not a finite number");
            return std::nullopt;
        }
        return ParameterValue(d);
    }
    r.fail(ErrorCode::TypeMismatch, path, "expected true/false, a number or a string, got " + typeOf(v));
    return std::nullopt;
}

// Keys and values are checked by the parameter registry: unknown keys, wrong
// types and out-of-range values come back as its errors. `path` is where the
// object sits ("parameters", "presets[1].parameters").
void readParameterObject(Reader& r, const Json& params, const std::string& path, ParameterSet& out) {
    if (!params.is_object()) {
        r.fail(ErrorCode::TypeMismatch, path, "expected an object, got " + typeOf(params));
        return;
    }
    for (auto it = params.begin(); it != params.end() && r.ok(); ++it) {
        const std::string at = fieldPath(path, it.key());
        const auto value = toParameterValue(r, it.value(), at);
        if (!value)
            return;
        if (auto set = out.set(it.key(), *value, r.file()); !set) {
            // The registry names the key as a top-level parameter; a preset's sit deeper.
            Error error = set.error();
            error.location = at;
            r.fail(std::move(error));
        }
    }
}

void readParameters(Fields& top, ParameterSet& out) {
    if (const Json* params = top.get("parameters"))
        readParameterObject(top.reader(), *params, "parameters", out);
}

// Optional (added in 1.1): a file without "presets" has none. Names must be
// non-empty and unique, since the editor lists and picks presets by name.
void readPresets(Fields& top, std::vector<ParameterPreset>& out) {
    if (!top.has("presets"))
        return;
    out = readArray<ParameterPreset>(top, "presets", [](Fields& f) {
        ParameterPreset preset;
        f.text("name", preset.name);
        if (const Json* params = f.get("parameters"))
            readParameterObject(f.reader(), *params, f.pathOf("parameters"), preset.parameters);
        return preset;
    });
    Reader& r = top.reader();
    for (std::size_t i = 0; i < out.size() && r.ok(); ++i) {
        const std::string at = indexPath("presets", i) + ".name";
        if (out[i].name.empty())
            r.fail(ErrorCode::InvalidValue, at, "a preset needs a name");
        for (std::size_t j = 0; j < i && r.ok(); ++j)
            if (out[j].name == out[i].name)
                r.fail(ErrorCode::InvalidValue, at,
                       concat("the preset name \"", out[i].name, "\" is already used by presets[", j, "]"));
    }
}

// Parent indices are already in range; a chain that comes back to an object
// it passed would make world matrices undefined. Each object is walked once.
void checkParentChains(Reader& r, const std::vector<Object>& objects) {
    enum class State : unsigned char { Unvisited, OnChain, ReachesRoot };
    std::vector<State> state(objects.size(), State::Unvisited);
    std::vector<std::size_t> chain;
    for (std::size_t start = 0; start < objects.size(); ++start) {
        chain.clear();
        std::size_t i = start;
        while (state[i] == State::Unvisited) {
            state[i] = State::OnChain;
            chain.push_back(i);
            if (objects[i].parent < 0)
                break;
            i = static_cast<std::size_t>(objects[i].parent);
        }
        if (state[i] == State::OnChain && objects[i].parent >= 0) {
            const auto first = std::find(chain.begin(), chain.end(), i);
            const std::span<const std::size_t> loop(first, chain.end());
            // A loop of 100,000 objects is named by its ends and its length, not listed.
            constexpr std::size_t kHead = 8;
            constexpr std::size_t kTail = 2;
            std::string text;
            for (std::size_t k = 0; k < loop.size(); ++k) {
                if (loop.size() > kHead + kTail + 1 && k == kHead) {
                    text += "... -> ";
                    k = loop.size() - kTail;
                }
                text += std::to_string(loop[k]) + " -> ";
            }
            text += std::to_string(i);
            if (loop.size() > kHead + kTail + 1)
                text += concat(": a loop of ", loop.size(), " objects");
            r.fail(ErrorCode::InvalidValue, indexPath("objects", i) + ".parent",
                   concat("object \"", objects[i].name, "\" is its own ancestor (parent chain ", text, ")"));
            return;
        }
        for (const std::size_t c : chain)
            state[c] = State::ReachesRoot;
    }
}

// --- versions -----------------------------------------------------------------

// Format migrations: kMigrations[v - 1] turns a version-v document into a
// version v+1 one. Version 1 is the first format.
// When the format changes: bump kProjectFormatVersion, append one step that
// rewrites the JSON (rename fields, add new ones with the value that keeps the
// old behaviour), and never edit or drop an older step, so that every file
// ever written still loads. The result is then validated like any document of
// the current version.
using Migration = Json (*)(Json);

// 1 -> 2 (issue #22): area lights ("type": "area" and the fields only they
// have). A version-1 file has none, and every field it has keeps its meaning.
Json fromVersion1(Json document) { return document; }

constexpr std::array<Migration, static_cast<std::size_t>(kProjectFormatVersion - 1)> kMigrations{fromVersion1};

// The format name and version of a document (`what` is "project" or "camera
// path"); the version read, at most `newest`.
Expected<std::int64_t> checkFormat(const Json& document, const std::string& file, const char* formatName,
                                   std::int64_t newest, const char* what) {
    if (!document.is_object())
        return makeError(ErrorCode::UnknownFormat, file, "(top level)",
                         concat("not an LPV Studio ", what, ": the top level is ", typeOf(document),
                                ", not an object"));
    const auto format = document.find("format");
    if (format == document.end())
        return makeError(ErrorCode::UnknownFormat, file, "format",
                         concat("not an LPV Studio ", what, ": no \"format\" field (expected \"", formatName,
                                "\")"));
    if (!format->is_string() || format->get<std::string>() != formatName)
        return makeError(ErrorCode::UnknownFormat, file, "format",
                         concat("format is ", format->dump(), ", expected \"", formatName, "\""));

    const auto version = document.find("version");
    if (version == document.end())
        return makeError(ErrorCode::MissingField, file, "version", "required field \"version\" is missing");
    if (!version->is_number_integer())
        return makeError(ErrorCode::TypeMismatch, file, "version", "expected an integer, got " + typeOf(*version));
    // Unsigned first: a huge version must not wrap to a negative one.
    const bool huge =
        version->is_number_unsigned() && version->get<std::uint64_t>() > static_cast<std::uint64_t>(newest);
    if (huge || version->get<std::int64_t>() > newest)
        return makeError(ErrorCode::NewerVersion, file, "version",
                         concat(what, " format version ", version->dump(), " is newer than this build reads (up to "
                                "version ", newest, "); open it with a newer LPV Studio"));
    const std::int64_t from = version->get<std::int64_t>();
    if (from < 1)
        return makeError(ErrorCode::OutOfRange, file, "version",
                         concat(what, " format version ", from, " does not exist (the first is 1)"));
    return from;
}

Expected<Json> upgradeToCurrentVersion(const Json& document, const std::string& file) {
    const auto checked = checkFormat(document, file, kProjectFormatName, kProjectFormatVersion, "project");
    if (!checked)
        return std::unexpected(checked.error());
    const std::int64_t from = *checked;

    Json current = document;
    const std::span<const Migration> steps(kMigrations);
    for (std::int64_t v = from; v < kProjectFormatVersion; ++v)
        current = steps[static_cast<std::size_t>(v - 1)](std::move(current));
    current["version"] = kProjectFormatVersion;
    return current;
}

// --- writing ------------------------------------------------------------------

// The shortest decimal that reads back as `f` ("0.8", not 0.800000011920929),
// as a double that nlohmann prints exactly that way. Falls back to the exact
// double value in the unlikely case the decimal rounds differently through
// double than directly to float.
Json number(float f) {
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, f);
    double d = 0.0;
    if (ec == std::errc() && std::from_chars(buffer, end, d).ec == std::errc() && static_cast<float>(d) == f)
        return d;
    return static_cast<double>(f);
}

template <glm::length_t L, glm::qualifier Q>
Json numbers(const glm::vec<L, float, Q>& v) {
    Json out = Json::array();
    for (glm::length_t i = 0; i < L; ++i)
        out.push_back(number(v[i]));
    return out;
}

Json numbers(const glm::quat& q) { return Json::array({number(q.x), number(q.y), number(q.z), number(q.w)}); }

template <class T> Json arrayOf(const std::vector<T>& items);

// One field's JSON form, following its C++ type (the reader's readField).
template <class T> Json fieldJson(const T& v) {
    if constexpr (std::is_same_v<T, float>)
        return number(v);
    else if constexpr (std::is_enum_v<T>)
        return toString(v);
    else if constexpr (std::is_same_v<T, std::string> || std::is_same_v<T, bool> || std::is_same_v<T, int>)
        return v;
    else if constexpr (requires {
                           v.size();
                           typename T::value_type;
                       })
        return arrayOf(v);
    else
        return numbers(v);
}

// Every field of S that applies and is written, in table order (the order
// files have always listed them).
template <class S> Json toJson(const S& s) {
    Json j = Json::object();
    forEachField<S>([&](const auto& field) {
        if (field.appliesTo(s) && (!field.written || field.written(s)))
            j[field.name] = fieldJson(field.of(s));
    });
    return j;
}

Json toJson(const Mesh& m, const std::string& asset) {
    Json j = Json::object();
    j["name"] = m.name;
    j["asset"] = asset;
    j["vertices"] = m.positions.size();
    j["triangles"] = m.triangleCount();
    return j;
}

// The shortest decimal number of degrees that reads back as `radians` exactly.
Json degreesNumber(float radians) {
    const double exact = degreesFromRadians(radians);
    for (int digits = 1; digits <= 17; ++digits) {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.*g", digits, exact);
        double d = 0.0;
        const auto [end, ec] = std::from_chars(buffer, buffer + std::strlen(buffer), d);
        if (ec == std::errc() && radiansFromDegrees(d) == radians)
            return d;
    }
    return exact;
}

// Only the overrides, sorted by key (ParameterSet keeps them sorted).
Json toJson(const ParameterSet& parameters) {
    Json out = Json::object();
    for (const auto& [key, value] : parameters.overrides())
        out[key] = std::visit([](const auto& v) { return Json(v); }, value);
    return out;
}

template <class T>
Json arrayOf(const std::vector<T>& items) {
    Json out = Json::array();
    for (const T& item : items)
        out.push_back(toJson(item));
    return out;
}

} // namespace

Expected<void> checkAssetPath(const std::string& path, const std::string& file, const std::string& location) {
    const auto invalid = [&](const std::string& why) {
        return makeError(ErrorCode::InvalidValue, file, location,
                         concat("asset path \"", path, "\" ", why, "; assets must lie inside the project's folder"));
    };
    if (path.empty())
        return invalid("is empty");
    if (path.front() == '/')
        return invalid("is absolute");
    // ':' would be a drive letter or stream name on Windows, '\' a separator
    // there; control characters (NUL above all) could cut the name short.
    for (const char c : path)
        if (c == '\\' || c == ':' || static_cast<unsigned char>(c) < 0x20)
            return invalid("contains '\\', ':' or a control character");
    std::size_t start = 0;
    while (start <= path.size()) {
        const std::size_t end = std::min(path.find('/', start), path.size());
        const std::string_view part = std::string_view(path).substr(start, end - start);
        if (part.empty() || part == "." || part == "..")
            return invalid(part.empty() ? "has an empty component" : concat("has a \"", part, "\" component"));
        start = end + 1;
    }
    return {};
}

Expected<ProjectDocument> projectFromJson(const Json& document, const std::string& file) {
    const auto current = upgradeToCurrentVersion(document, file);
    if (!current)
        return std::unexpected(current.error());

    Reader r(file);
    ProjectDocument out;
    Scene& scene = out.project.scene;
    Fields top(r, *current, "");
    top.text("name", out.project.name);
    readSky(top, scene.sky);
    scene.materials = readStructs<Material>(top, "materials", {});
    out.meshes = readArray<MeshReference>(top, "meshes", readMeshReference);
    const Json* objects = top.array("objects");
    const IndexCounts counts{out.meshes.size(), objects ? objects->size() : 0};
    scene.objects = readStructs<Object>(top, "objects", counts);
    scene.lights = readStructs<Light>(top, "lights", counts);
    scene.cameras = readStructs<Camera>(top, "cameras", counts);
    scene.cameraPaths = readStructs<CameraPath>(top, "cameraPaths", counts);
    readParameters(top, out.project.parameters);
    readPresets(top, out.project.presets);
    // Optional (added with issue #26): the editor's view when last saved.
    if (const Json* view = top.has("editorView") ? top.get("editorView") : nullptr) {
        Fields f(r, *view, "editorView");
        const Camera c = readStruct<Camera>(f, counts);
        if (r.ok())
            out.project.editorView = c;
    }
    if (r.ok())
        checkParentChains(r, scene.objects);
    if (r.ok())
        if (const auto problem = checkObjectChains(scene))
            r.fail(problem->code, problem->field, problem->message);
    if (!r.ok())
        return std::unexpected(r.error());
    return out;
}

Json projectToJson(const Project& project, const std::vector<std::string>& assetPaths) {
    const Scene& scene = project.scene;
    Json doc = Json::object();
    doc["format"] = kProjectFormatName;
    doc["version"] = kProjectFormatVersion;
    doc["name"] = project.name;
    doc["sky"] = toJson(scene.sky);
    doc["materials"] = arrayOf(scene.materials);
    Json meshes = Json::array();
    for (std::size_t i = 0; i < scene.meshes.size(); ++i)
        meshes.push_back(toJson(scene.meshes[i], i < assetPaths.size() ? assetPaths[i] : std::string()));
    doc["meshes"] = std::move(meshes);
    doc["objects"] = arrayOf(scene.objects);
    doc["lights"] = arrayOf(scene.lights);
    doc["cameras"] = arrayOf(scene.cameras);
    doc["cameraPaths"] = arrayOf(scene.cameraPaths);
    doc["parameters"] = toJson(project.parameters);
    // Only when there are any, so projects without presets keep the bytes
    // they had before presets existed.
    if (!project.presets.empty()) {
        Json presets = Json::array();
        for (const ParameterPreset& preset : project.presets) {
            Json j = Json::object();
            j["name"] = preset.name;
            j["parameters"] = toJson(preset.parameters);
            presets.push_back(std::move(j));
        }
        doc["presets"] = std::move(presets);
    }
    if (project.editorView)
        doc["editorView"] = toJson(*project.editorView);
    return doc;
}

Expected<CameraPath> cameraPathFromDocument(const Json& document, const std::string& file) {
    const auto version = checkFormat(document, file, kCameraPathFormatName, kCameraPathFormatVersion, "camera path");
    if (!version)
        return std::unexpected(version.error());
    Reader r(file);
    Fields top(r, document, "");
    CameraPath p;
    // The table's fields, but the keyframes name their field of view in degrees.
    forEachField<CameraPath>([&](const auto& field) {
        if (std::string_view(field.name) == "keyframes")
            p.keyframes = readArray<CameraKeyframe>(top, "keyframes", readPathFileKeyframe);
        else if (field.requiredIn(p) || top.has(field.name))
            readField(top, field, field.of(p), {});
    });
    if (top.ok())
        report(top, checkFieldRules(p));
    if (!r.ok())
        return std::unexpected(r.error());
    return p;
}

Json cameraPathToDocument(const CameraPath& p) {
    Json doc = Json::object();
    doc["format"] = kCameraPathFormatName;
    doc["version"] = kCameraPathFormatVersion;
    doc["name"] = p.name;
    doc["closed"] = p.closed;
    doc["constantSpeed"] = p.constantSpeed;
    Json keyframes = Json::array();
    for (const CameraKeyframe& k : p.keyframes) {
        Json j = Json::object();
        j["time"] = number(k.time);
        j["position"] = numbers(k.position);
        j["orientation"] = numbers(k.orientation);
        j["fovYDegrees"] = degreesNumber(k.fovY);
        keyframes.push_back(std::move(j));
    }
    doc["keyframes"] = std::move(keyframes);
    return doc;
}

namespace {

// Builds the document Json::parse would, in time linear in the number of
// keys. nlohmann's ordered_map finds a key by a linear search, so its parser
// took N^2/2 string comparisons for an object of N keys (100,000 unknown
// parameter keys: 6.9 s before the loader could name the first). Objects of a
// few keys keep that search; a larger one gets a hash index. A repeated key
// keeps its first place and its last value, as with Json::parse. A parse
// error is recorded, not thrown: where parsing stopped and the token there.
class DocumentBuilder final : public nlohmann::json_sax<Json> {
public:
    struct Failure {
        bool numberOverflow = false; // else a syntax error
        std::size_t position = 0;    // bytes read, which ends after the bad token
        std::string token;
        std::string what;
    };

    bool null() override { return add(Json(nullptr)); }
    bool boolean(bool v) override { return add(Json(v)); }
    bool number_integer(number_integer_t v) override { return add(Json(v)); }
    bool number_unsigned(number_unsigned_t v) override { return add(Json(v)); }
    bool number_float(number_float_t v, const string_t&) override { return add(Json(v)); }
    bool string(string_t& v) override { return add(Json(std::move(v))); }
    bool binary(binary_t&) override { return false; } // JSON text has no binary values
    bool start_object(std::size_t) override { return open(Json::object()); }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(Json::array()); }
    bool end_array() override { return close(); }

    bool key(string_t& k) override {
        Level& level = levels_.back();
        // ordered_map is a vector of pairs; as one, an index is a position and
        // appending skips the map's own key search.
        Json::object_t::Container& members = level.value->get_ref<Json::object_t&>();
        if (level.index.empty() && members.size() < kIndexedFrom) {
            for (auto& [name, value] : members)
                if (name == k) {
                    slot_ = &value;
                    return true;
                }
        } else {
            if (level.index.empty())
                for (std::size_t i = 0; i < members.size(); ++i)
                    level.index.emplace(members[i].first, i);
            if (const auto it = level.index.find(k); it != level.index.end()) {
                slot_ = &members[it->second].second;
                return true;
            }
            level.index.emplace(k, members.size());
        }
        members.emplace_back(std::move(k), nullptr);
        slot_ = &members.back().second;
        return true;
    }

    bool parse_error(std::size_t position, const std::string& lastToken, const Json::exception& e) override {
        // nlohmann reports a number too large for a double (1e999) as out_of_range 406.
        failure = Failure{e.id == 406, position, lastToken, e.what()};
        return false;
    }

    Json document;
    std::optional<Failure> failure;

private:
    static constexpr std::size_t kIndexedFrom = 16;

    struct Level {
        Json* value; // an object or an array
        std::unordered_map<std::string, std::size_t> index; // key -> member, once the object is large
    };

    // The new value's place: the root, the end of the open array, or the
    // open object's member named by the last key.
    Json* place(Json&& v) {
        if (levels_.empty()) {
            document = std::move(v);
            return &document;
        }
        Json& open = *levels_.back().value;
        if (open.is_array()) {
            auto& elements = open.get_ref<Json::array_t&>();
            elements.push_back(std::move(v));
            return &elements.back();
        }
        *slot_ = std::move(v);
        return slot_;
    }
    bool add(Json&& v) {
        place(std::move(v));
        return true;
    }
    bool open(Json&& v) {
        levels_.push_back(Level{place(std::move(v)), {}});
        return true;
    }
    bool close() {
        levels_.pop_back();
        return true;
    }

    std::vector<Level> levels_;
    Json* slot_ = nullptr;
};

// Far deeper than any project file (the format nests 6 levels). nlohmann
// parses any depth without recursion, but copying or dumping a document
// recurses once per level: 50,000 nested arrays (100 KB) overflowed the stack
// in upgradeToCurrentVersion (docs/fuzzing.md).
constexpr std::size_t kMaxJsonDepth = 64;

// The byte offset of the first '[' or '{' outside a string that opens level
// kMaxJsonDepth + 1, if there is one; the text need not be valid JSON.
std::optional<std::size_t> findTooDeep(const std::string& text) {
    std::size_t depth = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\')
                ++i; // the escaped character cannot end the string
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth)
                return i;
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
    return std::nullopt;
}

// "[json.exception.parse_error.101] parse error at line 1, column 8: ..." -> "line 1, column 8: ..."
std::string withoutExceptionPrefix(const std::string& what) {
    const std::string marker = "parse error at ";
    const std::size_t at = what.find(marker);
    return at == std::string::npos ? what : what.substr(at + marker.size());
}


// The encoding of text that is not UTF-8 but UTF-16 or UTF-32 (a byte-order
// mark, or the NUL bytes every ASCII character of those encodings carries).
std::optional<std::string> wideEncoding(const std::string& text) {
    auto starts = [&](std::string_view bom) { return text.compare(0, bom.size(), bom) == 0; };
    using namespace std::string_view_literals;
    if (starts("\xFF\xFE\x00\x00"sv))
        return "UTF-32 (little-endian)";
    if (starts("\x00\x00\xFE\xFF"sv))
        return "UTF-32 (big-endian)";
    if (starts("\xFF\xFE"sv))
        return "UTF-16 (little-endian)";
    if (starts("\xFE\xFF"sv))
        return "UTF-16 (big-endian)";
    if (text.size() >= 4 && text[0] != '\0' && text[1] == '\0' && text[2] != '\0' && text[3] == '\0')
        return "UTF-16 (little-endian, no byte-order mark)";
    if (text.size() >= 4 && text[0] == '\0' && text[1] != '\0' && text[2] == '\0' && text[3] != '\0')
        return "UTF-16 (big-endian, no byte-order mark)";
    return std::nullopt;
}

} // namespace

Expected<Json> parseProjectText(const std::string& text, const std::string& file) {
    if (text.empty())
        return makeError(ErrorCode::Truncated, file, atByte(0), "the file is empty");
    if (const auto encoding = wideEncoding(text))
        return makeError(ErrorCode::NotJson, file, atByte(0),
                         "the file is " + *encoding + " text; LPV Studio reads UTF-8 JSON (convert it, e.g. "
                         "`iconv -f UTF-16 -t UTF-8`)");
    // Before parsing: the depth is checked on the text, so no parser or
    // document operation ever sees more than kMaxJsonDepth levels (a worker
    // thread's smaller stack included).
    if (const auto at = findTooDeep(text))
        return makeError(ErrorCode::InvalidValue, file, atByte(*at),
                         concat("the JSON nests more than ", kMaxJsonDepth,
                                " arrays and objects inside each other; no project file does"));
    DocumentBuilder builder;
    bool parsed = false;
    try {
        parsed = Json::sax_parse(text, &builder);
    } catch (const Json::exception& e) {
        return makeError(ErrorCode::NotJson, file, "", e.what());
    }
    if (parsed)
        return std::move(builder.document);
    if (!builder.failure)
        return makeError(ErrorCode::NotJson, file, "", "not valid JSON");
    const DocumentBuilder::Failure& failure = *builder.failure;
    if (failure.numberOverflow)
        return makeError(ErrorCode::NonFinite, file,
                         atByte(failure.position >= failure.token.size() ? failure.position - failure.token.size() : 0),
                         "the number " + failure.token + " is too large to be finite");
    // nlohmann counts bytes from 1; an error past the last byte means the text stopped early.
    const std::size_t offset = failure.position > 0 ? failure.position - 1 : 0;
    if (offset >= text.size())
        return makeError(ErrorCode::Truncated, file, atByte(text.size()),
                         "the file ends in the middle of the JSON (cut off?): " + withoutExceptionPrefix(failure.what));
    return makeError(ErrorCode::NotJson, file, atByte(offset), "not valid JSON: " + withoutExceptionPrefix(failure.what));
}

} // namespace lpv::scene::detail
