#pragma once
// The one parameter registry (DESIGN.md): every tunable is declared once here.
// Project files, inspector panels, `lpv --set`, `lpv params` and benchmark
// sweeps are generated from it.
#include "lpv/scene/Error.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace lpv::scene {

enum class ParameterType { Bool, Int, Float, Enum };
const char* toString(ParameterType t);

// The passes a parameter change invalidates (bit flags), for the passes
// that had a bit before a pass could name itself in its own file
// (renderer/src/graph/PassId.h: a new pass needs no bit here; it lists the
// keys it reads in its PassSpec::parameters). One name per pass (passName):
// the frame graph's node, its GPU timer row, `lpv render --dump` and `--graph`.
enum class Pass : std::uint32_t {
    None = 0,
    ShadowMaps = 1u << 0,
    Rsm = 1u << 1,
    LpvInjection = 1u << 2,
    GeometryVolume = 1u << 3,
    LpvPropagation = 1u << 4,
    Shading = 1u << 5,
    SkyInjection = 1u << 6,
    Subsurface = 1u << 7,
    GlossyReflections = 1u << 8,
    SunRays = 1u << 9,
    Tonemap = 1u << 10,
    Radiosity = 1u << 11,
    Reference = 1u << 12,
    LocalRsm = 1u << 13,     // spot and point lights' RSM faces
    EmissiveVpls = 1u << 14, // emissive surfaces sampled into VPLs
    SkyHeight = 1u << 15,    // the sky injection's top-down depth map
    LpvNormals = 1u << 16,   // directed propagation's normals volume
    LpvBounces = 1u << 17,   // bounces 2.. lpv.bounces
    Exposure = 1u << 18,     // auto exposure's meter
    DepthPrepass = 1u << 19, // the camera's depth before shading
    // 1u << 20 was radiosityIndirect's: it names itself now (renderer/src/graph/PassId.h).
    LpvLookup = 1u << 21,         // the LPV's lookup at 1/2 or 1/4 of the view's resolution (lpv.lookupResolution)
};
constexpr Pass operator|(Pass a, Pass b) { return Pass(std::uint32_t(a) | std::uint32_t(b)); }
constexpr bool any(Pass a, Pass b) { return (std::uint32_t(a) & std::uint32_t(b)) != 0; }
std::vector<std::string> passNames(Pass passes);
// The name of one pass ("shadowMaps"); empty for None or several flags.
std::string passName(Pass pass);
// Every single pass, in frame order.
const std::vector<Pass>& allPasses();

// Enum values are stored as their name, so project files stay readable.
using ParameterValue = std::variant<bool, int, double, std::string>;

struct ParameterInfo {
    std::string key; // "group.name", e.g. "lpv.propagationSteps"
    ParameterType type = ParameterType::Float;
    ParameterValue defaultValue;
    double minValue = 0.0; // Int/Float only
    double maxValue = 0.0;
    // Enum: the choices. Float: words accepted besides a number in
    // [min, max] (lpv.cellSize's "auto": the renderer fits it to the scene).
    std::vector<std::string> enumValues;
    std::string unit;
    std::string description;
    std::string group; // display group: LPV, RSM, Shadows, Effects, Output, Radiosity, Reference
    Pass invalidates = Pass::None;

    bool operator==(const ParameterInfo&) const = default;
};

class ParameterRegistry {
public:
    // The registry of the product, built once; immutable afterwards.
    static const ParameterRegistry& instance();

    const std::vector<ParameterInfo>& all() const { return params_; }
    const ParameterInfo* find(std::string_view key) const;

    // Checks type and range; `where` names the source for the error (file or "--set").
    Expected<ParameterValue> validate(std::string_view key, const ParameterValue& value,
                                      const std::string& where) const;
    // Parses the text form ("8", "true", "computeGather", "0.5") of a value.
    Expected<ParameterValue> parse(std::string_view key, std::string_view text,
                                   const std::string& where) const;

    // The whole registry as JSON (for `lpv params --json`, tools and docs), and back.
    std::string toJson() const;
    static Expected<ParameterRegistry> fromJson(std::string_view json, const std::string& where);

    explicit ParameterRegistry(std::vector<ParameterInfo> params);

private:
    std::vector<ParameterInfo> params_;
};

std::string formatValue(const ParameterValue& v);

// Values set for one project or one run; unset keys read as their default.
class ParameterSet {
public:
    ParameterSet() = default;

    // Validated against the registry; returns the error unchanged on failure.
    Expected<void> set(std::string_view key, const ParameterValue& value, const std::string& where = "");
    Expected<void> setFromText(std::string_view key, std::string_view text, const std::string& where = "");
    void reset(std::string_view key);

    ParameterValue get(std::string_view key) const; // asserts the key exists
    bool getBool(std::string_view key) const;
    int getInt(std::string_view key) const;
    float getFloat(std::string_view key) const;
    std::string getEnum(std::string_view key) const;
    bool isSet(std::string_view key) const;
    // A Float parameter holding one of its words (e.g. lpv.cellSize = auto)
    // instead of a number; getFloat must not be asked for it then.
    bool isWord(std::string_view key, std::string_view word) const;

    // Only the keys that differ from defaults or were set explicitly, sorted by key.
    const std::vector<std::pair<std::string, ParameterValue>>& overrides() const { return values_; }

    bool operator==(const ParameterSet&) const = default;

private:
    std::vector<std::pair<std::string, ParameterValue>> values_;
};

} // namespace lpv::scene
