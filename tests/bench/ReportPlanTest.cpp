// `lpv bench report`'s plan and its shards' files (bench/ReportPlan.h,
// bench/ReportShards.h), called directly: which references a scene needs and
// which sweep measures against which, what --resume takes as done, and where
// a shard's pieces lie. Before issue #44 these were reached only through
// whole report runs of the CLI.
#include "lpv/bench/ReportPlan.h"
#include "lpv/bench/ReferenceFile.h"
#include "lpv/bench/ReportShards.h"
#include "lpv/bench/SavedSweep.h"
#include "lpv/scene/CornellBox.h"

#include "TestPaths.h"

#include "TestFiles.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>
#include <unistd.h>

using namespace lpv;
using lpv::test::freshTempDir;
using namespace lpv::bench::report;
namespace fs = std::filesystem;

namespace {

const SceneSpec& cornell() {
    return *std::ranges::find(kScenes, std::string("cornell-box"), &SceneSpec::name);
}

// Options whose output folder holds the Cornell box's project where the plan looks for it.
ReportOptions withCornellProject(const std::string& name) {
    ReportOptions o;
    o.outDir = freshTempDir("report-plan", name);
    const fs::path project = projectFileOf(cornell(), o);
    fs::copy(fs::path(test::kSourceDir) / "projects/cornell-box", project.parent_path(),
             fs::copy_options::recursive);
    return o;
}

void writeReference(const fs::path& file, int width, int height, int spp, int bounces,
                    const std::string& shard = "") {
    reference::ReferenceImage image;
    image.resize(width, height);
    std::map<std::string, std::string> attributes{{"lpv:spp", std::to_string(spp)},
                                                  {"lpv:bounces", std::to_string(bounces)}};
    if (!shard.empty())
        attributes["lpv:shard"] = shard;
    ASSERT_TRUE(bench::writeReferenceExr(file, image, attributes));
}

TEST(ReportPlan, OptionsChooseScenesQuestionsAndSamples) {
    ReportOptions o;
    EXPECT_TRUE(o.wantsScene("sponza")) << "no --scene: every scene";
    o.scenes = {"sibenik"};
    EXPECT_TRUE(o.wantsScene("sibenik"));
    EXPECT_FALSE(o.wantsScene("sponza"));
    o.questions = {"steps"};
    EXPECT_TRUE(o.wantsQuestion("steps"));
    EXPECT_FALSE(o.wantsQuestion("grid"));
    EXPECT_EQ(o.sppFor(cornell()), cornell().defaultSpp);
    o.quick = true;
    EXPECT_EQ(o.sppFor(cornell()), 256) << "--quick is a smoke run";
    o.spp = 32;
    EXPECT_EQ(o.sppFor(cornell()), 32) << "--spp wins";
    const std::string command = reportCommand(o);
    for (const char* part : {"--scene sibenik", "--question steps", "--spp 32", "--quick", "--rounds 9"})
        EXPECT_NE(command.find(part), std::string::npos) << part << " in " << command;
    EXPECT_EQ(command.find("--resume"), std::string::npos) << command;
}

TEST(ReportPlan, SweepValuesAreTheListAfterTheKey) {
    EXPECT_EQ(splitValues("lpv.bounces=1,2,3"), (std::vector<std::string>{"1", "2", "3"}));
    EXPECT_EQ(splitValues("lpv.cellSize=auto"), (std::vector<std::string>{"auto"}));
}

TEST(ReportPlan, EachSweepMeasuresAgainstItsLikeForLikeReference) {
    const ReportOptions o = withCornellProject("like-for-like");
    const auto plan = planScene(cornell(), o);
    ASSERT_TRUE(plan) << plan.error().describe();
    EXPECT_EQ(plan->project, projectFileOf(cornell(), o));
    EXPECT_EQ(timingFileOf(*plan), o.outDir / "cornell-box" / "timing.json");
    ASSERT_FALSE(plan->references.empty());
    EXPECT_EQ(plan->references[0].bounces, plan->projectBounces) << "the project's own reference first";
    EXPECT_EQ(plan->references[0].sky, "");
    std::set<fs::path> files;
    for (const PlannedReference& r : plan->references)
        EXPECT_TRUE(files.insert(r.file).second) << "one reference per bounce count and sky: " << r.file;
    std::size_t bounceSweeps = 0, skySweeps = 0;
    for (const PlannedSweep& s : plan->sweeps) {
        ASSERT_LT(s.reference, plan->references.size());
        const PlannedReference& r = plan->references[s.reference];
        if (s.question == "bounces") {
            ++bounceSweeps;
            EXPECT_EQ("lpv.bounces=" + std::to_string(r.bounces), s.sweep);
        } else if (s.question == "sky") {
            ++skySweeps;
            EXPECT_EQ("effects.skyInjection=" + r.sky, s.sweep);
            EXPECT_EQ(r.bounces, plan->projectBounces);
        } else {
            EXPECT_EQ(s.reference, 0u) << s.question;
            EXPECT_EQ(s.dir, plan->dir / s.question);
        }
    }
    EXPECT_EQ(bounceSweeps, 3u) << "one sweep per bounce count";
    EXPECT_EQ(skySweeps, 2u) << "one sweep per sky setting";
}

TEST(ReportPlan, QuickAndChosenQuestionsPlanOnlyThoseSweeps) {
    ReportOptions o = withCornellProject("quick");
    o.quick = true;
    o.questions = {"steps", "cascades"}; // cascades has no quick sweep
    const auto plan = planScene(cornell(), o);
    ASSERT_TRUE(plan) << plan.error().describe();
    ASSERT_EQ(plan->sweeps.size(), 1u);
    EXPECT_EQ(plan->sweeps[0].sweep, "lpv.propagationSteps=0,4,16");
    EXPECT_EQ(plan->references.size(), 1u);
}

TEST(ReportPlan, EverySweptSettingIsTimedOnce) {
    ReportOptions o = withCornellProject("distinct");
    o.questions = {"steps", "occlusion"};
    const auto plan = planScene(cornell(), o);
    ASSERT_TRUE(plan) << plan.error().describe();
    const auto settings = distinctSettings(*plan, plan->current);
    // steps 0,1,2,4,8,...,64 and occlusion false,true: where both sweeps hold
    // the project's own value, the project's setting is one, not two.
    const auto steps = splitValues(plan->sweeps[0].sweep);
    const bool projectStepsSwept =
        std::ranges::find(steps, std::to_string(plan->current.getInt("lpv.propagationSteps"))) != steps.end();
    EXPECT_EQ(settings.size(), steps.size() + 2 - (projectStepsSwept ? 1 : 0));
    for (std::size_t i = 0; i < settings.size(); ++i)
        for (std::size_t j = i + 1; j < settings.size(); ++j)
            EXPECT_FALSE(bench::sameValues(settings[i].second, settings[j].second)) << i << " and " << j;
}

TEST(ReportPlan, RadiosityPatchesAreCoarsenedOnlyForALargeScene) {
    scene::Project cornellBox = scene::makeCornellBoxProject();
    const float area = cornellBox.parameters.getFloat("radiosity.maxPatchArea");
    EXPECT_FLOAT_EQ(reportPatchArea(cornellBox), area) << "the Cornell box meshes finely at its own size";
    // The same box 100x larger: 10^4 times the patches at the project's size.
    for (scene::Object& object : cornellBox.scene.objects)
        object.transform.scale *= 100.0f;
    EXPECT_GT(reportPatchArea(cornellBox), area);
}

TEST(ReportPlan, AScenesPlanNeedsItsProject) {
    ReportOptions o;
    o.outDir = freshTempDir("report-plan", "no-project");
    const auto plan = planScene(cornell(), o);
    ASSERT_FALSE(plan);
    EXPECT_NE(plan.error().file.find("cornell-box.lpvproj"), std::string::npos) << plan.error().describe();
}

TEST(ReportPlan, AReferenceIsReusedOnlyAtItsSizeBouncesAndEnoughSamples) {
    const fs::path file = freshTempDir("report-plan", "reuse") / "ref.exr";
    EXPECT_FALSE(referenceMatches(file, 4, 2)) << "none there";
    writeReference(file, 4, 2, 64, 2);
    EXPECT_TRUE(referenceMatches(file, 4, 2));
    EXPECT_TRUE(referenceMatches(file, 4, 2, 2, 64));
    EXPECT_FALSE(referenceMatches(file, 4, 3, 2, 64)) << "another size";
    EXPECT_FALSE(referenceMatches(file, 4, 2, 1, 64)) << "another bounce count";
    EXPECT_FALSE(referenceMatches(file, 4, 2, 2, 65)) << "fewer samples than asked";
}

TEST(ReportPlan, ASweepIsDoneWhenTheSameCommandWroteItAfterItsReferenceAndTiming) {
    const ReportOptions o = withCornellProject("resume");
    const auto plan = planScene(cornell(), o);
    ASSERT_TRUE(plan) << plan.error().describe();
    const PlannedSweep& sweep = plan->sweeps.front();
    const fs::path result = sweep.dir / "sweep.json";
    fs::create_directories(sweep.dir);
    writeReference(plan->references[sweep.reference].file, o.width, o.height, plan->spp,
                   plan->projectBounces);
    std::ofstream(timingFileOf(*plan)) << "{}";
    auto writeResult = [&](int width) {
        const std::string command =
            "lpv bench " + plan->project.string() + " --width " + std::to_string(width) + " --height " +
            std::to_string(o.height) + " --frames " + std::to_string(o.frames) + " --warmup " +
            std::to_string(o.warmup) + " --times-from " + timingFileOf(*plan).string() + " --sweep " +
            sweep.sweep + " --reference " + plan->references[sweep.reference].file.string();
        // Written after the reference and timing: a file system's clock may be coarse.
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        std::ofstream(result) << nlohmann::json{{"command", command}, {"runs", {1}}}.dump();
    };
    EXPECT_FALSE(sweepDoneAlready(result, *plan, sweep, o)) << "no sweep.json yet";
    writeResult(o.width);
    EXPECT_TRUE(sweepDoneAlready(result, *plan, sweep, o));
    writeResult(o.width + 1);
    EXPECT_FALSE(sweepDoneAlready(result, *plan, sweep, o)) << "made at another width";
    writeResult(o.width);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    std::ofstream(timingFileOf(*plan)) << "{}";
    EXPECT_FALSE(sweepDoneAlready(result, *plan, sweep, o)) << "older than the scene's timing";
}

TEST(ReportShards, ShardPiecesLieBesideWhatTheyMakeAndAreDoneAtTheirOwnShard) {
    const ReportOptions o = withCornellProject("shards");
    const auto plan = planScene(cornell(), o);
    ASSERT_TRUE(plan) << plan.error().describe();
    const PlannedReference& ref = plan->references[0];
    const fs::path piece = referenceShardFile(ref, {1, 4});
    EXPECT_EQ(piece.parent_path(), ref.file.parent_path());
    EXPECT_EQ(piece.filename().string(), ref.file.stem().string() + ".shard-1-of-4.exr");
    EXPECT_EQ(sweepShardDir(plan->sweeps[0], {2, 4}), plan->sweeps[0].dir / "shards" / "2-of-4");

    EXPECT_FALSE(referenceShardDone(piece, {1, 4}, ref, *plan, o));
    writeReference(piece, o.width, o.height, plan->spp, ref.bounces, "1/4");
    EXPECT_TRUE(referenceShardDone(piece, {1, 4}, ref, *plan, o));
    EXPECT_FALSE(referenceShardDone(piece, {2, 4}, ref, *plan, o)) << "another shard's piece";

    EXPECT_TRUE(anyReferenceMissing({*plan}, o));
    for (const PlannedReference& r : plan->references)
        writeReference(r.file, o.width, o.height, plan->spp, r.bounces);
    EXPECT_FALSE(anyReferenceMissing({*plan}, o));
}

} // namespace
