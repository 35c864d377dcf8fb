#include "BenchSweepShard.h"

#include "BenchReport.h"
#include "lpv/bench/ContentHash.h"
#include "lpv/bench/ReferenceFile.h"

#include "lpv/bench/SweepRunJson.h"
#include "lpv/importers/ImageIO.h"
#include "lpv/scene/Project.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <set>

namespace lpv::cli {

namespace fs = std::filesystem;
using Json = nlohmann::json;

namespace {

constexpr const char* kFormat = "lpvstudio-sweep-shard";
constexpr int kVersion = 1;

std::string runImageName(int index) {
    return "run-" + std::to_string(index) + ".exr";
}

// Reads DIR/shard.json and its run images; the error names the file.
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
            SweepRun run = bench::sweepRunFromJson(r);
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

} // namespace

bool shardRunsCombination(const reference::ShardSpec& shard, int combinationIndex) {
    return combinationIndex % shard.count == shard.index;
}

bool writeSweepShard(const fs::path& dir, const SweepShard& shard) {
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
        if (auto ok = importers::writeImageChannels(dir / runImageName(index), rgb); !ok) {
            std::cerr << "lpv: " << ok.error().describe() << "\n";
            return false;
        }
        Json run = bench::sweepRunToJson(r);
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
    return writeReportFiles({{(dir / "shard.json").string(), j.dump(1) + "\n"}});
}

void printBenchMergeHelp() {
    std::cout << R"(
bench merge OUT_DIR SHARD_DIR... [--reference REF.exr]:
joins the shards of one sweep (`lpv bench PROJECT --sweep ... --reference
REF.exr --shard I/N --out SHARD_DIR`, one per process or cluster task, see
docs/cluster.md) and writes into OUT_DIR the files the sweep writes unsharded
(sweep.csv, sweep.json, sweep.md, the plots and crops), its error columns
exactly as one process would have measured them. Refuses shards of different
sweeps (command, size, reference file content, shard count), a shard given
twice, a shard folder without its shard.json (killed before it finished) and
an incomplete set, naming the missing shards. Warns, and says so in sweep.md,
when the shards ran on different machines (their timings do not compare).
  --reference REF.exr   The reference, where it is no longer at the path the
                        shards recorded (its content must be the same)
)";
}

int benchMerge(Args args) {
    const auto referenceOverride = args.option("--reference");
    if (!args.missingValue().empty())
        return usageError(args.missingValue() + " needs a value", "bench");
    if (auto unknown = args.unknownOption())
        return usageError("unknown option '" + *unknown + "'", "bench");
    auto pos = args.positionals();
    pos.erase(pos.begin()); // "merge"
    if (pos.size() < 2)
        return usageError("bench merge expects OUT_DIR and at least one shard folder", "bench");
    const fs::path outDir = pos.front();
    std::vector<SweepShard> shards;
    std::vector<std::string> folders(pos.begin() + 1, pos.end());
    for (const std::string& folder : folders) {
        auto s = readSweepShard(folder);
        if (!s) {
            std::cerr << "lpv: " << s.error().describe() << "\n";
            return kFailure;
        }
        shards.push_back(std::move(*s));
    }
    if (shards.empty()) // not reached (two positionals at least); GCC 14 cannot see it
        return usageError("bench merge expects at least one shard folder", "bench");
    const SweepShard& first = shards.front();
    std::vector<const SweepShard*> byIndex(std::size_t(first.shard.count), nullptr);
    std::set<std::string> machines;
    auto refuse = [&](const std::string& folder, const std::string& why) {
        std::cerr << "lpv: " << folder << ": " << why << "\n";
        return kFailure;
    };
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
    std::vector<bool> present(static_cast<std::size_t>(first.shard.count));
    for (std::size_t i = 0; i < present.size(); ++i)
        present[i] = byIndex[i] != nullptr;
    if (const std::string missing = reference::describeMissingShards(present); !missing.empty())
        return refuse("lpv bench merge", "incomplete set: " + missing);

    // The reference: for the crops and the report's header; it must be the one measured against.
    fs::path refFile = referenceOverride ? fs::path(*referenceOverride) : fs::path(first.referenceAbsolute);
    if (!referenceOverride && !fs::exists(refFile))
        refFile = first.referenceFile;
    if (const auto hash = bench::fileContentHash(refFile); !hash || *hash != first.referenceHash)
        return refuse(refFile.string(), "not the reference the shards were measured against (content hash " +
                                            first.referenceHash + "); give that file with --reference");
    auto loaded = bench::readReferenceExr(refFile);
    if (!loaded) {
        std::cerr << "lpv: " << loaded.error().describe() << "\n";
        return kFailure;
    }
    reference::ReferenceImage ref = std::move(loaded->image);
    if (auto it = loaded->attributes.find("lpv:seconds"); it != loaded->attributes.end())
        ref.seconds = std::atof(it->second.c_str());

    std::vector<SweepRun> runs(std::size_t(first.combinations));
    for (const SweepShard* s : byIndex)
        for (std::size_t k = 0; k < s->runs.size(); ++k)
            runs[std::size_t(s->indices[k])] = s->runs[k];
    std::string note;
    if (machines.size() > 1) {
        note = "**The shards ran on different machines**; their timings do not compare:";
        for (const std::string& m : machines)
            note += "\n- " + m;
        std::cerr << "lpv: warning: the shards ran on " << machines.size()
                  << " different machines; their timings do not compare (listed in sweep.md)\n";
    }
    std::error_code ec;
    fs::create_directories(outDir, ec);
    if (ec)
        return refuse(outDir.string(), "cannot create the folder: " + ec.message());
    scene::ParameterSet display;
    for (const auto& [key, value] : first.display)
        (void)display.setFromText(key, value, "shard.json");
    if (!writeSweepFiles(outDir, runs, first.width, first.height, first.command, first.machine, ref, note,
                         first.timing, display))
        return kFailure;
    std::printf("merged %d shards: %d runs\n", first.shard.count, first.combinations);
    return kOk;
}

} // namespace lpv::cli
