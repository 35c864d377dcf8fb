// `lpv bench`: measured figures, printed, never asserted (machines are shared
// and noisy). `lpv bench import` compares importing a source file with
// loading the project it becomes.
#include "BenchReport.h"
#include "Cli.h"

#include "lpv/importers/Importer.h"
#include "lpv/scene/ProcessId.h"
#include "lpv/scene/Project.h"
#include "lpv/scene/ProjectTextures.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

namespace lpv::cli {

namespace fs = std::filesystem;

void printBenchLpvHelp();
void printBenchSweepHelp();
void printBenchAccuracyReportHelp();
void printBenchFlickerHelp();
void printBenchPackHelp();

void printBenchHelp() {
    std::cout << R"(Usage: lpv bench import FILE... [--repeat N]
       lpv bench pack PROJECT -o FILE.lpvpack
       lpv bench render PROJECT|PACK [--width N --height N --frames N --warmup N
                                 --camera NAME --set KEY=VALUE[,VALUE...] --per-frame
                                 --thesis-settings [--thesis-run FILE] --turn DEG --csv FILE --markdown FILE
                                 --rounds N --time-budget S --spread-target P]
       lpv bench lpv PROJECT|PACK [--tiles LIST --steps LIST ... see below]
       lpv bench PROJECT --sweep KEY=V1,V2,... [--reference REF.exr --out DIR --shard I/N ... see below]
       lpv bench merge OUT_DIR SHARD_DIR... [--reference REF.exr]
       lpv bench report [--out DIR --scenes DIR --scene NAME --quick ... see below]
       lpv bench compare-times A/timing.json B/timing.json
       lpv bench PROJECT --flicker (--path NAME | --sun-rotate DEG) [--frames N ... see below]

bench render: renders the project headless at the given size (default
1280x720) and prints each pass's GPU time (timer queries). Each setting gets
--warmup frames first (default 5, not counted); then the settings are timed
in interleaved rounds (A B C, then C B A, ...), each round one untimed frame
after the switch and --frames timed frames (default 20). A pass's sample in
a round is its median over that round's frames; the table gives per pass
and for the total (each round's sum of pass medians) the median over the
rounds, the quartiles q1-q3, the interquartile range in % of the median,
min-max, rounds and frames. A --set with a list of values sweeps that key
(several lists: every combination); settings whose totals lie within each
other's noise are listed as the same cost. --per-frame also prints every
timed frame of every round. --csv and --markdown write the tables (the
Markdown one headed by the command, the machine: CPU, cores, GL renderer and
version, its load before -> after and why the rounds stopped).
--thesis-settings measures as the thesis application was measured beside us
(issue #25): 1024x600 (unless --width/--height), its start camera (-2.2, 5.7,
4.3, pitched 5 degrees down along +x, 60 degrees vertical), 4 LPV cascades of
32^3, RSM tiles of 128^2, 6 shadow cascades of 1024^2, 8 propagation steps
(a --set wins); the same frames with gi.method=off are the second setting of
the rounds; then a table of the thesis application's phases (shadow maps,
RSM, injection, propagation, final shading, whole frame, LPV off) with its
medians beside ours (per round a phase's pass medians summed, then the
median over the rounds). Use it on Sibenik imported from sibenik.4ds.
Its figures are those of issue #25's day, another day's machine; --thesis-run
FILE takes them from tools/thesis-app/run.sh's output saved in this session
(its "phase NAME MS" lines), the only like-for-like comparison.
--turn DEG measures the frame where only the camera turned, as the editor
draws it while the user looks around: the camera yaws by +DEG and back on
alternate frames about the up axis, the frame graph's reuse stays on (what
does not depend on the view direction is kept), and it prints, per pass,
the median over the frames it ran in and in how many, the passes the frame
graph reused instead (in how many frames, and why), and the median of the
per-frame totals (every pass that ran in that frame). --turn times
frame by frame, each setting once, not in rounds (the passes that run
differ from frame to frame): it takes no round options, --csv or --markdown.
Round options of bench render (it only times: --rounds at least 1):
)";
    std::cout << kRoundOptionsHelp << "\n";
    printBenchLpvHelp();
    printBenchPackHelp();
    printBenchSweepHelp();
    printBenchMergeHelp();
    printBenchAccuracyReportHelp();
    printBenchCompareTimesHelp();
    printBenchFlickerHelp();
    std::cout << R"(
bench import:
Times, for each scene file: importing it (parse, mesh clean-up, texture
lookup), saving the project it becomes, and loading that project again;
prints the median of N runs (default 5) of each and the ratio import/load.
Loading a saved project is meant to be at least 10x faster than importing
the source. Nothing is asserted: the figures depend on the machine.

Example:
  lpv bench lpv sibenik.lpvproj --markdown lpv-bench.md --csv lpv-bench.csv
  lpv bench cornell.lpvproj --sweep lpv.propagationSteps=0,4,8,16 --reference ref.exr --out sweep
  lpv bench import ../shared/scenes/sponza/sponza.obj ../shared/scenes/sibenik/sibenik.obj
  lpv bench report --out bench-report
)";
}

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct ImportFigures {
    std::size_t triangles = 0;
    double importMs = 0, saveMs = 0, loadMs = 0;
};

// `repeat` runs of `step`, each timed in ms; the first error stops them.
template <typename Step> scene::Expected<std::vector<double>> timedRuns(int repeat, Step step) {
    std::vector<double> ms;
    for (int i = 0; i < repeat; ++i) {
        const auto start = Clock::now();
        if (auto done = step(); !done)
            return std::unexpected(done.error());
        ms.push_back(msSince(start));
    }
    return ms;
}

scene::Expected<ImportFigures> benchOne(const fs::path& file, int repeat, const fs::path& scratch) {
    ImportFigures f;
    scene::Project project;
    const auto imports = timedRuns(repeat, [&]() -> scene::Expected<void> {
        auto imported = importers::importScene(file);
        if (!imported)
            return std::unexpected(imported.error());
        project.scene = std::move(imported->scene);
        return {};
    });
    if (!imports)
        return std::unexpected(imports.error());
    f.triangles = project.scene.triangleCount();
    project.name = file.stem().string();
    const fs::path projectFile = scratch / (file.stem().string() + ".lpvproj");
    const auto saveStart = Clock::now();
    if (auto t = scene::copyTexturesIntoProject(project.scene, projectFile); !t)
        return std::unexpected(t.error());
    if (auto saved = scene::saveProject(project, projectFile); !saved)
        return std::unexpected(saved.error());
    f.saveMs = msSince(saveStart);
    const auto loads = timedRuns(repeat, [&]() -> scene::Expected<void> {
        auto loaded = scene::loadProject(projectFile);
        if (!loaded)
            return std::unexpected(loaded.error());
        return {};
    });
    if (!loads)
        return std::unexpected(loads.error());
    f.importMs = median(*imports);
    f.loadMs = median(*loads);
    return f;
}

int benchImport(Args& args) {
    const int repeat = args.integer("--repeat", 5, {1, 1000});
    if (auto e = args.error())
        return usageError(*e, "bench");
    auto files = args.positionals();
    files.erase(files.begin()); // "import"
    if (files.empty())
        return usageError("bench import needs at least one scene file", "bench");

    const fs::path scratch = fs::temp_directory_path() / ("lpv-bench-import-" + std::to_string(scene::processId()));
    fs::create_directories(scratch);
    std::printf("%-28s %12s %12s %10s %10s %14s\n", "file", "triangles", "import ms", "save ms", "load ms",
                "import/load");
    int status = kOk;
    for (const std::string& file : files) {
        auto f = benchOne(file, repeat, scratch);
        if (!f) {
            std::cerr << "lpv: " << f.error().describe() << "\n";
            status = kFailure;
            continue;
        }
        std::printf("%-28s %12zu %12.1f %10.1f %10.1f %13.1fx\n", fs::path(file).filename().string().c_str(),
                    f->triangles, f->importMs, f->saveMs, f->loadMs, f->importMs / std::max(f->loadMs, 1e-3));
    }
    std::printf("(median of %d runs; one process, one thread)\n", repeat);
    std::error_code ec;
    fs::remove_all(scratch, ec);
    return status;
}

} // namespace

int runBench(Args args) {
    const auto pos = args.positionals();
    if (pos.empty())
        return usageError("which benchmark? (import, render, lpv, report, merge, compare-times, or a project with "
                          "--sweep)",
                          "bench");
    if (fs::path(pos.front()).extension() == ".lpvproj")
        return args.flag("--flicker") ? benchFlicker(std::move(args)) : benchSweep(std::move(args));
    if (pos.front() == "render")
        return benchRender(std::move(args));
    if (pos.front() == "lpv")
        return benchLpv(std::move(args));
    if (pos.front() == "report")
        return benchAccuracyReport(std::move(args));
    if (pos.front() == "compare-times")
        return benchCompareTimes(std::move(args));
    if (pos.front() == "merge")
        return benchMerge(std::move(args));
    if (pos.front() == "import")
        return benchImport(args);
    if (pos.front() == "pack")
        return benchPack(std::move(args));
    return usageError("unknown benchmark '" + pos.front() + "' (import, render, lpv, report, merge, pack)", "bench");
}

} // namespace lpv::cli
