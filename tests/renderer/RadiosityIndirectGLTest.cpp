// gi.method = radiosity (issue #27 item 1): the Cornell box solved with
// coarse patches (ray-cast form factors), saved beside a temporary project,
// loaded back with loadBakedSolution and drawn by the radiosityIndirect pass
// as the indirect light that shading adds to the direct light it draws.
#include "CheckerAlpha.h"
#include "GlFixture.h"

#include "lpv/radiosity/BakedSolution.h"
#include "lpv/radiosity/PatchMesh.h"
#include "lpv/radiosity/RadiositySession.h"
#include "lpv/radiosity/SolveLoop.h"
#include "lpv/radiosity/VertexRadiosity.h"
#include "lpv/renderer/FormFactorSources.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/CornellBox.h"

#include "TestPaths.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>

using namespace lpv;
namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 240, kHeight = 180;

struct Solved {
    scene::Project project;
    fs::path projectFile; // never written: the solution sits where it would be
    std::shared_ptr<const radiosity::BakedSolution> solution;
};

// Solved once for the suite: coarse patches and residual 0.05 keep it to seconds.
const Solved& solved() {
    static const Solved s = [] {
        Solved out;
        out.project = scene::makeCornellBoxProject();
        const fs::path dir = fs::path(test::kBinaryDir) / "tests" / "radiosity-indirect";
        fs::remove_all(dir);
        fs::create_directories(dir);
        out.projectFile = dir / "cornell.lpvproj";
        const scene::Scene& scene = out.project.scene;
        static const scene::TextureImages
            noTextures; // the Cornell box has none; the source keeps a reference
        auto session = radiosity::RadiositySession::create(scene, noTextures, 0.5f, 1000000);
        EXPECT_TRUE(session.has_value()) << session.error().describe();
        auto formFactors = renderer::makeFormFactorSource("raycast", session->mesh(), scene, noTextures,
                                                          out.project.parameters);
        EXPECT_TRUE(formFactors.has_value()) << formFactors.error().describe();
        radiosity::SolveOptions options;
        options.residualTarget = 0.05;
        options.shootersPerBatch = (*formFactors)->preferredBatch();
        const auto stop = radiosity::solve(session->solver(), **formFactors, options);
        EXPECT_TRUE(stop.has_value()) << stop.error().describe();
        const auto saved =
            radiosity::saveSolution(session->stored(), radiosity::solutionPath(out.projectFile));
        EXPECT_TRUE(saved.has_value()) << saved.error().describe();
        auto loaded = radiosity::loadBakedSolution(scene, noTextures, out.projectFile);
        EXPECT_TRUE(loaded.has_value()) << loaded.error().describe();
        if (loaded)
            out.solution = std::make_shared<const radiosity::BakedSolution>(std::move(*loaded));
        return out;
    }();
    return s;
}

scene::ParameterSet withSets(std::initializer_list<std::pair<const char*, const char*>> sets) {
    scene::ParameterSet params = solved().project.parameters;
    for (const auto& [key, value] : sets)
        EXPECT_TRUE(params.setFromText(key, value, "test").has_value()) << key;
    return params;
}

// One frame's linear image and G-buffer, rows top to bottom.
struct Frame {
    std::vector<float> hdr, normal, depth;
};

Frame render(renderer::ForwardRenderer& r, const scene::ParameterSet& params,
             const std::optional<scene::Camera>& camera = std::nullopt) {
    const Solved& s = solved();
    const auto ok =
        r.render(s.project.scene, params, camera.value_or(s.project.scene.cameras.front()), kWidth, kHeight);
    EXPECT_TRUE(ok.has_value()) << ok.error().describe();
    return {r.readHdr(), r.readGBufferNormal(), r.readDepth()};
}

glm::vec3 rgb(const std::vector<float>& px, std::size_t i) {
    return {px[4 * i], px[4 * i + 1], px[4 * i + 2]};
}
float luminance(glm::vec3 c) {
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

// The world position a pixel shows, from the camera depth.
glm::vec3 worldAt(const glm::mat4& inverseViewProj, int x, int y, float depth) {
    const glm::vec4 ndc{2.0f * (float(x) + 0.5f) / float(kWidth) - 1.0f,
                        1.0f - 2.0f * (float(y) + 0.5f) / float(kHeight), 2.0f * depth - 1.0f, 1.0f};
    const glm::vec4 w = inverseViewProj * ndc;
    return glm::vec3(w) / w.w;
}

glm::mat4 inverseViewProj() {
    const scene::Camera& c = solved().project.scene.cameras.front();
    return glm::inverse(c.projection(float(kWidth) / float(kHeight)) * c.view());
}

// The smoothed incident light at `p` on the solution's patches, as the pass
// interpolates it (the patch's triangle that holds p, barycentric), and the
// material there; nullopt where no patch holds p.
struct PatchPoint {
    glm::vec3 incident;
    std::uint32_t material;
};
std::optional<PatchPoint> incidentAt(const radiosity::BakedSolution& solution,
                                     const std::vector<glm::vec3>& corners, glm::vec3 p) {
    std::optional<PatchPoint> best;
    float bestDistance = 1e-3f; // scene units: the Cornell box is 5.5 across
    for (std::size_t i = 0; i < solution.mesh.size(); ++i) {
        const radiosity::Patch& patch = solution.mesh.patches[i];
        const float distance = std::abs(glm::dot(patch.normal, p - patch.corners[0]));
        if (distance >= bestDistance)
            continue;
        for (const auto& tri : {std::array{0, 1, 2}, std::array{0, 2, 3}}) {
            if (tri[2] >= patch.cornerCount)
                continue;
            const glm::vec3 a = patch.corners[std::size_t(tri[0])], b = patch.corners[std::size_t(tri[1])],
                            c = patch.corners[std::size_t(tri[2])];
            const glm::vec3 n = glm::cross(b - a, c - a);
            const float area = glm::dot(n, n);
            const float u = glm::dot(glm::cross(c - b, p - b), n) / area;
            const float v = glm::dot(glm::cross(a - c, p - c), n) / area;
            const float w = 1.0f - u - v;
            if (std::min({u, v, w}) < -1e-4f)
                continue;
            const auto value = [&](int k) { return corners[4 * i + std::size_t(k)]; };
            best = PatchPoint{u * value(tri[0]) + v * value(tri[1]) + w * value(tri[2]), patch.material};
            bestDistance = distance;
        }
    }
    return best;
}

class RadiosityIndirectGLTest : public GlTest {
  protected:
    void SetUp() override {
        GlTest::SetUp();
        ASSERT_TRUE(solved().solution) << "the Cornell box did not solve";
        auto created = renderer::ForwardRenderer::create();
        ASSERT_TRUE(created.has_value()) << created.error().describe();
        renderer_.emplace(std::move(*created));
        renderer_->setScene(solved().project.scene);
    }
    void TearDown() override { renderer_.reset(); }
    std::optional<renderer::ForwardRenderer> renderer_;
};

// The box in the shade of the direct light gets light, and the red wall
// bleeds onto the floor beside it.
TEST_F(RadiosityIndirectGLTest, TheSolutionLightsTheShadeAndBleedsTheRedWall) {
    const Solved& s = solved();
    renderer_->setBakedRadiosity(s.solution);
    const Frame off = render(*renderer_, withSets({{"gi.method", "off"}}));
    const Frame baked = render(*renderer_, withSets({{"gi.method", "radiosity"}}));
    const glm::mat4 inverse = inverseViewProj();
    // The ceiling beside the lamp: the one-sided area light does not reach it.
    double ceilingOff = 0.0, ceilingBaked = 0.0;
    int ceiling = 0;
    glm::dvec3 redSide(0.0), greenSide(0.0);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = std::size_t(y) * kWidth + std::size_t(x);
            const glm::vec3 n = rgb(off.normal, i);
            if (off.normal[4 * i + 3] == 0.0f)
                continue;
            if (n.y < -0.99f && luminance(rgb(off.hdr, i)) < 1.0f) {
                ceilingOff += luminance(rgb(off.hdr, i));
                ceilingBaked += luminance(rgb(baked.hdr, i));
                ++ceiling;
            }
            const glm::vec3 p = worldAt(inverse, x, y, off.depth[i]);
            if (n.y > 0.99f && p.y < 0.01f) { // the floor, not the short box's top
                const glm::vec3 added = rgb(baked.hdr, i) - rgb(off.hdr, i);
                if (p.x > 3.9f)
                    redSide += glm::dvec3(added);
                else if (p.x < 1.6f)
                    greenSide += glm::dvec3(added);
            }
        }
    ASSERT_GT(ceiling, 100);
    EXPECT_LT(ceilingOff / ceiling, 1e-4) << "the ceiling is unlit without indirect light";
    EXPECT_GT(ceilingBaked / ceiling, 0.02) << "the solution lights the ceiling";
    ASSERT_GT(redSide.g, 0.0);
    ASSERT_GT(greenSide.g, 0.0);
    const double redRatio = redSide.r / redSide.g, greenRatio = greenSide.r / greenSide.g;
    EXPECT_GT(redRatio, 1.3 * greenRatio) << "red/green of the added light: " << redRatio
                                          << " near the red wall, " << greenRatio << " near the green wall";
}

// Each pixel gains the albedo times the smoothed incident light of the patch
// point it shows, with and without the depth pre-pass; the indirect view
// shows pi times it (the irradiance).
TEST_F(RadiosityIndirectGLTest, APixelGainsItsAlbedoTimesTheIncidentLightThere) {
    const Solved& s = solved();
    renderer_->setBakedRadiosity(s.solution);
    const std::vector<glm::vec3> corners =
        radiosity::cornerValues(s.solution->mesh, s.solution->incident, true);
    const glm::mat4 inverse = inverseViewProj();
    for (const char* prepass : {"true", "false"}) {
        const Frame off =
            render(*renderer_, withSets({{"gi.method", "off"}, {"output.depthPrepass", prepass}}));
        const Frame baked =
            render(*renderer_, withSets({{"gi.method", "radiosity"}, {"output.depthPrepass", prepass}}));
        const Frame view = render(*renderer_, withSets({{"gi.method", "radiosity"},
                                                        {"output.depthPrepass", prepass},
                                                        {"output.view", "indirect"}}));
        int tested = 0, agreed = 0, viewAgreed = 0;
        for (int y = 3; y < kHeight; y += 7)
            for (int x = 3; x < kWidth; x += 7) {
                const std::size_t i = std::size_t(y) * kWidth + std::size_t(x);
                if (off.normal[4 * i + 3] == 0.0f)
                    continue;
                const auto expected = incidentAt(*s.solution, corners, worldAt(inverse, x, y, off.depth[i]));
                if (!expected || luminance(expected->incident) < 1e-3f)
                    continue;
                const glm::vec3 albedo = s.project.scene.materials[expected->material].diffuseColor;
                const glm::vec3 want = albedo * expected->incident;
                const glm::vec3 added = rgb(baked.hdr, i) - rgb(off.hdr, i);
                const glm::vec3 irradiance = rgb(view.hdr, i);
                auto close = [](glm::vec3 got, glm::vec3 wanted) {
                    const glm::vec3 error = glm::abs(got - wanted);
                    return glm::all(glm::lessThanEqual(error, 0.02f * wanted + 2e-3f));
                };
                ++tested;
                agreed += close(added, want);
                viewAgreed += close(irradiance, 3.14159265f * expected->incident);
            }
        // Pixels on the creases between walls may take the other wall's patch.
        ASSERT_GT(tested, 300) << "depth pre-pass " << prepass;
        EXPECT_GE(agreed, tested * 95 / 100) << agreed << " of " << tested << ", depth pre-pass " << prepass;
        EXPECT_GE(viewAgreed, tested * 95 / 100)
            << viewAgreed << " of " << tested << ", depth pre-pass " << prepass;
    }
}

// A still camera reuses the pass (no timer row that frame); a camera move
// reruns it; its name is in the timing table.
TEST_F(RadiosityIndirectGLTest, TheFrameGraphReusesAndTimesThePass) {
    renderer_->setBakedRadiosity(solved().solution);
    const scene::ParameterSet params = withSets({{"gi.method", "radiosity"}});
    const Frame first = render(*renderer_, params);
    auto status = [&] { return renderer_->graphReport().find("radiosityIndirect")->status; };
    EXPECT_EQ(status(), renderer::PassStatus::Ran);
    const Frame second = render(*renderer_, params);
    EXPECT_EQ(status(), renderer::PassStatus::Reused);
    EXPECT_EQ(first.hdr, second.hdr);
    scene::Camera moved = solved().project.scene.cameras.front();
    moved.position.x += 0.1f;
    moved.target.x += 0.1f;
    render(*renderer_, params, moved);
    EXPECT_EQ(status(), renderer::PassStatus::Ran);
    renderer_->timer().resolveAll();
    const auto table = renderer_->timer().table();
    EXPECT_TRUE(
        std::any_of(table.begin(), table.end(), [](const auto& t) { return t.pass == "radiosityIndirect"; }));
    // Nothing of the LPV runs: the solution is the indirect light.
    for (const char* pass : {"lpvInjection", "lpvPropagation", "geometryVolume", "localRsm"}) {
        const auto* report = renderer_->graphReport().find(pass);
        ASSERT_NE(report, nullptr) << pass;
        EXPECT_EQ(report->status, renderer::PassStatus::Culled) << pass;
        EXPECT_NE(report->reason.find("gi.method is radiosity"), std::string::npos)
            << pass << ": " << report->reason;
    }
}

// Without a solution the frame is the direct light alone, and says why.
TEST_F(RadiosityIndirectGLTest, WithoutASolutionTheFrameHasDirectLightOnlyAndSaysWhy) {
    const Frame off = render(*renderer_, withSets({{"gi.method", "off"}}));
    const Frame none = render(*renderer_, withSets({{"gi.method", "radiosity"}}));
    EXPECT_EQ(off.hdr, none.hdr);
    const auto& effects = renderer_->frameEffects();
    const auto it = std::find_if(effects.begin(), effects.end(), [](const renderer::EffectDecision& e) {
        return e.effect == "Baked radiosity";
    });
    ASSERT_NE(it, effects.end());
    EXPECT_FALSE(it->runs());
    EXPECT_NE(it->reason.find("no radiosity solution: run lpv radiosity"), std::string::npos) << it->reason;
    EXPECT_NE(renderer_->lpvNote().find("no radiosity solution"), std::string::npos) << renderer_->lpvNote();
    EXPECT_EQ(renderer_->graphReport().find("radiosityIndirect")->status, renderer::PassStatus::Culled);
}

namespace {

// A horizontal quad facing up, x0..x1 by z0..z1 at height y.
scene::Mesh horizontalQuad(float x0, float x1, float z0, float z1, float y, std::uint32_t material) {
    scene::Mesh m;
    m.positions = {{x0, y, z1}, {x1, y, z1}, {x1, y, z0}, {x0, y, z0}};
    m.normals.assign(4, {0.0f, 1.0f, 0.0f});
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m.indices = {0, 1, 2, 0, 2, 3};
    m.submeshes = {{0, 6, material}};
    return m;
}

} // namespace

// A patch is a whole quad, but an alpha-masked leaf has holes: after the
// depth pre-pass the ground seen through them reads the ground's light, not
// the leaf's (the solution is made by hand: green on the ground, red on the leaf).
TEST_F(RadiosityIndirectGLTest, TheGroundSeenThroughAMaskedLeafReadsItsOwnLight) {
    scene::Scene s;
    scene::Material white, leaves;
    white.diffuseColor = leaves.diffuseColor = glm::vec3(1.0f);
    leaves.alphaMode = scene::AlphaMode::Mask;
    leaves.alphaTexture = "checker.png";
    s.materials = {white, leaves};
    s.meshes = {horizontalQuad(-2, 2, -2, 2, 0.0f, 0), horizontalQuad(-1, 1, -1, 1, 0.3f, 1)};
    s.objects = {{"ground", 0, -1, {}, true, {}}, {"leaf", 1, -1, {}, true, {}}};
    s.sky.intensity = 0.0f;
    scene::TextureImages textures;
    textures["checker.png"] = test::checkerAlpha(); // 4x4 cells of 0.5 m
    auto solution = std::make_shared<radiosity::BakedSolution>();
    solution->mesh = radiosity::buildPatchMesh(s, {0.25f});
    for (const radiosity::Patch& p : solution->mesh.patches)
        solution->incident.push_back(p.material == 0 ? glm::vec3(0.0f, 0.5f, 0.0f)
                                                     : glm::vec3(0.5f, 0.0f, 0.0f));
    renderer_->setScene(s, textures);
    renderer_->setBakedRadiosity(solution);
    scene::Camera camera; // straight down; image right = +x, image up = -z
    camera.position = {0.0f, 3.0f, 0.0f};
    camera.target = {0.0f, 0.0f, 0.0f};
    camera.up = {0.0f, 0.0f, -1.0f};
    camera.fovY = glm::radians(60.0f);
    scene::ParameterSet params;
    ASSERT_TRUE(params.setFromText("gi.method", "radiosity", "test").has_value());
    ASSERT_TRUE(renderer_->render(s, params, camera, kWidth, kHeight).has_value());
    const std::vector<float> hdr = renderer_->readHdr(), depth = renderer_->readDepth();
    const glm::mat4 inverse = glm::inverse(camera.projection(float(kWidth) / float(kHeight)) * camera.view());
    int holes = 0, holesGreen = 0, leaf = 0, leafRed = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::size_t i = std::size_t(y) * kWidth + std::size_t(x);
            const glm::vec3 p = worldAt(inverse, x, y, depth[i]);
            if (std::abs(p.x) > 0.9f || std::abs(p.z) > 0.9f)
                continue;
            const glm::vec3 c = rgb(hdr, i); // no light: the frame is the indirect light alone
            if (p.y < 0.1f) {
                ++holes;
                holesGreen += c.g > 0.45f && c.r < 0.05f;
            } else {
                ++leaf;
                leafRed += c.r > 0.45f && c.g < 0.05f;
            }
        }
    ASSERT_GT(holes, 1000);
    ASSERT_GT(leaf, 1000);
    EXPECT_GE(holesGreen, holes * 98 / 100) << holesGreen << " of " << holes << " ground pixels";
    EXPECT_GE(leafRed, leaf * 98 / 100) << leafRed << " of " << leaf << " leaf pixels";
}

// A solution is shown only with the scene it was solved for.
TEST_F(RadiosityIndirectGLTest, ASolutionOfAnotherSceneOrNoneIsRefusedWithTheReason) {
    const Solved& s = solved();
    scene::Scene moved = s.project.scene;
    moved.lights.front().position.x -= 0.5f;
    const auto other = radiosity::loadBakedSolution(moved, {}, s.projectFile);
    ASSERT_FALSE(other.has_value());
    EXPECT_NE(other.error().message.find("solved for another scene"), std::string::npos)
        << other.error().describe();
    EXPECT_EQ(fs::path(other.error().file).filename(), "radiosity.lpvrad");
    const auto none =
        radiosity::loadBakedSolution(s.project.scene, {}, s.projectFile.parent_path() / "unsolved.lpvproj");
    ASSERT_FALSE(none.has_value());
    EXPECT_NE(none.error().message.find("no radiosity solution is saved"), std::string::npos)
        << none.error().describe();
}

} // namespace
