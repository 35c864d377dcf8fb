#pragma once
// The form factor source a project asks for (radiosity.formFactors): ray
// casting on the CPU (radiosity::RayCastFormFactors, Embree) or hemicubes on
// the GPU (GpuHemicube, which needs a current GL 4.5 context). One place, so
// `lpv radiosity`, the editor's Radiosity dock and `lpv bench report` choose
// the same way.
#include "lpv/radiosity/FormFactors.h"
#include "lpv/scene/Error.h"
#include "lpv/scene/Image.h"
#include "lpv/scene/ParameterRegistry.h"
#include "lpv/scene/Scene.h"

#include <memory>
#include <string>

namespace lpv::renderer {

// `kind` is "raycast" or "hemicube" (anything else is an error value);
// radiosity.shooterSamples, radiosity.hemicubeResolution and
// radiosity.shootersPerBatch come from `params`. `mesh`, `scene` and
// `textures` must outlive the source.
scene::Expected<std::unique_ptr<radiosity::FormFactorSource>> makeFormFactorSource(
    const std::string& kind, const radiosity::PatchMesh& mesh, const scene::Scene& scene,
    const scene::TextureImages& textures, const scene::ParameterSet& params);

// A line for logs: "raycast, 4 points per shooter, 16 shooters per batch".
std::string describeFormFactorSource(const radiosity::FormFactorSource& source);

} // namespace lpv::renderer
