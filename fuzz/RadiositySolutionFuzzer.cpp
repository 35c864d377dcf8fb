// libFuzzer target fuzz_radiosity_solution: decodeSolution
// (radiosity/src/SolutionFile.cpp), the .lpvrad reader behind loadSolution,
// which the CLI and the editor call to resume a solve.
//
// Each input is decoded twice, like fuzz_mesh_asset's:
//  1. as given, which mostly exercises the header checks (magic, version,
//     payload size, checksum, the patch count against the payload);
//  2. with the header's payload size and checksum (contentHash64 of the
//     payload) rewritten to match the bytes, so mutations of patch counts,
//     corners, indices, radiosity and the solver's counters reach the checks
//     behind the checksum.
// The patches' material and object indices are bounded by the counts of the
// committed Cornell box project, which the seeds were solved for.
//
// A decoded solution must keep what the decoder promises (patch and state
// counts agree, 3 or 4 finite corners, indices in range, radiosity and
// unshot light finite and >= 0, energy totals finite and >= 0), hold finite
// patch geometry (area, centre, normal: what the solver computes with), have a
// consistent adjacency (buildAdjacency's offsets and indices in range), and
// encode back to the very bytes it came from (the header's reserved field
// aside, which the encoder writes as 0).
//
// Then it is resumed the way `lpv radiosity` and the editor resume it: a
// RadiositySession of the Cornell box scene meshed with the header's maximum
// patch area (when finite and in [0.25, 100]: finer would mesh the box into
// up to 10^5 patches per input), which takes the stored patches and state
// when the header's scene signature matches (the seeds' does, and most
// payload mutations keep it) and restores the solver from them.
#include "SceneChecks.h"

#include "lpv/radiosity/RadiositySession.h"
#include "lpv/radiosity/SolutionFile.h"
#include "lpv/scene/Project.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>

namespace {

using namespace lpv;

scene::Scene gCornellBox;
std::size_t gMaterialCount = 0;
std::size_t gObjectCount = 0;
// Header (docs/project-format.md): magic 8, version 4, patch count 4,
// signature 8, max patch area 4, reserved 4 at 28, payload size 8 at 32,
// checksum 8 at 40; 48 bytes.
constexpr std::size_t kHeaderSize = 48;
constexpr std::size_t kReservedOffset = 28;
constexpr std::size_t kPayloadSizeOffset = 32;
constexpr std::size_t kChecksumOffset = 40;

bool finiteAndNotNegative(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) &&
           std::min({v.x, v.y, v.z}) >= 0.0f;
}

bool finiteAndNotNegative(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::min({v.x, v.y, v.z}) >= 0.0;
}

// Compressed rows (offsets.size() == rows + 1, non-decreasing, ending at
// values.size()), every value below `bound`.
void checkRows(const std::vector<std::uint32_t>& offsets, const std::vector<std::uint32_t>& values,
               std::size_t rows, std::size_t bound, const std::string& what) {
    if (offsets.size() != rows + 1 || offsets.front() != 0 || offsets.back() != values.size())
        fuzz::invariantBroken(what + ": " + std::to_string(offsets.size()) + " offsets for " +
                              std::to_string(rows) + " rows and " + std::to_string(values.size()) +
                              " values");
    if (!std::is_sorted(offsets.begin(), offsets.end()))
        fuzz::invariantBroken(what + ": offsets decrease");
    for (const std::uint32_t v : values)
        if (v >= bound)
            fuzz::invariantBroken(what + ": index " + std::to_string(v) + " of " + std::to_string(bound));
}

void checkSolution(const radiosity::StoredSolution& s) {
    const radiosity::PatchMesh& mesh = s.mesh;
    const std::size_t n = mesh.size();
    if (s.state.radiosity.size() != n || s.state.unshot.size() != n)
        fuzz::invariantBroken(std::to_string(n) + " patches but " + std::to_string(s.state.radiosity.size()) +
                              " radiosity and " + std::to_string(s.state.unshot.size()) + " unshot values");
    for (std::size_t i = 0; i < n; ++i) {
        const radiosity::Patch& p = mesh.patches[i];
        const std::string at = "patch " + std::to_string(i);
        if (p.cornerCount != 3 && p.cornerCount != 4)
            fuzz::invariantBroken(at + " has " + std::to_string(p.cornerCount) + " corners");
        for (int k = 0; k < p.cornerCount; ++k) {
            fuzz::checkFinite(p.corners[std::size_t(k)], at + " corner " + std::to_string(k));
            if (p.vertices[std::size_t(k)] >= mesh.vertices.size())
                fuzz::invariantBroken(at + " names vertex " + std::to_string(p.vertices[std::size_t(k)]) +
                                      " of " + std::to_string(mesh.vertices.size()));
        }
        // Derived by computePatchGeometry on load; the decoder refuses finite
        // corners far enough apart (about 1e19) to overflow them.
        fuzz::checkFinite(p.area, at + " area");
        fuzz::checkFinite(p.center, at + " centre");
        fuzz::checkFinite(p.normal, at + " normal");
        if (p.material >= gMaterialCount || p.object >= gObjectCount)
            fuzz::invariantBroken(at + " names material " + std::to_string(p.material) + ", object " +
                                  std::to_string(p.object));
        if (!finiteAndNotNegative(s.state.radiosity[i]) || !finiteAndNotNegative(s.state.unshot[i]))
            fuzz::invariantBroken(at + " has radiosity or unshot light that is not finite or is negative");
    }
    const radiosity::EnergyBalance& b = s.state.balance;
    if (!finiteAndNotNegative(b.emitted) || !finiteAndNotNegative(b.absorbed) ||
        !finiteAndNotNegative(b.escaped))
        fuzz::invariantBroken("energy totals that are not finite or are negative");
    checkRows(mesh.neighbourOffsets, mesh.neighbours, n, n, "neighbours");
    checkRows(mesh.vertexPatchOffsets, mesh.vertexPatches, mesh.vertices.size(), n, "vertex patches");
}

void resume(radiosity::StoredSolution solution) {
    const float area = solution.maxPatchArea;
    if (!(area >= 0.25f && area <= 100.0f))
        return;
    const std::size_t stored = solution.mesh.size();
    radiosity::RadiositySession session(gCornellBox, {}, area, std::move(solution));
    const radiosity::SolverState& state = session.solver().state();
    if (state.radiosity.size() != session.mesh().size() || state.unshot.size() != session.mesh().size())
        fuzz::invariantBroken("the resumed solver holds " + std::to_string(state.radiosity.size()) +
                              " values for " + std::to_string(session.mesh().size()) + " patches");
    if (session.resumed() && session.mesh().size() != stored)
        fuzz::invariantBroken("resumed with " + std::to_string(session.mesh().size()) + " patches of " +
                              std::to_string(stored));
    const double residual = session.solver().residual();
    if (!std::isfinite(residual) || residual < 0.0)
        fuzz::invariantBroken("the resumed solver's residual is " + std::to_string(residual));
}

void decodeAndCheck(std::string_view bytes) {
    auto solution = radiosity::decodeSolution(bytes, "fuzz.lpvrad", gMaterialCount, gObjectCount);
    if (!solution)
        return;
    checkSolution(*solution);
    std::string expected(bytes);
    std::memset(expected.data() + kReservedOffset, 0, 4);
    if (radiosity::encodeSolution(*solution) != expected)
        fuzz::invariantBroken("decode -> encode changed the bytes");
    resume(std::move(*solution));
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    const auto project =
        scene::loadProject(std::filesystem::path(LPV_FUZZ_PROJECT_DIR) / "cornell-box.lpvproj");
    if (!project) {
        std::fprintf(stderr, "fuzz_radiosity_solution: %s\n", project.error().describe().c_str());
        std::exit(1);
    }
    gCornellBox = project->scene;
    gMaterialCount = gCornellBox.materials.size();
    gObjectCount = gCornellBox.objects.size();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view raw(reinterpret_cast<const char*>(data), size);
    decodeAndCheck(raw);
    if (size < kHeaderSize)
        return 0;
    std::string fixed(raw);
    const std::uint64_t payloadSize = size - kHeaderSize;
    const std::uint64_t checksum = scene::contentHash64(std::string_view(fixed).substr(kHeaderSize));
    std::memcpy(fixed.data() + kPayloadSizeOffset, &payloadSize, sizeof payloadSize); // little-endian host
    std::memcpy(fixed.data() + kChecksumOffset, &checksum, sizeof checksum);
    if (fixed != raw)
        decodeAndCheck(fixed);
    return 0;
}
