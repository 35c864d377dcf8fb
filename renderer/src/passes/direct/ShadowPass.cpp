#include "passes/direct/ShadowPass.h"
#include "gl/ImageRows.h"

#include "gl/GpuMemoryLedger.h"
#include "graph/ContentHash.h"

#include "lpv/renderer/ShaderLibrary.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cassert>
#include <map>
#include <cmath>
#include <string>

namespace lpv::renderer {

using scene::ErrorCode;
using scene::makeError;

namespace {

// Opaque draw items, then the alpha-masked and blended ones, which must cut
// holes: the opaque ones go through a program that never discards.
std::pair<std::vector<const DrawItem*>, std::vector<const DrawItem*>> splitOpaque(
    const std::vector<const DrawItem*>& items) {
    std::pair<std::vector<const DrawItem*>, std::vector<const DrawItem*>> out;
    for (const DrawItem* d : items)
        (d->bucket == DrawBucket::Opaque ? out.first : out.second).push_back(d);
    return out;
}

// The geometry shader's invocation count: one layer per invocation.
constexpr int kMaxLayersPerPass = 8;

GLint loc(GLuint program, const std::string& name) { return glGetUniformLocation(program, name.c_str()); }

// A cascade layer's content: what it was drawn from and with which matrix.
std::uint64_t cascadeKey(std::uint64_t contentKey, const glm::mat4& viewProj) {
    return graph::ContentHash().add(contentKey).add(viewProj).value() | 1u; // never 0, the "nothing drawn" key
}

// "name[i]", built once per name and index rather than every frame.
const std::string& indexed(const char* name, int i) {
    static std::map<std::pair<std::string, int>, std::string> names;
    auto [it, inserted] = names.try_emplace({name, i});
    if (inserted)
        it->second = std::string(name) + "[" + std::to_string(i) + "]";
    return it->second;
}

void setDepthSampling(GLuint texture, bool compare) {
    glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, compare ? GL_LINEAR : GL_NEAREST);
    glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, compare ? GL_LINEAR : GL_NEAREST);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture, GL_TEXTURE_COMPARE_MODE, compare ? GL_COMPARE_REF_TO_TEXTURE : GL_NONE);
    glTextureParameteri(texture, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
}

// A cube face of a point light's map is half the size of the other maps:
// six of them per light would otherwise cost 6x the memory and fill.
int pointFaceSize(int mapSize) { return std::max(mapSize / 2, 128); }

CascadeCamera cascadeCamera(const FrameContext& frame) {
    CascadeCamera c;
    c.position = frame.camera.position;
    const glm::vec3 forward = frame.camera.target - frame.camera.position;
    c.forward = glm::length(forward) > 0.0f ? glm::normalize(forward) : glm::vec3(0.0f, 0.0f, -1.0f);
    c.fovY = frame.camera.fovY;
    c.aspect = frame.height > 0 ? float(frame.width) / float(frame.height) : 1.0f;
    c.nearPlane = frame.camera.nearPlane;
    c.farPlane = frame.camera.farPlane;
    return c;
}

// A box around a point light that contains its whole cube (for culling).
glm::mat4 sphereBoxViewProj(const glm::vec3& center, float radius) {
    const glm::mat4 translate{1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f, 0.0f,
                              -center.x, -center.y, -center.z, 1.0f};
    return glm::mat4{1.0f / radius, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f / radius, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f / radius,
                     0.0f, 0.0f, 0.0f, 0.0f, 1.0f} *
           translate;
}

} // namespace

scene::Expected<ShadowPass> ShadowPass::create() {
    // Build the programs a default frame needs now, so a shader error shows at start-up.
    ShadowPass pass;
    if (auto p = pass.programFor(false, 6); !p)
        return std::unexpected(p.error());
    if (auto p = pass.programFor(true, 6); !p)
        return std::unexpected(p.error());
    return pass;
}

scene::Expected<GLuint> ShadowPass::programFor(bool distance, int layers, bool opaque) {
    if (layers < 1 || layers > kMaxLayersPerPass)
        return makeError(ErrorCode::OutOfRange, "render", "shadow layers",
                         std::to_string(layers) + " is outside 1.." + std::to_string(kMaxLayersPerPass));
    opaque = opaque && !distance; // distance maps write gl_FragDepth: no early test to keep
    Program& program =
        (distance ? distancePrograms_ : opaque ? opaqueDepthPrograms_ : depthPrograms_)[std::size_t(layers - 1)];
    if (!program) {
        std::vector<std::string> defines{"SHADOW_LAYERS " + std::to_string(layers)};
        if (opaque)
            defines.push_back("SHADOW_OPAQUE 1");
        auto built = buildEmbeddedProgram({"shadow.vert", "shadow.geom", distance ? "shadow_distance.frag" : "shadow.frag"},
                                          defines);
        if (!built)
            return std::unexpected(built.error());
        program = std::move(*built);
    }
    return program.id();
}

scene::Expected<void> ShadowPass::ensureTarget(LayeredTarget& t, GLenum target, int size, int layers) {
    if (layers == 0) {
        t = LayeredTarget{}; // free what a light that is gone used
        return {};
    }
    GLint maxSize = 0, maxLayers = 0;
    glGetIntegerv(target == GL_TEXTURE_CUBE_MAP_ARRAY ? GL_MAX_CUBE_MAP_TEXTURE_SIZE : GL_MAX_TEXTURE_SIZE, &maxSize);
    glGetIntegerv(GL_MAX_ARRAY_TEXTURE_LAYERS, &maxLayers);
    if (size > maxSize)
        return makeError(ErrorCode::OutOfRange, "render", "parameters.shadow.mapSize",
                         std::to_string(size) + " exceeds this GPU's GL_MAX_TEXTURE_SIZE " + std::to_string(maxSize));
    if (layers > maxLayers)
        return makeError(ErrorCode::OutOfRange, "render", "shadow maps",
                         std::to_string(layers) + " layers exceed GL_MAX_ARRAY_TEXTURE_LAYERS " +
                             std::to_string(maxLayers));
    if (t.target == target && t.size == size && t.layers == layers)
        return {};
    t.target = target;
    t.size = size;
    t.layers = layers;
    t.texture = createTexture(target);
    glTextureStorage3D(t.texture.id(), 1, GL_DEPTH_COMPONENT32F, size, size, layers);
    setDepthSampling(t.texture.id(), false);
    GLuint view = 0;
    glGenTextures(1, &view); // a view needs a name that was never bound
    glTextureView(view, target, t.texture.id(), GL_DEPTH_COMPONENT32F, 0, 1, 0, GLuint(layers));
    t.compareView = Texture(view);
    setDepthSampling(view, true);
    t.fbo = createFramebuffer();
    glNamedFramebufferTexture(t.fbo.id(), GL_DEPTH_ATTACHMENT, t.texture.id(), 0); // layered: gl_Layer picks
    glNamedFramebufferDrawBuffer(t.fbo.id(), GL_NONE);
    glNamedFramebufferReadBuffer(t.fbo.id(), GL_NONE);
    if (glGetError() == GL_OUT_OF_MEMORY) {
        t = LayeredTarget{};
        return makeError(ErrorCode::OutOfRange, "render", "shadow maps", "the GPU ran out of memory allocating them");
    }
    return {};
}

void ShadowPass::drawLayers(GLuint p, const SceneGpu& geometry, const MaterialGpu& materials,
                            const std::vector<const DrawItem*>& items, const glm::mat4* viewProj, int layerCount,
                            int firstLayer) const {
    glProgramUniform1i(p, loc(p, "uLayerCount"), layerCount);
    glProgramUniform1i(p, loc(p, "uFirstLayer"), firstLayer);
    glProgramUniformMatrix4fv(p, loc(p, "uLayerViewProj"), layerCount, GL_FALSE, glm::value_ptr(viewProj[0]));
    geometry.draw(p, items, [&](std::uint32_t m) { materials.bind(p, m, MaterialBindMode::Coverage); });
}

bool ShadowPass::mayKeepFarCascade(std::size_t k, std::uint64_t contentKey, int farInterval,
                                   const glm::vec3& sunDirection) const {
    const std::size_t count = cascades_.size();
    if (farInterval <= 1 || contentKey == 0 || k < count / 2 || layerContent_[k] != contentKey)
        return false;
    if ((cascadeFrame_ + k) % std::uint64_t(farInterval) == 0)
        return false; // this cascade's turn
    // A point the kept layer no longer covers falls to the next cascade
    // (shadow_sampling.glsl); past the last one it would be unshadowed, so
    // the last cascade is kept only while it covers its whole slice.
    return k + 1 < count || cascadeCovers(drawnCascades_[k], cascades_[k], sunDirection);
}

scene::Expected<void> ShadowPass::drawCascadesOneByOne(const SceneGpu& geometry, const MaterialGpu& materials,
                                                       std::uint64_t contentKey, int farInterval,
                                                       const glm::vec3& sunDirection) {
    for (bool opaque : {false, true}) {
        Program& program = opaque ? perCascadeOpaqueProgram_ : perCascadeProgram_;
        if (program)
            continue;
        std::vector<std::string> defines{"SHADOW_NO_GEOMETRY_SHADER 1"};
        if (opaque)
            defines.push_back("SHADOW_OPAQUE 1");
        auto built = buildEmbeddedProgram({"shadow.vert", "shadow.frag"}, defines);
        if (!built)
            return std::unexpected(built.error());
        program = std::move(*built);
    }
    const GLuint masked = perCascadeProgram_.id(), opaque = perCascadeOpaqueProgram_.id();
    const GLuint fbo = cascadeMap_.fbo.id(), map = cascadeMap_.texture.id();
    // A cascade whose snapped matrix did not move keeps its layer while the
    // scene, the lights and the map are the same: far cascades mostly stay
    // put while the camera moves.
    if (cascadeKeys_.size() != cascades_.size() || cascadeMapId_ != map) {
        cascadeKeys_.assign(cascades_.size(), 0);
        layerContent_.assign(cascades_.size(), 0);
        drawnCascades_.assign(cascades_.size(), ShadowCascade{});
    }
    cascadeMapId_ = map;
    cascadesDrawn_ = 0;
    staleCascades_ = 0;
    for (std::size_t k = 0; k < cascades_.size(); ++k) {
        const std::uint64_t key = cascadeKey(contentKey, cascades_[k].viewProj);
        if (contentKey != 0 && key == cascadeKeys_[k])
            continue; // 0: the caller cannot say what the maps are drawn from, so every layer is drawn
        if (mayKeepFarCascade(k, contentKey, farInterval, sunDirection)) {
            // Shade from the layer as it was drawn: its matrix, texel and depth
            // range; the split distances are this frame's.
            ShadowCascade kept = drawnCascades_[k];
            kept.splitNear = cascades_[k].splitNear;
            kept.splitFar = cascades_[k].splitFar;
            cascades_[k] = kept;
            ++staleCascades_;
            continue;
        }
        cascadeKeys_[k] = key;
        layerContent_[k] = contentKey;
        drawnCascades_[k] = cascades_[k];
        ++cascadesDrawn_;
        // Each cascade culls with its own volume and draws only what it holds.
        glNamedFramebufferTextureLayer(fbo, GL_DEPTH_ATTACHMENT, map, 0, GLint(k));
        glClear(GL_DEPTH_BUFFER_BIT);
        const auto items = buildDrawList(geometry.draws(), cascades_[k].viewProj, glm::vec3(0.0f));
        const auto [solid, cut] = splitOpaque(items);
        for (const auto& [p, list] : {std::pair{opaque, &solid}, std::pair{masked, &cut}}) {
            if (list->empty())
                continue;
            glUseProgram(p);
            glProgramUniformMatrix4fv(p, loc(p, "uViewProj"), 1, GL_FALSE, glm::value_ptr(cascades_[k].viewProj));
            geometry.draw(p, *list, [&](std::uint32_t m) { materials.bind(p, m, MaterialBindMode::Coverage); });
        }
    }
    ++cascadeFrame_;
    glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, map, 0); // layered again
    return {};
}

scene::Expected<void> ShadowPass::render(const FrameContext& frame, const SceneGpu& geometry,
                                         const MaterialGpu& materials, std::uint64_t contentKey) {
    const scene::Scene& s = frame.scene;
    lights_ = selectShadowLights(s);
    const int mapSize = frame.params.getInt("shadow.mapSize");
    const int cascadeCount = std::clamp(frame.params.getInt("shadow.cascades"), 1, kMaxLayersPerPass);
    const scene::Bounds bounds = frame.sceneBounds;

    if (auto ok = ensureTarget(cascadeMap_, GL_TEXTURE_2D_ARRAY, mapSize, lights_.sun >= 0 ? cascadeCount : 0); !ok)
        return ok;
    if (auto ok = ensureTarget(spotMap_, GL_TEXTURE_2D_ARRAY, mapSize, int(lights_.spots.size())); !ok)
        return ok;
    // A point light's map is one cube, an area light's one per quarter (areaShadowCentres).
    int pointCubes = 0;
    for (int i : lights_.points)
        pointCubes += s.lights[std::size_t(i)].type == scene::LightType::Area ? kAreaShadowCubes : 1;
    if (auto ok = ensureTarget(pointMap_, GL_TEXTURE_CUBE_MAP_ARRAY, pointFaceSize(mapSize), 6 * pointCubes); !ok)
        return ok;

    cascades_.clear();
    staleCascades_ = 0;
    spotViews_.clear();
    pointViews_.clear();
    spotPositions_.clear();
    pointPositions_.clear();
    localLightRadius_ = 0.5f * frame.params.getFloat("shadow.softness");
    if (lights_.sun >= 0) {
        const CascadeSettings settings{cascadeCount, mapSize, frame.params.getBool("shadow.stabilize"),
                                       kCascadeSplitLambda};
        cascades_ = buildCascades(cascadeCamera(frame), s.lights[std::size_t(lights_.sun)].direction, bounds, settings);
    }
    for (int i : lights_.spots) {
        spotViews_.push_back(spotShadowView(s.lights[std::size_t(i)], bounds));
        spotPositions_.push_back(s.lights[std::size_t(i)].position);
    }
    pointRadii_.clear();
    pointFirstCube_.clear();
    for (int i : lights_.points) {
        const scene::Light& light = s.lights[std::size_t(i)];
        pointFirstCube_.push_back(int(pointViews_.size()));
        if (light.type != scene::LightType::Area) {
            pointViews_.push_back(pointShadowView(light, bounds));
            pointPositions_.push_back(light.position);
            pointRadii_.push_back(localLightRadius_);
            continue;
        }
        // An area light's penumbrae follow its own size, not shadow.softness,
        // which stands in for the size of lights that have none.
        for (const glm::vec3& centre : areaShadowCentres(light)) {
            scene::Light quarter = light;
            quarter.position = centre;
            pointViews_.push_back(pointShadowView(quarter, bounds));
            pointPositions_.push_back(centre);
            pointRadii_.push_back(0.0f); // unused: shadow_sampling.glsl samples the quarter itself
        }
    }
    // shadow_sampling.glsl's arrays hold this many (selectShadowLights caps the lights).
    assert(pointViews_.size() <= std::size_t(kMaxPointShadowCubes));
    if (cascades_.empty() && spotViews_.empty() && pointViews_.empty())
        return {};

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE); // one-sided walls (the Cornell box) must still cast shadows

    if (!cascades_.empty()) {
        glBindFramebuffer(GL_FRAMEBUFFER, cascadeMap_.fbo.id());
        glViewport(0, 0, mapSize, mapSize);
        // Slope-scaled depth bias: receivers nearly parallel to the light's rays
        // otherwise show acne stripes.
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(2.0f, 2.0f);
        const glm::vec3 sunDirection = s.lights[std::size_t(lights_.sun)].direction;
        if (frame.params.getEnum("shadow.cascadeDraws") == "perCascade") {
            // Unstabilised cascades draw each on its own texel grid: a stale
            // layer would shade other depths, so they are always redrawn.
            const int farInterval =
                frame.params.getBool("shadow.stabilize") ? frame.params.getInt("shadow.farCascadeInterval") : 1;
            if (auto ok = drawCascadesOneByOne(geometry, materials, contentKey, farInterval, sunDirection); !ok)
                return ok;
        } else {
            cascadeKeys_.clear(); // the broadcast draws every layer
            staleCascades_ = 0;
            cascadesDrawn_ = int(cascades_.size());
            auto program = programFor(false, int(cascades_.size()));
            if (!program)
                return std::unexpected(program.error());
            auto opaqueProgram = programFor(false, int(cascades_.size()), true);
            if (!opaqueProgram)
                return std::unexpected(opaqueProgram.error());
            glClear(GL_DEPTH_BUFFER_BIT);
            // Cull once against the box around all cascades; shadow.geom drops
            // triangles outside each cascade.
            const glm::mat4 unionBox = cascadeUnionViewProj(cascades_, sunDirection, bounds);
            const auto items = buildDrawList(geometry.draws(), unionBox, glm::vec3(0.0f));
            std::vector<glm::mat4> matrices;
            for (const ShadowCascade& c : cascades_)
                matrices.push_back(c.viewProj);
            const auto [solid, cut] = splitOpaque(items);
            for (const auto& [p, list] : {std::pair{*opaqueProgram, &solid}, std::pair{*program, &cut}}) {
                if (list->empty())
                    continue;
                glUseProgram(p);
                drawLayers(p, geometry, materials, *list, matrices.data(), int(matrices.size()), 0);
            }
        }
        glDisable(GL_POLYGON_OFFSET_FILL);
    }

    // Local lights write distance / far from the fragment shader (no polygon
    // offset applies to it; shadow_sampling.glsl biases the comparison instead).
    auto drawLocal = [&](const LayeredTarget& target, const std::vector<LocalShadowView>& views,
                         const std::vector<glm::vec3>& positions, bool cube) -> scene::Expected<void> {
        auto program = programFor(true, cube ? 6 : 1);
        if (!program)
            return std::unexpected(program.error());
        const GLuint dp = *program;
        glUseProgram(dp);
        glBindFramebuffer(GL_FRAMEBUFFER, target.fbo.id());
        glViewport(0, 0, target.size, target.size);
        glClear(GL_DEPTH_BUFFER_BIT);
        for (std::size_t i = 0; i < views.size(); ++i) {
            const LocalShadowView& v = views[i];
            glProgramUniform3fv(dp, loc(dp, "uLightPos"), 1, glm::value_ptr(positions[i]));
            glProgramUniform1f(dp, loc(dp, "uFar"), v.farPlane);
            const glm::mat4 cullBox = cube ? sphereBoxViewProj(positions[i], v.farPlane) : v.viewProj[0];
            const auto items = buildDrawList(geometry.draws(), cullBox, positions[i]);
            drawLayers(dp, geometry, materials, items, v.viewProj.data(), v.faces, int(i) * v.faces);
        }
        return {};
    };
    if (!spotViews_.empty())
        if (auto ok = drawLocal(spotMap_, spotViews_, spotPositions_, false); !ok)
            return ok;
    if (!pointViews_.empty())
        if (auto ok = drawLocal(pointMap_, pointViews_, pointPositions_, true); !ok)
            return ok;
    return {};
}

void ShadowPass::bindForShading(const CachedProgram& shader, const FrameContext& frame,
                                const UnitAllocator& nextUnit) const {
    const GLuint p = shader.id();
    glProgramUniform1f(p, shader.uniform("uShadowBias"), frame.params.getFloat("shadow.bias"));
    glProgramUniformMatrix4fv(p, shader.uniform("uShadowCameraView"), 1, GL_FALSE, glm::value_ptr(frame.view));

    // The sun: shadow.softness is its angular diameter in degrees.
    glProgramUniform1i(p, shader.uniform("uSunShadowLight"), cascades_.empty() ? -1 : lights_.sun);
    glProgramUniform1i(p, shader.uniform("uCascadeCount"), int(cascades_.size()));
    for (std::size_t k = 0; k < cascades_.size(); ++k) {
        const int idx = int(k);
        const ShadowCascade& c = cascades_[k];
        glProgramUniformMatrix4fv(p, shader.uniform(indexed("uCascadeViewProj", idx)), 1, GL_FALSE, glm::value_ptr(c.viewProj));
        glProgramUniform1f(p, shader.uniform(indexed("uCascadeSplitFar", idx)), c.splitFar);
        glProgramUniform1f(p, shader.uniform(indexed("uCascadeTexel", idx)), c.texelWorld);
        glProgramUniform1f(p, shader.uniform(indexed("uCascadeDepthRange", idx)), c.depthRange);
    }
    const float softness = frame.params.getFloat("shadow.softness");
    glProgramUniform1f(p, shader.uniform("uSunTanHalfAngle"), std::tan(glm::radians(0.5f * softness)));

    // Point and spot lights: shadow.softness is their diameter in scene units.
    glProgramUniform1f(p, shader.uniform("uLocalLightRadius"), localLightRadius_);
    for (int i = 0; i < kMaxShadedLights; ++i) {
        const int idx = int(i);
        const auto spot = std::find(lights_.spots.begin(), lights_.spots.end(), i);
        const auto point = std::find(lights_.points.begin(), lights_.points.end(), i);
        glProgramUniform1i(p, shader.uniform(indexed("uSpotShadowLayer", idx)),
                           spot == lights_.spots.end() ? -1 : int(spot - lights_.spots.begin()));
        glProgramUniform1i(p, shader.uniform(indexed("uPointShadowLayer", idx)),
                           point == lights_.points.end()
                               ? -1
                               : pointFirstCube_[std::size_t(point - lights_.points.begin())]);
    }
    for (std::size_t i = 0; i < spotViews_.size(); ++i) {
        const int idx = int(i);
        glProgramUniformMatrix4fv(p, shader.uniform(indexed("uSpotViewProj", idx)), 1, GL_FALSE,
                                  glm::value_ptr(spotViews_[i].viewProj[0]));
        glProgramUniform1f(p, shader.uniform(indexed("uSpotTanHalfFov", idx)), spotViews_[i].tanHalfFov);
        glProgramUniform3fv(p, shader.uniform(indexed("uSpotPosition", idx)), 1, glm::value_ptr(spotPositions_[i]));
        glProgramUniform1f(p, shader.uniform(indexed("uSpotFar", idx)), spotViews_[i].farPlane);
    }
    for (std::size_t i = 0; i < pointViews_.size(); ++i) {
        const int idx = int(i);
        glProgramUniform3fv(p, shader.uniform(indexed("uPointPosition", idx)), 1, glm::value_ptr(pointPositions_[i]));
        glProgramUniform1f(p, shader.uniform(indexed("uPointFar", idx)), pointViews_[i].farPlane);
        glProgramUniform1f(p, shader.uniform(indexed("uPointRadius", idx)), pointRadii_[i]);
    }

    // Every sampler gets its own unit even when its map does not exist:
    // samplers of different types may not share a unit.
    struct Binding {
        const char* name;
        GLuint texture;
    };
    const Binding bindings[] = {{"uCascadeCompare", cascadeMap_.compareView.id()},
                                {"uCascadeDepth", cascadeMap_.texture.id()},
                                {"uSpotCompare", spotMap_.compareView.id()},
                                {"uSpotDepth", spotMap_.texture.id()},
                                {"uPointCompare", pointMap_.compareView.id()},
                                {"uPointDepth", pointMap_.texture.id()}};
    for (const Binding& b : bindings) {
        const GLuint unit = nextUnit();
        glProgramUniform1i(p, shader.uniform(b.name), GLint(unit));
        glBindTextureUnit(unit, b.texture);
    }
}

std::vector<DebugImage> ShadowPass::debugImages() const {
    std::vector<DebugImage> images;
    auto readLayer = [&](const LayeredTarget& t, int layer, std::string name) {
        DebugImage image{std::move(name), t.size, t.size, 1, {}};
        image.pixels.resize(std::size_t(t.size) * std::size_t(t.size));
        glGetTextureSubImage(t.texture.id(), 0, 0, 0, layer, t.size, t.size, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                             GLsizei(image.pixels.size() * sizeof(float)), image.pixels.data());
        flipRows(image.pixels, t.size, t.size, 1);
        images.push_back(std::move(image));
    };
    for (std::size_t k = 0; k < cascades_.size() && cascadeMap_.texture; ++k)
        readLayer(cascadeMap_, int(k), "shadow-cascade-" + std::to_string(k));
    for (std::size_t i = 0; i < spotViews_.size() && spotMap_.texture; ++i)
        readLayer(spotMap_, int(i), "shadow-spot-" + std::to_string(i));
    static const char* faces[] = {"px", "nx", "py", "ny", "pz", "nz"};
    for (std::size_t i = 0; i < pointViews_.size() && pointMap_.texture; ++i)
        for (int f = 0; f < 6; ++f)
            readLayer(pointMap_, int(i) * 6 + f, "shadow-point-" + std::to_string(i) + "-" + faces[f]);
    return images;
}

void ShadowPass::addGpuMemory(GpuMemoryLedger& ledger) const {
    // compareView is a view of the same storage: nothing of its own.
    ledger.addTexture("shadowMaps.sun", cascadeMap_.texture.id());
    ledger.addTexture("shadowMaps.spot", spotMap_.texture.id());
    ledger.addTexture("shadowMaps.point", pointMap_.texture.id());
}

} // namespace lpv::renderer
