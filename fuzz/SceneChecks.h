#pragma once
// What a successful load promises the renderer, checked on every scene a
// fuzz target gets back: finite numbers in materials, lights and cameras;
// meshes that pass validateMesh (indices below the vertex count, submeshes
// inside the index buffer with existing materials, finite values); object
// mesh/LOD/parent indices in range, parent chains without cycles, finite
// transforms. A broken promise aborts, so libFuzzer reports the input like
// any crash.
//
// Last, unless `render` is false, checkRenderFinite (RenderChecks.h): the
// products a render of the scene computes are finite. fuzz_4ds checks the
// reader's raw scene without it, and the render of the scene as importScene
// finishes it (finishImport).
//
// checkTexturesInside adds the importers' read-root promise for the targets
// that import from a path (fuzz_gltf, fuzz_obj).
#include "RenderChecks.h"

#include "lpv/scene/MeshAsset.h"
#include "lpv/scene/Scene.h"
#include "lpv/scene/SceneFields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <type_traits>
#include <vector>

namespace lpv::fuzz {

[[noreturn]] inline void invariantBroken(const std::string& what) {
    std::fprintf(stderr, "==fuzz== invariant broken: %s\n", what.c_str());
    std::abort();
}

inline bool isIndexOf(int index, std::size_t size) {
    return index >= -1 && (index < 0 || static_cast<std::size_t>(index) < size);
}

inline void checkFinite(float v, const std::string& what) {
    if (!std::isfinite(v))
        invariantBroken(what + " = " + std::to_string(v) + " is not finite");
}

inline void checkFinite(const glm::vec3& v, const std::string& what) {
    for (int c = 0; c < 3; ++c)
        checkFinite(v[c], what + "[" + std::to_string(c) + "]");
}

// Every number in the fields of a scene struct's table (SceneFields.h), so
// a field added there is checked here without being named.
template <class S> void checkFiniteFields(const S& s, const std::string& at) {
    scene::forEachField<S>([&](const auto& field) {
        const auto& v = field.of(s);
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, float>)
            checkFinite(v, at + field.name);
        else if constexpr (std::is_same_v<T, glm::vec2> || std::is_same_v<T, glm::vec3> ||
                           std::is_same_v<T, glm::quat>)
            for (int c = 0; c < T::length(); ++c)
                checkFinite(v[c], at + field.name + "[" + std::to_string(c) + "]");
    });
}

inline void checkScene(const scene::Scene& s, const std::string& file, bool render = true) {
    for (std::size_t i = 0; i < s.materials.size(); ++i)
        checkFiniteFields(s.materials[i], "materials[" + std::to_string(i) + "].");
    for (std::size_t i = 0; i < s.lights.size(); ++i)
        checkFiniteFields(s.lights[i], "lights[" + std::to_string(i) + "].");
    for (std::size_t i = 0; i < s.cameras.size(); ++i)
        checkFiniteFields(s.cameras[i], "cameras[" + std::to_string(i) + "].");
    checkFiniteFields(s.sky, "sky.");

    for (std::size_t i = 0; i < s.meshes.size(); ++i)
        if (auto valid = scene::validateMesh(s.meshes[i], file, "meshes[" + std::to_string(i) + "]",
                                             s.materials.size());
            !valid)
            invariantBroken("loaded mesh fails validateMesh: " + valid.error().describe());

    for (std::size_t i = 0; i < s.objects.size(); ++i) {
        const scene::Object& o = s.objects[i];
        const std::string label = "objects[" + std::to_string(i) + "]";
        if (!isIndexOf(o.mesh, s.meshes.size()))
            invariantBroken(label + ".mesh = " + std::to_string(o.mesh) + " of " +
                            std::to_string(s.meshes.size()));
        for (const scene::LodLevel& lod : o.lods)
            if (!isIndexOf(lod.mesh, s.meshes.size()))
                invariantBroken(label + " has a LOD with mesh " + std::to_string(lod.mesh));
        if (!isIndexOf(o.parent, s.objects.size()))
            invariantBroken(label + ".parent = " + std::to_string(o.parent));
        checkFiniteFields(o, label + ".");
    }

    // Parent chains end at a root: each object is walked once (0 = unvisited,
    // 1 = on the chain being walked, 2 = reaches a root).
    std::vector<unsigned char> state(s.objects.size(), 0);
    std::vector<std::size_t> chain;
    for (std::size_t start = 0; start < s.objects.size(); ++start) {
        chain.clear();
        int at = static_cast<int>(start);
        while (at >= 0 && state[static_cast<std::size_t>(at)] == 0) {
            state[static_cast<std::size_t>(at)] = 1;
            chain.push_back(static_cast<std::size_t>(at));
            at = s.objects[static_cast<std::size_t>(at)].parent;
        }
        if (at >= 0 && state[static_cast<std::size_t>(at)] == 1)
            invariantBroken("objects[" + std::to_string(at) + "] is its own ancestor");
        for (const std::size_t c : chain)
            state[c] = 2;
    }

    if (render)
        checkRenderFinite(s);
}

// Importers promise that a texture path they hand back as found, i.e.
// absolute, lies in a folder the import may read: the model's folder, its
// texture folders, the search paths. A name that was not found is kept as
// stored and is not a read, so it is not checked here.
// The comparison is lexical (normalised, no symbolic links resolved): the
// fuzz work folders hold copies, no links, so any "..", "%2e%2e" or absolute
// name that reached a file outside shows up as a path outside every root.
inline bool isInside(const std::filesystem::path& path, const std::filesystem::path& root) {
    const std::filesystem::path p = path.lexically_normal();
    const std::filesystem::path r = root.lexically_normal();
    auto pi = p.begin();
    for (auto ri = r.begin(); ri != r.end(); ++ri, ++pi) {
        if (ri->empty() && std::next(ri) == r.end())
            break; // a root written with a trailing separator
        if (pi == p.end() || *pi != *ri)
            return false;
    }
    return true;
}

inline void checkTexturesInside(const scene::Scene& s, const std::vector<std::filesystem::path>& roots) {
    for (std::size_t i = 0; i < s.materials.size(); ++i) {
        const scene::Material& m = s.materials[i];
        for (const std::string* texture :
             {&m.diffuseTexture, &m.normalTexture, &m.heightTexture, &m.specularTexture,
              &m.metallicRoughnessTexture, &m.occlusionTexture, &m.emissiveTexture, &m.alphaTexture,
              &m.environmentTexture}) {
            const std::filesystem::path path(*texture);
            if (texture->empty() || !path.is_absolute())
                continue;
            if (std::none_of(roots.begin(), roots.end(),
                             [&](const std::filesystem::path& root) { return isInside(path, root); }))
                invariantBroken("materials[" + std::to_string(i) + "] ('" + m.name + "') reads texture '" +
                                *texture + "', outside every folder the import may read");
        }
    }
}

} // namespace lpv::fuzz
