// lpv-gl-bench (issue #45): the GPU bench on any Linux with a GL driver.
// `render` and `lpv` are `lpv bench render` and `lpv bench lpv` (the CLI's
// own command sources, so the same tables, CSV and Markdown), read from a
// bench pack (`lpv bench pack`); `image` writes one frame as PPM or PFM;
// `--version` names the GPU, the driver and the EGL platform.
#include "BenchReport.h"
#include "Cli.h"
#include "ImageFiles.h"
#include "RenderSetup.h"

#include "lpv/renderer/GlContext.h"
#include "lpv/scene/BenchPack.h"

#include <cstdio>
#include <iostream>

namespace lpv::cli {
void printBenchLpvHelp(); // BenchLpvCommand.cpp
} // namespace lpv::cli

namespace {

using namespace lpv::cli;

void printHelp() {
    std::cout << R"(lpv-gl-bench - LPV Studio's GPU bench on a bench pack (lpv bench pack PROJECT -o FILE.lpvpack)

Usage: lpv-gl-bench render PACK [--width N --height N --frames N --warmup N --camera NAME
                                 --set KEY=VALUE[,VALUE...] --per-frame --thesis-settings
                                 --turn DEG --csv FILE --markdown FILE
                                 --rounds N --time-budget S --spread-target P]
       lpv-gl-bench lpv PACK [--tiles LIST --steps LIST ... as lpv bench lpv]
       lpv-gl-bench image PACK -o OUT.ppm|OUT.pfm [--width N --height N --frames N
                                 --camera NAME --set KEY=VALUE]
       lpv-gl-bench --version

render and lpv are `lpv bench render` and `lpv bench lpv` (`lpv bench --help`
describes every option), with the same tables, CSV and Markdown. image
renders --frames frames (default 3) and writes the last one: PPM is the
display image (8 bits, after exposure and tonemapping), PFM the HDR image
(32-bit float RGB). LPV_EGL_PLATFORM=device|surfaceless|default picks the
EGL platform (default: the first that works, in that order).
Round options:
)";
    std::cout << kRoundOptionsHelp << "\n";
    printBenchLpvHelp();
}

int printVersion() {
    std::printf("lpv-gl-bench %s (bench pack version %u)\n", LPV_GLBENCH_VERSION, lpv::scene::kBenchPackVersion);
    auto context = lpv::renderer::HeadlessContext::create();
    if (!context) {
        std::printf("OpenGL:    unavailable: %s\n", context.error().describe().c_str());
        return kFailure;
    }
    const lpv::renderer::GlInfo& gl = context->info();
    std::printf("GPU:       %s (%s)\ndriver:    OpenGL %s\nplatform:  EGL %s\n", gl.renderer.c_str(), gl.vendor.c_str(),
                gl.version.c_str(), gl.eglPlatform.c_str());
    return kOk;
}

int runImage(Args args) {
    RenderRequest request = renderRequestOptions(args);
    const auto output = args.option("--output", "-o");
    args.require(output.has_value(), "missing -o OUT.ppm or OUT.pfm");
    const int width = args.integer("--width", 1280, {1});
    const int height = args.integer("--height", 720, {1});
    const int frames = args.integer("--frames", 3, {1});
    const auto pos = args.expectPositionals(1, "image expects exactly one bench pack", 1); // after "image"
    if (pos.empty())
        return usageError(*args.error(), "image");
    const std::filesystem::path file(*output);
    if (file.extension() != ".ppm" && file.extension() != ".pfm")
        return usageError("-o: write .ppm (display image) or .pfm (HDR image), not '" + *output + "'", "image");
    request.projectFile = pos.front();
    int exitCode = kOk;
    auto setup = prepareRender(request, "image", exitCode);
    if (!setup)
        return exitCode;
    if (!renderFrames(*setup, width, height, frames))
        return kFailure;
    const auto written = file.extension() == ".ppm"
                             ? lpv::glbench::writePpm(file, width, height, setup->renderer->readDisplay())
                             : lpv::glbench::writePfm(file, width, height, setup->renderer->readHdr());
    if (!written) {
        std::cerr << "lpv-gl-bench: " << written.error().describe() << "\n";
        return kFailure;
    }
    std::printf("wrote %s (%dx%d)\n", output->c_str(), width, height);
    return kOk;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    if (args.empty() || args.front() == "--help" || args.front() == "-h" || args.front() == "help") {
        printHelp();
        return args.empty() ? kUsage : kOk;
    }
    if (args.front() == "--version")
        return printVersion();
    Args parsed(args);
    if (parsed.flag("--help") || parsed.flag("-h")) {
        printHelp();
        return kOk;
    }
    // The commands read their positionals after the command word, as `lpv bench` does.
    if (args.front() == "render")
        return benchRender(std::move(parsed));
    if (args.front() == "lpv")
        return benchLpv(std::move(parsed));
    if (args.front() == "image")
        return runImage(std::move(parsed));
    return usageError("unknown command '" + args.front() + "' (render, lpv, image, --version)", "");
}
