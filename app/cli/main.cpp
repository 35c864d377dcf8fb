// lpv: the command-line face of LPV Studio. A thin dispatcher; each command
// is a function over the libraries (scene, importers, renderer).
#include "Cli.h"

#include <iostream>
#include <map>

namespace {

void printHelp() {
    std::cout << R"(lpv - LPV Studio command-line tool

Usage: lpv <command> [options]
       lpv <command> --help

Commands:
  render PROJECT -o OUT.png   Render a project to an image and print per-pass GPU times
  params [--json]             List every parameter of the registry (key, type, default, range, unit)
  new FILE.lpvproj            Create a project (--template cornell-box|empty)
  import FILE... -o PROJECT   Import 4ds, glTF, OBJ, 3DS ... scenes into a new or existing project
  bench import FILE...        Time importing scene files against loading the projects they become
  bench render PROJECT        Per-pass GPU times over many frames (default 1280x720, 60 frames)
  bench lpv PROJECT           The thesis' LPV measurements: RSM tile sizes, steps x variants x occlusion
  bench pack PROJECT -o FILE.lpvpack
                              One file with what a frame needs, for render, bench render|lpv
                              and lpv-gl-bench (the GPU bench without image libraries)
  bench PROJECT --sweep KEY=V1,V2 ...
                              Sweep parameters: per-pass GPU time and error against a reference,
                              CSV/JSON/Markdown report and PNG plots (--reference REF.exr)
  bench PROJECT --flicker --path NAME | --sun-rotate DEG
                              Temporal stability: frame-to-frame change of the indirect light
  bench report [--out DIR]    The accuracy-against-time report: references and sweeps on the
                              Cornell box, Sibenik and Sponza, radiosity error against solve time
  info PROJECT                Validate a project and print what it contains
  video PROJECT --path NAME -o OUT.mp4
                              Render a camera path offline into an H.264 MP4 or PNG sequence
                              (side by side with --compare-set), with a progress line
  path export PROJECT --path NAME -o FILE.json|FILE.csv
                              Write a camera path as JSON, or as CSV per frame (--fps)
  path import PROJECT FILE.json
                              Add or replace a camera path of the project from a JSON file
  reference PROJECT -o REF.exr
                              Path-trace (CPU, Embree) the reference image and indirect light
                              with per-pixel variance (--spp, --max-seconds, --bounces);
                              --shard I/N traces 1/N of it, for a cluster (docs/cluster.md)
  merge OUT.exr SHARD.exr...  Join the shards of one reference, bit-identical to one process
  compare TEST.exr REF.exr    Error of a rendered EXR against the reference: relMSE, MARE,
                              SSIM, each beside the reference's own noise
  radiosity PROJECT [-o OUT.lpvproj]
                              Solve the diffuse light with GPU progressive radiosity (hemicubes),
                              saved into the project; a second run resumes
  dump PROJECT --what lpv|gv|leak|backside|rsm|shadow -o OUT.png
                              Write a visualizer image (LPV slice, geometry volume, leak maps,
                              RSM or shadow tiles) as the editor's Visualizers dock shows it

Options:
  -h, --help                  Show this help
  --version                   Show the version, git revision, OpenGL driver and library versions

Exit codes: 0 success, 1 failure (the message names the file and what was wrong), 2 usage error.
)";
}

int dispatch(std::vector<std::string> args) {
    using namespace lpv::cli;
    if (args.empty())
        return usageError("no command given", "");
    const std::string command = args.front();
    args.erase(args.begin());
    if (command == "-h" || command == "--help" || command == "help") {
        if (!args.empty()) // "lpv help render" == "lpv render --help"
            return dispatch({args.front(), "--help"});
        printHelp();
        return kOk;
    }
    if (command == "--version")
        return runVersion();

    struct Command {
        int (*run)(Args);
        void (*help)();
    };
    const std::map<std::string, Command> commands{
        {"render", {runRender, printRenderHelp}},
        {"params", {runParams, printParamsHelp}},
        {"new", {runNew, printNewHelp}},
        {"import", {runImport, printImportHelp}},
        {"bench", {runBench, printBenchHelp}},
        {"info", {runInfo, printInfoHelp}},
        {"video", {runVideo, printVideoHelp}},
        {"path", {runPath, printPathHelp}},
        {"radiosity", {runRadiosity, printRadiosityHelp}},
        {"reference", {runReference, printReferenceHelp}},
        {"compare", {runCompare, printCompareHelp}},
        {"merge", {runMerge, printMergeHelp}},
        {"dump", {runDump, printDumpHelp}},
    };
    auto it = commands.find(command);
    if (it == commands.end())
        return usageError("unknown command '" + command + "'", "");
    Args parsed(args);
    if (parsed.flag("--help") || parsed.flag("-h")) {
        it->second.help();
        return kOk;
    }
    return it->second.run(std::move(parsed));
}

} // namespace

int main(int argc, char** argv) { return dispatch(std::vector<std::string>(argv + 1, argv + argc)); }
