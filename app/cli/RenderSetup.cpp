#include "RenderSetup.h"

#include "Cli.h"
#include "RenderInputs.h"

#include "lpv/scene/FramingCamera.h"

#include <filesystem>

#include <cstdio>
#include <iostream>
#include <sstream>

namespace lpv::cli {


std::optional<scene::Camera> pickCamera(const scene::Scene& s, const std::optional<std::string>& name,
                                        const std::string& projectFile) {
    if (!name)
        return s.cameras.empty() ? scene::framingCamera(s) : s.cameras.front();
    if (const scene::Camera* c = s.findCamera(*name))
        return *c;
    std::string names;
    for (const auto& cam : s.cameras)
        names += (names.empty() ? "" : ", ") + cam.name;
    std::cerr << "lpv: " << projectFile << ": no camera named '" << *name
              << "' (cameras: " << (names.empty() ? "none" : names) << ")\n";
    return std::nullopt;
}

void printLoadWarnings(const std::string& projectFile, const std::vector<std::string>& warnings) {
    constexpr std::size_t kShown = 20;
    for (std::size_t i = 0; i < warnings.size() && i < kShown; ++i)
        std::cerr << "  warning: " << projectFile << ": " << warnings[i] << "\n";
    if (warnings.size() > kShown)
        std::cerr << "  ... and " << warnings.size() - kShown << " more warnings\n";
}

std::optional<scene::Project> loadProjectWithSets(const std::string& projectFile, const std::vector<std::string>& sets,
                                                  const std::string& command, int& exitCode) {
    exitCode = kFailure;
    auto project = scene::loadProject(projectFile);
    if (!project) {
        std::cerr << "lpv: " << project.error().describe() << "\n";
        return std::nullopt;
    }
    printLoadWarnings(projectFile, project->loadWarnings);
    if (!applySets(project->parameters, sets, command, exitCode))
        return std::nullopt;
    exitCode = kOk;
    return std::move(*project);
}

bool applySets(scene::ParameterSet& parameters, const std::vector<std::string>& sets, const std::string& command,
               int& exitCode) {
    for (const std::string& kv : sets) {
        const auto eq = kv.find('=');
        if (eq == std::string::npos) {
            exitCode = usageError("--set expects KEY=VALUE, got '" + kv + "'", command);
            return false;
        }
        if (auto ok = parameters.setFromText(kv.substr(0, eq), kv.substr(eq + 1), "--set"); !ok) {
            exitCode = usageError(ok.error().describe(), command);
            return false;
        }
    }
    return true;
}

std::optional<RenderSetup> prepareRender(const RenderRequest& request, const std::string& command, int& exitCode) {
    // A project or a bench pack (RenderInputs.h: each program links its own reader).
    auto inputs = loadRenderInputs(request, command, exitCode);
    if (!inputs)
        return std::nullopt;
    exitCode = kFailure;

    RenderSetup setup;
    auto camera = pickCamera(inputs->project.scene, request.cameraName, request.projectFile);
    if (!camera)
        return std::nullopt;
    setup.camera = *camera;

    auto context = renderer::HeadlessContext::create();
    if (!context) {
        std::cerr << "lpv: " << context.error().describe() << "\n";
        return std::nullopt;
    }
    const renderer::GlInfo& gl = context->info();
    std::printf("GL: %s | %s | %s (EGL %s)\n", gl.renderer.c_str(), gl.version.c_str(), gl.vendor.c_str(),
                gl.eglPlatform.c_str());
    auto renderer = renderer::ForwardRenderer::create();
    if (!renderer) {
        std::cerr << "lpv: " << renderer.error().describe() << "\n";
        return std::nullopt;
    }
    setup.project = std::move(inputs->project);
    setup.context.emplace(std::move(*context));
    setup.renderer.emplace(std::move(*renderer));
    setup.renderer->setScene(setup.project.scene, inputs->textures);
    if (inputs->bakedRadiosity)
        setup.renderer->setBakedRadiosity(std::move(inputs->bakedRadiosity));
    exitCode = kOk;
    return setup;
}

RenderRequest renderRequestOptions(Args& args) {
    RenderRequest request;
    request.cameraName = args.option("--camera");
    request.sets = args.options("--set");
    return request;
}

bool sweepShowsBakedRadiosity(const std::vector<std::vector<bench::Setting>>& combinations) {
    for (const auto& combination : combinations)
        for (const auto& [key, value] : combination)
            if (key == "gi.method" && value == "radiosity")
                return true;
    return false;
}

bool renderFrames(RenderSetup& setup, int width, int height, int frames) {
    for (int f = 0; f < frames; ++f)
        if (auto ok = setup.renderer->render(setup.project.scene, setup.project.parameters, setup.camera, width, height);
            !ok) {
            std::cerr << "lpv: " << ok.error().describe() << "\n";
            return false;
        }
    setup.renderer->timer().resolveAll();
    return true;
}

std::string formatPerFrameTimes(const renderer::GpuTimer& timer) {
    const auto history = timer.history();
    std::ostringstream out;
    // Each column is as wide as its name or its widest figure, whichever is wider.
    auto width = [](const std::string& pass, const std::vector<double>& ms) {
        int w = int(pass.size());
        for (double v : ms)
            w = std::max(w, std::snprintf(nullptr, 0, "%.3f", v));
        return w;
    };
    out << "frame";
    std::size_t frames = 0;
    for (const auto& [pass, ms] : history) {
        out << "  " << std::string(std::size_t(width(pass, ms) - int(pass.size())), ' ') << pass;
        frames = std::max(frames, ms.size());
    }
    out << "  (ms)\n";
    for (std::size_t f = 0; f < frames; ++f) {
        char cell[32];
        std::snprintf(cell, sizeof cell, "%5zu", f + 1);
        out << cell;
        for (const auto& [pass, ms] : history) {
            // Right-align each figure under its pass name.
            std::snprintf(cell, sizeof cell, "%*.3f", width(pass, ms) + 2, f < ms.size() ? ms[f] : 0.0);
            out << cell;
        }
        out << "\n";
    }
    return out.str();
}

} // namespace lpv::cli
