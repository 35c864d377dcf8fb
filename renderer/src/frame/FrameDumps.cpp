// `lpv render --dump NAME`: every output the frame graph declared, by its
// resource name (FrameResources.h: rsm.flux, camera.depth, lpv.accumulator) or by the
// name of the pass that wrote it ("rsm" = all three RSM images). Passes
// with a picture of their own (the LPV's slices of the DC term, shadow
// maps as depth) give theirs; everything else is read back as stored.
#include "frame/ForwardRendererImpl.h"
#include "gl/ImageRows.h"

#include <algorithm>

namespace lpv::renderer {

namespace {

std::vector<DebugImage> keepSuffix(std::vector<DebugImage> images, const std::string& suffix) {
    std::erase_if(images, [&](const DebugImage& i) { return !i.name.ends_with(suffix); });
    return images;
}

// One layer (or z slice) of a texture as stored, rows top to bottom.
DebugImage readLayer(GLuint texture, const graph::ResourceDesc& d, int layer, std::string name) {
    const bool depth = d.format == GL_DEPTH_COMPONENT32F;
    const int channels = depth ? 1 : 4;
    DebugImage image{std::move(name), d.width, d.height, channels, {}};
    image.pixels.resize(std::size_t(d.width) * std::size_t(d.height) * std::size_t(channels));
    glGetTextureSubImage(texture, 0, 0, 0, layer, d.width, d.height, 1, depth ? GL_DEPTH_COMPONENT : GL_RGBA,
                         GL_FLOAT, GLsizei(image.pixels.size() * sizeof(float)), image.pixels.data());
    flipRows(image.pixels, d.width, d.height, channels);
    return image;
}

std::vector<DebugImage> readResource(GLuint id, const graph::ResourceDesc& d, const std::string& name) {
    std::vector<DebugImage> images;
    if (!id || !known(d))
        return images;
    if (d.kind == graph::ResourceKind::Buffer) {
        // As RGBA float texels, one row.
        DebugImage image{name, int(d.bytes / 16), 1, 4, {}};
        image.pixels.resize(std::size_t(image.width) * 4);
        glGetNamedBufferSubData(id, 0, GLsizeiptr(image.pixels.size() * sizeof(float)), image.pixels.data());
        if (image.width > 0)
            images.push_back(std::move(image));
        return images;
    }
    if (d.kind == graph::ResourceKind::Texture2D) {
        images.push_back(readLayer(id, d, 0, name));
        return images;
    }
    for (int layer = 0; layer < d.layers; ++layer)
        images.push_back(readLayer(id, d, layer, name + "-" + std::to_string(layer)));
    return images;
}

} // namespace

std::vector<DebugImage> ForwardRenderer::Impl::dump(const std::string& name) const {
    // A pass's name: everything it wrote this frame.
    for (const GraphPassReport& pass : graph.report().passes)
        if (pass.name == name) {
            std::vector<DebugImage> all;
            if (pass.status == PassStatus::Culled)
                return all;
            // RSMs in their pass's own order: position, normal, flux per tile.
            if (name == "rsm")
                return rsm->maps().active() ? rsm->maps().debugImages() : all;
            if (name == "localRsm")
                return localRsm->maps() ? localRsm->maps()->debugImages() : all;
            for (const GraphResourceUse& w : pass.writes) {
                auto images = dumpResource(w.name.substr(0, w.name.find(' ')));
                all.insert(all.end(), std::make_move_iterator(images.begin()), std::make_move_iterator(images.end()));
            }
            return all;
        }
    return dumpResource(name);
}

std::vector<DebugImage> ForwardRenderer::Impl::dumpResource(const std::string& name) const {
    // Outputs whose pass draws them better than the raw texels.
    if (name == resources::ShadowMaps.name())
        return shadows->maps().debugImages();
    if (name == resources::RsmPosition.name() || name == resources::RsmNormal.name() || name == resources::RsmFlux.name())
        return rsm->maps().active() ? keepSuffix(rsm->maps().debugImages(), "-" + name.substr(4)) : std::vector<DebugImage>{};
    if (name == resources::LocalRsmPosition.name() || name == resources::LocalRsmNormal.name() ||
        name == resources::LocalRsmFlux.name())
        return localRsm->maps() ? keepSuffix(localRsm->maps()->debugImages(), "-" + name.substr(9))
                                              : std::vector<DebugImage>{};
    if (name == resources::LpvAccumulator.name())
        return lpv->active() ? keepSuffix(lpv->debugImages(), "-accum") : std::vector<DebugImage>{};
    if (name == resources::LpvGeometry.name())
        return lpv->active() && graph.produced(scene::Pass::GeometryVolume) ? keepSuffix(lpv->debugImages(), "-gv")
                                                                            : std::vector<DebugImage>{};
    const std::optional<graph::ResourceDesc> desc = graph.resourceDesc(name);
    if (!desc)
        return {};
    return readResource(graph.resourceId(name), *desc, name);
}

std::vector<std::string> ForwardRenderer::Impl::dumpNames() const {
    std::vector<std::string> names = graph.resourceNames();
    for (const GraphPassReport& pass : graph.report().passes)
        if (std::find(names.begin(), names.end(), pass.name) == names.end())
            names.push_back(pass.name);
    return names;
}

} // namespace lpv::renderer
