#pragma once
// What a rendering command renders (issue #45): a project with its --set
// overrides, the textures decoded as the renderer gets them and, when the
// frames show it, the baked radiosity solution; read from a project
// (.lpvproj, through lpv_importers' decoders) or from a bench pack
// (.lpvpack, everything inside). `lpv` links RenderInputs.cpp, which reads
// both; the GPU bench program (app/glbench) links its own
// loadRenderInputs that reads packs only, so it needs no image library.
#include "RenderSetup.h"

#include "lpv/radiosity/BakedSolution.h"
#include "lpv/scene/Image.h"
#include "lpv/scene/Project.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lpv::cli {

struct RenderInputs {
    scene::Project project;
    scene::TextureImages textures;
    std::shared_ptr<const radiosity::BakedSolution> bakedRadiosity; // when request.bakedRadiosity or gi.method asks
};

// On failure prints the message and returns the exit code in `exitCode`
// (as prepareRender, RenderSetup.h).
std::optional<RenderInputs> loadRenderInputs(const RenderRequest& request, const std::string& command, int& exitCode);

// The bench pack's project with the --set overrides applied and its
// textures; a pack holds no radiosity solution, so frames that show one are
// refused ("make the pack's frames with gi.method=lpv"). Shared by both
// loadRenderInputs.
std::optional<RenderInputs> loadPackInputs(const RenderRequest& request, const std::string& command, int& exitCode);

// Each KEY=VALUE of `sets` applied to `parameters`; a bad one is a usage
// error (its code in `exitCode`, message printed) and gives false.
bool applySets(scene::ParameterSet& parameters, const std::vector<std::string>& sets, const std::string& command,
               int& exitCode);

} // namespace lpv::cli
