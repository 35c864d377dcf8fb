// The rules between fields, and the texts made from the tables (SceneFields.h).
#include "lpv/scene/SceneFields.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

namespace lpv::scene {
namespace {

// Shortest text that reads back as the same value (so messages show what is in the file).
template <class T> std::string shortest(T v) {
    char buffer[64];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    return ec == std::errc() ? std::string(buffer, end) : std::string("?");
}

ValueProblem problem(ErrorCode code, std::string field, std::string message) {
    return ValueProblem{code, std::move(field), std::move(message)};
}

constexpr double kInfinity = std::numeric_limits<double>::infinity();

} // namespace

std::string FieldRange::describe() const {
    if (std::isinf(max))
        return (openMin ? "> " : ">= ") + shortest(min);
    return std::string(openMin ? "(" : "[") + shortest(min) + ", " + shortest(max) + (openMax ? ")" : "]");
}

std::optional<ValueProblem> checkFieldRules(const Light& l) {
    if (l.type == LightType::Area && l.shape == AreaShape::Rectangle) {
        const glm::vec3 d = l.direction == glm::vec3(0.0f) ? glm::vec3(0.0f) : glm::normalize(l.direction);
        const glm::vec3 t = l.tangent == glm::vec3(0.0f) ? glm::vec3(0.0f) : glm::normalize(l.tangent);
        if (l.tangent == glm::vec3(0.0f) || std::abs(glm::dot(d, t)) > 0.9999f)
            return problem(
                ErrorCode::InvalidValue, "tangent",
                "a rectangular area light needs a tangent that is not zero and not along its direction");
    }
    if (l.innerConeAngle > l.outerConeAngle)
        return problem(ErrorCode::OutOfRange, "innerConeAngle",
                       "inner cone angle " + shortest(l.innerConeAngle) + " exceeds the outer cone angle " +
                           shortest(l.outerConeAngle));
    // A point light has no direction; the others need one.
    if (l.type != LightType::Point && l.direction == glm::vec3(0.0f))
        return problem(ErrorCode::InvalidValue, "direction",
                       std::string("a ") + toString(l.type) + " light needs a non-zero direction");
    return checkLight(l);
}

std::optional<ValueProblem> checkFieldRules(const Camera& c) {
    if (c.farPlane <= c.nearPlane)
        return problem(ErrorCode::OutOfRange, "farPlane",
                       "far plane " + shortest(c.farPlane) + " is not beyond the near plane " +
                           shortest(c.nearPlane));
    // Both would make the view matrix NaN.
    if (c.position == c.target)
        return problem(ErrorCode::InvalidValue, "target", "the camera looks at its own position");
    if (c.up == glm::vec3(0.0f))
        return problem(ErrorCode::InvalidValue, "up", "the up vector is zero");
    return checkCamera(c);
}

// Playback interpolates between neighbours, which needs them in time order.
std::optional<ValueProblem> checkFieldRules(const CameraPath& p) {
    for (std::size_t i = 1; i < p.keyframes.size(); ++i)
        if (p.keyframes[i].time < p.keyframes[i - 1].time)
            return problem(ErrorCode::InvalidValue, "keyframes[" + std::to_string(i) + "].time",
                           "keyframe time " + shortest(p.keyframes[i].time) +
                               " is earlier than the previous keyframe's " +
                               shortest(p.keyframes[i - 1].time) + "; keyframes must be sorted by time");
    return std::nullopt;
}

FieldRange rangeGivenOthers(const Light& l, std::string_view field) {
    if (field == "innerConeAngle")
        return {0.0, double(l.outerConeAngle)};
    if (field == "outerConeAngle")
        return {double(l.innerConeAngle), kInfinity};
    return {};
}

FieldRange rangeGivenOthers(const Camera& c, std::string_view field) {
    // Strictly in front of the far plane, and within the depth buffer's ratio of it.
    if (field == "nearPlane")
        return {double(c.farPlane) / kMaxDepthRatio, double(c.farPlane), false, true};
    if (field == "farPlane")
        return {double(c.nearPlane), double(c.nearPlane) * kMaxDepthRatio, true, false};
    return {};
}

namespace {

template <class T> std::string typeName(const char* shape) {
    if (shape)
        return shape;
    if constexpr (std::is_same_v<T, std::string> || std::is_enum_v<T>)
        return "string";
    else if constexpr (std::is_same_v<T, bool>)
        return "boolean";
    else if constexpr (std::is_same_v<T, float>)
        return "number";
    else if constexpr (std::is_same_v<T, int>)
        return "integer";
    else if constexpr (std::is_same_v<T, glm::vec2>)
        return "[x, y]";
    else if constexpr (std::is_same_v<T, glm::vec3>)
        return "[x, y, z]";
    else if constexpr (std::is_same_v<T, glm::quat>)
        return "[x, y, z, w]";
    else
        return "array";
}

// "directional, point, spot, area" -> "`directional`, `point`, `spot` or `area`"
std::string quotedChoices(std::string_view allowed) {
    std::vector<std::string> names;
    for (std::size_t start = 0; start <= allowed.size();) {
        const std::size_t end = std::min(allowed.find(", ", start), allowed.size());
        names.emplace_back(allowed.substr(start, end - start));
        start = end + 2;
    }
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i)
        out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + ("`" + names[i] + "`");
    return out;
}

template <class S> std::string markdownOf() {
    std::ostringstream out;
    out << "| field | type | range | unit | notes |\n|---|---|---|---|---|\n";
    forEachField<S>([&](const auto& f) {
        using T = typename std::decay_t<decltype(f)>::Type;
        std::string range;
        if constexpr (std::is_enum_v<T>)
            range = quotedChoices(kEnumNames<T>.allowed);
        else if constexpr (std::is_same_v<T, int>)
            range =
                f.index == IndexOf::Meshes ? "-1 or an index into `meshes`" : "-1 or an index into `objects`";
        else if (f.range.bounded())
            range = (std::is_same_v<T, float> ? "" : "each ") + f.range.describe();
        std::string notes = f.optional ? "optional (1.1)" : "";
        if (*f.description)
            notes += (notes.empty() ? "" : ": ") + std::string(f.description);
        out << "|";
        for (const std::string& cell :
             {"`" + std::string(f.name) + "`", typeName<T>(f.shape), range, std::string(f.unit), notes})
            out << (cell.empty() ? "" : " " + cell) << " |";
        out << "\n";
    });
    return out.str();
}

} // namespace

std::string sceneFieldsMarkdown(std::string_view table) {
    if (table == "light")
        return markdownOf<Light>();
    if (table == "material")
        return markdownOf<Material>();
    if (table == "object")
        return markdownOf<Object>();
    if (table == "camera")
        return markdownOf<Camera>();
    if (table == "cameraPath")
        return markdownOf<CameraPath>() + "\nEach keyframe:\n\n" + markdownOf<CameraKeyframe>();
    if (table == "sky")
        return markdownOf<Sky>();
    return {};
}

std::vector<std::string> sceneFieldNames() {
    std::vector<std::string> names;
    const auto add = [&](const auto& f) { names.emplace_back(f.name); };
    forEachField<Light>(add);
    forEachField<Material>(add);
    forEachField<Object>(add);
    forEachField<LodLevel>(add);
    forEachField<Camera>(add);
    forEachField<CameraKeyframe>(add);
    forEachField<CameraPath>(add);
    forEachField<Sky>(add);
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

} // namespace lpv::scene
