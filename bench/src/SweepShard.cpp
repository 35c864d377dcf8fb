#include "lpv/bench/SweepShard.h"

#include "lpv/bench/ContentHash.h"
#include "lpv/bench/ReferenceFile.h"
#include "lpv/bench/SweepRunJson.h"
#include "lpv/importers/ImageIO.h"
#include "lpv/scene/Project.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <set>

namespace lpv::bench {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

constexpr const char* kFormat = "lpvstudio-sweep-shard";
constexpr int kVersion = 1;

std::string runImageName(int index) {
    return "run-" + std::to_string(index) + ".exr";
}

} // namespace

scene::Expected<SweepShard> readSweepShard(const fs::path& dir) {
    const fs::path file = dir / "shard.json";
    std::error_code ec;
    if (!fs::exists(file, ec))
        return scene::makeError(scene::ErrorCode::FileNotFound, file.string(), "",
                                "no shard.json: the shard did not finish (run it again; a killed shard "
                                "leaves none)");
    std::ifstream in(file);
    const Json j = Json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.is_object())
        return scene::makeError(scene::ErrorCode::NotJson, file.string(), "", "not JSON");
    const auto format = j.find("format");
    const auto version = j.find("version");
    if (format == j.end() || *format != kFormat || version == j.end() || *version != kVersion)
        return scene::makeError(scene::ErrorCode::UnknownFormat, file.string(), "format",
                                std::string("not a sweep shard (") + kFormat + " version " +
                                    std::to_string(kVersion) + ")");
    SweepShard s;
    try {
        auto spec = reference::parseShard(j.at("shard").get<std::string>());
        if (!spec)
            return scene::makeError(scene::ErrorCode::InvalidValue, file.string(), "shard",
                                    spec.error().message);
        s.shard = *spec;
        s.combinations = j.at("combinations").get<int>();
        s.command = j.at("command").get<std::string>();
        s.machine = j.at("machine").get<std::string>();
        s.width = j.at("width").get<int>();
        s.height = j.at("height").get<int>();
        s.referenceFile = j.at("reference").at("file").get<std::string>();
        s.referenceAbsolute = j.at("reference").at("absolute").get<std::string>();
        s.referenceHash = j.at("reference").at("hash").get<std::string>();
        for (const Json& kv : j.value("display", Json::array()))
            s.display.emplace_back(kv.at(0).get<std::string>(), kv.at(1).get<std::string>());
        if (j.contains("timing")) {
            s.timing.rounds = j["timing"].at("rounds").get<int>();
            s.timing.stopReason = j["timing"].at("stopReason").get<std::string>();
            s.timing.load = j["timing"].at("load").get<std::string>();
        }
        for (const Json& r : j.at("runs")) {
            SweepRun run = sweepRunFromJson(r);
            const int index = r.at("index").get<int>();
            auto pixels = importers::readImageChannels(dir / runImageName(index));
            if (!pixels)
                return std::unexpected(pixels.error());
            // R, G, B: the indirect light; image.R, image.G, image.B: the final frame (absent in older shards).
            auto channel = [&](const std::string& name) -> int {
                const auto it = std::ranges::find(pixels->names, name);
                return it == pixels->names.end() ? -1 : int(it - pixels->names.begin());
            };
            const int cr = channel("R"), cg = channel("G"), cb = channel("B");
            const int ir = channel("image.R"), ig = channel("image.G"), ib = channel("image.B");
            if (pixels->width != s.width || pixels->height != s.height || cr < 0 || cg < 0 || cb < 0)
                return scene::makeError(scene::ErrorCode::InvalidValue, (dir / runImageName(index)).string(),
                                        "",
                                        "not this shard's " + std::to_string(s.width) + "x" +
                                            std::to_string(s.height) + " RGB image");
            const std::size_t n = pixels->names.size();
            const std::size_t count = pixels->pixels.size() / std::max<std::size_t>(n, 1);
            run.indirectPixels.resize(count);
            for (std::size_t i = 0; i < count; ++i)
                run.indirectPixels[i] = {pixels->pixels[n * i + std::size_t(cr)],
                                         pixels->pixels[n * i + std::size_t(cg)],
                                         pixels->pixels[n * i + std::size_t(cb)]};
            if (ir >= 0 && ig >= 0 && ib >= 0) {
                run.imagePixels.resize(count);
                for (std::size_t i = 0; i < count; ++i)
                    run.imagePixels[i] = {pixels->pixels[n * i + std::size_t(ir)],
                                          pixels->pixels[n * i + std::size_t(ig)],
                                          pixels->pixels[n * i + std::size_t(ib)]};
            }
            s.indices.push_back(index);
            s.runs.push_back(std::move(run));
        }
    } catch (const Json::exception& e) {
        return scene::makeError(scene::ErrorCode::MissingField, file.string(), "", e.what());
    }
    return s;
}

bool shardRunsCombination(const reference::ShardSpec& shard, int combinationIndex) {
    return combinationIndex % shard.count == shard.index;
}

scene::Expected<fs::path> writeSweepShard(const fs::path& dir, const SweepShard& shard) {
    Json display = Json::array();
    for (const auto& [key, value] : shard.display)
        display.push_back({key, value});
    Json runs = Json::array();
    for (std::size_t k = 0; k < shard.runs.size(); ++k) {
        const SweepRun& r = shard.runs[k];
        const int index = shard.indices[k];
        const bool frame = r.imagePixels.size() == r.indirectPixels.size();
        importers::FloatChannels rgb{shard.width, shard.height, {"R", "G", "B"}, {}, {}};
        if (frame)
            rgb.names.insert(rgb.names.end(), {"image.R", "image.G", "image.B"});
        for (std::size_t i = 0; i < r.indirectPixels.size(); ++i) {
            const glm::vec3& c = r.indirectPixels[i];
            rgb.pixels.insert(rgb.pixels.end(), {c.r, c.g, c.b});
            if (frame)
                rgb.pixels.insert(rgb.pixels.end(), {r.imagePixels[i].r, r.imagePixels[i].g, r.imagePixels[i].b});
        }
        if (auto ok = importers::writeImageChannels(dir / runImageName(index), rgb); !ok)
            return std::unexpected(ok.error());
        Json run = sweepRunToJson(r);
        run["index"] = index;
        runs.push_back(std::move(run));
    }
    const Json j{{"format", kFormat},
                 {"version", kVersion},
                 {"shard", reference::formatShard(shard.shard)},
                 {"combinations", shard.combinations},
                 {"command", shard.command},
                 {"machine", shard.machine},
                 {"width", shard.width},
                 {"height", shard.height},
                 {"reference",
                  {{"file", shard.referenceFile},
                   {"absolute", shard.referenceAbsolute},
                   {"hash", shard.referenceHash}}},
                 {"display", display},
                 {"timing",
                  {{"rounds", shard.timing.rounds},
                   {"stopReason", shard.timing.stopReason},
                   {"load", shard.timing.load}}},
                 {"runs", runs}};
    const fs::path file = dir / "shard.json";
    if (auto ok = scene::writeFileAtomically(file, j.dump(1) + "\n"); !ok)
        return std::unexpected(ok.error());
    return file;
}

scene::Expected<MergedSweep> mergeSweepShards(const std::vector<SweepShard>& shards,
                                              const std::vector<std::string>& folders) {
    auto refuse = [](const std::string& folder, const std::string& why) -> scene::Expected<MergedSweep> {
        return scene::makeError(scene::ErrorCode::InvalidValue, folder, "", why);
    };
    if (shards.empty() || shards.size() != folders.size())
        return refuse("", "no shards to merge");
    const SweepShard& first = shards.front();
    std::vector<const SweepShard*> byIndex(std::size_t(first.shard.count), nullptr);
    std::set<std::string> machines;
    for (std::size_t k = 0; k < shards.size(); ++k) {
        const SweepShard& s = shards[k];
        const std::string& folder = folders[k];
        if (s.shard.count != first.shard.count)
            return refuse(folder, "shard " + reference::formatShard(s.shard) + " is one of " +
                                      std::to_string(s.shard.count) + ", but " + folders[0] + " is one of " +
                                      std::to_string(first.shard.count));
        if (s.command != first.command || s.combinations != first.combinations || s.width != first.width ||
            s.height != first.height)
            return refuse(folder, "not a shard of the same sweep as " + folders[0] + ": its command is\n  " +
                                      s.command + "\nagainst\n  " + first.command);
        if (s.referenceHash != first.referenceHash)
            return refuse(folder, "measured against another reference (content hash " + s.referenceHash +
                                      ", " + folders[0] + " has " + first.referenceHash + ")");
        if (const SweepShard*& slot = byIndex[std::size_t(s.shard.index)]; slot)
            return refuse(folder, "shard " + reference::formatShard(s.shard) + " is given twice");
        else
            slot = &s;
        std::vector<int> expected;
        for (int i = 0; i < s.combinations; ++i)
            if (shardRunsCombination(s.shard, i))
                expected.push_back(i);
        if (s.indices != expected)
            return refuse(folder, "shard " + reference::formatShard(s.shard) + " has " +
                                      std::to_string(s.indices.size()) + " runs, not its " +
                                      std::to_string(expected.size()) + " combinations");
        machines.insert(s.machine);
    }
    std::vector<bool> present(byIndex.size());
    for (std::size_t i = 0; i < present.size(); ++i)
        present[i] = byIndex[i] != nullptr;
    if (const std::string missing = reference::describeMissingShards(present); !missing.empty())
        return refuse("", "incomplete set: " + missing);

    MergedSweep merged;
    merged.runs.resize(std::size_t(first.combinations));
    for (const SweepShard* s : byIndex)
        for (std::size_t k = 0; k < s->runs.size(); ++k)
            merged.runs[std::size_t(s->indices[k])] = s->runs[k];
    merged.machineCount = machines.size();
    if (machines.size() > 1) {
        merged.note = "**The shards ran on different machines**; their timings do not compare:";
        for (const std::string& m : machines)
            merged.note += "\n- " + m;
    }
    for (const auto& [key, value] : first.display)
        (void)merged.display.setFromText(key, value, "shard.json");
    return merged;
}

scene::Expected<reference::ReferenceImage> loadShardsReference(const SweepShard& first,
                                                              const std::optional<fs::path>& override) {
    fs::path file = override ? *override : fs::path(first.referenceAbsolute);
    std::error_code ec;
    if (!override && !fs::exists(file, ec))
        file = first.referenceFile;
    if (const auto hash = fileContentHash(file); !hash || *hash != first.referenceHash)
        return scene::makeError(scene::ErrorCode::InvalidValue, file.string(), "",
                                "not the reference the shards were measured against (content hash " +
                                    first.referenceHash + "); give that file with --reference");
    auto loaded = readReferenceExr(file);
    if (!loaded)
        return std::unexpected(loaded.error());
    return std::move(loaded->image);
}
} // namespace lpv::bench
