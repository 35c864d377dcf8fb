// fuzz_seeds: writes the generated seed inputs of the fuzz targets
// (docs/fuzzing.md) into OUT/<target>/, for scripts/fuzz.sh. The hand-made
// text seeds live in fuzz/seeds/<target>/; these are the ones that are
// binary, large, or derived from the shared scenes and the Cornell box
// project (never copied into the repository):
//
//   fuzz_gltf                the shared Box models as .glb (one with its
//                            image in a buffer view) and with data: uris, a
//                            300-character image uri, a 24-level DAG of
//                            shared nodes (2^24 paths), a 100,000-deep chain
//   fuzz_obj                 every shared Cornell OBJ with its MTL, Sponza's
//                            and Sibenik's MTL with the start of their OBJ
//                            (in the target's "<obj>\n#mtl\n<mtl>" layout),
//                            a 300-character map_Kd
//   fuzz_radiosity_solution  the Cornell box solved on the CPU (4 batches of
//                            16 shooters, deterministic) with one patch per
//                            face and with patches of at most 0.5 m^2, an
//                            empty solution, and the coarse one with patch
//                            count 0x80000000, NaN energy totals, version 0
//   fuzz_project_structure   the Cornell box project compact, 100,000 nested
//                            arrays, 64 and 65 nested objects, UTF-16 LE and
//                            BE, 100,000 unknown keys, a 10,000-object
//                            parent chain, a parent cycle
//   fuzz_image               small PNG, JPEG, GIF, BMP, TGA and EXR files and
//                            their header bombs (fuzz/ImageSeeds.cpp)
//   fuzz_bench_pack          the Cornell box as a bench pack, with a 4x2 RGBA
//                            and a 3x1 grey texture, and without textures
//
//   fuzz_seeds OUT
#include "ImageSeeds.h"

#include "lpv/radiosity/FormFactors.h"
#include "lpv/radiosity/RadiositySession.h"
#include "lpv/radiosity/SolutionFile.h"
#include "lpv/scene/BenchPack.h"
#include "lpv/scene/MeshAsset.h"
#include "lpv/scene/Project.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

[[noreturn]] void fail(const std::string& what) {
    std::fprintf(stderr, "fuzz_seeds: %s\n", what.c_str());
    std::exit(1);
}

std::string readFile(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in)
        fail("cannot read " + file.string());
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

Json readJson(const fs::path& file) {
    Json j = Json::parse(readFile(file), nullptr, false);
    if (j.is_discarded())
        fail(file.string() + " is not JSON");
    return j;
}

std::size_t gWritten = 0;

void writeSeed(const fs::path& file, std::string_view bytes) {
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.close();
    if (!out)
        fail("cannot write " + file.string());
    ++gWritten;
}

template <class T> void put(std::string& bytes, std::size_t offset, T value) {
    std::memcpy(bytes.data() + offset, &value, sizeof value); // little-endian host
}

// ----- glTF

std::string base64(std::string_view bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t v = std::uint32_t(std::uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size())
            v |= std::uint32_t(std::uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size())
            v |= std::uint8_t(bytes[i + 2]);
        out += digits[(v >> 18) & 63];
        out += digits[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[v & 63] : '=';
    }
    return out;
}

// The binary container: header, JSON chunk (padded with spaces), BIN chunk (padded with zeros).
std::string glb(const Json& gltf, std::string bin) {
    std::string json = gltf.dump();
    json.append((4 - json.size() % 4) % 4, ' ');
    bin.append((4 - bin.size() % 4) % 4, '\0');
    std::string out(12, '\0');
    auto chunk = [&](const std::string& data, std::uint32_t type) {
        std::string head(8, '\0');
        put(head, 0, std::uint32_t(data.size()));
        put(head, 4, type);
        out += head + data;
    };
    chunk(json, 0x4E4F534A); // "JSON"
    chunk(bin, 0x004E4942);  // "BIN\0"
    std::memcpy(out.data(), "glTF", 4);
    put(out, 4, std::uint32_t(2));
    put(out, 8, std::uint32_t(out.size()));
    return out;
}

void gltfSeeds(const fs::path& out, const fs::path& shared) {
    const fs::path boxDir = shared / "gltf-small/Box/glTF";
    const fs::path texturedDir = shared / "gltf-small/BoxTextured/glTF";
    const Json box = readJson(boxDir / "Box.gltf");
    const std::string boxBin = readFile(boxDir / "Box0.bin");
    const Json textured = readJson(texturedDir / "BoxTextured.gltf");
    const std::string texturedBin = readFile(texturedDir / "BoxTextured0.bin");
    const std::string png = readFile(texturedDir / "CesiumLogoFlat.png");

    Json j = box;
    j["buffers"][0].erase("uri");
    writeSeed(out / "box.glb", glb(j, boxBin));

    // The image in a buffer view after the geometry: the embedded-image path.
    j = textured;
    j["buffers"][0].erase("uri");
    std::string bin = texturedBin;
    bin.append((4 - bin.size() % 4) % 4, '\0');
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", png.size()}});
    j["images"][0] = {{"bufferView", j["bufferViews"].size() - 1}, {"mimeType", "image/png"}};
    bin += png;
    j["buffers"][0]["byteLength"] = bin.size();
    writeSeed(out / "box-textured-image-in-buffer.glb", glb(j, bin));

    j = textured;
    j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(texturedBin);
    j["images"][0]["uri"] = "data:image/png;base64," + base64(png);
    writeSeed(out / "box-textured-data-uris.gltf", j.dump());

    j = textured;
    j["images"][0]["uri"] = std::string(296, 'a') + ".png";
    writeSeed(out / "image-uri-300-characters.gltf", j.dump());

    // Node k lists node k + 1 twice: 24 nodes, 2^24 root-to-leaf paths.
    j = box;
    j["nodes"] = Json::array();
    for (int k = 0; k < 24; ++k)
        j["nodes"].push_back({{"children", {k + 1, k + 1}}});
    j["nodes"].push_back({{"mesh", 0}});
    j["scenes"] = Json::array({{{"nodes", {0}}}});
    writeSeed(out / "node-dag-24-levels.gltf", j.dump());

    j = box;
    constexpr int kChain = 100000;
    j["nodes"] = Json::array();
    for (int k = 0; k < kChain; ++k)
        j["nodes"].push_back({{"children", {k + 1}}});
    j["nodes"].push_back({{"mesh", 0}});
    j["scenes"] = Json::array({{{"nodes", {0}}}});
    writeSeed(out / "node-chain-100000-deep.gltf", j.dump());
}

// ----- OBJ + MTL (the "<obj>\n#mtl\n<mtl>" layout of ObjFuzzer.cpp)

constexpr std::string_view kSeparator = "\n#mtl\n";

// The OBJ without its mtllib lines (the target names its own MTL), cut at a line end within `limit` bytes.
std::string objPart(const std::string& obj, std::size_t limit) {
    std::string out;
    std::istringstream lines(obj);
    for (std::string line; std::getline(lines, line);) {
        if (line.rfind("mtllib", 0) == 0)
            continue;
        if (out.size() + line.size() + 1 > limit)
            break;
        out += line + '\n';
    }
    return out;
}

void objSeeds(const fs::path& out, const fs::path& shared) {
    constexpr std::size_t kObjLimit = 48 * 1024; // with the MTL, within the target's 64 KiB -max_len
    std::error_code ec;
    for (const fs::directory_entry& entry : fs::directory_iterator(shared / "cornell", ec)) {
        if (entry.path().extension() != ".obj")
            continue;
        const fs::path mtl = fs::path(entry.path()).replace_extension(".mtl");
        writeSeed(out / ("cornell-" + entry.path().stem().string() + ".objmtl"),
                  objPart(readFile(entry.path()), kObjLimit) + std::string(kSeparator) +
                      (fs::exists(mtl) ? readFile(mtl) : std::string()));
    }
    for (const char* name : {"sponza", "sibenik"}) {
        const fs::path folder = shared / name;
        writeSeed(out / (std::string(name) + "-start.objmtl"),
                  objPart(readFile(folder / (std::string(name) + ".obj")), 32 * 1024) +
                      std::string(kSeparator) + readFile(folder / (std::string(name) + ".mtl")));
    }
    writeSeed(out / "map-kd-300-characters.objmtl",
              "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl long\nf 1/1 2/2 3/3" +
                  std::string(kSeparator) + "newmtl long\nKd 1 1 1\nmap_Kd " + std::string(296, 'b') +
                  ".png\n");
}

// ----- .lpvrad

// Header offsets (SolutionFile.cpp): version 8, patch count 12, checksum 40; 48 bytes.
constexpr std::size_t kHeaderSize = 48;

void rechecksum(std::string& bytes) {
    put(bytes, 40, lpv::scene::contentHash64(std::string_view(bytes).substr(kHeaderSize)));
}

std::string solvedCornellBox(const lpv::scene::Scene& scene, float maxPatchArea) {
    lpv::radiosity::RadiositySession session(scene, {}, maxPatchArea);
    lpv::radiosity::CpuFormFactors formFactors(session.mesh());
    for (int batch = 0; batch < 4; ++batch)
        if (auto shot = session.solver().step(formFactors, 16); !shot)
            fail("radiosity: " + shot.error().describe());
    return lpv::radiosity::encodeSolution(session.stored());
}

void radiositySeeds(const fs::path& out, const lpv::scene::Scene& cornell) {
    const std::string coarse = solvedCornellBox(cornell, 100.0f);
    writeSeed(out / "cornell-box-one-patch-per-face.lpvrad", coarse);
    writeSeed(out / "cornell-box-0.5m2.lpvrad", solvedCornellBox(cornell, 0.5f));
    writeSeed(out / "empty.lpvrad", lpv::radiosity::encodeSolution({}));

    std::string bytes = coarse;
    put(bytes, 12, std::uint32_t{0x80000000}); // the payload, so the checksum, unchanged
    writeSeed(out / "patch-count-0x80000000.lpvrad", bytes);

    // The last 72 payload bytes are the emitted, absorbed and escaped totals (3 x dvec3).
    bytes = coarse;
    put(bytes, bytes.size() - 72, std::numeric_limits<double>::quiet_NaN());
    put(bytes, bytes.size() - 40, std::numeric_limits<double>::quiet_NaN());
    rechecksum(bytes);
    writeSeed(out / "nan-energy-totals.lpvrad", bytes);

    bytes = coarse;
    put(bytes, 8, std::uint32_t{0});
    writeSeed(out / "version-0.lpvrad", bytes);
}

// ----- projects

std::string widen(std::string_view text, bool bigEndian) {
    std::string out = bigEndian ? "\xfe\xff" : "\xff\xfe";
    for (const char c : text)
        out += bigEndian ? std::string{'\0', c} : std::string{c, '\0'};
    return out;
}

void projectSeeds(const fs::path& out, const fs::path& projectDir) {
    const std::string text = readFile(projectDir / "cornell-box.lpvproj");
    const Json cornell = readJson(projectDir / "cornell-box.lpvproj");
    const std::string compact = cornell.dump();
    writeSeed(out / "cornell-box-compact.lpvproj", compact);

    // A nested value under an unknown key in front of the real document.
    auto withValueInFront = [&](const std::string& value) {
        return "{\"deep\":" + value + "," + compact.substr(1);
    };
    writeSeed(out / "nested-arrays-100000.lpvproj",
              withValueInFront(std::string(100000, '[') + std::string(100000, ']')));
    for (const int depth : {63, 64}) { // with the document's own level: 64 and 65
        std::string objects;
        for (int i = 0; i < depth; ++i)
            objects += "{\"a\":";
        objects += "0" + std::string(std::size_t(depth), '}');
        writeSeed(out / ("nested-objects-" + std::to_string(depth + 1) + "-levels.lpvproj"),
                  withValueInFront(objects));
    }

    writeSeed(out / "cornell-box-utf16le.lpvproj", widen(text, false));
    writeSeed(out / "cornell-box-utf16be.lpvproj", widen(text, true));

    std::string keys = "{";
    for (int i = 0; i < 100000; ++i)
        keys += "\"u" + std::to_string(i) + "\":0,";
    writeSeed(out / "unknown-keys-100000.lpvproj", keys + compact.substr(1));

    Json j = cornell;
    const Json first = j["objects"][0];
    const std::int64_t base = std::int64_t(j["objects"].size());
    for (std::int64_t k = 0; k < 10000; ++k) {
        Json o = first;
        o["name"] = "chain" + std::to_string(k);
        o["parent"] = k == 0 ? 0 : base + k - 1;
        j["objects"].push_back(o);
    }
    writeSeed(out / "parent-chain-10000.lpvproj", j.dump());

    j = cornell;
    j["objects"][1]["parent"] = 2;
    j["objects"][2]["parent"] = 1;
    writeSeed(out / "parent-cycle.lpvproj", j.dump(2));
}

} // namespace

void benchPackSeeds(const fs::path& out, const lpv::scene::Project& cornell) {
    lpv::scene::BenchPack pack;
    pack.project = cornell;
    pack.project.loadWarnings.clear();
    pack.projectHash = "0123456789abcdef";
    auto encode = [&] {
        auto bytes = lpv::scene::encodeBenchPack(pack, "seed.lpvpack");
        if (!bytes)
            fail(bytes.error().describe());
        return *bytes;
    };
    writeSeed(out / "cornell-box.lpvpack", encode());
    lpv::scene::Image8 rgba{4, 2, 4, std::vector<std::uint8_t>(4 * 2 * 4, 200)};
    lpv::scene::Image8 grey{3, 1, 1, {0, 128, 255}};
    pack.project.scene.materials.at(0).diffuseTexture = "t/rgba.png";
    pack.textures["t/rgba.png"] = rgba;
    pack.textures["t/grey.png#height-normal"] = grey;
    writeSeed(out / "cornell-box-textures.lpvpack", encode());
}

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: fuzz_seeds OUT\n  writes OUT/<target>/ for each fuzz target\n");
        return 2;
    }
    const fs::path out = argv[1];
    const char* env = std::getenv("LPV_SHARED_SCENES_DIR");
    const fs::path shared = env && *env ? fs::path(env) : fs::path(LPV_FUZZ_SHARED_SCENES_DIR);
    const fs::path projectDir = LPV_FUZZ_PROJECT_DIR;

    const auto project = lpv::scene::loadProject(projectDir / "cornell-box.lpvproj");
    if (!project)
        fail(project.error().describe());

    gltfSeeds(out / "fuzz_gltf", shared);
    objSeeds(out / "fuzz_obj", shared);
    radiositySeeds(out / "fuzz_radiosity_solution", project->scene);
    projectSeeds(out / "fuzz_project_structure", projectDir);
    gWritten += lpv::fuzz::writeImageSeeds(out / "fuzz_image");
    benchPackSeeds(out / "fuzz_bench_pack", *project);
    std::printf("fuzz_seeds: %zu seeds in %s\n", gWritten, out.string().c_str());
    return 0;
}
