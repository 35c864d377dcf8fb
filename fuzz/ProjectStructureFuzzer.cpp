// libFuzzer target fuzz_project_structure: loadProject like fuzz_project, fed
// by a structure-aware mutator (LLVMFuzzerCustomMutator) that edits the
// project as JSON instead of as bytes, so mutations stay parseable and reach
// the field, index, asset and parameter checks behind the JSON parser.
//
// An input is the project file's bytes, as in fuzz_project (a finding here
// replays there too). The mutator parses it with nlohmann::json and applies
// one to three of: a value of the wrong type; extreme numbers (2^31, 2^64,
// -1, 1e308, 1e999, -0); hostile strings (300 and 100,000 characters,
// "../../etc/passwd", "%2e%2e/", ".", a NUL, invalid UTF-8, another field's
// enum value); unknown keys (up to 100,000); duplicated array elements and
// duplicated keys; a deleted field; one subtree copied over another; nesting
// 63 to 100,000 levels deep (arrays, objects, unterminated, inside a string);
// parent chains (a chain of thousands of objects, a cycle, an index out of
// range); registry parameters with values at, past and beside their ranges;
// version and format changes; wrong mesh vertex and triangle counts; float
// extremes (FloatExtremes.h: +-0, denormals, +-3.4e38, 1e30, NaN and
// Infinity as text) in one number, one vector, every number of an object
// or of the whole project, and degenerate cameras, lights and paths. The
// text is then sometimes re-encoded (UTF-16 LE/BE, UTF-32, a UTF-8 byte order
// mark), cut short or given trailing bytes. Inputs that do not parse, or nest
// deeper than the mutator itself walks, get libFuzzer's byte mutations or
// restart from the Cornell box project.
//
// Values that JSON cannot carry (1e999, invalid UTF-8, duplicate keys, deep
// nesting) go into the tree as placeholder strings "\u0001lpvfuzz:N" and are
// replaced with their text after serialisation.
//
// Inputs grow to -max_len (256 KiB in scripts/fuzz.sh: 100,000 levels of
// nested arrays fit, about 13,000 unknown keys, a chain of about 1,800
// objects); a count that would not fit is cut to what does. The generated
// seeds with 100,000 unknown keys and a 10,000-object chain (1.1 and 1.4 MB)
// are run whole once by scripts/fuzz.sh before fuzzing.
#include "FloatExtremes.h"
#include "ProjectInput.h"
#include "SceneChecks.h"
#include "WorkFolder.h"

#include "lpv/scene/ParameterRegistry.h"
#include "lpv/scene/Project.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

extern "C" size_t LLVMFuzzerMutate(std::uint8_t* data, size_t size, size_t maxSize);

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using Rng = std::mt19937_64;

// Deeper inputs are not parsed by the mutator: nlohmann copies and
// serialises recursively, and the mutator must not overflow its own stack.
constexpr int kMaxTreeDepth = 256;
constexpr std::string_view kPlaceholderPrefix = "\x01lpvfuzz:";

fs::path gProjectFile;
Json gCornellBox;                // the committed project, a base when an input is not JSON
std::vector<std::string> gWords; // keys, enum values and strings of the Cornell box and the registry

// ----- small helpers

std::size_t below(Rng& rng, std::size_t n) {
    return n == 0 ? 0 : std::size_t(rng() % n);
}
bool oneIn(Rng& rng, std::size_t n) {
    return below(rng, n) == 0;
}
template <class T> const T& pick(Rng& rng, const std::vector<T>& v) {
    return v[below(rng, v.size())];
}

// How many of something to add: mostly a few, sometimes hundreds or
// thousands, rarely `most`. Inputs that grow large stay in the corpus (their
// loops reach new hit counts) and slow every later execution, so size is
// spent sparingly.
std::size_t howMany(Rng& rng, std::size_t most) {
    const std::size_t roll = below(rng, 32);
    if (roll < 16)
        return 1 + below(rng, 2);
    if (roll < 26)
        return 16 + below(rng, 100);
    if (roll < 31)
        return 1000 + below(rng, 1000);
    return most;
}

// Nesting depth of JSON text, ignoring brackets inside strings.
int nestingDepth(std::string_view text) {
    int depth = 0, deepest = 0;
    bool inString = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return deepest;
}

// A place in the tree: the node, and where it hangs (for deletion).
struct Site {
    Json* node = nullptr;
    Json* parent = nullptr; // null for the root
    std::string key;        // in an object parent
    std::size_t index = 0;  // in an array parent
};

std::vector<Site> collectSites(Json& root) {
    std::vector<Site> sites{{&root, nullptr, {}, 0}};
    for (std::size_t i = 0; i < sites.size(); ++i) {
        Json* node = sites[i].node;
        if (node->is_object())
            for (auto it = node->begin(); it != node->end(); ++it)
                sites.push_back({&it.value(), node, it.key(), 0});
        else if (node->is_array())
            for (std::size_t k = 0; k < node->size(); ++k)
                sites.push_back({&(*node)[k], node, {}, k});
    }
    return sites;
}

// A random site for which `accept` holds (a few tries, then any non-root site, else the root).
template <class Accept> Site pickSite(Rng& rng, const std::vector<Site>& sites, Accept accept) {
    for (int attempt = 0; attempt < 16; ++attempt) {
        const Site& s = pick(rng, sites);
        if (accept(*s.node))
            return s;
    }
    std::vector<Site> matching;
    for (const Site& s : sites)
        if (accept(*s.node))
            matching.push_back(s);
    if (!matching.empty())
        return pick(rng, matching);
    return sites.size() > 1 ? sites[1 + below(rng, sites.size() - 1)] : sites[0];
}

// ----- the mutation context: the tree, placeholders and the size budget

class Mutation {
  public:
    Mutation(Json& root, Rng& rng, std::size_t inputSize, std::size_t maxSize)
        : root_(root), rng_(rng), maxSize_(maxSize), estimate_(inputSize) {}

    // Room left, estimated from the input's size plus what was added.
    std::size_t budget() const { return estimate_ < maxSize_ ? maxSize_ - estimate_ : 0; }
    void grew(std::size_t bytes) { estimate_ += bytes; }

    // A string that serialisation turns into `text`, verbatim.
    Json raw(std::string text) {
        raws_.push_back(std::move(text));
        grew(raws_.back().size());
        return std::string(kPlaceholderPrefix) + std::to_string(raws_.size() - 1);
    }
    std::string rawKey(std::string text) { return raw(std::move(text)).get<std::string>(); }

    std::string serialise() const {
        std::string text = oneIn(rng_, 8) ? root_.dump(2, ' ', false, Json::error_handler_t::replace)
                                          : root_.dump(-1, ' ', false, Json::error_handler_t::replace);
        if (raws_.empty())
            return text;
        // nlohmann writes the control character 0x01 as \u0001.
        const std::string marker = "\"\\u0001lpvfuzz:";
        std::string out;
        out.reserve(text.size());
        std::size_t at = 0;
        for (std::size_t found; (found = text.find(marker, at)) != std::string::npos;) {
            std::size_t end = found + marker.size();
            std::size_t index = 0;
            while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end])))
                index = index * 10 + std::size_t(text[end++] - '0');
            if (end >= text.size() || text[end] != '"' || index >= raws_.size()) {
                out.append(text, at, end - at);
                at = end;
                continue;
            }
            out.append(text, at, found - at);
            out += raws_[index];
            at = end + 1;
        }
        out.append(text, at, std::string::npos);
        return out;
    }

    Json& root() { return root_; }
    Rng& rng() { return rng_; }

  private:
    Json& root_;
    Rng& rng_;
    std::size_t maxSize_;
    std::size_t estimate_;
    std::vector<std::string> raws_;
};

// ----- values

Json anyValue(Mutation& m) {
    Rng& rng = m.rng();
    switch (below(rng, 12)) {
    case 0:
        return nullptr;
    case 1:
        return bool(rng() & 1);
    case 2:
        return std::int64_t(rng() % 9) - 2;
    case 3:
        return 0.5;
    case 4:
        return "";
    case 5:
        return pick(rng, gWords);
    case 6:
        return Json::array();
    case 7:
        return Json::object();
    case 8:
        return Json::array({0.0, 0.0, 0.0});
    case 9:
        return Json::array({0.0, 0.0, 0.0, 1.0});
    case 10:
        return Json::object({{pick(rng, gWords), 1}});
    default:
        return Json::array({1, "a", nullptr});
    }
}

Json wrongType(Mutation& m, const Json& old) {
    for (int attempt = 0; attempt < 8; ++attempt) {
        Json v = anyValue(m);
        if (v.type() != old.type())
            return v;
    }
    return old.is_null() ? Json(0) : Json(nullptr);
}

Json extremeNumber(Mutation& m, const Json& old) {
    Rng& rng = m.rng();
    static const std::vector<Json> numbers = {-1,
                                              0,
                                              1,
                                              2,
                                              3,
                                              4,
                                              5,
                                              63,
                                              64,
                                              65,
                                              255,
                                              256,
                                              65535,
                                              65536,
                                              std::numeric_limits<std::int32_t>::max(),
                                              std::int64_t{1} << 31,
                                              std::int64_t{1} << 32,
                                              std::numeric_limits<std::int32_t>::min(),
                                              std::int64_t{-1} - (std::int64_t{1} << 31),
                                              (std::int64_t{1} << 53) + 1,
                                              std::numeric_limits<std::int64_t>::max(),
                                              std::numeric_limits<std::int64_t>::min(),
                                              std::numeric_limits<std::uint64_t>::max(),
                                              0.5,
                                              -0.5,
                                              1e-7,
                                              1e-30,
                                              1e-45,
                                              5e-324,
                                              1e30,
                                              3.4e38,
                                              3.5e38,
                                              1e300,
                                              1.7976931348623157e308,
                                              -1e308,
                                              -0.0,
                                              0.1,
                                              0.7853982,
                                              3.14159265,
                                              6.2831853,
                                              1e6};
    switch (below(rng, 8)) {
    case 0: {
        static const std::vector<std::string> rawNumbers = {"1e999",
                                                            "-1e999",
                                                            "18446744073709551616",
                                                            "-9223372036854775809",
                                                            "1e-400",
                                                            "-0",
                                                            "0e0",
                                                            "1E+2",
                                                            "00",
                                                            "01",
                                                            "1.",
                                                            ".5",
                                                            "+1",
                                                            "0x10",
                                                            "NaN",
                                                            "Infinity",
                                                            "-Infinity",
                                                            "1e",
                                                            "--1"};
        return m.raw(pick(rng, rawNumbers));
    }
    case 1:
        if (old.is_number()) {
            const double d = old.get<double>();
            static const double factors[] = {-1.0, 2.0, 0.5, 1e6, 1e-6, 1e30};
            return d * factors[below(rng, std::size(factors))];
        }
        [[fallthrough]];
    case 2:
        if (old.is_number_integer())
            return old.get<std::int64_t>() + (oneIn(rng, 2) ? 1 : -1);
        [[fallthrough]];
    default:
        return pick(rng, numbers);
    }
}

Json hostileString(Mutation& m) {
    Rng& rng = m.rng();
    static const std::vector<std::string> strings = {"",
                                                     ".",
                                                     "..",
                                                     "/",
                                                     "\\",
                                                     "../../../../../../etc/passwd",
                                                     "/etc/passwd",
                                                     "/dev/zero",
                                                     "/dev/stdin",
                                                     "/proc/self/mem",
                                                     "/tmp",
                                                     "cornell-box.assets",
                                                     "cornell-box.assets/",
                                                     "cornell-box.assets/meshes",
                                                     "cornell-box.assets/meshes/",
                                                     "cornell-box.assets/../cornell-box.lpvproj",
                                                     "cornell-box.assets/meshes/../../../../etc/passwd",
                                                     "cornell-box.assets/%2e%2e/%2e%2e/etc/passwd",
                                                     "%2e%2e/%2e%2e/etc/passwd",
                                                     "..\\..\\..\\windows\\win.ini",
                                                     "C:\\Windows\\win.ini",
                                                     "\\\\server\\share\\x",
                                                     "file:///etc/passwd",
                                                     "cornell-box.assets/meshes/0-27dbdbce914cebff.lpvmesh",
                                                     "cornell-box.assets/meshes/3-26198fc42f5b9973.lpvmesh",
                                                     "cornell-box.assets/radiosity.lpvrad",
                                                     "cornell-box.lpvproj",
                                                     std::string("a\0b", 3),
                                                     "\t\n",
                                                     "\xc3\xa9\xe2\x82\xac\xf0\x9f\x92\xa1",
                                                     "NaN",
                                                     "true",
                                                     "null",
                                                     "0"};
    switch (below(rng, 7)) {
    case 0:
        return std::string(300, 'a');
    case 1: {
        const std::size_t length = std::min({howMany(rng, 1000) * 100, std::size_t{100000}, m.budget() / 2});
        m.grew(length);
        return std::string(length, oneIn(rng, 2) ? 'x' : '/');
    }
    case 2: {
        std::string dots;
        for (int i = 0; i < 100; ++i)
            dots += "../";
        return dots + "etc/passwd";
    }
    case 3: {
        static const std::vector<std::string> invalidUtf8 = {
            "\"\xff\xfe\"", "\"\xc3\"",    "\"\xed\xa0\x80\"",   "\"\xf4\x90\x80\x80\"",
            "\"\xc0\xaf\"", "\"\\ud800\"", "\"\\udc00\\ud800\"", "\"\\u0000\""};
        return m.raw(pick(rng, invalidUtf8));
    }
    case 4:
        return pick(rng, gWords);
    default:
        return pick(rng, strings);
    }
}

// `depth` levels of nesting around a number, as text.
std::string nested(Rng& rng, std::size_t depth) {
    std::string out;
    switch (below(rng, 5)) {
    case 0: // arrays
        out.append(depth, '[');
        out += '0';
        out.append(depth, ']');
        break;
    case 1: // objects
        for (std::size_t i = 0; i < depth; ++i)
            out += "{\"a\":";
        out += '0';
        out.append(depth, '}');
        break;
    case 2: // unterminated
        out.append(depth, oneIn(rng, 2) ? '[' : '{');
        break;
    case 3: // brackets in a string are not nesting
        out = '"' + std::string(depth, '[') + '"';
        break;
    default: // arrays of objects
        for (std::size_t i = 0; i < depth; ++i)
            out += i % 2 ? "{\"a\":" : "[";
        out += '0';
        for (std::size_t i = depth; i-- > 0;)
            out += i % 2 ? '}' : ']';
        break;
    }
    return out;
}

// ----- mutations (each returns false when it did nothing)

bool replaceWithWrongType(Mutation& m, std::vector<Site>& sites) {
    Site s = pickSite(m.rng(), sites, [](const Json&) { return true; });
    *s.node = wrongType(m, *s.node);
    return true;
}

bool replaceNumber(Mutation& m, std::vector<Site>& sites) {
    Site s = pickSite(m.rng(), sites, [](const Json& j) { return j.is_number(); });
    *s.node = extremeNumber(m, *s.node);
    return true;
}

bool replaceString(Mutation& m, std::vector<Site>& sites) {
    Site s = pickSite(m.rng(), sites, [](const Json& j) { return j.is_string(); });
    *s.node = hostileString(m);
    return true;
}

bool addUnknownKeys(Mutation& m, std::vector<Site>& sites) {
    Site s = pickSite(m.rng(), sites, [](const Json& j) { return j.is_object(); });
    if (!s.node->is_object())
        return false;
    // "unknownNNNNNN":0, is about 18 bytes.
    const std::size_t count = std::min(howMany(m.rng(), 100000), m.budget() / 20);
    if (count == 0)
        return false;
    const bool sameValue = oneIn(m.rng(), 2);
    for (std::size_t i = 0; i < count; ++i)
        (*s.node)["unknown" + std::to_string(i)] = sameValue ? Json(0) : anyValue(m);
    m.grew(count * 20);
    return true;
}

bool duplicateElement(Mutation& m, std::vector<Site>& sites) {
    Site s = pickSite(m.rng(), sites, [](const Json& j) { return j.is_array() && !j.empty(); });
    if (!s.node->is_array() || s.node->empty())
        return false;
    const Json element = (*s.node)[below(m.rng(), s.node->size())];
    const std::size_t elementSize = element.dump(-1, ' ', false, Json::error_handler_t::replace).size() + 1;
    const std::size_t count = std::min(howMany(m.rng(), 10000), m.budget() / elementSize);
    if (count == 0)
        return false;
    const std::size_t at = below(m.rng(), s.node->size() + 1);
    s.node->insert(s.node->begin() + std::ptrdiff_t(at), count, element);
    m.grew(count * elementSize);
    return true;
}

bool duplicateKey(Mutation& m, std::vector<Site>& sites) {
    Site s = pickSite(m.rng(), sites, [](const Json& j) { return j.is_object() && !j.empty(); });
    if (!s.node->is_object() || s.node->empty())
        return false;
    auto it = s.node->begin();
    std::advance(it, std::ptrdiff_t(below(m.rng(), s.node->size())));
    const std::string key = it.key();
    Json value = oneIn(m.rng(), 2) ? it.value() : anyValue(m);
    (*s.node)[m.rawKey(Json(key).dump(-1, ' ', false, Json::error_handler_t::replace))] = std::move(value);
    return true;
}

bool removeSite(Mutation& m, std::vector<Site>& sites) {
    if (sites.size() < 2)
        return false;
    const Site& s = sites[1 + below(m.rng(), sites.size() - 1)];
    if (s.parent->is_object())
        s.parent->erase(s.key);
    else
        s.parent->erase(s.index);
    return true;
}

bool copySubtree(Mutation& m, std::vector<Site>& sites) {
    const Site& from = pick(m.rng(), sites);
    const Site& to = pick(m.rng(), sites);
    Json copy = *from.node; // a copy first: `to` may lie inside `from`
    const std::size_t size = copy.dump(-1, ' ', false, Json::error_handler_t::replace).size();
    if (size > m.budget())
        return false;
    *to.node = std::move(copy);
    m.grew(size);
    return true;
}

bool nestDeeply(Mutation& m, std::vector<Site>& sites) {
    // Mostly around the loader's limit of 64 levels; 100,000 levels is 200 KB to 600 KB of text.
    static const std::size_t depths[] = {63, 64, 65, 66, 63, 64, 65, 66, 100, 1000, 10000, 100000};
    const std::size_t depth = depths[below(m.rng(), std::size(depths))];
    if (depth * 6 > m.budget())
        return false;
    Site s = pickSite(m.rng(), sites, [](const Json&) { return true; });
    *s.node = m.raw(nested(m.rng(), depth));
    return true;
}

Json& objectsArray(Mutation& m) {
    Json& root = m.root();
    if (!root.is_object())
        root = gCornellBox;
    if (!root.contains("objects") || !root["objects"].is_array() || root["objects"].empty())
        root["objects"] = gCornellBox["objects"];
    return root["objects"];
}

bool mutateParents(Mutation& m, std::vector<Site>&) {
    Rng& rng = m.rng();
    Json& objects = objectsArray(m);
    const std::int64_t n = std::int64_t(objects.size());
    const std::size_t i = below(rng, objects.size());
    if (!objects[i].is_object())
        objects[i] = gCornellBox["objects"][0];
    switch (below(rng, 6)) {
    case 0: { // a long chain: each new object the child of the one before
        Json templateObject = objects[i];
        const std::size_t objectSize =
            templateObject.dump(-1, ' ', false, Json::error_handler_t::replace).size() + 8;
        const std::size_t length = std::min(howMany(rng, 100000), m.budget() / objectSize);
        if (length == 0)
            return false;
        for (std::size_t k = 0; k < length; ++k) {
            templateObject["parent"] =
                k == 0 ? Json(oneIn(rng, 2) ? -1 : std::int64_t(i)) : Json(n + std::int64_t(k) - 1);
            templateObject["name"] = "chain" + std::to_string(k);
            objects.push_back(templateObject);
        }
        m.grew(length * objectSize);
        return true;
    }
    case 1:
        objects[i]["parent"] = std::int64_t(i);
        return true; // its own parent
    case 2: {        // a cycle of two or through the chain
        const std::size_t j = below(rng, objects.size());
        if (!objects[j].is_object())
            return false;
        objects[i]["parent"] = std::int64_t(j);
        objects[j]["parent"] = std::int64_t(i);
        return true;
    }
    case 3: { // every object the child of the next: one chain, then a cycle at the end or not
        for (std::int64_t k = 0; k < n; ++k)
            if (objects[std::size_t(k)].is_object())
                objects[std::size_t(k)]["parent"] = k + 1 < n ? k + 1 : (oneIn(rng, 2) ? -1 : 0);
        return true;
    }
    case 4: {
        const std::vector<Json> outOfRange = {
            -2, n, n + 1, std::numeric_limits<std::int32_t>::max(), std::int64_t{1} << 32, -1.5, 0.5};
        objects[i][oneIn(rng, 3) ? "mesh" : "parent"] = pick(rng, outOfRange);
        return true;
    }
    default: { // LODs naming meshes, in and out of range
        Json lod = {{"mesh", std::int64_t(below(rng, 6)) - 1}, {"distance", extremeNumber(m, 1.0)}};
        objects[i]["lods"] = Json::array({lod, lod});
        return true;
    }
    }
}

bool mutateParameter(Mutation& m, std::vector<Site>&) {
    Rng& rng = m.rng();
    Json& root = m.root();
    if (!root.is_object())
        root = gCornellBox;
    if (!root.contains("parameters") || !root["parameters"].is_object())
        root["parameters"] = Json::object();
    const auto& all = lpv::scene::ParameterRegistry::instance().all();
    const lpv::scene::ParameterInfo& p = pick(rng, all);
    Json value;
    switch (below(rng, 8)) {
    case 0:
        value = p.minValue;
        break;
    case 1:
        value = p.maxValue;
        break;
    case 2:
        value =
            p.maxValue + (p.type == lpv::scene::ParameterType::Int ? 1.0 : std::max(1e-3, p.maxValue * 1e-3));
        break;
    case 3:
        value = p.minValue - (p.type == lpv::scene::ParameterType::Int ? 1.0 : 1e-3);
        break;
    case 4:
        value = p.enumValues.empty() ? Json(pick(rng, gWords)) : Json(pick(rng, p.enumValues));
        break;
    case 5:
        value = (p.minValue + p.maxValue) / 2 + 0.25;
        break; // a fraction for an integer
    case 6:
        value = extremeNumber(m, 1.0);
        break;
    default:
        value = wrongType(m, Json(0.5));
        break;
    }
    root["parameters"][oneIn(rng, 16) ? p.key + "x" : p.key] = std::move(value);
    return true;
}

bool mutateHeader(Mutation& m, std::vector<Site>&) {
    Rng& rng = m.rng();
    Json& root = m.root();
    if (!root.is_object())
        root = gCornellBox;
    if (oneIn(rng, 2)) {
        static const std::vector<Json> versions = {0,   1,   2,      3, -1, 999, std::int64_t{1} << 32,
                                                   1.5, "2", nullptr};
        root["version"] = pick(rng, versions);
    } else {
        static const std::vector<Json> formats = {
            "lpvstudio-project", "lpvstudio-project ", "LPVSTUDIO-PROJECT", "lpvstudio", "", 0};
        root["format"] = pick(rng, formats);
    }
    return true;
}

bool mutateMeshCounts(Mutation& m, std::vector<Site>&) {
    Rng& rng = m.rng();
    Json& root = m.root();
    if (!root.is_object())
        root = gCornellBox;
    if (!root.contains("meshes") || !root["meshes"].is_array() || root["meshes"].empty())
        root["meshes"] = gCornellBox["meshes"];
    Json& mesh = root["meshes"][below(rng, root["meshes"].size())];
    if (!mesh.is_object())
        return false;
    const char* field = oneIn(rng, 2) ? "vertices" : "triangles";
    mesh[field] = extremeNumber(m, mesh.contains(field) ? mesh[field] : Json(10));
    if (oneIn(rng, 4)) // the asset of another mesh
        mesh["asset"] = pick(
            rng, std::vector<Json>{gCornellBox["meshes"][0]["asset"], gCornellBox["meshes"][3]["asset"]});
    return true;
}

// Float extremes (FloatExtremes.h) in one number, one vector, every number
// of one object, every number of the project (each with a chance of one in
// eight), or a degenerate camera, light or path.
bool plantFloatExtremes(Mutation& m, std::vector<Site>& sites) {
    Rng& rng = m.rng();
    const auto raw = [&m](const std::string& text) { return m.raw(text); };
    switch (below(rng, 5)) {
    case 0: {
        Site s = pickSite(rng, sites, [](const Json& j) { return j.is_number(); });
        return lpv::fuzz::plantInNumbers(*s.node, rng, 1, raw) > 0;
    }
    case 1: { // a vector: one component or all of them
        Site s = pickSite(rng, sites, [](const Json& j) {
            return j.is_array() && !j.empty() && j.size() <= 4 &&
                   std::all_of(j.begin(), j.end(), [](const Json& e) { return e.is_number(); });
        });
        return lpv::fuzz::plantInNumbers(*s.node, rng, oneIn(rng, 2) ? 1 : s.node->size(), raw) > 0;
    }
    case 2: {
        Site s = pickSite(rng, sites, [](const Json& j) { return j.is_object(); });
        return lpv::fuzz::plantInNumbers(*s.node, rng, 1 + below(rng, 2), raw) > 0;
    }
    case 3:
        return lpv::fuzz::plantInNumbers(m.root(), rng, 8, raw) > 0;
    default:
        return lpv::fuzz::plantDegenerateWhole(m.root(), rng);
    }
}

using MutationFn = bool (*)(Mutation&, std::vector<Site>&);
constexpr MutationFn kMutations[] = {
    replaceWithWrongType, replaceNumber,   replaceNumber,   replaceString, replaceString,    addUnknownKeys,
    duplicateElement,     duplicateKey,    removeSite,      copySubtree,   nestDeeply,       mutateParents,
    mutateParents,        mutateParameter, mutateParameter, mutateHeader,  mutateMeshCounts,
    plantFloatExtremes,   plantFloatExtremes, plantFloatExtremes,
};

// ----- text-level changes after serialisation

std::string widen(std::string_view text, int unit, bool bigEndian) {
    std::string out;
    out.reserve(text.size() * std::size_t(unit));
    for (const char c : text) {
        std::string code(std::size_t(unit), '\0');
        code[bigEndian ? std::size_t(unit - 1) : 0] = c;
        out += code;
    }
    return out;
}

void changeText(Rng& rng, std::string& text) {
    switch (below(rng, 24)) {
    case 0:
        text = "\xff\xfe" + widen(text, 2, false);
        break; // UTF-16 LE
    case 1:
        text = "\xfe\xff" + widen(text, 2, true);
        break; // UTF-16 BE
    case 2:
        text = widen(text, 2, false);
        break; // UTF-16 LE, no byte order mark
    case 3:
        text = std::string("\xff\xfe\0\0", 4) + widen(text, 4, false);
        break; // UTF-32 LE
    case 4:
        text = "\xef\xbb\xbf" + text;
        break; // UTF-8 byte order mark
    case 5:
        text.resize(below(rng, text.size() + 1));
        break; // cut short
    case 6:
        text += oneIn(rng, 2) ? std::string("\0", 1) : std::string(" x");
        break;
    case 7:
        text += oneIn(rng, 2) ? text : std::string("{}");
        break; // two documents
    default:
        break; // most inputs stay UTF-8 JSON
    }
}

std::size_t emit(const std::string& text, std::uint8_t* data, std::size_t maxSize) {
    if (text.size() > maxSize)
        return 0;
    std::memcpy(data, text.data(), text.size());
    return text.size();
}

// The input as a tree the mutator may walk, or null.
bool parseForMutation(std::string_view text, Json& out) {
    if (nestingDepth(text) > kMaxTreeDepth)
        return false;
    out = Json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
    return !out.is_discarded();
}

void collectWords(const Json& j) {
    std::vector<const Json*> todo{&j};
    while (!todo.empty()) {
        const Json* node = todo.back();
        todo.pop_back();
        if (node->is_object())
            for (auto it = node->begin(); it != node->end(); ++it) {
                gWords.push_back(it.key());
                todo.push_back(&it.value());
            }
        else if (node->is_array())
            for (const Json& element : *node)
                todo.push_back(&element);
        else if (node->is_string())
            gWords.push_back(node->get<std::string>());
    }
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    const fs::path folder = lpv::fuzz::makeCornellBoxFolder("project_structure", LPV_FUZZ_PROJECT_DIR);
    gProjectFile = folder / "cornell-box.lpvproj";
    std::ifstream in(fs::path(LPV_FUZZ_PROJECT_DIR) / "cornell-box.lpvproj", std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    gCornellBox = Json::parse(text.str(), nullptr, false);
    if (gCornellBox.is_discarded() || !gCornellBox.is_object())
        lpv::fuzz::setUpFailed("project_structure",
                               "cannot read the Cornell box project in " LPV_FUZZ_PROJECT_DIR);
    collectWords(gCornellBox);
    for (const lpv::scene::ParameterInfo& p : lpv::scene::ParameterRegistry::instance().all()) {
        gWords.push_back(p.key);
        gWords.insert(gWords.end(), p.enumValues.begin(), p.enumValues.end());
    }
    for (const char* word : {"blinnPhong", "metallicRoughness", "opaque", "mask", "blend", "point", "spot",
                             "directional", "area", "rectangle", "disc", "radiance", "power", "lods",
                             "distance", "keys", "time", "cameraPaths"})
        gWords.push_back(word);
    std::sort(gWords.begin(), gWords.end());
    gWords.erase(std::unique(gWords.begin(), gWords.end()), gWords.end());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    lpv::fuzz::loadAndCheckProject(gProjectFile, std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}

extern "C" size_t LLVMFuzzerCustomMutator(std::uint8_t* data, size_t size, size_t maxSize,
                                          unsigned int seed) {
    Rng rng(seed);
    // Some byte-level mutation keeps the parser's own error paths in reach.
    if (oneIn(rng, 8))
        return LLVMFuzzerMutate(data, size, maxSize);
    try {
        Json root;
        const std::string_view input(reinterpret_cast<const char*>(data), size);
        std::size_t baseSize = size;
        if (!parseForMutation(input, root)) {
            if (oneIn(rng, 2))
                return LLVMFuzzerMutate(data, size, maxSize);
            root = gCornellBox;
            baseSize = 6600; // the committed file, indented
        }
        for (int attempt = 0; attempt < 4; ++attempt) {
            Json tree = root;
            Mutation m(tree, rng, baseSize, maxSize);
            const std::size_t rounds = 1 + below(rng, 3);
            for (std::size_t r = 0; r < rounds; ++r) {
                std::vector<Site> sites = collectSites(tree);
                kMutations[below(rng, std::size(kMutations))](m, sites);
            }
            std::string text = m.serialise();
            changeText(rng, text);
            if (const std::size_t written = emit(text, data, maxSize); written > 0)
                return written;
        }
    } catch (const std::exception&) {
        // A mutation the tree refused (nlohmann type errors): mutate the bytes instead.
    }
    return LLVMFuzzerMutate(data, size, maxSize);
}

// Grafts a subtree of the second input into the first, both as JSON; plain
// halves when either is not JSON.
extern "C" size_t LLVMFuzzerCustomCrossOver(const std::uint8_t* data1, size_t size1,
                                            const std::uint8_t* data2, size_t size2, std::uint8_t* out,
                                            size_t maxOutSize, unsigned int seed) {
    Rng rng(seed);
    try {
        Json first, second;
        if (parseForMutation(std::string_view(reinterpret_cast<const char*>(data1), size1), first) &&
            parseForMutation(std::string_view(reinterpret_cast<const char*>(data2), size2), second)) {
            std::vector<Site> from = collectSites(second);
            std::vector<Site> to = collectSites(first);
            *pick(rng, to).node = *pick(rng, from).node;
            const std::string text = first.dump(-1, ' ', false, Json::error_handler_t::replace);
            if (const std::size_t written = emit(text, out, maxOutSize); written > 0)
                return written;
        }
    } catch (const std::exception&) {
    }
    const std::size_t head = std::min(size1 / 2, maxOutSize);
    const std::size_t tail = std::min(size2 - size2 / 2, maxOutSize - head);
    std::memcpy(out, data1, head);
    std::memcpy(out + head, data2 + size2 / 2, tail);
    return head + tail;
}
