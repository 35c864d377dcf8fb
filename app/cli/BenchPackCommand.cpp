// `lpv bench pack PROJECT -o FILE.lpvpack` (issue #45): the project, its
// meshes and its textures decoded as the renderer gets them, in one bench
// pack (scene/BenchPack.h) that `lpv bench render|lpv` and the GPU bench
// program (lpv-gl-bench) read in place of the project.
#include "Cli.h"

#include "lpv/bench/ContentHash.h"
#include "lpv/importers/SceneTextures.h"
#include "lpv/scene/BenchPack.h"
#include "lpv/scene/FileRead.h"
#include "lpv/scene/Project.h"

#include <cstdio>
#include <filesystem>
#include <iostream>

namespace lpv::cli {

void printBenchPackHelp() {
    std::cout << R"(
bench pack PROJECT -o FILE.lpvpack: writes one file with what a frame of the
project needs: the project document (materials, lights, cameras, camera
paths, parameters and presets, its name), every mesh as a mesh asset, the
textures decoded at the sizes the GPU gets (RGBA8, within the texture
budget, colour-keyed and height-derived images included) and the content
hash of the project file. Versioned and checksummed like the mesh assets.
`lpv bench render|lpv FILE.lpvpack` and `lpv-gl-bench render|lpv
FILE.lpvpack` render the same frames from it as from the project. A pack
holds no radiosity solution (gi.method=radiosity is refused from a pack).
)";
}

int benchPack(Args args) {
    const auto outputText = args.option("--output", "-o");
    args.require(outputText.has_value(), "missing -o FILE.lpvpack");
    const auto output = outputText ? std::optional<std::filesystem::path>(*outputText) : std::nullopt;
    const auto pos = args.expectPositionals(1, "bench pack expects exactly one project file", 1); // after "pack"
    if (pos.empty())
        return usageError(*args.error(), "bench");
    if (!scene::isBenchPackFile(*output))
        return usageError("the pack's name must end in .lpvpack (got '" + output->string() + "')", "bench");
    const std::string projectFile = pos.front();
    auto project = scene::loadProject(projectFile);
    if (!project) {
        std::cerr << "lpv: " << project.error().describe() << "\n";
        return kFailure;
    }
    printLoadWarnings(projectFile, project->loadWarnings);
    auto hash = bench::fileContentHash(projectFile);
    if (!hash) {
        std::cerr << "lpv: " << hash.error().describe() << "\n";
        return kFailure;
    }
    auto textures =
        importers::loadSceneTextures(project->scene, std::filesystem::absolute(projectFile).parent_path());
    for (const std::string& w : textures.warnings)
        std::cerr << "lpv: warning: " << w << "\n";

    scene::BenchPack pack{std::move(*project), std::move(textures.images), *hash};
    if (auto saved = scene::saveBenchPack(pack, *output); !saved) {
        std::cerr << "lpv: " << saved.error().describe() << "\n";
        return kFailure;
    }
    // What takes the space: vertex streams and indices, then the pixels.
    std::uint64_t meshBytes = 0, pixelBytes = 0;
    for (const scene::Mesh& m : pack.project.scene.meshes)
        meshBytes += m.positions.size() * 12 + m.normals.size() * 12 + m.tangents.size() * 16 + m.uvs.size() * 8 +
                     m.indices.size() * 4;
    for (const auto& [key, image] : pack.textures)
        pixelBytes += image.pixels.size();
    std::error_code ec;
    const std::uint64_t size = std::filesystem::file_size(*output, ec);
    std::printf("wrote %s: %s; %zu meshes, %zu triangles (%s); %zu textures (%s of pixels); project %s, hash %s\n",
                output->string().c_str(), scene::formatBytes(size).c_str(), pack.project.scene.meshes.size(),
                pack.project.scene.triangleCount(), scene::formatBytes(meshBytes).c_str(), pack.textures.size(),
                scene::formatBytes(pixelBytes).c_str(), pack.project.name.c_str(), pack.projectHash.c_str());
    return kOk;
}

} // namespace lpv::cli
