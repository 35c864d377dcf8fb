#include "Cli.h"

#include "lpv/scene/CameraSpline.h"
#include "lpv/scene/FileRead.h"
#include "lpv/scene/Project.h"
#include "lpv/scene/ProjectTextures.h"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <set>

namespace lpv::cli {

void printInfoHelp() {
    std::cout << R"(Usage: lpv info PROJECT.lpvproj

Loads and validates a project (JSON, ranges, parameters, mesh assets and
their checksums) and prints what it contains. Exit code 1 with the error
(file, field or byte offset, what was wrong) if anything is invalid.
)";
}

int runInfo(Args args) {
    const auto pos = args.expectPositionals(1, "expected exactly one project file");
    if (pos.empty())
        return usageError(*args.error(), "info");
    auto project = scene::loadProject(pos.front());
    if (!project) {
        std::cerr << "lpv: " << project.error().describe() << "\n";
        return kFailure;
    }
    printLoadWarnings(pos.front(), project->loadWarnings);
    const scene::Scene& s = project->scene;
    std::printf("project     %s\n", project->name.c_str());
    std::printf("objects     %zu\nmeshes      %zu\ntriangles   %zu\nmaterials   %zu\nlights      %zu\n"
                "cameras     %zu\npaths       %zu\n",
                s.objects.size(), s.meshes.size(), s.triangleCount(), s.materials.size(), s.lights.size(),
                s.cameras.size(), s.cameraPaths.size());
    // Texture references, and those whose file is not there (drawn as a placeholder).
    std::set<std::string> textures, missing;
    const std::filesystem::path folder = std::filesystem::path(pos.front()).parent_path();
    for (const scene::Material& m : s.materials)
        for (const std::string* slot : scene::textureSlots(m))
            if (!slot->empty() && textures.insert(*slot).second && scene::notARegularFile(folder / *slot))
                missing.insert(*slot);
    std::printf("textures    %zu (%zu missing)\n", textures.size(), missing.size());
    for (const std::string& name : missing)
        std::printf("missing     %s\n", name.c_str());
    const scene::Bounds b = s.worldBounds();
    if (!b.empty())
        std::printf("bounds      (%.3f, %.3f, %.3f) .. (%.3f, %.3f, %.3f)\n", b.min.x, b.min.y, b.min.z, b.max.x,
                    b.max.y, b.max.z);
    for (const scene::CameraPath& p : s.cameraPaths)
        std::printf("path        %s: %zu keyframes, %.3g s, %s, %s\n", p.name.c_str(), p.keyframes.size(),
                    double(scene::CameraSpline(p).duration()), p.closed ? "closed" : "open",
                    p.constantSpeed ? "constant speed" : "timed by its keys");
    for (const auto& [key, value] : project->parameters.overrides())
        std::printf("parameter   %s = %s\n", key.c_str(), scene::formatValue(value).c_str());
    return kOk;
}

} // namespace lpv::cli
