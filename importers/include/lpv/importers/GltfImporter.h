#pragma once
// glTF 2.0 (.gltf and .glb) through tinygltf: metallic-roughness PBR, normal /
// occlusion / emissive maps, alpha modes, KHR_materials_transmission (as
// translucency), KHR_lights_punctual, cameras and the node hierarchy.
#include "lpv/importers/Importer.h"

namespace lpv::importers {

scene::Expected<ImportResult> importGltf(const std::filesystem::path& file, const ImportOptions& options);

} // namespace lpv::importers
