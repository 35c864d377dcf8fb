#include "lpv/radiosity/SolutionFile.h"

#include "lpv/scene/FileRead.h"
#include "lpv/scene/MeshAsset.h"
#include "lpv/scene/Project.h"
#include "lpv/scene/ProjectLimits.h"
#include "lpv/scene/SceneFields.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace lpv::radiosity {
namespace {

constexpr char kMagic[8] = {'L', 'P', 'V', 'R', 'A', 'D', '\0', '\1'};
// magic 8, version 4, patch count 4, signature 8, max patch area 4, reserved 4, payload size 8, checksum 8
constexpr std::size_t kHeaderSize = 48;

class Writer {
  public:
    template <class T> void put(const T& v) {
        const auto* p = reinterpret_cast<const char*>(&v);
        bytes.append(p, sizeof(T));
    }
    void putVec3(const glm::vec3& v) {
        put(v.x);
        put(v.y);
        put(v.z);
    }
    void putDVec3(const glm::dvec3& v) {
        put(v.x);
        put(v.y);
        put(v.z);
    }
    std::string bytes;
};

class Reader {
  public:
    Reader(std::string_view data, std::size_t base) : data_(data), base_(base) {}
    template <class T> bool get(T& v) {
        if (pos_ + sizeof(T) > data_.size())
            return false;
        std::memcpy(&v, data_.data() + pos_, sizeof(T));
        pos_ += sizeof(T);
        return true;
    }
    bool getVec3(glm::vec3& v) { return get(v.x) && get(v.y) && get(v.z); }
    bool getDVec3(glm::dvec3& v) { return get(v.x) && get(v.y) && get(v.z); }
    std::size_t offset() const { return base_ + pos_; }
    bool atEnd() const { return pos_ == data_.size(); }

  private:
    std::string_view data_;
    std::size_t base_;
    std::size_t pos_ = 0;
};

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

std::uint64_t sceneSignature(const PatchMesh& unrefined, const SurfaceProperties& surfaces,
                             std::span<const scene::Light> lights) {
    Writer w;
    // Every light shoots (its direct light is the first bounce): moving,
    // dimming or recolouring one changes the solution. Every field its table
    // hashes (SceneFields.h), so a field added there is part of the signature.
    for (const scene::Light& l : lights)
        scene::hashFields(
            l, [&](const void* p, std::size_t n) { w.bytes.append(static_cast<const char*>(p), n); });
    for (std::size_t i = 0; i < unrefined.size(); ++i) {
        const Patch& p = unrefined.patches[i];
        w.put(p.cornerCount);
        for (int k = 0; k < p.cornerCount; ++k)
            w.putVec3(p.corners[std::size_t(k)]);
        w.put(p.material);
        w.putVec3(surfaces.reflectance[i]);
        w.putVec3(surfaces.emission[i]);
    }
    return scene::contentHash64(w.bytes);
}

std::filesystem::path solutionPath(const std::filesystem::path& projectFile) {
    return projectFile.parent_path() / (projectFile.stem().string() + ".assets") / "radiosity.lpvrad";
}

std::string encodeSolution(const StoredSolution& s) {
    Writer payload;
    for (const Patch& p : s.mesh.patches) {
        payload.put(p.cornerCount);
        for (int k = 0; k < 4; ++k) {
            payload.putVec3(p.corners[std::size_t(k)]);
            payload.put(p.uvs[std::size_t(k)].x);
            payload.put(p.uvs[std::size_t(k)].y);
        }
        payload.put(p.material);
        payload.put(p.object);
    }
    for (std::size_t i = 0; i < s.mesh.size(); ++i) {
        payload.putVec3(s.state.radiosity[i]);
        payload.putVec3(s.state.unshot[i]);
        payload.putVec3(s.state.incident.empty() ? glm::vec3(0.0f) : s.state.incident[i]);
        payload.putVec3(s.state.direct.empty() ? glm::vec3(0.0f) : s.state.direct[i]);
    }
    payload.put(s.state.shots);
    payload.put(s.state.batches);
    payload.put(s.state.seconds);
    payload.putDVec3(s.state.balance.emitted);
    payload.putDVec3(s.state.balance.absorbed);
    payload.putDVec3(s.state.balance.escaped);

    Writer header;
    header.bytes.append(kMagic, sizeof(kMagic));
    header.put(kSolutionVersion);
    header.put(std::uint32_t(s.mesh.size()));
    header.put(s.sceneSignature);
    header.put(s.maxPatchArea);
    header.put(std::uint32_t(0));
    header.put(std::uint64_t(payload.bytes.size()));
    header.put(scene::contentHash64(payload.bytes));
    return header.bytes + payload.bytes;
}

scene::Expected<StoredSolution> decodeSolution(std::string_view bytes, const std::string& fileName,
                                               std::size_t materialCount, std::size_t objectCount) {
    using scene::ErrorCode;
    using scene::makeError;
    auto at = [](std::size_t offset) { return "byte offset " + std::to_string(offset); };
    if (bytes.size() < kHeaderSize)
        return makeError(ErrorCode::Truncated, fileName, at(bytes.size()),
                         "the header needs " + std::to_string(kHeaderSize) + " bytes");
    if (std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
        return makeError(ErrorCode::UnknownFormat, fileName, at(0), "not a radiosity solution (bad magic)");
    Reader h(bytes.substr(8, kHeaderSize - 8), 8);
    std::uint32_t version = 0, patchCount = 0, reserved = 0;
    std::uint64_t payloadSize = 0, checksum = 0;
    StoredSolution s;
    h.get(version);
    h.get(patchCount);
    h.get(s.sceneSignature);
    h.get(s.maxPatchArea);
    h.get(reserved);
    h.get(payloadSize);
    h.get(checksum);
    if (version == 0)
        return makeError(ErrorCode::OutOfRange, fileName, at(8), "version 0 does not exist (versions start at 1)");
    if (version > kSolutionVersion)
        return makeError(ErrorCode::NewerVersion, fileName, at(8),
                         "version " + std::to_string(version) + " is newer than this program's " +
                             std::to_string(kSolutionVersion));
    if (version < kSolutionVersion)
        return makeError(ErrorCode::InvalidValue, fileName, at(8),
                         "version " + std::to_string(version) +
                             " was saved before the lights shot and keeps no incident light; solve again "
                             "(lpv radiosity PROJECT --restart)");
    if (bytes.size() - kHeaderSize != payloadSize)
        return makeError(ErrorCode::Truncated, fileName, at(bytes.size()),
                         "the header announces " + std::to_string(payloadSize) +
                             " payload bytes, the file has " + std::to_string(bytes.size() - kHeaderSize));
    const std::string_view payload = bytes.substr(kHeaderSize);
    if (scene::contentHash64(payload) != checksum)
        return makeError(ErrorCode::ChecksumMismatch, fileName, at(kHeaderSize),
                         "the payload's checksum does not match the header");
    // Every patch takes its record and its radiosity and unshot light: a count
    // the payload cannot hold is refused before anything is allocated for it
    // (a valid checksum over 465 KB once announced 0x9C09C09 patches).
    constexpr std::uint64_t kBytesPerPatch = sizeof(Patch::cornerCount) + 4 * (3 + 2) * sizeof(float) +
                                             sizeof(Patch::material) + sizeof(Patch::object) + 4 * 3 * sizeof(float);
    if (std::uint64_t{patchCount} * kBytesPerPatch > payload.size())
        return makeError(ErrorCode::Truncated, fileName, at(12),
                         "the header announces " + std::to_string(patchCount) + " patches; the " +
                             std::to_string(payload.size()) + "-byte payload holds at most " +
                             std::to_string(payload.size() / kBytesPerPatch));
    Reader r(payload, kHeaderSize);
    s.mesh.patches.resize(patchCount);
    for (std::uint32_t i = 0; i < patchCount; ++i) {
        Patch& p = s.mesh.patches[i];
        const std::size_t start = r.offset();
        bool ok = r.get(p.cornerCount);
        for (int k = 0; k < 4 && ok; ++k)
            ok = r.getVec3(p.corners[std::size_t(k)]) && r.get(p.uvs[std::size_t(k)].x) &&
                 r.get(p.uvs[std::size_t(k)].y);
        ok = ok && r.get(p.material) && r.get(p.object);
        if (!ok)
            return makeError(ErrorCode::Truncated, fileName, at(r.offset()),
                             "patch " + std::to_string(i) + " is cut off");
        if (p.cornerCount != 3 && p.cornerCount != 4)
            return makeError(ErrorCode::InvalidValue, fileName, at(start),
                             "patch " + std::to_string(i) + " has " + std::to_string(p.cornerCount) +
                                 " corners");
        for (int k = 0; k < p.cornerCount; ++k)
            if (!finite(p.corners[std::size_t(k)]))
                return makeError(ErrorCode::NonFinite, fileName, at(start),
                                 "patch " + std::to_string(i) + " has a non-finite corner");
        // Centre, normal and area follow from the corners (in float, as for a
        // meshed scene): finite corners about 1e19 apart overflow the area's
        // cross product, near the float limit their sum the centre.
        computePatchGeometry(p);
        const char* derived = nullptr;
        if (!std::isfinite(p.area))
            derived = "area";
        else if (!finite(p.center))
            derived = "centre";
        else if (!finite(p.normal))
            derived = "normal";
        if (derived)
            return makeError(ErrorCode::NonFinite, fileName, at(start),
                             "patch " + std::to_string(i) + "'s corners are too far apart: its " + derived +
                                 " is not finite");
        if (p.material >= materialCount || p.object >= objectCount)
            return makeError(ErrorCode::IndexOutOfRange, fileName, at(start),
                             "patch " + std::to_string(i) + " names material " + std::to_string(p.material) +
                                 " and object " + std::to_string(p.object) + "; the project has " +
                                 std::to_string(materialCount) + " and " + std::to_string(objectCount));
    }
    s.state.radiosity.resize(patchCount);
    s.state.unshot.resize(patchCount);
    s.state.incident.resize(patchCount);
    s.state.direct.resize(patchCount);
    for (std::uint32_t i = 0; i < patchCount; ++i) {
        const std::size_t start = r.offset();
        glm::vec3& radiosity = s.state.radiosity[i];
        glm::vec3& unshot = s.state.unshot[i];
        glm::vec3& incident = s.state.incident[i];
        glm::vec3& direct = s.state.direct[i];
        if (!r.getVec3(radiosity) || !r.getVec3(unshot) || !r.getVec3(incident) || !r.getVec3(direct))
            return makeError(ErrorCode::Truncated, fileName, at(r.offset()),
                             "radiosity of patch " + std::to_string(i) + " is cut off");
        if (!finite(radiosity) || !finite(unshot) || !finite(incident) || !finite(direct))
            return makeError(ErrorCode::NonFinite, fileName, at(start),
                             "radiosity of patch " + std::to_string(i) + " is not finite");
        const glm::vec3 least = glm::min(glm::min(radiosity, unshot), glm::min(incident, direct));
        if (std::min({least.x, least.y, least.z}) < 0.0f)
            return makeError(ErrorCode::OutOfRange, fileName, at(start),
                             "radiosity of patch " + std::to_string(i) + " is negative: light is never below 0");
    }
    auto& b = s.state.balance;
    if (!r.get(s.state.shots) || !r.get(s.state.batches) || !r.get(s.state.seconds) ||
        !r.getDVec3(b.emitted) || !r.getDVec3(b.absorbed) || !r.getDVec3(b.escaped))
        return makeError(ErrorCode::Truncated, fileName, at(r.offset()), "the solver counters are cut off");
    const std::size_t countersAt = r.offset() - 3 * sizeof(glm::dvec3);
    for (const glm::dvec3& total : {b.emitted, b.absorbed, b.escaped})
        if (!std::isfinite(total.x) || !std::isfinite(total.y) || !std::isfinite(total.z) ||
            std::min({total.x, total.y, total.z}) < 0.0)
            return makeError(ErrorCode::NonFinite, fileName, at(countersAt),
                             "the energy totals (emitted, absorbed, escaped) must be finite and at least 0");
    if (!r.atEnd())
        return makeError(ErrorCode::InvalidValue, fileName, at(r.offset()),
                         "unexpected bytes after the solution");
    buildAdjacency(s.mesh);
    return s;
}

namespace {
// Regular files only, the size checked before reading: 1 GiB holds about
// 9 million patches (Sponza meshes 1.4 million). saveSolution refuses to
// write more (issue #42: no write that a read refuses).
const scene::ReadLimit kSolutionLimit{std::uint64_t{1} << 30, "radiosity solution"};
} // namespace

scene::Expected<void> saveSolution(const StoredSolution& solution, const std::filesystem::path& file) {
    const std::string bytes = encodeSolution(solution);
    if (auto fits = scene::checkWriteFits(bytes.size(), kSolutionLimit, file.string()); !fits)
        return fits;
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    if (ec)
        return scene::makeError(scene::ErrorCode::IoError, file.parent_path().string(), "",
                                "cannot create the folder: " + ec.message());
    return scene::writeFileAtomically(file, bytes);
}

scene::Expected<StoredSolution> loadSolution(const std::filesystem::path& file, std::size_t materialCount,
                                             std::size_t objectCount) {
    const auto bytes = scene::readFileBytes(file, kSolutionLimit);
    if (!bytes)
        return std::unexpected(bytes.error());
    return decodeSolution(*bytes, file.string(), materialCount, objectCount);
}

} // namespace lpv::radiosity
