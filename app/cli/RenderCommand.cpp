#include "Cli.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/importers/SceneTextures.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/renderer/GlContext.h"
#include "lpv/scene/Project.h"

#include <charconv>
#include <filesystem>
#include <cstdio>
#include <iostream>

namespace lpv::cli {

void printRenderHelp() {
    std::cout << R"(Usage: lpv render PROJECT.lpvproj -o OUT.png [options]

Renders the project headless (EGL: the GPU where present, Mesa llvmpipe
otherwise), writes the image and prints per-pass GPU times (timer queries;
median/min/max over the frames rendered).

  -o, --output FILE     Image to write (.png, .jpg, .exr, ...), required
  --width N             Image width in pixels (default 1280)
  --height N            Image height in pixels (default 720)
  --camera NAME         Named camera of the project (default: the first)
  --set KEY=VALUE       Override a registry parameter for this run; repeatable
                        (see `lpv params` for keys, types and ranges)
  --frames N            Frames to render for the timing table (default 5)
)";
}

namespace {

std::optional<int> parsePositive(const std::string& s) {
    int v = 0;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size() || v <= 0)
        return std::nullopt;
    return v;
}

} // namespace

int runRender(Args args) {
    auto output = args.option("--output");
    if (auto o = args.option("-o"))
        output = o;
    const auto widthText = args.option("--width");
    const auto heightText = args.option("--height");
    const auto framesText = args.option("--frames");
    const auto cameraName = args.option("--camera");
    const auto sets = args.options("--set");
    if (!args.missingValue().empty())
        return usageError(args.missingValue() + " needs a value", "render");
    if (auto unknown = args.unknownOption())
        return usageError("unknown option '" + *unknown + "'", "render");
    const auto pos = args.positionals();
    if (pos.size() != 1)
        return usageError("expected exactly one project file", "render");
    if (!output)
        return usageError("missing -o OUT.png", "render");
    const auto width = parsePositive(widthText.value_or("1280"));
    const auto height = parsePositive(heightText.value_or("720"));
    const auto frames = parsePositive(framesText.value_or("5"));
    if (!width || !height)
        return usageError("--width and --height must be positive integers", "render");
    if (!frames)
        return usageError("--frames must be a positive integer", "render");

    auto project = scene::loadProject(pos.front());
    if (!project) {
        std::cerr << "lpv: " << project.error().describe() << "\n";
        return kFailure;
    }
    for (const std::string& kv : sets) {
        const auto eq = kv.find('=');
        if (eq == std::string::npos)
            return usageError("--set expects KEY=VALUE, got '" + kv + "'", "render");
        if (auto ok = project->parameters.setFromText(kv.substr(0, eq), kv.substr(eq + 1), "--set"); !ok)
            return usageError(ok.error().describe(), "render");
    }

    const scene::Scene& s = project->scene;
    scene::Camera camera;
    if (cameraName) {
        const scene::Camera* c = s.findCamera(*cameraName);
        if (!c) {
            std::string names;
            for (const auto& cam : s.cameras)
                names += (names.empty() ? "" : ", ") + cam.name;
            std::cerr << "lpv: " << pos.front() << ": no camera named '" << *cameraName
                      << "' (cameras: " << (names.empty() ? "none" : names) << ")\n";
            return kFailure;
        }
        camera = *c;
    } else if (!s.cameras.empty()) {
        camera = s.cameras.front();
    } else {
        // No camera: look at the scene's bounds from the front.
        const scene::Bounds b = s.worldBounds();
        const glm::vec3 c = b.empty() ? glm::vec3(0.0f) : b.center();
        const float r = b.empty() ? 1.0f : glm::length(b.size()) * 0.5f;
        camera.position = c + glm::vec3(0.0f, 0.0f, 2.5f * r);
        camera.target = c;
        camera.farPlane = 10.0f * r;
        camera.nearPlane = 0.01f * r;
    }

    auto context = renderer::HeadlessContext::create();
    if (!context) {
        std::cerr << "lpv: " << context.error().describe() << "\n";
        return kFailure;
    }
    const renderer::GlInfo& gl = context->info();
    std::printf("GL: %s | %s | %s (EGL %s)\n", gl.renderer.c_str(), gl.version.c_str(), gl.vendor.c_str(),
                gl.eglPlatform.c_str());
    auto renderer = renderer::ForwardRenderer::create();
    if (!renderer) {
        std::cerr << "lpv: " << renderer.error().describe() << "\n";
        return kFailure;
    }
    // Texture paths are relative to the project file's folder.
    const auto textures =
        importers::loadSceneTextures(s, std::filesystem::absolute(pos.front()).parent_path());
    for (const std::string& w : textures.warnings)
        std::cerr << "lpv: warning: " << w << "\n";
    renderer->setScene(s, textures.images);
    for (int f = 0; f < *frames; ++f)
        if (auto ok = renderer->render(s, project->parameters, camera, *width, *height); !ok) {
            std::cerr << "lpv: " << ok.error().describe() << "\n";
            return kFailure;
        }
    renderer->timer().resolveAll();

    importers::Image8 image{*width, *height, 4, renderer->readDisplay()};
    if (auto ok = importers::writeImage(*output, image); !ok) {
        std::cerr << "lpv: " << ok.error().describe() << "\n";
        return kFailure;
    }
    std::printf("%s: %zu triangles, %dx%d, %d frames\n", pos.front().c_str(), s.triangleCount(), *width, *height,
                *frames);
    std::printf("%s", renderer::formatTimingTable(renderer->timer().table()).c_str());
    std::printf("wrote %s\n", output->c_str());
    return kOk;
}

} // namespace lpv::cli
