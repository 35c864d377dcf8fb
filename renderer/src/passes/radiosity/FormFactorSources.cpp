#include "lpv/renderer/FormFactorSources.h"

#include "lpv/radiosity/RayCastFormFactors.h"
#include "lpv/renderer/GpuHemicube.h"

namespace lpv::renderer {

scene::Expected<std::unique_ptr<radiosity::FormFactorSource>> makeFormFactorSource(
    const std::string& kind, const radiosity::PatchMesh& mesh, const scene::Scene& scene,
    const scene::TextureImages& textures, const scene::ParameterSet& params) {
    const int batch = params.getInt("radiosity.shootersPerBatch");
    if (kind == "raycast") {
        auto source = radiosity::RayCastFormFactors::create(mesh, scene, textures,
                                                            params.getInt("radiosity.shooterSamples"), batch);
        if (!source)
            return std::unexpected(source.error());
        return std::unique_ptr<radiosity::FormFactorSource>(std::move(*source));
    }
    if (kind == "hemicube") {
        auto source = GpuHemicube::create(mesh, params.getInt("radiosity.hemicubeResolution"), batch);
        if (!source)
            return std::unexpected(source.error());
        return std::unique_ptr<radiosity::FormFactorSource>(std::move(*source));
    }
    return scene::makeError(scene::ErrorCode::InvalidValue, "radiosity", "radiosity.formFactors",
                            "unknown form factor source '" + kind + "' (raycast or hemicube)");
}

std::string describeFormFactorSource(const radiosity::FormFactorSource& source) {
    if (const auto* rays = dynamic_cast<const radiosity::RayCastFormFactors*>(&source))
        return std::string(source.name()) + ", " + std::to_string(rays->samples()) + " points per shooter, " +
               std::to_string(source.preferredBatch()) + " shooters per batch";
    if (const auto* cube = dynamic_cast<const GpuHemicube*>(&source))
        return std::string(source.name()) + ", hemicube " + std::to_string(cube->resolution()) + " px, " +
               std::to_string(source.preferredBatch()) + " shooters per batch";
    return std::string(source.name()) + ", " + std::to_string(source.preferredBatch()) + " shooters per batch";
}

} // namespace lpv::renderer
