// The sweep runner called in process (issue #26 item 1): the built-in Cornell
// box, a small traced reference, two settings; then cancel and the files.
#include "lpv/bench/Reference.h"
#include "lpv/bench/Sweep.h"
#include "lpv/bench/SweepOutput.h"
#include "lpv/radiosity/RadiositySession.h"
#include "lpv/radiosity/RayCastFormFactors.h"
#include "lpv/radiosity/SolveLoop.h"
#include "lpv/scene/CornellBox.h"

#include "TestFiles.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace lpv;
using lpv::test::freshTempDir;
namespace fs = std::filesystem;

namespace {

constexpr int kWidth = 64, kHeight = 36;

struct CornellSweep {
    bench::SweepSpec spec;
    reference::ReferenceImage reference;
};

// One reference for the file: tracing is the slow part.
const CornellSweep& cornell() {
    static const CornellSweep sweep = [] {
        CornellSweep s;
        s.spec.project = scene::makeCornellBoxProject();
        s.spec.projectDir = fs::temp_directory_path();
        s.spec.camera = s.spec.project.scene.cameras.front();
        s.spec.width = kWidth;
        s.spec.height = kHeight;
        s.spec.frames = 1;
        s.spec.warmup = 1;
        s.spec.rounds = {2, 2, 0.10, 0.0}; // two interleaved rounds: forward, then backward
        (void)s.spec.project.parameters.setFromText("lpv.reuse", "false", "test");
        scene::Project traced = s.spec.project;
        (void)traced.parameters.setFromText("reference.samplesPerPixel", "32", "test");
        auto ref = bench::traceReference(traced, s.spec.projectDir, s.spec.camera, {kWidth, kHeight, 0, {}});
        if (ref) {
            s.reference = std::move(ref->image);
            s.spec.referenceBounces = ref->bounces;
        }
        return s;
    }();
    return sweep;
}

} // namespace

TEST(SweepGL, EachSettingIsTimedAndMeasuredAgainstTheReference) {
    const CornellSweep& c = cornell();
    ASSERT_EQ(c.reference.width, kWidth) << "the reference did not trace";
    bench::SweepSpec spec = c.spec;
    spec.combinations = {{{"lpv.propagationSteps", "0"}}, {{"lpv.propagationSteps", "8"}}};
    ASSERT_FALSE(bench::checkSweep(spec, "ref").has_value());
    std::vector<std::string> labels;
    int measured = 0, finished = 0;
    double lastFraction = -1.0;
    bench::SweepCallbacks callbacks;
    callbacks.progress = [&](const bench::SweepProgress& p) {
        labels.push_back((p.round < 0 ? "" : "round " + std::to_string(p.round) + ": ") + p.label);
        EXPECT_EQ(p.total, 2);
        EXPECT_GE(p.fraction, lastFraction) << "progress goes forward";
        lastFraction = p.fraction;
        return true;
    };
    callbacks.runMeasured = [&](const bench::SweepRun& run) {
        ++measured;
        EXPECT_EQ(finished, 0) << "accuracy first, then the timing rounds";
        EXPECT_EQ(run.total.rounds, 0);
    };
    callbacks.runDone = [&](const bench::SweepRun&) { ++finished; };
    auto result = bench::runSweep(spec, c.reference, callbacks);
    ASSERT_TRUE(result.has_value()) << result.error().describe();
    ASSERT_EQ(result->runs.size(), 2u);
    EXPECT_EQ(measured, 2);
    EXPECT_EQ(finished, 2);
    // Each setting measured once, then timed in interleaved rounds: forward, then backward.
    EXPECT_EQ(labels, (std::vector<std::string>{"propagationSteps=0", "propagationSteps=8",
                                                "round 0: propagationSteps=0", "round 0: propagationSteps=8",
                                                "round 1: propagationSteps=8", "round 1: propagationSteps=0", ""}));
    EXPECT_EQ(result->rounds, 2);
    EXPECT_NE(result->stopReason.find("round limit"), std::string::npos) << result->stopReason;
    EXPECT_NE(result->load.find("->"), std::string::npos) << result->load;
    EXPECT_FALSE(result->gl.renderer.empty());
    for (const bench::SweepRun& run : result->runs) {
        EXPECT_GT(run.totalMs, 0.0);
        EXPECT_EQ(run.total.rounds, 2);
        EXPECT_DOUBLE_EQ(run.totalMs, run.total.median);
        EXPECT_LE(run.total.min, run.total.median);
        EXPECT_GE(run.total.max, run.total.median);
        EXPECT_FALSE(run.passes.empty());
        EXPECT_EQ(run.passStats.size(), run.passes.size());
        // The frame's memory, counted to the byte: the LPV's volumes are part of it.
        EXPECT_GT(run.lpvBytes, 0u);
        EXPECT_GT(run.gpuBytes, run.lpvBytes);
        EXPECT_TRUE(std::isfinite(run.indirect.mare));
        EXPECT_GT(run.indirect.pixels, std::size_t(kWidth * kHeight / 2)); // the box fills most of the view
        EXPECT_EQ(run.indirectPixels.size(), std::size_t(kWidth * kHeight));
        EXPECT_GT(run.indirect.meanReference, 0.0);
    }
    // Propagation carries the injected light into the room: more steps, more indirect light.
    EXPECT_GT(result->runs[1].indirect.meanTest, 1.2 * result->runs[0].indirect.meanTest);
}

TEST(SweepGL, StoppingFromTheProgressCallbackEndsAfterTheRunInFlight) {
    const CornellSweep& c = cornell();
    ASSERT_EQ(c.reference.width, kWidth);
    bench::SweepSpec spec = c.spec;
    spec.combinations = {{{"lpv.gridSize", "16"}}, {{"lpv.gridSize", "32"}}, {{"lpv.gridSize", "64"}}};
    int measured = 0, finished = 0;
    bench::SweepCallbacks callbacks;
    callbacks.progress = [](const bench::SweepProgress& p) { return p.done < 1; };
    callbacks.runMeasured = [&](const bench::SweepRun&) { ++measured; };
    callbacks.runDone = [&](const bench::SweepRun&) { ++finished; };
    auto result = bench::runSweep(spec, c.reference, callbacks);
    ASSERT_FALSE(result.has_value());
    EXPECT_EQ(result.error().code, scene::ErrorCode::Cancelled);
    EXPECT_EQ(measured, 1);
    EXPECT_EQ(finished, 0) << "a stopped sweep has no times to give";
}

TEST(SweepGL, ARunOfMoreBouncesThanTheReferenceIsRefusedBeforeRendering) {
    const CornellSweep& c = cornell();
    bench::SweepSpec spec = c.spec;
    spec.combinations = {{{"lpv.bounces", "3"}}};
    const auto problem = bench::checkSweep(spec, "ref.exr");
    ASSERT_TRUE(problem.has_value());
    EXPECT_NE(problem->find("lpv.bounces=3"), std::string::npos) << *problem;
    EXPECT_NE(problem->find("ref.exr"), std::string::npos) << *problem;
    spec.combinations = {{{"lpv.propagationSteps", "-4"}}};
    EXPECT_TRUE(bench::checkSweep(spec, "ref.exr").has_value()) << "a value the registry refuses";
}

TEST(SweepGL, AReferenceOfAnotherSizeIsAnErrorNotAWrongMeasurement) {
    const CornellSweep& c = cornell();
    bench::SweepSpec spec = c.spec;
    spec.width = kWidth * 2;
    auto result = bench::runSweep(spec, c.reference);
    ASSERT_FALSE(result.has_value());
    EXPECT_NE(result.error().message.find("64x36"), std::string::npos) << result.error().message;
}

TEST(SweepGL, TheFilesOfASweepNameEveryRun) {
    const CornellSweep& c = cornell();
    ASSERT_EQ(c.reference.width, kWidth);
    bench::SweepSpec spec = c.spec;
    spec.combinations = {{{"lpv.occlusion", "false"}}, {{"lpv.occlusion", "true"}}};
    auto result = bench::runSweep(spec, c.reference);
    ASSERT_TRUE(result.has_value()) << result.error().describe();
    const fs::path dir = freshTempDir("bench-files");
    auto written = bench::writeSweepOutputs(dir, result->runs, kWidth, kHeight, "test", "machine", c.reference);
    ASSERT_TRUE(written.has_value()) << written.error().describe();
    for (const char* name : {"sweep.csv", "sweep.json", "sweep.md", "error-time.png", "error-memory.png", "crops.png",
                             "frames.png"})
        EXPECT_TRUE(fs::exists(dir / name)) << name;
    std::ifstream in(dir / "sweep.json");
    const auto json = nlohmann::json::parse(in);
    ASSERT_EQ(json.at("runs").size(), 2u);
    EXPECT_EQ(json.at("runs")[1].at("settings").at("lpv.occlusion"), "true");
    // The figures read back exactly (a report resumed from sweep.json is the report).
    EXPECT_EQ(json.at("runs")[0].at("totalMs").get<double>(), result->runs[0].totalMs);
    EXPECT_EQ(json.at("runs")[1].at("indirect").at("mare").get<double>(), result->runs[1].indirect.mare);
    // The spread, the memory and the symmetric error with its bias travel with every run.
    const auto& run0 = json.at("runs")[0];
    EXPECT_EQ(run0.at("total").at("rounds").get<int>(), result->runs[0].total.rounds);
    EXPECT_EQ(run0.at("total").at("q3Ms").get<double>(), result->runs[0].total.q3);
    EXPECT_EQ(run0.at("gpuBytes").get<std::uint64_t>(), result->runs[0].gpuBytes);
    EXPECT_EQ(run0.at("indirect").at("logError").get<double>(), result->runs[0].indirect.logError);
    EXPECT_EQ(run0.at("biased").get<bool>(), bench::biasedMean(bench::meanRatio(result->runs[0].indirect)));
    std::ifstream md(dir / "sweep.md");
    const std::string markdown = (std::ostringstream() << md.rdbuf()).str();
    EXPECT_NE(markdown.find("same cost as"), std::string::npos);
    EXPECT_NE(markdown.find("symmetric error"), std::string::npos);
    fs::remove_all(dir);
}

// Issue #27 item 5: radiosity is a GI method beside the LPV settings. The
// sweep reads the solution saved beside the project, measures it against the
// reference's multi-bounce layer (a solution holds every bounce) and carries
// its solve time; without a solution the sweep fails and says what to do.
TEST(SweepGL, RadiosityIsMeasuredBesideTheLpvFromTheSavedSolution) {
    const CornellSweep& c = cornell();
    ASSERT_EQ(c.reference.width, kWidth) << "the reference did not trace";
    const fs::path dir = fs::temp_directory_path() / "lpv-sweep-radiosity";
    fs::remove_all(dir);
    fs::create_directories(dir);
    bench::SweepSpec spec = c.spec;
    spec.projectFile = dir / "cornell.lpvproj";
    spec.combinations = {{{"gi.method", "lpv"}}, {{"gi.method", "radiosity"}}};

    auto missing = bench::runSweep(spec, c.reference);
    ASSERT_FALSE(missing.has_value());
    EXPECT_NE(missing.error().message.find("no radiosity solution"), std::string::npos)
        << missing.error().describe();

    auto session = radiosity::RadiositySession::create(spec.project.scene, {}, 0.5f, 1000000);
    ASSERT_TRUE(session.has_value()) << session.error().describe();
    auto rays = radiosity::RayCastFormFactors::create(session->mesh(), spec.project.scene, {}, 1, 16);
    ASSERT_TRUE(rays.has_value()) << rays.error().describe();
    radiosity::SolveOptions options;
    options.residualTarget = 0.02;
    options.shootersPerBatch = 16;
    ASSERT_TRUE(radiosity::solve(session->solver(), **rays, options).has_value());
    ASSERT_TRUE(radiosity::saveSolution(session->stored(), radiosity::solutionPath(spec.projectFile)).has_value());

    auto result = bench::runSweep(spec, c.reference);
    ASSERT_TRUE(result.has_value()) << result.error().describe();
    ASSERT_EQ(result->runs.size(), 2u);
    const bench::SweepRun& lpv = result->runs[0];
    const bench::SweepRun& baked = result->runs[1];
    EXPECT_EQ(lpv.solveSeconds, 0.0);
    EXPECT_GT(baked.solveSeconds, 0.0);
    EXPECT_LE(baked.solveResidual, 0.02);
    EXPECT_EQ(baked.bounces, spec.referenceBounces);
    // Against the multi-bounce layer, not the one-bounce one.
    EXPECT_NE(baked.indirect.mare, baked.indirectOne.mare);
    EXPECT_NEAR(baked.indirect.meanTest / baked.indirect.meanReference, 1.0, 0.25);
    EXPECT_LT(baked.indirect.mare, lpv.indirect.mare);
}
