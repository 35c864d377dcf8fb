#include "lpv/bench/SavedSweep.h"

#include "lpv/bench/SweepRunJson.h"
#include "lpv/scene/FileRead.h"
#include "lpv/scene/Project.h"
#include "lpv/scene/SaveCleanup.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <set>

namespace lpv::bench {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

constexpr char kBase64[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

std::string toBase64(const std::vector<std::uint8_t>& bytes) {
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t n = std::uint32_t(bytes[i]) << 16 |
                                (i + 1 < bytes.size() ? std::uint32_t(bytes[i + 1]) << 8 : 0u) |
                                (i + 2 < bytes.size() ? std::uint32_t(bytes[i + 2]) : 0u);
        out += kBase64[n >> 18 & 63];
        out += kBase64[n >> 12 & 63];
        out += i + 1 < bytes.size() ? kBase64[n >> 6 & 63] : '=';
        out += i + 2 < bytes.size() ? kBase64[n & 63] : '=';
    }
    return out;
}

std::optional<std::vector<std::uint8_t>> fromBase64(const std::string& text) {
    if (text.size() % 4 != 0)
        return std::nullopt;
    std::vector<std::uint8_t> out;
    out.reserve(text.size() / 4 * 3);
    for (std::size_t i = 0; i < text.size(); i += 4) {
        std::uint32_t n = 0;
        int pad = 0;
        for (int k = 0; k < 4; ++k) {
            const char c = text[i + std::size_t(k)];
            const char* at = std::char_traits<char>::find(kBase64, 64, c);
            if (c == '=' && i + 4 == text.size() && k >= 2)
                ++pad;
            else if (!at || pad > 0)
                return std::nullopt;
            n = n << 6 | (at ? std::uint32_t(at - kBase64) : 0u);
        }
        out.push_back(std::uint8_t(n >> 16));
        if (pad < 2)
            out.push_back(std::uint8_t(n >> 8 & 255));
        if (pad < 1)
            out.push_back(std::uint8_t(n & 255));
    }
    return out;
}

// RGB only: a preview has no alpha worth keeping.
Json imageToJson(const scene::Image8& image) {
    std::vector<std::uint8_t> rgb;
    rgb.reserve(std::size_t(image.width) * std::size_t(image.height) * 3);
    const std::size_t step = std::size_t(std::max(image.channels, 1));
    for (std::size_t i = 0; i + step <= image.pixels.size(); i += step)
        for (std::size_t c = 0; c < 3; ++c)
            rgb.push_back(image.pixels[i + std::min(c, step - 1)]);
    return {{"width", image.width}, {"height", image.height}, {"rgb", toBase64(rgb)}};
}

scene::Image8 imageFromJson(const Json& j) {
    scene::Image8 image;
    image.width = j.at("width").get<int>();
    image.height = j.at("height").get<int>();
    const auto rgb = fromBase64(j.at("rgb").get<std::string>());
    if (image.width < 0 || image.height < 0 || image.width > 4096 || image.height > 4096 || !rgb ||
        rgb->size() != std::size_t(image.width) * std::size_t(image.height) * 3)
        throw std::invalid_argument("a preview's pixels do not match its size");
    image.pixels.reserve(rgb->size() / 3 * 4);
    for (std::size_t i = 0; i < rgb->size(); i += 3)
        image.pixels.insert(image.pixels.end(), {(*rgb)[i], (*rgb)[i + 1], (*rgb)[i + 2], 255});
    return image;
}

Json settingsToJson(const std::vector<Setting>& settings) {
    Json out = Json::array();
    for (const auto& [key, value] : settings)
        out.push_back({key, value});
    return out;
}

std::vector<Setting> settingsFromJson(const Json& j) {
    std::vector<Setting> out;
    for (const Json& kv : j)
        out.emplace_back(kv.at(0).get<std::string>(), kv.at(1).get<std::string>());
    return out;
}

} // namespace

fs::path savedSweepFileOf(const fs::path& projectFile) {
    return scene::assetsFolderOf(projectFile) / "sweep.json";
}

scene::Expected<void> saveSweep(const SavedSweep& s, const fs::path& file) {
    Json runs = Json::array();
    for (std::size_t i = 0; i < s.runs.size(); ++i) {
        Json run = sweepRunToJson(s.runs[i]);
        if (i < s.previews.size())
            run["preview"] = imageToJson(s.previews[i]);
        runs.push_back(std::move(run));
    }
    Json j{{"format", kSavedSweepFormat},
           {"version", kSavedSweepVersion},
           {"createdAt", s.createdAt},
           {"machine", s.machine},
           {"width", s.width},
           {"height", s.height},
           {"frames", s.frames},
           {"warmup", s.warmup},
           {"reference",
            {{"spp", s.referenceSpp},
             {"seconds", s.referenceSeconds},
             {"noiseMare", s.referenceNoiseMare},
             {"preview", imageToJson(s.referencePreview)}}},
           {"base", settingsToJson(s.base)},
           {"runs", runs}};
    // Optional (issue #46): a reader of version 1 before it ignores the field.
    if (!s.questions.empty()) {
        Json rows = Json::array();
        for (const SweepQuestionRow& q : s.questions)
            rows.push_back({{"name", q.name}, {"values", q.values}, {"checked", q.checked}});
        j["questions"] = std::move(rows);
    }
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    if (ec)
        return scene::makeError(scene::ErrorCode::IoError, file.parent_path().string(), "",
                                "cannot create the folder: " + ec.message());
    return scene::writeFileAtomically(file, j.dump(1) + "\n");
}

scene::Expected<SavedSweep> loadSweep(const fs::path& file) {
    auto text = scene::readFileBytes(file);
    if (!text)
        return std::unexpected(text.error());
    const Json j = Json::parse(*text, nullptr, false);
    if (j.is_discarded() || !j.is_object())
        return scene::makeError(scene::ErrorCode::NotJson, file.string(), "", "not JSON");
    if (j.value("format", "") != kSavedSweepFormat)
        return scene::makeError(scene::ErrorCode::UnknownFormat, file.string(), "format",
                                std::string("not a saved sweep (") + kSavedSweepFormat + ")");
    if (j.value("version", 0) > kSavedSweepVersion)
        return scene::makeError(scene::ErrorCode::NewerVersion, file.string(), "version",
                                "written by a newer LPV Studio (version " + std::to_string(j.value("version", 0)) +
                                    "; this one reads " + std::to_string(kSavedSweepVersion) + ")");
    SavedSweep s;
    try {
        s.createdAt = j.at("createdAt").get<std::string>();
        s.machine = j.at("machine").get<std::string>();
        s.width = j.at("width").get<int>();
        s.height = j.at("height").get<int>();
        s.frames = j.at("frames").get<int>();
        s.warmup = j.at("warmup").get<int>();
        const Json& ref = j.at("reference");
        s.referenceSpp = ref.at("spp").get<int>();
        s.referenceSeconds = ref.at("seconds").get<double>();
        s.referenceNoiseMare = ref.at("noiseMare").get<double>();
        s.referencePreview = imageFromJson(ref.at("preview"));
        s.base = settingsFromJson(j.at("base"));
        for (const Json& r : j.at("runs")) {
            s.runs.push_back(sweepRunFromJson(r));
            s.previews.push_back(r.contains("preview") ? imageFromJson(r.at("preview")) : scene::Image8{});
        }
        if (j.contains("questions"))
            for (const Json& q : j.at("questions"))
                s.questions.push_back({q.at("name").get<std::string>(), q.at("values").get<std::string>(),
                                       q.at("checked").get<bool>()});
    } catch (const std::exception& e) {
        return scene::makeError(scene::ErrorCode::MissingField, file.string(), "", e.what());
    }
    return s;
}

scene::ParameterSet runParameters(const std::vector<Setting>& base, const SweepRun& run) {
    scene::ParameterSet p;
    for (const auto& [key, value] : base)
        (void)p.setFromText(key, value, "sweep");
    for (const auto& [key, value] : run.settings)
        (void)p.setFromText(key, value, "sweep");
    return p;
}

bool sameValues(const scene::ParameterSet& a, const scene::ParameterSet& b) {
    std::set<std::string> keys;
    for (const auto& [key, value] : a.overrides())
        keys.insert(key);
    for (const auto& [key, value] : b.overrides())
        keys.insert(key);
    return std::ranges::all_of(keys, [&](const std::string& key) { return a.get(key) == b.get(key); });
}

std::vector<Setting> settingsOf(const scene::ParameterSet& parameters) {
    std::vector<Setting> out;
    for (const auto& [key, value] : parameters.overrides())
        out.emplace_back(key, scene::formatValue(value));
    return out;
}

} // namespace lpv::bench
