#pragma once
// The numeric step of fuzz_project_structure's mutator (issue #42): float
// extremes planted in the project's numbers. Each value is one a float
// field can be handed through JSON and that broke a product downstream in
// the hand-made runs: +0 and -0, denormals (1e-45 is the smallest,
// 1e-38 the edge of the normal range), the largest floats (+-3.4e38, and
// 3.4028236e38, which JSON carries but a float rounds to infinity), 1e30 and
// 1e39 (finite as a double, infinite as a float), and as raw text what JSON
// cannot carry (NaN, Infinity, 1e999).
//
// Where they go: one field; one vector, one component or all of them; every
// number of one object (a camera, a light, a material); every number in the
// project, each with some chance; or a degenerate whole that no single value
// shows: a camera whose up is its view direction, a light whose direction
// vanishes, a far plane 1e83 times its near one.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace lpv::fuzz {

using FloatJson = nlohmann::json;

inline const std::vector<double>& floatExtremeValues() {
    static const std::vector<double> values = {
        0.0,  -0.0,  1e-45,  -1e-45,  1.4e-45,      1e-40,        1e-38, 1.17549435e-38, 1e-30, -1e-30,
        1e30, -1e30, 3.4e38, -3.4e38, 3.4028235e38, 3.4028236e38, 1e39,  -1e39,          1e-7,  16777217.0};
    return values;
}

inline const std::vector<std::string>& floatExtremeTexts() {
    static const std::vector<std::string> texts = {"NaN",   "-NaN",   "Infinity", "-Infinity", "inf",
                                                   "1e999", "-1e999", "1e-999",   "-0"};
    return texts;
}

// One extreme: mostly a number JSON holds, one time in six a text it cannot
// (through `raw`, the mutator's verbatim placeholder).
template <class Rng, class Raw> FloatJson floatExtreme(Rng& rng, Raw&& raw) {
    if (rng() % 6 == 0) {
        const auto& texts = floatExtremeTexts();
        return raw(texts[rng() % texts.size()]);
    }
    const auto& values = floatExtremeValues();
    return values[rng() % values.size()];
}

// Replaces each number under `node` with an extreme, each with chance
// 1/oneIn; returns how many. The walk is iterative: the mutator only parses
// trees up to its own depth limit, but a stack is not spent on them.
template <class Rng, class Raw>
std::size_t plantInNumbers(FloatJson& node, Rng& rng, std::size_t oneIn, Raw&& raw) {
    std::size_t planted = 0;
    std::vector<FloatJson*> todo{&node};
    while (!todo.empty()) {
        FloatJson* j = todo.back();
        todo.pop_back();
        if (j->is_number()) {
            if (oneIn <= 1 || rng() % oneIn == 0) {
                *j = floatExtreme(rng, raw);
                ++planted;
            }
        } else if (j->is_object() || j->is_array()) {
            for (auto& child : *j)
                todo.push_back(&child);
        }
    }
    return planted;
}

// A camera, light or path key made degenerate as a whole; false when the
// project has none of the array it picked.
template <class Rng> bool plantDegenerateWhole(FloatJson& root, Rng& rng) {
    const auto element = [&](const char* array) -> FloatJson* {
        if (!root.is_object() || !root.contains(array) || !root[array].is_array() || root[array].empty())
            return nullptr;
        FloatJson& a = root[array];
        FloatJson& e = a[rng() % a.size()];
        return e.is_object() ? &e : nullptr;
    };
    const auto vec = [](double x, double y, double z) { return FloatJson::array({x, y, z}); };
    switch (rng() % 6) {
    case 0: // up along the view direction (or against it, or a sliver off it)
        if (FloatJson* c = element("cameras"); c && c->contains("position") && c->contains("target") &&
                                               (*c)["position"].is_array() && (*c)["target"].is_array() &&
                                               (*c)["position"].size() == 3 && (*c)["target"].size() == 3) {
            FloatJson up = FloatJson::array();
            const double sign = rng() % 2 ? 1.0 : -1.0;
            for (std::size_t k = 0; k < 3; ++k) {
                const FloatJson& p = (*c)["position"][k];
                const FloatJson& t = (*c)["target"][k];
                if (!p.is_number() || !t.is_number())
                    return false;
                up.push_back(sign * (t.get<double>() - p.get<double>()) +
                             (k == 0 && rng() % 3 == 0 ? 1e-7 : 0.0));
            }
            (*c)["up"] = up;
            return true;
        }
        return false;
    case 1: // up vanishing: non-zero, but its square underflows
        if (FloatJson* c = element("cameras")) {
            (*c)["up"] = rng() % 2 ? vec(0.0, 1e-45, 0.0) : vec(1e-30, 1e-30, 0.0);
            return true;
        }
        return false;
    case 2: // the near plane at the smallest float, the far one at the largest
        if (FloatJson* c = element("cameras")) {
            (*c)["nearPlane"] = rng() % 2 ? 1e-45 : 1e-30;
            (*c)["farPlane"] = rng() % 2 ? 3.4e38 : 1e30;
            if (rng() % 2)
                (*c)["fovY"] = rng() % 2 ? 1e-45 : 1e-30;
            return true;
        }
        return false;
    case 3: // a direction that normalises to NaN
        if (FloatJson* l = element("lights")) {
            (*l)["direction"] = rng() % 2 ? vec(0.0, -1e-45, 0.0) : vec(0.0, 0.0, 0.0);
            return true;
        }
        return false;
    case 4: // each factor finite, the product not: colour x intensity x area
        if (FloatJson* l = element("lights")) {
            (*l)["intensity"] = rng() % 2 ? 3.4e38 : 1e30;
            (*l)["color"] = vec(3.4e38, 1.0, 1e30);
            (*l)["size"] = FloatJson::array({3e38, 3e38});
            (*l)["radius"] = 3e38;
            return true;
        }
        return false;
    default: { // a path that lasts 1e30 s (or ends at the largest float)
        if (!root.is_object())
            return false;
        const auto key = [](double time) {
            return FloatJson{{"time", time},
                             {"position", FloatJson::array({0.0, 1.0, 0.0})},
                             {"orientation", FloatJson::array({0.0, 0.0, 0.0, 1.0})},
                             {"fovY", 0.8}};
        };
        if (!root.contains("cameraPaths") || !root["cameraPaths"].is_array())
            root["cameraPaths"] = FloatJson::array();
        FloatJson path = {{"name", "fuzz"},
                          {"keyframes", FloatJson::array({key(0.0), key(rng() % 2 ? 1e30 : 3.4e38)})}};
        root["cameraPaths"].push_back(path);
        return true;
    }
    }
}

} // namespace lpv::fuzz
