// `lpv radiosity`: progressive radiosity with GPU hemicubes, saved into the
// project (docs/radiosity.md). A second run resumes where the first stopped.
#include "Cli.h"
#include "RenderSetup.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/importers/SceneTextures.h"
#include "lpv/radiosity/RadiositySession.h"
#include "lpv/radiosity/SolveLoop.h"
#include "lpv/renderer/GlContext.h"
#include "lpv/renderer/FormFactorSources.h"
#include "lpv/renderer/GpuHemicube.h"
#include "lpv/renderer/RadiosityView.h"
#include "lpv/scene/FramingCamera.h"
#include "lpv/scene/Project.h"
#include "lpv/scene/ProjectLock.h"
#include "lpv/scene/ProjectTextures.h"
#include "lpv/scene/SaveCleanup.h"

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

namespace lpv::cli {

void printRadiosityHelp() {
    std::cout << R"(Usage: lpv radiosity PROJECT.lpvproj [options]

Solves the project's diffuse light by progressive refinement. Every light
shoots: the sun, spot, point and area lights deliver their direct light to
the patches first (with shadows, radiosity.lightSamples points per patch),
and emissive surfaces shoot their own light. Then the patches with the most
unshot energy shoot it, a batch at a time, found by ray casting on the CPU
(radiosity.formFactors=raycast, Embree) or by hemicubes rendered on the GPU
(hemicube; EGL: the GPU where present, Mesa llvmpipe otherwise). Prints
progress (shots, residual = unshot / emitted energy, shooters per second) and
the time each residual decade was first reached. `lpv render --set
gi.method=radiosity` shows the solution as the indirect light. The solution (patches and radiosity, with a
checksum) goes into PROJECT.assets/radiosity.lpvrad, or into OUT's assets
with -o; running again resumes an unfinished solve. Ctrl+C pauses: the
solution so far is saved.

  -o, --output FILE     Save the project with its solution as FILE (default: in place)
  --residual R          Stop at this residual (default radiosity.convergenceThreshold)
  --max-seconds S       Stop after S seconds of solving in this run (default 3600, an
                        hour; 0: no limit). Stopped there, the solution is saved and a
                        second run resumes it. A residual that is not finite (a light
                        whose energy overflows) stops the solve with an error, unsaved
  --restart             Ignore a saved solution and start over
  --refine T            After converging, split patches whose radiosity differs
                        from a neighbour's by more than T (relative, e.g. 0.3),
                        then solve on to the residual again
  --set KEY=VALUE       Override a registry parameter (radiosity.maxPatchArea,
                        radiosity.formFactors, radiosity.shooterSamples, radiosity.lightSamples,
                        radiosity.hemicubeResolution, radiosity.shootersPerBatch, ...)
  --image FILE          Also render the solution to an image (camera: --camera or the first);
                        FILE.exr keeps linear radiance, to measure with `lpv compare`
                        against `lpv reference --set reference.emissiveLight=true`
  --view MODE           radiosity (default), ambient (plus Cohen's ambient term
                        for the unshot energy), unshot, shot
  --wireframe           Draw the patch edges over the image
  --camera NAME         Camera for --image
  --width N, --height N Size of --image (default 800x600)
  --hemicube-image FILE Write the first shooter's hemicube of the last batch (patch IDs as
                        colours; radiosity.formFactors=hemicube only)
  --cpu                 Use the CPU reference form factors instead of the GPU (small scenes only)
  --progress-interval S Seconds between progress lines (default 1)
)";
}

namespace {

scene::Expected<void> writeRadianceExr(const std::filesystem::path& file, int width, int height,
                                       const std::vector<float>& rgba, const std::string& view) {
    importers::FloatChannels image{width, height, {"R", "G", "B"}, {}, {}};
    image.pixels.reserve(std::size_t(width) * std::size_t(height) * 3);
    for (std::size_t i = 0; i + 3 < rgba.size(); i += 4)
        image.pixels.insert(image.pixels.end(), {rgba[i], rgba[i + 1], rgba[i + 2]});
    return importers::writeImageChannels(file, image, {{"lpv:outputView", "radiosity-" + view}});
}

std::atomic<bool> gInterrupted{false};

extern "C" void onRadiosityInterrupt(int) {
    gInterrupted = true;
}

// Relative texture paths point into the source project's folder; a copy saved
// elsewhere gets them copied into its own assets.
void makeTexturePathsAbsolute(scene::Scene& s, const std::filesystem::path& projectDir) {
    for (scene::Material& m : s.materials)
        for (std::string* slot : scene::textureSlots(m))
            if (!slot->empty() && std::filesystem::path(*slot).is_relative())
                *slot = (projectDir / *slot).lexically_normal().string();
}

importers::Image8 hemicubeImage(const std::vector<std::uint32_t>& ids, int width, int height) {
    importers::Image8 image{width, height, 4, std::vector<std::uint8_t>(std::size_t(width * height) * 4, 0)};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::uint32_t id = ids[std::size_t((height - 1 - y) * width + x)];
            std::uint8_t* px = &image.pixels[std::size_t(y * width + x) * 4];
            px[3] = 255;
            if (id == 0)
                continue;
            std::uint32_t h =
                id * 2654435761u; // Knuth's multiplicative hash: neighbours get distinct colours
            px[0] = std::uint8_t(64 + (h >> 24) % 192);
            px[1] = std::uint8_t(64 + (h >> 16) % 192);
            px[2] = std::uint8_t(64 + (h >> 8) % 192);
        }
    return image;
}

struct Milestones {
    double next = 0.1;
    void check(const radiosity::SolveProgress& p) {
        while (p.residual <= next && next >= 1e-5) {
            std::printf("reached residual %g after %.2f s, %llu shots, %zu patches\n", next, p.seconds,
                        static_cast<unsigned long long>(p.shots), p.patches);
            next /= 10.0;
        }
    }
};

} // namespace

int runRadiosity(Args args) {
    RadiosityCommand c;
    c.output = args.option("--output", "-o");
    c.residual = args.optionalReal("--residual", {0.0, 1.0, true, false});
    c.maxSeconds = args.real("--max-seconds", radiosity::kDefaultMaxSeconds, RealRange::atLeast(0.0));
    c.refine = args.optionalReal("--refine", RealRange::atLeast(0.0));
    c.imageFile = args.option("--image");
    c.view = args.choice("--view", {"radiosity", "ambient", "unshot", "shot"}).value_or(c.view);
    c.cameraName = args.option("--camera");
    c.width = args.integer("--width", c.width, {1});
    c.height = args.integer("--height", c.height, {1});
    c.hemicubeFile = args.option("--hemicube-image");
    c.progressInterval = args.real("--progress-interval", c.progressInterval, RealRange::atLeast(0.0));
    c.restart = args.flag("--restart");
    c.wireframe = args.flag("--wireframe");
    c.useCpu = args.flag("--cpu");
    c.sets = args.options("--set");
    const auto pos = args.expectPositionals(1, "expected exactly one project file");
    if (pos.empty())
        return usageError(*args.error(), "radiosity");
    c.projectFile = pos.front();
    return runRadiosityCommand(c);
}

int runRadiosityCommand(const RadiosityCommand& c) {
    const auto& output = c.output;
    const auto& imageFile = c.imageFile;
    const auto& cameraName = c.cameraName;
    const auto& hemicubeFile = c.hemicubeFile;
    const auto& sets = c.sets;
    const std::string& view = c.view;
    const std::optional<double>& refine = c.refine;
    const bool restart = c.restart, wireframe = c.wireframe, useCpu = c.useCpu;
    const std::optional<double> maxSeconds = c.maxSeconds, interval = c.progressInterval, width = c.width,
                                height = c.height;
    const std::vector<std::string> pos{c.projectFile};
    const std::filesystem::path projectFile = pos.front();
    int exitCode = kFailure;
    auto project = loadProjectWithSets(projectFile.string(), sets, "radiosity", exitCode);
    if (!project)
        return exitCode;
    const scene::ParameterSet& params = project->parameters;
    const double residualTarget = c.residual.value_or(params.getFloat("radiosity.convergenceThreshold"));
    scene::Camera camera = project->scene.cameras.empty() ? scene::framingCamera(project->scene)
                                                          : project->scene.cameras.front();
    if (cameraName) {
        const scene::Camera* named = project->scene.findCamera(*cameraName);
        if (!named) {
            std::cerr << "lpv: " << projectFile.string() << ": no camera named '" << *cameraName << "'\n";
            return kFailure;
        }
        camera = *named;
    }

    auto context = renderer::HeadlessContext::create();
    if (!context) {
        std::cerr << "lpv: " << context.error().describe() << "\n";
        return kFailure;
    }
    std::printf("GL: %s | %s\n", context->info().renderer.c_str(), context->info().version.c_str());

    const auto textures = importers::loadSceneTextures(project->scene, projectFile.parent_path());
    std::optional<radiosity::StoredSolution> saved;
    if (!restart) {
        std::string ignored;
        saved = radiosity::loadSavedSolution(project->scene, projectFile, &ignored);
        if (!ignored.empty())
            std::printf("ignoring the saved solution: %s\n", ignored.c_str());
    }
    const auto meshStart = std::chrono::steady_clock::now();
    auto created = radiosity::RadiositySession::create(project->scene, params, textures.images, std::move(saved));
    if (!created) {
        std::cerr << "lpv: " << projectFile.string() << ": " << created.error().describe() << "\n";
        return kFailure;
    }
    radiosity::RadiositySession& session = *created;
    // radiosity.maxPatchArea, or unset the scene's own (radiosity::patchAreaFor).
    std::printf(
        "patches: %zu (%zu source quads, %zu source triangles, max area %g m^2%s), meshed in %.2f s\n",
        session.mesh().size(), session.mesh().sourceQuads, session.mesh().sourceTriangles,
        session.maxPatchArea(),
        params.isSet("radiosity.maxPatchArea") ? "" : ": 1/25 of the scene's largest side, squared",
        std::chrono::duration<double>(std::chrono::steady_clock::now() - meshStart).count());
    if (!session.note().empty())
        std::printf("%s\n", session.note().c_str());

    if (session.directLightSeconds() > 0.0)
        std::printf("lights: direct light at %d points per patch in %.2f s (the first shots)\n",
                    params.getInt("radiosity.lightSamples"), session.directLightSeconds());
    const std::string kind = useCpu ? "cpu-reference" : params.getEnum("radiosity.formFactors");
    std::unique_ptr<radiosity::FormFactorSource> formFactors;
    renderer::GpuHemicube* gpu = nullptr;
    auto makeSource = [&]() -> bool {
        if (useCpu) {
            formFactors = std::make_unique<radiosity::CpuFormFactors>(session.mesh());
            return true;
        }
        auto made = renderer::makeFormFactorSource(kind, session.mesh(), project->scene, textures.images, params);
        if (!made) {
            std::cerr << "lpv: " << made.error().describe() << "\n";
            return false;
        }
        formFactors = std::move(*made);
        gpu = dynamic_cast<renderer::GpuHemicube*>(formFactors.get());
        return true;
    };
    if (!makeSource())
        return kFailure;
    std::printf("form factors: %s, target residual %g\n", renderer::describeFormFactorSource(*formFactors).c_str(),
                residualTarget);
    if (*maxSeconds > 0.0)
        std::printf("time limit: %g s of solving in this run%s\n", *maxSeconds,
                    *maxSeconds == radiosity::kDefaultMaxSeconds
                        ? " (the default; --max-seconds S, 0 for none)"
                        : "");
    else
        std::printf("time limit: none (--max-seconds 0)\n");

    Milestones milestones;
    radiosity::SolveOptions options;
    options.residualTarget = residualTarget;
    options.maxSeconds = *maxSeconds;
    options.shootersPerBatch = useCpu ? params.getInt("radiosity.shootersPerBatch") : formFactors->preferredBatch();
    options.progressInterval = 0.0; // every batch: milestones are checked here, lines printed at `interval`
    options.cancel = &gInterrupted;
    auto lastLine = std::chrono::steady_clock::now();
    options.progress = [&](const radiosity::SolveProgress& p) {
        milestones.check(p);
        const auto now = std::chrono::steady_clock::now();
        if (std::chrono::duration<double>(now - lastLine).count() >= *interval) {
            std::printf("radiosity: %llu shots, %llu batches, residual %.5f, %.0f patches/s, %.1f s\n",
                        static_cast<unsigned long long>(p.shots), static_cast<unsigned long long>(p.batches),
                        p.residual, p.shootersPerSecond, p.seconds);
            std::fflush(stdout);
            lastLine = now;
        }
    };
    milestones.check(radiosity::progressOf(session.solver(), 0.0, 0));
    const auto previous = std::signal(SIGINT, onRadiosityInterrupt);
    auto reason = radiosity::solve(session.solver(), *formFactors, options);
    if (reason && refine && *reason == radiosity::StopReason::Converged) {
        const std::size_t split = session.refine(float(*refine));
        std::printf(
            "refined %zu patches whose radiosity differs from a neighbour's by more than %g: %zu patches\n",
            split, *refine, session.mesh().size());
        if (split > 0) {
            if (!makeSource())
                return kFailure;
            reason = radiosity::solve(session.solver(), *formFactors, options);
        }
    }
    std::signal(SIGINT, previous);
    if (!reason) {
        std::cerr << "lpv: " << reason.error().describe() << "\n";
        return kFailure;
    }
    const auto& state = session.solver().state();
    const auto& b = state.balance;
    const glm::dvec3 unshot = session.solver().unshotPower();
    const double emitted = b.emitted.x + b.emitted.y + b.emitted.z;
    std::printf("stopped: %s; %llu shots, residual %.5f, %.2f s in total\n", radiosity::toString(*reason),
                static_cast<unsigned long long>(state.shots), session.solver().residual(), state.seconds);
    if (emitted > 0.0)
        std::printf(
            "energy: emitted %.4g = absorbed %.4g + unshot %.4g + escaped %.4g (balance error %.2g)\n",
            emitted, b.absorbed.x + b.absorbed.y + b.absorbed.z, unshot.x + unshot.y + unshot.z,
            b.escaped.x + b.escaped.y + b.escaped.z,
            std::abs(emitted - (b.absorbed.x + b.absorbed.y + b.absorbed.z) -
                     (unshot.x + unshot.y + unshot.z) - (b.escaped.x + b.escaped.y + b.escaped.z)) /
                emitted);
    else
        std::printf("nothing emits light: give a material an emissive colour\n");

    // Assets first, the project last: a project file never names a solution
    // that is not there. If a step fails, the files this save created go
    // again (a replaced solution is not restored; its scene signature tells
    // it does not fit the project it sits beside).
    const std::filesystem::path target = output ? std::filesystem::path(*output) : projectFile;
    const auto solutionFile = radiosity::solutionPath(target);
    scene::SaveRollback rollback;
    auto fail = [&](const scene::Error& error) {
        rollback.undo();
        std::cerr << "lpv: " << error.describe() << "\n";
        if (output)
            std::cerr << "lpv: nothing was saved\n";
        return kFailure;
    };
    scene::Project copy;
    // The new project's lock spans its texture copies, the solution and the
    // save, as an import's does (issue #42): another save's clean-up must not
    // take copies no project file names yet.
    std::optional<scene::ProjectLock> lock;
    if (output) {
        auto held = scene::ProjectLock::acquire(target);
        if (!held)
            return fail(held.error());
        lock.emplace(std::move(*held));
        copy = *project;
        makeTexturePathsAbsolute(copy.scene, std::filesystem::absolute(projectFile).parent_path());
        rollback.watchTextureCopies(scene::assetsFolderOf(target) / "textures");
        if (auto copied = scene::copyTexturesIntoProject(copy.scene, target); !copied)
            return fail(copied.error());
    }
    scene::removeStaleTemporaries(solutionFile); // left by a killed save
    rollback.willWrite(solutionFile);
    if (auto ok = radiosity::saveSolution(session.stored(), solutionFile); !ok)
        return fail(ok.error());
    if (output) {
        scene::SaveOptions saveOptions;
        saveOptions.heldLock = &*lock;
        if (auto ok = scene::saveProject(copy, target, saveOptions); !ok)
            return fail(ok.error());
        std::printf("wrote %s\n", target.string().c_str());
    }
    std::printf("wrote %s\n", solutionFile.string().c_str());

    if (hemicubeFile && !gpu)
        std::fprintf(stderr, "lpv: --hemicube-image needs radiosity.formFactors=hemicube; no image written\n");
    if (hemicubeFile && gpu) {
        const auto ids = gpu->readHemicube(0);
        if (!ids.empty()) {
            if (auto ok = importers::writeImage(*hemicubeFile,
                                                hemicubeImage(ids, 3 * gpu->resolution(), gpu->resolution()));
                !ok) {
                std::cerr << "lpv: " << ok.error().describe() << "\n";
                return kFailure;
            }
            std::printf("wrote %s\n", hemicubeFile->c_str());
        }
    }
    if (imageFile) {
        auto viewer = renderer::RadiosityView::create();
        if (!viewer) {
            std::cerr << "lpv: " << viewer.error().describe() << "\n";
            return kFailure;
        }
        std::vector<glm::vec3> values = state.radiosity;
        if (view == "unshot")
            values = state.unshot;
        else if (view == "shot")
            for (std::size_t i = 0; i < values.size(); ++i)
                values[i] -= state.unshot[i];
        else if (view == "ambient") {
            const auto ambient = session.solver().ambient();
            for (std::size_t i = 0; i < values.size(); ++i)
                values[i] += ambient[i];
        }
        viewer->setPatches(session.mesh(), values, params.getBool("radiosity.smoothing"));
        viewer->render(camera, int(*width), int(*height), params.getFloat("output.exposure"), wireframe);
        // .exr keeps the linear radiance, for `lpv compare` against `lpv reference`.
        const bool hdr = std::filesystem::path(*imageFile).extension() == ".exr";
        auto ok = hdr ? writeRadianceExr(*imageFile, int(*width), int(*height), viewer->readRadiance(), view)
                      : importers::writeImage(*imageFile, importers::Image8{int(*width), int(*height), 4,
                                                                           viewer->readDisplay()});
        if (!ok) {
            std::cerr << "lpv: " << ok.error().describe() << "\n";
            return kFailure;
        }
        std::printf("wrote %s\n", imageFile->c_str());
    }
    return kOk;
}

} // namespace lpv::cli
