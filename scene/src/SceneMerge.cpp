#include "lpv/scene/SceneMerge.h"

#include <iterator>

namespace lpv::scene {
namespace {

template <class T>
void moveAppend(std::vector<T>& into, std::vector<T>& from) {
    into.insert(into.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
}

int shifted(int index, std::size_t offset) { return index < 0 ? index : index + static_cast<int>(offset); }

} // namespace

void appendScene(Scene& into, Scene from) {
    const std::size_t meshOffset = into.meshes.size();
    const std::size_t materialOffset = into.materials.size();
    const std::size_t objectOffset = into.objects.size();
    for (Mesh& mesh : from.meshes)
        for (Submesh& sub : mesh.submeshes)
            sub.materialIndex += static_cast<std::uint32_t>(materialOffset);
    for (Object& object : from.objects) {
        object.mesh = shifted(object.mesh, meshOffset);
        object.parent = shifted(object.parent, objectOffset);
        for (LodLevel& lod : object.lods)
            lod.mesh = shifted(lod.mesh, meshOffset);
    }
    moveAppend(into.meshes, from.meshes);
    moveAppend(into.materials, from.materials);
    moveAppend(into.objects, from.objects);
    moveAppend(into.lights, from.lights);
    moveAppend(into.cameras, from.cameras);
    moveAppend(into.cameraPaths, from.cameraPaths);
}

} // namespace lpv::scene
