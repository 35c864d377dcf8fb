// `lpv bench render`: per-pass GPU time of a project's frames at a chosen
// size, after warm-up frames that are not counted. Figures are printed,
// never asserted.
#include "Cli.h"
#include "BenchReport.h"
#include "BenchTurn.h"
#include "RenderSetup.h"
#include "ThesisSettings.h"

#include "lpv/scene/Project.h"

#include <charconv>
#include <cstdio>
#include <iostream>

namespace lpv::cli {


int benchRender(Args args) {
    RenderRequest request;
    request.cameraName = args.option("--camera");
    const std::vector<std::string> sets = args.options("--set");
    const auto csvFile = args.option("--csv");
    const auto markdownFile = args.option("--markdown");
    const bool thesis = args.flag("--thesis-settings");
    const auto width =
        parseCount(args.option("--width").value_or(thesis ? std::to_string(kThesisWidth) : "1280"), 1);
    const auto height =
        parseCount(args.option("--height").value_or(thesis ? std::to_string(kThesisHeight) : "720"), 1);
    const auto frames = parseCount(args.option("--frames").value_or("60"), 1);
    const auto warmup = parseCount(args.option("--warmup").value_or("5"), 0);
    const bool perFrame = args.flag("--per-frame");
    const auto turnText = args.option("--turn");
    if (!args.missingValue().empty())
        return usageError(args.missingValue() + " needs a value", "bench");
    if (auto unknown = args.unknownOption())
        return usageError("unknown option '" + *unknown + "'", "bench");
    auto pos = args.positionals();
    pos.erase(pos.begin()); // "render"
    if (pos.size() != 1)
        return usageError("bench render expects exactly one project file", "bench");
    if (!width || !height || !frames || !warmup)
        return usageError("--width, --height and --frames must be positive integers, --warmup zero or more", "bench");
    std::optional<float> turn;
    if (turnText) {
        const auto parsed = parseDegrees(*turnText);
        if (!parsed || !(*parsed > 0.0f) || *parsed > 180.0f)
            return usageError("--turn takes degrees in (0, 180], not '" + *turnText + "'", "bench");
        turn = *parsed;
    }
    std::string planError;
    const SetPlan plan = planSettings(sets, planError);
    if (!planError.empty())
        return usageError(planError, "bench");
    if (thesis && request.cameraName)
        return usageError("--thesis-settings sets the thesis application's camera; leave out --camera", "bench");
    if (thesis && !plan.combinations.empty())
        return usageError("--thesis-settings takes no --set lists (one value per key)", "bench");
    if (thesis)
        request.sets = thesisSettingsSets(); // before the --set values, which win
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
        setup->camera = thesisStartCamera();

    const std::vector<std::vector<Setting>> combinations =
        plan.combinations.empty() ? std::vector<std::vector<Setting>>{{}} : plan.combinations;
    const scene::ParameterSet base = setup->project.parameters;
    std::vector<BenchRun> runs;
    for (const auto& combination : combinations) {
        setup->project.parameters = base;
        for (const auto& [key, value] : combination)
            (void)setup->project.parameters.setFromText(key, value, "--set");
        if (!combination.empty())
            std::printf("\n== %s\n", combinationSuffix(combination).substr(1).c_str());
        if (turn) {
            TurnFrames turned;
            if (!renderTurnFrames(*setup, *width, *height, *warmup, *frames, *turn, turned))
                return kFailure;
            std::printf("%s: %dx%d, %d frames after %d warm-up\n%s", request.projectFile.c_str(), *width, *height,
                        *frames, *warmup, formatTurnFrames(turned, *turn).c_str());
            continue;
        }
        if (*warmup > 0 && !renderFrames(*setup, *width, *height, *warmup))
            return kFailure;
        setup->renderer->timer().clearHistory();
        if (!renderFrames(*setup, *width, *height, *frames))
            return kFailure;

        const renderer::DrawListStats draws = setup->renderer->cameraDrawStats();
        std::printf("%s: %zu triangles, %zu draw items (%zu culled in the camera pass), %dx%d, %d frames after %d "
                    "warm-up\n",
                    request.projectFile.c_str(), setup->project.scene.triangleCount(), draws.total, draws.culled,
                    *width, *height, *frames, *warmup);
        std::printf("%s\n", setup->renderer->lpvNote().c_str());
        if (perFrame)
            std::printf("%s", formatPerFrameTimes(setup->renderer->timer()).c_str());
        auto table = setup->renderer->timer().table();
        // Passes that did not run with these settings have no samples.
        std::erase_if(table, [](const renderer::PassTiming& t) { return t.samples == 0; });
        std::printf("%s", renderer::formatTimingTable(table).c_str());
        double total = 0.0;
        for (const auto& row : table)
            total += row.medianMs;
        std::printf("GPU frame rate from the total: %.1f frames/s\n", total > 0 ? 1000.0 / total : 0.0);
        runs.push_back({combination, table});
        if (thesis) {
            // The thesis application's "LPV off" figure: the same frames with GI off.
            const std::vector<renderer::PassTiming> lpvTable = table;
            (void)setup->project.parameters.setFromText("gi.method", "off", "--thesis-settings");
            if (*warmup > 0 && !renderFrames(*setup, *width, *height, *warmup))
                return kFailure;
            setup->renderer->timer().clearHistory();
            if (!renderFrames(*setup, *width, *height, *frames))
                return kFailure;
            double offTotal = 0.0;
            for (const auto& row : setup->renderer->timer().table())
                if (row.samples > 0)
                    offTotal += row.medianMs;
            std::printf("\nthe thesis application's phases (--thesis-settings: %dx%d, its start camera):\n%s", *width,
                        *height, formatThesisPhases(thesisPhases(lpvTable, offTotal)).c_str());
        }
    }

    const renderer::GlInfo& gl = setup->context->info();
    std::string command = "lpv bench render " + request.projectFile + " --width " + std::to_string(*width) +
                          " --height " + std::to_string(*height) + " --frames " + std::to_string(*frames) +
                          " --warmup " + std::to_string(*warmup) + (thesis ? " --thesis-settings" : "") +
                          (turnText ? " --turn " + *turnText : "");
    for (const std::string& kv : sets)
        command += " --set " + kv;
    const std::string machine = describeMachine(gl.renderer, gl.version);
    if (!writeReportFiles({{csvFile, benchCsv(runs)}, {markdownFile, benchMarkdown(runs, command, machine)}}))
        return kFailure;
    return kOk;
}

} // namespace lpv::cli
