// The frame graph on its own (graph/FrameGraph.h): ordering by versions,
// culling with reasons, reuse by key, in-place chains, transient targets and
// the errors a wrong declaration gets. Passes here record that they ran;
// the GL context is there for the timer scopes and graph-owned targets.
#include "GlFixture.h"

#include "graph/FrameGraph.h"
#include "lpv/scene/CornellBox.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace lpv;
using renderer::PassStatus;
using renderer::graph::FrameGraph;
using renderer::graph::Lifetime;
using renderer::graph::PassContext;
using renderer::graph::PassId;
using renderer::graph::PassSpec;
using renderer::graph::ResourceHandle;
using scene::Pass;

namespace {

// The test graph's resources (the frame's own are in FrameResources.h).
constexpr ResourceHandle kA{"a"}, kB{"b"}, kC{"c"}, kT{"t"};

class FrameGraphGLTest : public GlTest {
  protected:
    scene::Project project = scene::makeCornellBoxProject();
    scene::ParameterSet params;
    renderer::GpuTimer timer;
    std::vector<std::string> ran;
    FrameGraph graph;

    renderer::FrameContext frame() {
        return {project.scene, params, project.scene.cameras.front(), 8, 8, {}, {}, {}, timer};
    }
    // A pass that records its name when it runs; reads and writes as given.
    PassSpec pass(PassId id, std::vector<ResourceHandle> reads, std::vector<ResourceHandle> writes, bool final = false,
                  std::optional<std::uint64_t> key = 1) {
        PassSpec p;
        p.id = id;
        p.decision.wanted = true;
        p.decision.reason = "test";
        p.reads = std::move(reads);
        p.writes = std::move(writes);
        p.final = final;
        p.inputsKey = key;
        p.execute = [this, id](PassContext& ctx) {
            (void)ctx;
            ran.push_back(id.name());
            return scene::Expected<void>{};
        };
        return p;
    }
    void declareResources() {
        for (ResourceHandle name : {kA, kB, kC})
            graph.importResource(name, [] { return renderer::graph::ImportedView{}; });
    }
    // One frame: declare via `build`, compile with reuse, execute; returns the passes that ran.
    std::vector<std::string> runFrame(const std::function<void()>& build, bool reuse = true) {
        ran.clear();
        timer.beginFrame();
        graph.beginFrame();
        declareResources();
        build();
        auto compiled = graph.compile(params, reuse);
        EXPECT_TRUE(compiled.has_value()) << (compiled ? "" : compiled.error().describe());
        const auto f = frame();
        auto executed = graph.execute(f);
        EXPECT_TRUE(executed.has_value()) << (executed ? "" : executed.error().describe());
        return ran;
    }
    const renderer::GraphPassReport& report(const PassId& p) {
        const auto* r = graph.report().find(p.name());
        EXPECT_NE(r, nullptr) << p.name();
        static renderer::GraphPassReport none;
        return r ? *r : none;
    }
};

using Names = std::vector<std::string>;

TEST_F(FrameGraphGLTest, RunsWritersBeforeReadersAndCullsWhatNothingReads) {
    auto build = [&] {
        // Added out of order on purpose: the tonemap-like final pass first is still run last.
        graph.addPass(pass(Pass::Rsm, {}, {kA}));
        graph.addPass(pass(Pass::LpvInjection, {kA}, {kB}));
        graph.addPass(pass(Pass::SkyHeight, {}, {kC})); // nobody reads c
        graph.addPass(pass(Pass::Tonemap, {kB}, {}, true));
    };
    EXPECT_EQ(runFrame(build), (Names{"rsm", "lpvInjection", "tonemap"}));
    EXPECT_EQ(report(Pass::SkyHeight).status, PassStatus::Culled);
    EXPECT_EQ(report(Pass::SkyHeight).reason, "nothing this frame reads its outputs");
    // The report lists passes in execution order, culled ones last.
    ASSERT_EQ(graph.report().passes.size(), 4u);
    EXPECT_EQ(graph.report().passes.back().name, "skyHeight");
}

TEST_F(FrameGraphGLTest, AReadRunsBeforeTheNextWriterOfWhatItRead) {
    auto build = [&] {
        graph.addPass(pass(Pass::LpvInjection, {}, {kA}));
        graph.addPass(pass(Pass::LpvNormals, {kA}, {kB}));        // reads a as injection left it
        graph.addPass(pass(Pass::LpvPropagation, {kA, kB}, {kA})); // then a is updated in place
        graph.addPass(pass(Pass::Tonemap, {kA}, {}, true));
    };
    EXPECT_EQ(runFrame(build), (Names{"lpvInjection", "lpvNormals", "lpvPropagation", "tonemap"}));
}

TEST_F(FrameGraphGLTest, ADecisionThatSaysNoCullsThePassWithItsReason) {
    auto build = [&] {
        PassSpec sky = pass(Pass::SkyHeight, {}, {kC});
        sky.decision.wanted = false;
        sky.decision.reason = "closed interior: no sky light reaches the scene";
        graph.addPass(std::move(sky));
        graph.addPass(pass(Pass::Tonemap, {}, {}, true));
    };
    EXPECT_EQ(runFrame(build), (Names{"tonemap"}));
    EXPECT_EQ(report(Pass::SkyHeight).status, PassStatus::Culled);
    EXPECT_EQ(report(Pass::SkyHeight).reason, "closed interior: no sky light reaches the scene");
}

TEST_F(FrameGraphGLTest, AnOutputIsReusedUntilAParameterThatInvalidatesItChanges) {
    // rsm.tileSize invalidates the RSM; lpv.propagationSteps only what propagates.
    auto build = [&] {
        graph.addPass(pass(Pass::Rsm, {}, {kA}));
        graph.addPass(pass(Pass::LpvPropagation, {kA}, {kB}));
        graph.addPass(pass(Pass::Tonemap, {kB}, {}, true, std::nullopt));
    };
    EXPECT_EQ(runFrame(build), (Names{"rsm", "lpvPropagation", "tonemap"}));
    EXPECT_EQ(report(Pass::Rsm).reason, "nothing to reuse: first run");
    EXPECT_EQ(runFrame(build), (Names{"tonemap"}));
    EXPECT_EQ(report(Pass::Rsm).status, PassStatus::Reused);
    EXPECT_EQ(report(Pass::Tonemap).reason, "runs every frame");

    ASSERT_TRUE(params.set("lpv.propagationSteps", 4).has_value());
    EXPECT_EQ(runFrame(build), (Names{"lpvPropagation", "tonemap"}));
    EXPECT_EQ(report(Pass::LpvPropagation).reason, "lpv.propagationSteps changed");
    EXPECT_EQ(report(Pass::Rsm).status, PassStatus::Reused);

    ASSERT_TRUE(params.set("rsm.tileSize", 128).has_value());
    EXPECT_EQ(runFrame(build), (Names{"rsm", "lpvPropagation", "tonemap"}));
    EXPECT_EQ(report(Pass::Rsm).reason, "rsm.tileSize changed");
    // rsm.tileSize invalidates propagation too; either way it reran with its input.
    EXPECT_EQ(report(Pass::LpvPropagation).status, PassStatus::Ran);
}

TEST_F(FrameGraphGLTest, AParameterAPassDeclaresItReadsIsPartOfItsKey) {
    // radiosity.smoothing names shading in the registry, and radiosityIndirect
    // has no scene::Pass bit (it names itself, PassId.h): declared by the
    // pass (issue #44 item 3), it reruns it; undeclared it would not.
    const PassId radiosityIndirect("radiosityIndirect");
    bool declares = true;
    auto build = [&] {
        PassSpec p = pass(radiosityIndirect, {}, {kA});
        if (declares)
            p.parameters = {"radiosity.smoothing"};
        graph.addPass(std::move(p));
        graph.addPass(pass(Pass::Tonemap, {kA}, {}, true, std::nullopt));
    };
    EXPECT_EQ(runFrame(build), (Names{"radiosityIndirect", "tonemap"}));
    EXPECT_EQ(runFrame(build), (Names{"tonemap"}));
    ASSERT_TRUE(params.set("radiosity.smoothing", false).has_value());
    EXPECT_EQ(runFrame(build), (Names{"radiosityIndirect", "tonemap"}));
    EXPECT_EQ(report(radiosityIndirect).reason, "radiosity.smoothing changed");
    EXPECT_EQ(runFrame(build), (Names{"tonemap"}));
    declares = false;
    runFrame(build); // its key lost the parameter: it runs once more
    ASSERT_TRUE(params.set("radiosity.smoothing", true).has_value());
    EXPECT_EQ(runFrame(build), (Names{"tonemap"})) << "without the declaration the parameter is not in the key";

    // A key the registry does not declare is an error naming it.
    graph.beginFrame();
    declareResources();
    PassSpec wrong = pass(radiosityIndirect, {}, {kA});
    wrong.parameters = {"radiosity.smoothnes"};
    graph.addPass(std::move(wrong));
    auto compiled = graph.compile(params, true);
    ASSERT_FALSE(compiled.has_value());
    EXPECT_NE(compiled.error().describe().find("'radiosity.smoothnes'"), std::string::npos) << compiled.error().describe();
}

TEST_F(FrameGraphGLTest, ANewInputsKeyReruns) {
    std::uint64_t key = 1;
    auto build = [&] {
        graph.addPass(pass(Pass::ShadowMaps, {}, {kA}, false, key));
        graph.addPass(pass(Pass::Tonemap, {kA}, {}, true, std::nullopt));
    };
    runFrame(build);
    EXPECT_EQ(runFrame(build), (Names{"tonemap"}));
    key = 2;
    EXPECT_EQ(runFrame(build), (Names{"shadowMaps", "tonemap"}));
    EXPECT_EQ(report(Pass::ShadowMaps).reason, "the scene, lights or camera changed");
}

TEST_F(FrameGraphGLTest, PassesThatUpdateOneResourceRerunTogether) {
    // Injection writes a, propagation updates it in place: a changed
    // propagation must start again from a fresh injection, whose own key did not change.
    auto build = [&] {
        graph.addPass(pass(Pass::LpvInjection, {}, {kA}));
        graph.addPass(pass(Pass::LpvNormals, {kA}, {kB}));
        graph.addPass(pass(Pass::LpvPropagation, {kA, kB}, {kA}));
        graph.addPass(pass(Pass::Tonemap, {kA}, {}, true, std::nullopt));
    };
    runFrame(build);
    EXPECT_EQ(runFrame(build), (Names{"tonemap"}));
    ASSERT_TRUE(params.set("lpv.propagationSteps", 3).has_value());
    EXPECT_EQ(runFrame(build), (Names{"lpvInjection", "lpvPropagation", "tonemap"}));
    EXPECT_EQ(report(Pass::LpvInjection).reason, "reruns with lpvPropagation (they share a)");
    EXPECT_EQ(report(Pass::LpvNormals).status, PassStatus::Reused); // its own output b is intact
    // A pass that read the injected version reruns: the memory now holds the propagated one,
    // so injection runs again first.
    ASSERT_TRUE(params.set("lpv.directedDilation", 2).has_value());
    const Names again = runFrame(build);
    EXPECT_EQ(again.front(), "lpvInjection");
    EXPECT_NE(std::find(again.begin(), again.end(), "lpvNormals"), again.end());
}

TEST_F(FrameGraphGLTest, ReuseOffRunsEverything) {
    auto build = [&] {
        graph.addPass(pass(Pass::Rsm, {}, {kA}));
        graph.addPass(pass(Pass::Tonemap, {kA}, {}, true));
    };
    runFrame(build);
    EXPECT_EQ(runFrame(build, false), (Names{"rsm", "tonemap"}));
    EXPECT_EQ(report(Pass::Rsm).reason, "reuse is off (lpv.reuse = false)");
}

TEST_F(FrameGraphGLTest, TransientTargetsAreAllocatedForTheFrameAndNeverReused) {
    GLuint seen = 0;
    auto build = [&] {
        graph.createResource(kT, {renderer::graph::ResourceKind::Texture2D, GL_RGBA8, 4, 2}, Lifetime::Transient);
        PassSpec p = pass(Pass::SunRays, {}, {kT});
        p.execute = [&](PassContext& ctx) {
            seen = ctx.id(kT);
            ran.push_back("sunRays");
            return scene::Expected<void>{};
        };
        graph.addPass(std::move(p));
        graph.addPass(pass(Pass::Tonemap, {kT}, {}, true, std::nullopt));
    };
    runFrame(build);
    EXPECT_NE(seen, 0u);
    EXPECT_EQ(graph.resourceDesc(kT.name())->width, 4);
    EXPECT_EQ(runFrame(build), (Names{"sunRays", "tonemap"}));
    EXPECT_EQ(report(Pass::SunRays).reason, "t is transient: nothing is kept");
    EXPECT_EQ(report(Pass::SunRays).writes.at(0).description, "2D RGBA8 4x2");
}

TEST_F(FrameGraphGLTest, WrongDeclarationsAreErrorsNotCrashes) {
    graph.beginFrame();
    declareResources();
    graph.addPass(pass(Pass::Rsm, {ResourceHandle{"nope"}}, {kA}));
    auto compiled = graph.compile(params, true);
    ASSERT_FALSE(compiled.has_value());
    EXPECT_NE(compiled.error().describe().find("'nope'"), std::string::npos) << compiled.error().describe();

    graph.beginFrame();
    declareResources();
    graph.addPass(pass(Pass::Rsm, {}, {kA}));
    graph.addPass(pass(Pass::Rsm, {kA}, {kB}, true));
    ASSERT_FALSE(graph.compile(params, true).has_value()) << "two passes with one name";

    // Using a resource the pass did not declare fails the frame with a message.
    graph.beginFrame();
    declareResources();
    PassSpec p = pass(Pass::Tonemap, {}, {}, true);
    p.execute = [](PassContext& ctx) {
        (void)ctx.id(kA);
        return scene::Expected<void>{};
    };
    graph.addPass(std::move(p));
    ASSERT_TRUE(graph.compile(params, true).has_value());
    const auto f = frame();
    auto executed = graph.execute(f);
    ASSERT_FALSE(executed.has_value());
    EXPECT_NE(executed.error().describe().find("did not declare"), std::string::npos) << executed.error().describe();
}

TEST_F(FrameGraphGLTest, TexturesUnitsSkipTheReservedRange) {
    graph.reserveUnits(2, 5);
    std::vector<GLuint> units;
    auto build = [&] {
        PassSpec p = pass(Pass::Tonemap, {}, {}, true);
        p.execute = [&](PassContext& ctx) {
            for (int i = 0; i < 4; ++i)
                units.push_back(ctx.allocateUnit());
            return scene::Expected<void>{};
        };
        graph.addPass(std::move(p));
    };
    runFrame(build);
    EXPECT_EQ(units, (std::vector<GLuint>{0, 1, 6, 7}));
}

} // namespace
