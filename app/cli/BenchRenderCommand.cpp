// `lpv bench render`: per-pass GPU time of a project's frames at a chosen
// size, after warm-up frames that are not counted, over interleaved rounds
// (issue #43): each figure a median with its spread, settings within each
// other's noise called the same cost. Figures are printed, never asserted.
#include "Cli.h"
#include "BenchReport.h"
#include "BenchTurn.h"
#include "RenderSetup.h"
#include "lpv/bench/ThesisSettings.h"

#include "lpv/scene/FileRead.h"
#include "lpv/scene/Project.h"

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace lpv::cli {


namespace {

// Whether the command line names a round option (--turn refuses them).
bool namesRoundOption(const Args& args) {
    for (const std::string& a : args.positionals())
        for (const char* name : {"--rounds", "--time-budget", "--spread-target"})
            if (a == name || a.starts_with(std::string(name) + "="))
                return true;
    return false;
}

// "1 round", "3 rounds".
std::string counted(int n, const std::string& what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

} // namespace

int benchRender(Args args) {
    RenderRequest request;
    request.cameraName = args.option("--camera");
    const std::vector<std::string> sets = args.options("--set");
    const auto csvFile = args.option("--csv");
    const auto markdownFile = args.option("--markdown");
    const bool thesis = args.flag("--thesis-settings");
    const auto thesisRunFile = args.option("--thesis-run");
    const int width = args.integer("--width", thesis ? bench::kThesisWidth : 1280, {1});
    const int height = args.integer("--height", thesis ? bench::kThesisHeight : 720, {1});
    const int frames = args.integer("--frames", 20, {1});
    const int warmup = args.integer("--warmup", 5, {0});
    const bool perFrame = args.flag("--per-frame");
    // Degrees the camera turns each way; a turn of more than half a circle is the same as a smaller one.
    const auto turnDegrees = args.optionalReal("--turn", {0.0, 180.0, true, false});
    const bool roundOptionsGiven = namesRoundOption(args);
    bench::RoundPlan roundPlan;
    parseRoundOptions(args, roundPlan);
    const auto pos = args.expectPositionals(1, "bench render expects exactly one project file", 1); // after "render"
    if (pos.empty())
        return usageError(*args.error(), "bench");
    if (roundPlan.maxRounds < 1)
        return usageError("bench render times in rounds: --rounds must be 1 or more", "bench");
    std::optional<float> turn;
    if (turnDegrees) {
        turn = float(*turnDegrees);
        if (csvFile || markdownFile)
            return usageError("--turn prints its own table; --csv and --markdown write the rounds' tables", "bench");
        if (roundOptionsGiven)
            return usageError("--turn times frame by frame, not in rounds: leave out --rounds, --time-budget and "
                              "--spread-target",
                              "bench");
    }
    std::string planError;
    const SetPlan plan = planSettings(sets, planError);
    if (!planError.empty())
        return usageError(planError, "bench");
    if (thesis && request.cameraName)
        return usageError("--thesis-settings sets the thesis application's camera; leave out --camera", "bench");
    if (thesis && !plan.combinations.empty())
        return usageError("--thesis-settings takes no --set lists (one value per key)", "bench");
    if (thesisRunFile && (!thesis || turn))
        return usageError("--thesis-run gives the thesis application's figures to --thesis-settings' table of phases "
                          "(not printed with --turn)",
                          "bench");
    // Its figures from this session (tools/thesis-app/run.sh's output), read
    // before any frame so that a wrong file costs no rendering.
    bench::ThesisFigures thesisFigures = bench::issue25ThesisFigures();
    if (thesisRunFile) {
        const auto text = scene::readFileBytes(*thesisRunFile, {1u << 20, "thesis application run"});
        auto figures = text ? bench::parseThesisRun(*text, *thesisRunFile + " (tools/thesis-app/run.sh)")
                            : scene::Expected<bench::ThesisFigures>(std::unexpected(text.error()));
        if (!figures) {
            std::cerr << "lpv: " << figures.error().describe() << "\n";
            return kFailure;
        }
        thesisFigures = std::move(*figures);
    }
    if (thesis)
        request.sets = bench::thesisSettingsSets(); // before the --set values, which win
    for (const auto& [key, value] : plan.fixed)
        request.sets.push_back(key + "=" + value);

    // A benchmark measures the LPV being computed: no reuse of the last frame's
    // volumes (a later --set lpv.reuse=true wins). --turn measures what the
    // editor redraws when the camera only turned: reuse stays on.
    if (!turn)
        request.sets.insert(request.sets.begin(), "lpv.reuse=false");
    request.projectFile = pos.front();
    request.bakedRadiosity = sweepShowsBakedRadiosity(plan.combinations);
    int exitCode = kOk;
    auto setup = prepareRender(request, "bench", exitCode);
    if (!setup)
        return exitCode;
    if (auto error = checkCombinations(plan, setup->project.parameters, "--set"))
        return usageError(*error, "bench");
    if (thesis)
        setup->camera = bench::thesisStartCamera();

    const scene::ParameterSet base = setup->project.parameters;
    // The settings timed against each other: the combinations of the --set
    // lists; with --thesis-settings the project's GI and the thesis
    // application's "LPV off" figure, the same frames with gi.method=off.
    std::vector<std::vector<Setting>> combinations =
        plan.combinations.empty() ? std::vector<std::vector<Setting>>{{}} : plan.combinations;
    if (thesis)
        combinations = {{{"gi.method", base.getEnum("gi.method")}}, {{"gi.method", "off"}}};
    auto apply = [&](const std::vector<Setting>& combination) {
        setup->project.parameters = base;
        for (const auto& [key, value] : combination)
            (void)setup->project.parameters.setFromText(key, value, "--set");
    };
    auto heading = [&](const std::vector<Setting>& combination) {
        if (!combination.empty())
            std::printf("\n== %s\n", benchRunLabel(combination).c_str());
    };

    if (turn) {
        // A camera that turns is timed frame by frame, each setting once: the
        // passes that run differ from frame to frame (reuse), so a round's
        // sum of pass medians would not be a frame.
        for (const auto& combination : combinations) {
            apply(combination);
            heading(combination);
            TurnFrames turned;
            if (!renderTurnFrames(*setup, width, height, warmup, frames, *turn, turned))
                return kFailure;
            std::printf("%s: %dx%d, %d frames after %d warm-up (frame by frame, not in rounds)\n%s",
                        request.projectFile.c_str(), width, height, frames, warmup,
                        formatTurnFrames(turned, *turn).c_str());
        }
        return kOk;
    }

    // Each setting's warm-up once, before the rounds; what it draws and the
    // LPV's layout are shown with its times (so at least one frame).
    const int warmupFrames = std::max(warmup, 1);
    const std::string loadBefore = bench::describeLoad();
    std::vector<std::string> drawn(combinations.size()), lpvNotes(combinations.size());
    for (std::size_t i = 0; i < combinations.size(); ++i) {
        apply(combinations[i]);
        if (!renderFrames(*setup, width, height, warmupFrames))
            return kFailure;
        const renderer::DrawListStats draws = setup->renderer->cameraDrawStats();
        char line[256];
        std::snprintf(line, sizeof line, "%zu triangles, %zu draw items (%zu culled in the camera pass)",
                      setup->project.scene.triangleCount(), draws.total, draws.culled);
        drawn[i] = line;
        lpvNotes[i] = setup->renderer->lpvNote();
    }

    // The rounds (bench/Timing.h): each setting in turn, one untimed frame
    // after the switch (the camera's geometry volume reads the previous
    // frame), then --frames timed ones; the round's sample of a pass is its
    // median over those frames.
    std::vector<std::vector<std::vector<renderer::PassTiming>>> roundTables(combinations.size());
    int currentRound = 0;
    bool renderFailed = false;
    bench::RoundCallbacks callbacks;
    callbacks.progress = [&](int round, int, int) {
        currentRound = round;
        return true;
    };
    callbacks.timeOnce = [&](int index) -> scene::Expected<std::vector<renderer::PassTiming>> {
        const auto& combination = combinations[std::size_t(index)];
        apply(combination);
        renderer::GpuTimer& timer = setup->renderer->timer();
        // renderFrames has printed why a frame failed; the error only stops the rounds.
        auto failed = [&] {
            renderFailed = true;
            return scene::makeError(scene::ErrorCode::InvalidValue, request.projectFile, "", "a frame failed");
        };
        if (!renderFrames(*setup, width, height, 1))
            return failed();
        timer.clearHistory();
        if (!renderFrames(*setup, width, height, frames))
            return failed();
        if (perFrame)
            std::printf("\nround %d%s, every timed frame:\n%s", currentRound + 1,
                        combination.empty() ? "" : (" of " + benchRunLabel(combination)).c_str(),
                        formatPerFrameTimes(timer).c_str());
        auto table = timer.table();
        roundTables[std::size_t(index)].push_back(table);
        return table;
    };
    auto timed = bench::timeInRounds(int(combinations.size()), roundPlan, callbacks);
    if (!timed) {
        if (!renderFailed)
            std::cerr << "lpv: " << timed.error().describe() << "\n";
        return kFailure;
    }
    const std::string load = loadBefore + " -> " + bench::describeLoad();

    std::vector<BenchRun> runs;
    for (std::size_t i = 0; i < combinations.size(); ++i) {
        bench::SettingTiming& t = timed->settings[i];
        runs.push_back({combinations[i], std::move(t.passes), std::move(t.passStats), t.total});
        const BenchRun& run = runs.back();
        heading(combinations[i]);
        std::printf("%s: %s, %dx%d, %s of %s (after %s, and one untimed frame per round)\n",
                    request.projectFile.c_str(), drawn[i].c_str(), width, height,
                    counted(run.total.rounds, "round").c_str(), counted(frames, "frame").c_str(),
                    counted(warmupFrames, "warm-up frame").c_str());
        std::printf("%s\n", lpvNotes[i].c_str());
        std::printf("%s", benchTable(run).c_str());
        std::printf("GPU frame rate from the total's median: %.1f frames/s\n",
                    run.total.median > 0 ? 1000.0 / run.total.median : 0.0);
    }
    std::printf("\ntimed in %d interleaved round%s (%s); %s\n", timed->rounds, timed->rounds == 1 ? "" : "s",
                timed->stopReason.c_str(), load.c_str());
    if (runs.size() > 1)
        std::printf("\n%s", benchComparison(runs).c_str());
    if (thesis)
        std::printf("\nthe thesis application's phases (--thesis-settings: %dx%d, its start camera):\n%s", width,
                    height, bench::formatThesisPhases(bench::thesisPhases(roundTables[0], runs[1].total, thesisFigures),
                                              thesisFigures.source)
                        .c_str());

    const renderer::GlInfo& gl = setup->context->info();
    std::string command = "lpv bench render " + request.projectFile + " --width " + std::to_string(width) +
                          " --height " + std::to_string(height) + " --frames " + std::to_string(frames) +
                          " --warmup " + std::to_string(warmup) + roundOptionsText(roundPlan) +
                          (thesis ? " --thesis-settings" : "");
    for (const std::string& kv : sets)
        command += " --set " + kv;
    const std::string machine = describeMachine(gl.renderer, gl.version);
    const bench::SweepTimingInfo timing{timed->rounds, timed->stopReason, load};
    if (!writeReportFiles(
            {{csvFile, benchCsv(runs)}, {markdownFile, benchMarkdown(runs, command, machine, timing)}}))
        return kFailure;
    return kOk;
}

} // namespace lpv::cli
