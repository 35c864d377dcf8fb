#include "passes/lpv/LpvPass.h"

#include "gl/GpuMemoryLedger.h"
#include "passes/lpv/LpvStages.h"
#include "lpv/renderer/ShaderLibrary.h"
#include "lpv/renderer/lpv/LpvVisibility.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <stdexcept>

namespace lpv::renderer {

namespace {

constexpr const char* kVariantNames[] = {"computeGather", "computeScatter", "rasterGather", "rasterScatter"};

GLuint groups(int count, int size) { return GLuint((count + size - 1) / size); }


constexpr GLbitfield kComputeResults =
    GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT;

// SSBO bindings shared by the shaders (lpv_common.glsl and the passes).
constexpr GLuint kSumsBinding = 0, kScalesBinding = 1, kGvSumsBinding = 2, kNormalSumsBinding = 3;
// Texture unit of the directed propagation's normals (lpv_common.glsl, LPV_WITH_DIRECTED).
constexpr GLuint kNormalsUnit = 7;
// Image unit of the visibility moments in the lookup (lpv_lookup.glsl's uLpvMoments).
constexpr GLuint kVisibilityImageUnit = 7;

std::vector<glm::vec4> readVolumeBlock(GLuint texture, int size, int firstSlice) {
    std::vector<glm::vec4> v(std::size_t(size) * std::size_t(size) * std::size_t(size));
    glGetTextureSubImage(texture, 0, 0, 0, firstSlice, size, size, size, GL_RGBA, GL_FLOAT,
                         GLsizei(v.size() * sizeof(glm::vec4)), v.data());
    return v;
}

} // namespace

std::optional<LpvVariant> lpvVariantFromName(const std::string& name) {
    for (int i = 0; i < 4; ++i)
        if (name == kVariantNames[i])
            return LpvVariant(i);
    return std::nullopt;
}

const char* lpvVariantName(LpvVariant variant) { return kVariantNames[int(variant)]; }

LpvSettings LpvSettings::fromParameters(const scene::ParameterSet& params) {
    LpvSettings s;
    s.gridSize = params.getInt("lpv.gridSize");
    s.shBands = params.getInt("lpv.shBands");
    s.propagationSteps = params.getInt("lpv.propagationSteps");
    s.stepsByCellSize = params.getEnum("lpv.cascadeSteps") == "byCellSize";
    s.injectionOffset = float(params.getFloat("lpv.injectionOffset"));
    s.occlusion = params.getBool("lpv.occlusion");
    s.occludeFirstStep = params.getBool("lpv.occlusionFirstStep");
    s.occlusionStrength = float(params.getFloat("lpv.occlusionStrength"));
    s.twoSidedOcclusion = params.getBool("lpv.twoSidedOcclusion");
    s.gvFromScene = params.getEnum("lpv.geometrySource") == "scene";
    s.gvFromCamera = params.getBool("lpv.gvFromCamera");
    s.gvCameraStride = params.getInt("lpv.gvCameraStride");
    // The registry only admits the four names; anything else is a bug, not a default.
    const std::string variant = params.getEnum("lpv.variant");
    const auto parsed = lpvVariantFromName(variant);
    if (!parsed)
        throw std::logic_error("lpv.variant = '" + variant + "' is not a propagation variant");
    s.variant = *parsed;
    // auto: whenever the LPV runs (SceneAnalysis says the same); off by default in the registry.
    s.directed = params.getEnum("lpv.directedPropagation") != "off";
    s.directedDilation = params.getInt("lpv.directedDilation");
    s.bounces = params.getInt("lpv.bounces");
    s.bounceAlbedo = float(params.getFloat("lpv.bounceAlbedo"));
    s.requestedCascades = params.getInt("lpv.cascades");
    s.rsmCascades = params.getInt("rsm.cascades");
    s.visibility = params.getBool("lpv.visibilityLookup");
    // Asked for by name; an automatic choice must pick full for three bands (LpvLookupPass).
    const std::string lookup = params.getEnum("lpv.lookupResolution");
    s.reducedLookup = lookup == "half" || lookup == "quarter";
    if (s.shBands == 3) {
        // What reads or writes two bands only is off (docs/lpv.md, "Three bands"),
        // and the note says so; the effects list says it for the sky, the
        // subsurface LPV, the glossy march and bounces (SceneAnalysis).
        std::vector<std::string> off;
        if (s.bounces > 1)
            off.push_back("one bounce: bounces re-inject two bands");
        if (s.visibility)
            off.push_back("no visibility-aware lookup: it reads two bands");
        s.bounces = 1;
        s.visibility = false;
        for (const std::string& o : off)
            s.threeBandsNote += (s.threeBandsNote.empty() ? "" : "; ") + o;
    }
    return s;
}

scene::Expected<LpvPass> LpvPass::create() {
    LpvPass pass;
    pass.emptyVao_ = createVertexArray();
    return pass;
}

ProgramVariant LpvPass::variantOf(LpvKernel kernel) const {
    // Three bands: the kernels that hold SH take LPV_SH_BANDS (issue #47).
    if (bands_ == 3) {
        switch (kernel) {
        case LpvKernel::Inject: return {{"lpv_inject.comp"}, {"LPV_SH_BANDS 3"}};
        case LpvKernel::Resolve: return {{"lpv_resolve.comp"}, {"LPV_SH_BANDS 3"}};
        case LpvKernel::GvFromRsm: return {{"lpv_gv_inject.comp"}, {"GV_FROM_RSM 1", "LPV_SH_BANDS 3"}};
        case LpvKernel::GvFromCamera: return {{"lpv_gv_inject.comp"}, {"GV_FROM_CAMERA 1", "LPV_SH_BANDS 3"}};
        case LpvKernel::GvMerge: return {{"lpv_gv_merge.comp"}, {"LPV_SH_BANDS 3"}};
        case LpvKernel::FaceBlocking: return {{"lpv_face_blocking.comp"}, {"LPV_SH_BANDS 3"}};
        case LpvKernel::LocalInject: return {{"lpv_inject_local.comp"}, {"LPV_SH_BANDS 3"}};
        case LpvKernel::ComputeGather: return {{"lpv_gather.comp"}, {"LPV_SH_BANDS 3"}};
        case LpvKernel::SkyInject: return {{"lpv_sky_inject.comp"}, {"LPV_SH_BANDS 3"}};
        default: break;
        }
    }
    switch (kernel) {
    case LpvKernel::FluxMax: return {{"lpv_flux_max.comp"}, {}};
    case LpvKernel::Inject: return {{"lpv_inject.comp"}, {}};
    case LpvKernel::Resolve: return {{"lpv_resolve.comp"}, {}};
    case LpvKernel::GvFromRsm: return {{"lpv_gv_inject.comp"}, {"GV_FROM_RSM 1"}};
    case LpvKernel::GvFromCamera: return {{"lpv_gv_inject.comp"}, {"GV_FROM_CAMERA 1"}};
    case LpvKernel::GvMerge: return {{"lpv_gv_merge.comp"}, {}};
    case LpvKernel::FaceBlocking: return {{"lpv_face_blocking.comp"}, {}};
    case LpvKernel::Normals: return {{"lpv_normals.comp"}, {}};
    case LpvKernel::NormalsDilate: return {{"lpv_normals.comp"}, {"NORMALS_DILATE 1"}};
    case LpvKernel::SkyInject: return {{"lpv_sky_inject.comp"}, {}};
    case LpvKernel::BounceInject: return {{"lpv_bounce.comp"}, {"BOUNCE_INJECT 1"}};
    case LpvKernel::BounceAdd: return {{"lpv_bounce.comp"}, {}};
    case LpvKernel::LocalFluxMax: return {{"lpv_inject_local.comp"}, {"LOCAL_FLUX_MAX 1"}};
    case LpvKernel::LocalInject: return {{"lpv_inject_local.comp"}, {}};
    case LpvKernel::ComputeGather: return {{"lpv_gather.comp"}, {}};
    case LpvKernel::ComputeGatherFirst: return {{"lpv_gather.comp"}, {"LPV_FIRST_STEP 1"}};
    case LpvKernel::Deinterleave: return {{"lpv_deinterleave.comp"}, {}};
    case LpvKernel::ComputeScatter: return {{"lpv_scatter.comp"}, {}};
    case LpvKernel::RasterGather:
        return {{"lpv_raster_gather.vert", "lpv_raster.geom", "lpv_raster_gather.frag"}, {}};
    case LpvKernel::RasterScatter:
        return {{"lpv_raster_scatter.vert", "lpv_raster.geom", "lpv_raster_scatter.frag"}, {"LPV_POINTS 1"}};
    case LpvKernel::Visibility: return {{"lpv_visibility.comp"}, {}};
    }
    throw std::logic_error("unknown LPV kernel");
}

scene::Expected<void> LpvPass::buildKernel(LpvKernel k) {
    auto program = programs_.get(variantOf(k));
    if (!program)
        return std::unexpected(program.error());
    byId_[(*program)->id()] = *program;
    return {};
}

GLuint LpvPass::kernel(LpvKernel k) {
    // prepare() built what the settings select; anything else compiles here,
    // and a compile error fails the frame (the frame graph makes it an error value).
    auto program = programs_.get(variantOf(k));
    if (!program)
        throw std::logic_error(program.error().describe());
    byId_[(*program)->id()] = *program;
    return (*program)->id();
}

GLint LpvPass::loc(GLuint program, const char* name) const {
    const auto it = byId_.find(program);
    return it != byId_.end() ? it->second->uniform(name) : glGetUniformLocation(program, name);
}

scene::Expected<void> LpvPass::buildKernelsFor(const LpvSettings& settings) {
    std::vector<LpvKernel> kernels = {LpvKernel::FluxMax, LpvKernel::Inject, LpvKernel::Resolve};
    if (settings.geometryVolumeRuns()) {
        kernels.push_back(LpvKernel::FaceBlocking);
        // The scene's GV is uploaded: no surfel is injected or merged on the GPU.
        if (!settings.gvFromScene)
            kernels.insert(kernels.end(), {LpvKernel::GvFromRsm, LpvKernel::GvMerge});
    }
    if (settings.gvFromCamera && !settings.gvFromScene)
        kernels.push_back(LpvKernel::GvFromCamera);
    if (settings.directed)
        kernels.insert(kernels.end(), {LpvKernel::Normals, LpvKernel::NormalsDilate});
    if (settings.bounces > 1)
        kernels.insert(kernels.end(), {LpvKernel::BounceInject, LpvKernel::BounceAdd});
    if (settings.visibilityRuns())
        kernels.push_back(LpvKernel::Visibility);
    switch (settings.variant) {
    case LpvVariant::ComputeGather:
        if (settings.shBands == 3) // every step reads the interleaved volumes; no viewer capture
            kernels.push_back(LpvKernel::ComputeGather);
        else
            kernels.insert(kernels.end(),
                           {LpvKernel::ComputeGather, LpvKernel::ComputeGatherFirst, LpvKernel::Deinterleave});
        break;
    case LpvVariant::ComputeScatter: kernels.push_back(LpvKernel::ComputeScatter); break;
    case LpvVariant::RasterGather: kernels.push_back(LpvKernel::RasterGather); break;
    case LpvVariant::RasterScatter: kernels.push_back(LpvKernel::RasterScatter); break;
    }
    for (LpvKernel k : kernels)
        if (auto ok = buildKernel(k); !ok)
            return ok;
    return {};
}

void LpvPass::disable(std::string reason) {
    volumes_.release();
    cascades_.clear();
    snapshot_.reset();
    active_ = false;
    note_ = "LPV: off (" + std::move(reason) + ")";
}

void LpvPass::reuse() { note_ = "LPV: reused, nothing changed since the last frame (" + computedNote_ + ")"; }

void LpvPass::setCascadeUniforms(GLuint program) const {
    const std::vector<LpvCascade>& cascades = cascades_;
    std::array<glm::vec3, 6> origin{};
    std::array<float, 6> cellSize{};
    for (std::size_t k = 0; k < cascades.size() && k < 6; ++k) {
        origin[k] = cascades[k].origin;
        cellSize[k] = cascades[k].cellSize;
    }
    glProgramUniform1i(program, loc(program, "uGridSize"), volumes_.gridSize());
    glProgramUniform1i(program, loc(program, "uCascades"), volumes_.cascades());
    glProgramUniform3fv(program, loc(program, "uOrigin"), 6, glm::value_ptr(origin[0]));
    glProgramUniform1fv(program, loc(program, "uCellSize"), 6, cellSize.data());
}

namespace {

// Local inputs with something in them.
std::vector<LpvLocalInput> nonEmpty(const std::vector<LpvLocalInput>& all) {
    std::vector<LpvLocalInput> local;
    for (const LpvLocalInput& l : all)
        if (l.layers > 0 && l.size > 0 && l.position)
            local.push_back(l);
    return local;
}

} // namespace

// Three bands run in the compute gather with shading's full-resolution lookup
// (issue #47); anything else is refused with an error that names what to change.
scene::Expected<void> LpvPass::refuseBands(const LpvSettings& settings) {
    auto refuse = [&](const std::string& why) {
        return scene::makeError(scene::ErrorCode::OutOfRange, "render", "parameters.lpv.shBands",
                                "lpv.shBands = " + std::to_string(settings.shBands) + ": " + why);
    };
    if (settings.shBands == 2)
        return {};
    if (settings.shBands != 3)
        return refuse("the LPV runs two or three bands");
    if (settings.variant != LpvVariant::ComputeGather)
        return refuse(std::string("the ") + lpvVariantName(settings.variant) +
                      " LPV runs two bands only; three bands run in the computeGather variant "
                      "(lpv.variant = computeGather, issue #47)");
    if (settings.reducedLookup)
        return refuse("the lookup at reduced resolution (lpv.lookupResolution = half|quarter) reads two bands "
                      "only; set lpv.lookupResolution = full (issue #47)");
    GLint units = 0;
    glGetIntegerv(GL_MAX_TEXTURE_IMAGE_UNITS, &units);
    if (units < 17)
        return refuse("shading's three-band lookup needs 17 fragment texture units and this GL has " +
                      std::to_string(units) + "; set lpv.shBands = 2");
    return {};
}

scene::Expected<void> LpvPass::prepare(const LpvSettings& settings, const std::vector<LpvCascade>& requested) {
    if (auto refused = refuseBands(settings); !refused) {
        disable("lpv.shBands = " + std::to_string(settings.shBands) + " does not run here");
        return refused;
    }
    bands_ = settings.shBands;
    if (auto built = buildKernelsFor(settings); !built)
        return built;
    const int cascades = std::min<int>(int(requested.size()), 6);
    if (cascades == 0) {
        disable("no RSM to inject from");
        return {};
    }
    if (auto ok = volumes_.ensure(settings.gridSize, cascades, settings.shBands); !ok) {
        disable("volumes do not fit");
        if (cascades != settings.requestedCascades)
            ok.error().message += " (lpv.cascades is " + std::to_string(settings.requestedCascades) +
                                  "; the LPV has one volume per RSM tile, and rsm.cascades = " +
                                  std::to_string(settings.rsmCascades) + " makes " + std::to_string(cascades) + ")";
        return ok;
    }
    volumes_.ensureDirected(settings.directed);
    volumes_.ensureBounces(settings.bounces > 1);
    volumes_.ensureInterleaved(settings.variant == LpvVariant::ComputeGather);
    visibilityActive_ = settings.visibilityRuns();
    if (volumes_.ensureVisibility(visibilityActive_) || !visibilityActive_)
        visibilityReady_ = false; // new or freed: nothing built into them yet
    cascades_.assign(requested.begin(), requested.begin() + cascades);
    injectionOffset_ = settings.injectionOffset;
    gvCameraStride_ = std::max(settings.gvCameraStride, 1);
    occlusion_ = settings.occlusion;
    occlusionStrength_ = settings.occlusionStrength;
    twoSidedOcclusion_ = settings.twoSidedOcclusion;
    propagationSteps_ = settings.propagationSteps;
    active_ = true;
    return {};
}

void LpvPass::injectStage(const LpvRsmInput& rsm, const std::vector<LpvLocalInput>& local, bool directed) {
    tileSize_ = rsm.tileSize;
    snapshot_.reset();
    capturedStep_ = -1;
    inject(rsm, directed, nonEmpty(local));
}

void LpvPass::skyStage(const LpvSkyInput& sky) { injectSky(sky); }

void LpvPass::normalsStage(int dilation) { buildNormals(dilation); }

void LpvPass::geometryStage(const LpvRsmInput& rsm, const LpvCameraInput* camera,
                            const LpvSceneGeometry* sceneGeometry) {
    injectGeometry(rsm, camera, sceneGeometry);
}

void LpvPass::propagationStage(const LpvSettings& settings) {
    if (!settings.directed)
        normalsIndex_ = -1; // the normals volume of an earlier frame is not this frame's
    // V_0 is overwritten by the first step, so a capture of it happens before propagation.
    captureIfRequested(0, readIndex_);
    propagate(settings);
}

void LpvPass::bounceStage(const LpvSettings& settings) { propagateBounces(settings); }

void LpvPass::finish(const LpvSettings& settings, bool cameraGv, bool sky, const std::vector<LpvLocalInput>& local) {
    readCapture();
    const int n = settings.gridSize;
    note_ = "LPV: " + std::to_string(cascades_.size()) + " cascades of " + std::to_string(n) + "^3, " +
            std::to_string(settings.propagationSteps) + " steps, " + lpvVariantName(settings.variant) +
            (!settings.occlusion ? ", no occlusion"
             : sceneSurfels_ > 0 ? ", occlusion from the scene (" + std::to_string(sceneSurfels_) + " surfels)"
                                 : ", occlusion from the RSM" + std::string(settings.gvFromCamera && cameraGv ? " and the camera" : "")) +
            (settings.directed ? ", directed (" + std::to_string(settings.directedDilation) + "-cell dilation)" : "") +
            (sky ? ", sky light injected" : "") + localNote(nonEmpty(local)) +
            (settings.bounces > 1 ? ", " + std::to_string(settings.bounces) + " bounces" : "") +
            (visibilityActive_ ? ", visibility-aware lookup" : "") +
            (settings.shBands == 3 ? ", 3 SH bands" + (settings.threeBandsNote.empty() ? "" : " (" + settings.threeBandsNote + ")")
                                   : "");
    computedNote_ = note_.substr(5); // without "LPV: "
}

scene::Expected<void> LpvPass::run(const LpvSettings& settings, const LpvRsmInput& rsm,
                                   const LpvCameraInput* camera, GpuTimer& timer, const LpvSkyInput* sky,
                                   const std::vector<LpvLocalInput>& allLocal, const LpvSceneGeometry* sceneGeometry) {
    const std::vector<LpvLocalInput> local = nonEmpty(allLocal);
    if (rsm.cascades.empty() || ((rsm.tileSize <= 0 || !rsm.position) && local.empty())) {
        disable("no RSM to inject from");
        return {};
    }
    if (auto ok = prepare(settings, rsm.cascades); !ok)
        return ok;
    const bool withSky = sky && sky->depth && sky->size > 0;
    LpvStageInputs in;
    in.lpv = this;
    in.settings = settings;
    in.runs = true;
    in.sun = rsm.position && rsm.tileSize > 0;
    in.sky = withSky ? runsBecause("a sky height map was given") : skippedBecause("no sky height map was given");
    in.rsm = [&rsm] { return rsm; };
    in.localInputs = [&local] { return local; };
    in.skyInput = [sky] { return *sky; };
    in.camera = settings.gvFromCamera ? camera : nullptr;
    if (settings.gvFromScene)
        in.sceneGeometry = [sceneGeometry] { return sceneGeometry; };
    // The stages' own decisions schedule them, as in the frame graph; each
    // timed under its pass name.
    for (const std::unique_ptr<LpvStage>& stage : makeLpvStages()) {
        const LpvStageDefinition& s = stage->definition();
        graph::PassSpec declared;
        s.declare(declared, in);
        if (!declared.decision.runs())
            continue;
        const std::string name = scene::passName(s.id);
        timer.begin(name);
        s.run(in);
        timer.end(name);
    }
    finish(settings, camera != nullptr, withSky, local);
    return {};
}

void LpvPass::inject(const LpvRsmInput& rsm, bool directed, const std::vector<LpvLocalInput>& local) {
    const int tiles = volumes_.cascades();
    const bool sun = rsm.position && rsm.tileSize > 0;
    injectedTexels_ = sun ? rsm.tileSize * rsm.tileSize : 0;
    for (const LpvLocalInput& l : local)
        injectedTexels_ += l.size * l.size * l.layers;
    const GLuint zero = 0;
    glClearNamedBufferData(volumes_.scales.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSumsBinding, volumes_.lpvSums.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kScalesBinding, volumes_.scales.id());

    // 1. The brightest texel per tile sets the fixed-point scale.
    for (const LpvLocalInput& l : local)
        localFluxMax(l);
    GLuint p = kernel(LpvKernel::FluxMax);
    glUseProgram(p);
    glBindTextureUnit(0, rsm.position);
    glBindTextureUnit(1, rsm.flux);
    glProgramUniform1i(p, loc(p, "uRsmPosition"), 0);
    glProgramUniform1i(p, loc(p, "uRsmFlux"), 1);
    if (sun)
        glDispatchCompute(groups(rsm.tileSize, 8), groups(rsm.tileSize, 8), GLuint(tiles));
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    // 2. VPLs into the fixed-point sums.
    p = kernel(LpvKernel::Inject);
    glUseProgram(p);
    setCascadeUniforms(p);
    glBindTextureUnit(2, rsm.normal);
    glProgramUniform1i(p, loc(p, "uRsmPosition"), 0);
    glProgramUniform1i(p, loc(p, "uRsmNormal"), 2);
    glProgramUniform1i(p, loc(p, "uRsmFlux"), 1);
    glProgramUniform1i(p, loc(p, "uTexelsPerTile"), injectedTexels_);
    glProgramUniform1i(p, loc(p, "uScaleSlot"), -1);
    glProgramUniform1f(p, loc(p, "uInjectionOffset"), injectionOffset_);
    glProgramUniform1i(p, loc(p, "uDirected"), directed ? 1 : 0);
    if (directed)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kNormalSumsBinding, volumes_.normalSums.id());
    if (sun)
        glDispatchCompute(groups(rsm.tileSize, 8), groups(rsm.tileSize, 8), GLuint(tiles));
    for (const LpvLocalInput& l : local)
        injectLocal(l, directed);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    // 3. Sums to floats: volume 0 and the accumulator both start as V_0.
    resolveSums(0, false, -1, 0);
    readIndex_ = 0;
    scaleSlot_ = 0;
}

void LpvPass::resolveSums(int destination, bool accumulate, int scaleSlot, int recordSlot) {
    const GLuint p = kernel(LpvKernel::Resolve);
    glUseProgram(p);
    setCascadeUniforms(p);
    glProgramUniform1i(p, loc(p, "uTexelsPerTile"), injectedTexels_);
    glProgramUniform1i(p, loc(p, "uAccumulate"), accumulate ? 1 : 0);
    glProgramUniform1i(p, loc(p, "uScaleSlot"), scaleSlot);
    glProgramUniform1i(p, loc(p, "uRecordSlot"), recordSlot);
    bindStepImages(destination);
    const int n = volumes_.gridSize();
    glDispatchCompute(groups(n, 4), groups(n, 4), groups(n * volumes_.cascades(), 4));
    glMemoryBarrier(kComputeResults);
}

void LpvPass::bindStepImages(int destination) const {
    if (volumes_.bands() == 3) {
        // Three bands: the interleaved volume (7 texels per cell) and band 2 of the accumulator.
        glBindImageTexture(0, volumes_.interleaved[std::size_t(destination)].id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                           GL_RGBA32F);
        for (int c = 0; c < 3; ++c)
            glBindImageTexture(GLuint(3 + c), volumes_.accumulator.channel[std::size_t(c)].id(), 0, GL_TRUE, 0,
                               GL_READ_WRITE, GL_RGBA32F);
        glBindImageTexture(6, volumes_.accumulatorHigh.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
        return;
    }
    for (int c = 0; c < 3; ++c) {
        glBindImageTexture(GLuint(c), volumes_.volume[std::size_t(destination)].channel[std::size_t(c)].id(), 0,
                           GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        glBindImageTexture(GLuint(3 + c), volumes_.accumulator.channel[std::size_t(c)].id(), 0, GL_TRUE, 0,
                           GL_READ_WRITE, GL_RGBA32F);
    }
}

// The GV from the views: the RSM's and the camera's surfels, each summed into
// its half of the fixed-point sums, merged by maximum into the GV volume.
void LpvPass::injectViews(const LpvRsmInput& rsm, const LpvCameraInput* camera) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kGvSumsBinding, volumes_.gvSums.id());
    GLuint p = kernel(LpvKernel::GvFromRsm);
    glUseProgram(p);
    setCascadeUniforms(p);
    std::array<float, 6> texelArea{};
    std::copy_n(rsm.texelArea.begin(), std::min<std::size_t>(rsm.texelArea.size(), 6), texelArea.begin());
    glProgramUniform1fv(p, loc(p, "uTexelArea"), 6, texelArea.data());
    glProgramUniform3fv(p, loc(p, "uToSun"), 1, glm::value_ptr(rsm.towardSun));
    glBindTextureUnit(0, rsm.position);
    glBindTextureUnit(2, rsm.normal);
    glProgramUniform1i(p, loc(p, "uRsmPosition"), 0);
    glProgramUniform1i(p, loc(p, "uRsmNormal"), 2);
    if (rsm.position && rsm.tileSize > 0)
        glDispatchCompute(groups(rsm.tileSize, 8), groups(rsm.tileSize, 8), GLuint(volumes_.cascades()));

    if (camera && camera->depth && camera->normal) {
        p = kernel(LpvKernel::GvFromCamera);
        glUseProgram(p);
        setCascadeUniforms(p);
        glBindTextureUnit(0, camera->depth);
        glBindTextureUnit(2, camera->normal);
        glProgramUniform1i(p, loc(p, "uDepth"), 0);
        glProgramUniform1i(p, loc(p, "uNormal"), 2);
        glProgramUniformMatrix4fv(p, loc(p, "uInvViewProj"), 1, GL_FALSE, glm::value_ptr(camera->inverseViewProj));
        glProgramUniform3fv(p, loc(p, "uCameraPos"), 1, glm::value_ptr(camera->position));
        glProgramUniform1f(p, loc(p, "uPixelAngle"), camera->pixelAngle);
        glProgramUniform1i(p, loc(p, "uStride"), gvCameraStride_);
        GLint w = 0, h = 0;
        glGetTextureLevelParameteriv(camera->depth, 0, GL_TEXTURE_WIDTH, &w);
        glGetTextureLevelParameteriv(camera->depth, 0, GL_TEXTURE_HEIGHT, &h);
        const int s = gvCameraStride_;
        glDispatchCompute(groups((w + s - 1) / s, 8), groups((h + s - 1) / s, 8), 1);
    }
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);

    p = kernel(LpvKernel::GvMerge);
    glUseProgram(p);
    setCascadeUniforms(p);
    glBindImageTexture(0, volumes_.geometry.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    if (volumes_.bands() == 3)
        glBindImageTexture(1, volumes_.geometryHigh.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    const int m = volumes_.gridSize() + 1;
    glDispatchCompute(groups(m, 4), groups(m, 4), groups(m * volumes_.cascades(), 4));
    glMemoryBarrier(kComputeResults);
}

void LpvPass::injectGeometry(const LpvRsmInput& rsm, const LpvCameraInput* camera,
                             const LpvSceneGeometry* sceneGeometry) {
    const int m = volumes_.gridSize() + 1;
    const std::size_t cells = std::size_t(m) * std::size_t(m) * std::size_t(m) * std::size_t(volumes_.cascades());
    sceneSurfels_ = 0;
    const bool three = volumes_.bands() == 3;
    if (sceneGeometry && sceneGeometry->windows.size() == cells &&
        (!three || sceneGeometry->windowsHigh.size() == 2 * cells)) {
        // The scene's GV, windowed on the CPU: uploaded as the merged volume (the
        // surfel sums stay cleared; nothing is injected or merged).
        glTextureSubImage3D(volumes_.geometry.id(), 0, 0, 0, 0, m, m, m * volumes_.cascades(), GL_RGBA, GL_FLOAT,
                            sceneGeometry->windows.data());
        if (three) // band 2, a GV cell's two texels side by side
            glTextureSubImage3D(volumes_.geometryHigh.id(), 0, 0, 0, 0, 2 * m, m, m * volumes_.cascades(), GL_RGBA,
                                GL_FLOAT, sceneGeometry->windowsHigh.data());
        sceneSurfels_ = std::max<std::size_t>(sceneGeometry->surfels, 1);
    } else {
        injectViews(rsm, camera);
    }
    // The GV on every cell face, for the compute gather.
    const GLuint p = kernel(LpvKernel::FaceBlocking);
    glUseProgram(p);
    setCascadeUniforms(p);
    glProgramUniform1i(p, loc(p, "uOcclusion"), 1);
    glBindTextureUnit(3, volumes_.geometry.id());
    glBindImageTexture(0, volumes_.faceBlocking.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    if (volumes_.bands() == 3) {
        glBindTextureUnit(5, volumes_.geometryHigh.id());
        glBindImageTexture(1, volumes_.faceBlockingHigh.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    }
    const int n = volumes_.gridSize();
    glDispatchCompute(groups(n, 4), groups(n, 4), groups(n * volumes_.cascades(), 4));
    glMemoryBarrier(kComputeResults);
    if (visibilityActive_)
        buildVisibility();
}

void LpvPass::buildVisibility() {
    // lpvref::VisibilitySettings' defaults: the CPU twin and the GPU read the same constants.
    const lpvref::VisibilitySettings constants;
    const GLuint p = kernel(LpvKernel::Visibility);
    glUseProgram(p);
    setCascadeUniforms(p);
    glProgramUniform1f(p, loc(p, "uMaxDistance"), constants.maxDistance);
    glProgramUniform1f(p, loc(p, "uClosedCoverage"), constants.closedCoverage);
    glBindTextureUnit(3, volumes_.geometry.id());
    glBindImageTexture(0, volumes_.visibility.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    const int n = volumes_.gridSize();
    glDispatchCompute(groups(n, 4), groups(n, 4), groups(n * volumes_.cascades(), 4));
    // The forward pass reads them with imageLoad.
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    visibilityReady_ = true;
}

void LpvPass::buildNormals(int dilation) {
    const int n = volumes_.gridSize();
    const GLuint gx = groups(n, 4), gz = groups(n * volumes_.cascades(), 4);
    GLuint p = kernel(LpvKernel::Normals);
    glUseProgram(p);
    setCascadeUniforms(p);
    glProgramUniform1i(p, loc(p, "uTexelsPerTile"), injectedTexels_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kNormalSumsBinding, volumes_.normalSums.id());
    glBindImageTexture(0, volumes_.normals[0].id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(gx, gx, gz);
    glMemoryBarrier(kComputeResults);
    normalsIndex_ = 0;
    p = kernel(LpvKernel::NormalsDilate);
    glUseProgram(p);
    setCascadeUniforms(p);
    for (int i = 0; i < dilation; ++i) {
        glBindTextureUnit(0, volumes_.normals[std::size_t(normalsIndex_)].id());
        glBindImageTexture(0, volumes_.normals[std::size_t(1 - normalsIndex_)].id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                           GL_RGBA32F);
        glDispatchCompute(gx, gx, gz);
        glMemoryBarrier(kComputeResults);
        normalsIndex_ = 1 - normalsIndex_;
    }
}

void LpvPass::injectSky(const LpvSkyInput& sky) {
    const GLuint p = kernel(LpvKernel::SkyInject);
    glUseProgram(p);
    setCascadeUniforms(p);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kScalesBinding, volumes_.scales.id());
    if (volumes_.bands() == 3) {
        // The injected volume is interleaved[0] (lpv_resolve.comp), band 2 of the accumulator beside it.
        glBindImageTexture(0, volumes_.interleaved[0].id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
        glBindImageTexture(6, volumes_.accumulatorHigh.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
    }
    for (int c = 0; c < 3; ++c) {
        if (volumes_.bands() == 2)
            glBindImageTexture(GLuint(c), volumes_.volume[0].channel[std::size_t(c)].id(), 0, GL_TRUE, 0,
                               GL_READ_WRITE, GL_RGBA32F);
        glBindImageTexture(GLuint(3 + c), volumes_.accumulator.channel[std::size_t(c)].id(), 0, GL_TRUE, 0,
                           GL_READ_WRITE, GL_RGBA32F);
    }
    glBindTextureUnit(0, sky.depth);
    glProgramUniform1i(p, loc(p, "uSkyDepth"), 0);
    glProgramUniform2fv(p, loc(p, "uSkyMin"), 1, glm::value_ptr(sky.min));
    glProgramUniform1f(p, loc(p, "uSkyTexel"), sky.texelSize);
    glProgramUniform1i(p, loc(p, "uSkySize"), sky.size);
    glProgramUniform1f(p, loc(p, "uSkyTop"), sky.top);
    glProgramUniform1f(p, loc(p, "uSkyBottom"), sky.bottom);
    glProgramUniform3fv(p, loc(p, "uSkyRadiance"), 1, glm::value_ptr(sky.radiance));
    glProgramUniform1i(p, loc(p, "uTexelsPerTile"), injectedTexels_);
    glProgramUniform1i(p, loc(p, "uScaleSlot"), 0);
    const int n = volumes_.gridSize();
    glDispatchCompute(groups(n, 8), groups(n, 8), GLuint(volumes_.cascades()));
    glMemoryBarrier(kComputeResults);
}

void LpvPass::bindStepSources(GLuint program, int source, bool occlusion) const {
    // Layout bindings: sources 0..2, the GV 3, the face blocking 4.
    for (int c = 0; c < 3; ++c)
        glBindTextureUnit(GLuint(c), volumes_.volume[std::size_t(source)].channel[std::size_t(c)].id());
    glBindTextureUnit(4, volumes_.faceBlocking.id());
    glBindTextureUnit(3, volumes_.geometry.id()); // uGv, layout binding 3
    glProgramUniform1i(program, loc(program, "uOcclusion"), occlusion ? 1 : 0);
    glProgramUniform1f(program, loc(program, "uOcclusionStrength"), occlusionStrength_);
    glProgramUniform1i(program, loc(program, "uTwoSidedOcclusion"), twoSidedOcclusion_ ? 1 : 0);
    const bool directed = normalsIndex_ >= 0;
    glBindTextureUnit(kNormalsUnit, directed ? volumes_.normals[std::size_t(normalsIndex_)].id() : 0);
    glProgramUniform1i(program, loc(program, "uDirected"), directed ? 1 : 0);
}

void LpvPass::deinterleave(int index) {
    const GLuint p = kernel(LpvKernel::Deinterleave);
    const int n = volumes_.gridSize(), k = volumes_.cascades();
    glUseProgram(p);
    glProgramUniform3i(p, loc(p, "uSize"), n, n, n * k);
    glBindTextureUnit(0, volumes_.interleaved[std::size_t(index)].id());
    for (int c = 0; c < 3; ++c)
        glBindImageTexture(GLuint(c), volumes_.volume[std::size_t(index)].channel[std::size_t(c)].id(), 0, GL_TRUE,
                           0, GL_WRITE_ONLY, GL_RGBA32F);
    glDispatchCompute(groups(n, 8), groups(n, 8), GLuint(n * k));
    glMemoryBarrier(kComputeResults);
}

void LpvPass::propagate(const LpvSettings& settings) {
    const int n = volumes_.gridSize(), k = volumes_.cascades();
    const GLuint gatherProgram = kernel(LpvKernel::ComputeGather);
    // Two bands build every variant's kernel (as before); three run the compute gather only.
    const GLuint scatterProgram = bands_ == 3 ? 0 : kernel(LpvKernel::ComputeScatter);
    const GLuint rasterProgram = bands_ == 3                                  ? 0
                                 : settings.variant == LpvVariant::RasterScatter ? kernel(LpvKernel::RasterScatter)
                                                                                 : kernel(LpvKernel::RasterGather);
    const bool raster = settings.variant == LpvVariant::RasterGather || settings.variant == LpvVariant::RasterScatter;
    if (raster) {
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glViewport(0, 0, n, n);
        glBindVertexArray(emptyVao_.id());
        // The accumulator (targets 3-5) always adds; scatter also adds into the step's result.
        for (GLuint b = 0; b < 6; ++b) {
            if (b >= 3 || settings.variant == LpvVariant::RasterScatter)
                glEnablei(GL_BLEND, b);
            else
                glDisablei(GL_BLEND, b);
        }
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE);
    }
    for (int step = 0; step < settings.propagationSteps; ++step) {
        const int read = readIndex_, write = 1 - readIndex_;
        // The cascades that still propagate are the first `active` (lpv.cascadeSteps);
        // the others keep their accumulator and are not dispatched.
        const int active = settings.cascadesAtStep(step, k);
        switch (settings.variant) {
        case LpvVariant::ComputeGather: {
            if (volumes_.bands() == 3) {
                // Three bands: every step reads an interleaved volume (injection wrote the first).
                glUseProgram(gatherProgram);
                setCascadeUniforms(gatherProgram);
                bindStepSources(gatherProgram, read, settings.occludesStep(step));
                glBindTextureUnit(0, volumes_.interleaved[std::size_t(read)].id());
                glBindTextureUnit(5, volumes_.faceBlockingHigh.id());
                bindStepImages(write);
                glDispatchCompute(groups(n, 32), groups(n, 8), GLuint(n * active));
                glMemoryBarrier(kComputeResults);
                break;
            }
            // The first step reads the injected per-channel volume and writes
            // the interleaved one the later steps read: no separate packing pass.
            const GLuint program = step == 0 ? kernel(LpvKernel::ComputeGatherFirst) : gatherProgram;
            glUseProgram(program);
            setCascadeUniforms(program);
            bindStepSources(program, read, settings.occludesStep(step));
            if (step > 0)
                glBindTextureUnit(0, volumes_.interleaved[std::size_t(read)].id());
            bindStepImages(write);
            glBindImageTexture(0, volumes_.interleaved[std::size_t(write)].id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                               GL_RGBA32F);
            // 32 x 8 cells per work group: llvmpipe runs a group per task, and
            // 4x fewer tasks than 8 x 8 measured faster (docs/lpv.md).
            glDispatchCompute(groups(n, 32), groups(n, 8), GLuint(n * active));
            glMemoryBarrier(kComputeResults);
            if (capture_ && step + 1 == std::clamp(capture_->step, 0, settings.propagationSteps))
                deinterleave(write); // the viewer reads the per-channel volume
            break;
        }
        case LpvVariant::ComputeScatter:
            glUseProgram(scatterProgram);
            setCascadeUniforms(scatterProgram);
            glProgramUniform1i(scatterProgram, loc(scatterProgram, "uScaleSlot"), scaleSlot_);
            bindStepSources(scatterProgram, read, settings.occludesStep(step));
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSumsBinding, volumes_.lpvSums.id());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kScalesBinding, volumes_.scales.id());
            glDispatchCompute(groups(n, 4), groups(n, 4), groups(n * active, 4));
            {
                // The next step's scale is recorded into the other slot, cleared first.
                const GLuint zero = 0;
                const GLintptr slotOffset = GLintptr(k * (2 - scaleSlot_)) * 4;
                glClearNamedBufferSubData(volumes_.scales.id(), GL_R32UI, slotOffset, GLsizeiptr(k) * 4,
                                          GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
            }
            glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
            resolveSums(write, true, scaleSlot_, 1 - scaleSlot_);
            scaleSlot_ = 1 - scaleSlot_;
            break;
        case LpvVariant::RasterGather:
        case LpvVariant::RasterScatter: {
            const GLuint fbo = volumes_.rasterTarget[std::size_t(write)].id();
            glBindFramebuffer(GL_FRAMEBUFFER, fbo);
            glUseProgram(rasterProgram);
            setCascadeUniforms(rasterProgram);
            bindStepSources(rasterProgram, read, settings.occludesStep(step));
            if (settings.variant == LpvVariant::RasterGather) {
                glDrawArraysInstanced(GL_TRIANGLES, 0, 3, n * active);
            } else {
                const float zero[] = {0.0f, 0.0f, 0.0f, 0.0f};
                for (GLint b = 0; b < 3; ++b)
                    glClearNamedFramebufferfv(fbo, GL_COLOR, b, zero);
                glDrawArrays(GL_POINTS, 0, n * n * n * active * 6);
            }
            break;
        }
        }
        readIndex_ = write;
        if (capture_ && capture_->step > 0)
            captureIfRequested(step + 1, readIndex_);
    }
    if (raster) {
        glDisable(GL_BLEND);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }
}

void LpvPass::bindForShading(const CachedProgram& shader, const scene::ParameterSet& params, const UnitAllocator& nextUnit) const {
    const GLuint program = shader.id();
    const int count = active_ ? volumes_.cascades() : 0;
    glProgramUniform1i(program, shader.uniform("uLpvCascadeCount"), count);
    const bool visibility = count > 0 && visibilityActive_ && visibilityReady_;
    glProgramUniform1i(program, shader.uniform("uLpvVisibility"), visibility ? 1 : 0);
    if (visibility) // an image unit: the fragment stage has no sampler unit left (docs/lpv.md)
        glBindImageTexture(kVisibilityImageUnit, volumes_.visibility.id(), 0, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA32F);
    static constexpr const char* kSamplers[] = {"uLpvAccumR", "uLpvAccumG", "uLpvAccumB"};
    for (int c = 0; c < 3; ++c) {
        // Samplers must name a 3D texture unit even when nothing reads them (count 0).
        const GLuint unit = nextUnit();
        glProgramUniform1i(program, shader.uniform(kSamplers[c]), GLint(unit));
        glBindTextureUnit(unit, count ? volumes_.accumulator.channel[std::size_t(c)].id() : 0);
    }
    if (count > 0 && volumes_.bands() == 3) { // lpv_lookup.glsl's band 2 (LPV_SH_BANDS 3)
        const GLuint unit = nextUnit();
        glProgramUniform1i(program, shader.uniform("uLpvAccumHigh"), GLint(unit));
        glBindTextureUnit(unit, volumes_.accumulatorHigh.id());
    }
    if (count == 0)
        return;
    std::array<glm::vec3, 6> origin{};
    std::array<float, 6> cellSize{};
    for (std::size_t k = 0; k < cascades_.size(); ++k) {
        origin[k] = cascades_[k].origin;
        cellSize[k] = cascades_[k].cellSize;
    }
    glProgramUniform1i(program, shader.uniform("uLpvGridSize"), volumes_.gridSize());
    glProgramUniform3fv(program, shader.uniform("uLpvOrigin"), 6, glm::value_ptr(origin[0]));
    glProgramUniform1fv(program, shader.uniform("uLpvCellSize"), 6, cellSize.data());
    glProgramUniform1f(program, shader.uniform("uLpvIntensity"), float(params.getFloat("lpv.intensity")));
    glProgramUniform1f(program, shader.uniform("uLpvBleedingDamping"), float(params.getFloat("lpv.bleedingDamping")));
    glProgramUniform1f(program, shader.uniform("uLpvLookupOffset"), float(params.getFloat("lpv.lookupOffset")));
    glProgramUniform1i(program, shader.uniform("uLpvBlendLevels"), params.getInt("lpv.cascadeBlendLevels"));
    glProgramUniform1f(program, shader.uniform("uLpvVisibilityBias"), float(params.getFloat("lpv.visibilityBias")));
}

std::array<std::vector<glm::vec4>, 3> LpvPass::readAccumulator(int cascade) const {
    std::array<std::vector<glm::vec4>, 3> out;
    if (!active_ || cascade < 0 || cascade >= volumes_.cascades())
        return out;
    const int n = volumes_.gridSize();
    for (int c = 0; c < 3; ++c)
        out[std::size_t(c)] = readVolumeBlock(volumes_.accumulator.channel[std::size_t(c)].id(), n, cascade * n);
    return out;
}

std::array<std::vector<std::array<float, 9>>, 3> LpvPass::readAccumulatorBands(int cascade) const {
    std::array<std::vector<std::array<float, 9>>, 3> out;
    if (!active_ || volumes_.bands() != 3 || cascade < 0 || cascade >= volumes_.cascades())
        return out;
    const int n = volumes_.gridSize();
    const std::size_t cells = std::size_t(n) * std::size_t(n) * std::size_t(n);
    // Band 2's four planes, side by side along x: read the cascade's block whole.
    std::vector<glm::vec4> high(4 * cells);
    glGetTextureSubImage(volumes_.accumulatorHigh.id(), 0, 0, 0, cascade * n, 4 * n, n, n, GL_RGBA, GL_FLOAT,
                         GLsizei(high.size() * sizeof(glm::vec4)), high.data());
    const auto low = readAccumulator(cascade);
    for (int c = 0; c < 3; ++c) {
        out[std::size_t(c)].resize(cells);
        for (std::size_t i = 0; i < cells; ++i) {
            const std::size_t x = i % std::size_t(n), row = i / std::size_t(n); // row = y + n z
            const glm::vec4 l = low[std::size_t(c)][i];
            const glm::vec4 h = high[row * 4 * std::size_t(n) + std::size_t(c) * std::size_t(n) + x];
            const float last = high[row * 4 * std::size_t(n) + 3 * std::size_t(n) + x][c];
            out[std::size_t(c)][i] = {l.x, l.y, l.z, l.w, h.x, h.y, h.z, h.w, last};
        }
    }
    return out;
}

std::vector<std::array<float, 9>> LpvPass::readGeometryVolumeBands(int cascade) const {
    if (!active_ || volumes_.bands() != 3 || cascade < 0 || cascade >= volumes_.cascades())
        return {};
    const int m = volumes_.gridSize() + 1;
    const std::size_t cells = std::size_t(m) * std::size_t(m) * std::size_t(m);
    std::vector<glm::vec4> high(2 * cells);
    glGetTextureSubImage(volumes_.geometryHigh.id(), 0, 0, 0, cascade * m, 2 * m, m, m, GL_RGBA, GL_FLOAT,
                         GLsizei(high.size() * sizeof(glm::vec4)), high.data());
    const std::vector<glm::vec4> low = readGeometryVolume(cascade);
    std::vector<std::array<float, 9>> out(cells);
    for (std::size_t i = 0; i < cells; ++i) {
        const glm::vec4 l = low[i], h = high[2 * i], last = high[2 * i + 1];
        out[i] = {l.x, l.y, l.z, l.w, h.x, h.y, h.z, h.w, last.x};
    }
    return out;
}

void LpvPass::setCapture(std::optional<LpvCaptureRequest> request) {
    capture_ = request;
    if (!capture_) {
        snapshot_.reset();
        captureCopy_ = {}; // a closed view keeps no GPU memory either
        captureGrid_ = 0;
    }
}

std::vector<LpvGridFrame> LpvPass::cascadeFrames() const {
    std::vector<LpvGridFrame> frames;
    if (!active_)
        return frames;
    for (const LpvCascade& c : cascades_)
        frames.push_back({c.origin, c.cellSize, volumes_.gridSize()});
    return frames;
}

void LpvPass::captureIfRequested(int step, int index) {
    // Three bands keep no per-channel step volumes: the viewer shows nothing for them yet.
    if (!capture_ || !active_ || bouncing_ || volumes_.bands() == 3)
        return;
    const int cascade = capture_->cascade;
    if (cascade < 0 || cascade >= volumes_.cascades())
        return;
    // A request past the last step shows the last one.
    if (step != std::clamp(capture_->step, 0, propagationSteps_))
        return;
    const int n = volumes_.gridSize();
    if (captureGrid_ != n) {
        for (Texture& t : captureCopy_) {
            t = createTexture(GL_TEXTURE_3D);
            glTextureStorage3D(t.id(), 1, GL_RGBA32F, n, n, n);
        }
        captureGrid_ = n;
    }
    // Image stores (compute) must land before the copy reads them.
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    for (std::size_t c = 0; c < 3; ++c) {
        glCopyImageSubData(volumes_.volume[std::size_t(index)].channel[c].id(), GL_TEXTURE_3D, 0, 0, 0, cascade * n,
                           captureCopy_[c].id(), GL_TEXTURE_3D, 0, 0, 0, 0, n, n, n);
        glCopyImageSubData(volumes_.accumulator.channel[c].id(), GL_TEXTURE_3D, 0, 0, 0, cascade * n,
                           captureCopy_[3 + c].id(), GL_TEXTURE_3D, 0, 0, 0, 0, n, n, n);
    }
    capturedStep_ = step;
}

void LpvPass::readCapture() {
    if (capturedStep_ < 0 || !capture_)
        return;
    const int n = volumes_.gridSize(), cascade = capture_->cascade;
    LpvSnapshot s;
    s.frame = {cascades_[std::size_t(cascade)].origin, cascades_[std::size_t(cascade)].cellSize, n};
    s.cascade = cascade;
    s.cascades = volumes_.cascades();
    s.step = capturedStep_;
    s.propagationSteps = propagationSteps_;
    for (std::size_t c = 0; c < 3; ++c) {
        s.stepVolume[c] = readVolumeBlock(captureCopy_[c].id(), n, 0);
        s.accumulatedToStep[c] = readVolumeBlock(captureCopy_[3 + c].id(), n, 0);
    }
    if (occlusion_)
        s.geometry = readGeometryVolume(cascade);
    snapshot_ = std::move(s);
}

std::vector<glm::vec4> LpvPass::readGeometryVolume(int cascade) const {
    if (!active_ || cascade < 0 || cascade >= volumes_.cascades())
        return {};
    const int m = volumes_.gridSize() + 1;
    return readVolumeBlock(volumes_.geometry.id(), m, cascade * m);
}

std::vector<glm::vec4> LpvPass::readVisibilityMoments(int cascade) const {
    if (!active_ || !volumes_.visibility || cascade < 0 || cascade >= volumes_.cascades())
        return {};
    const int n = volumes_.gridSize();
    std::vector<glm::vec4> v(std::size_t(3 * n) * std::size_t(n) * std::size_t(n));
    glGetTextureSubImage(volumes_.visibility.id(), 0, 0, 0, cascade * n, 3 * n, n, n, GL_RGBA, GL_FLOAT,
                         GLsizei(v.size() * sizeof(glm::vec4)), v.data());
    return v;
}

std::vector<DebugImage> LpvPass::debugImages() const {
    std::vector<DebugImage> images;
    if (!active_)
        return images;
    // Slices side by side (z left to right), y up; rgb = the DC coefficient per channel (or of the GV).
    auto sliceImage = [](std::string name, int size, const std::array<const std::vector<glm::vec4>*, 3>& channels) {
        DebugImage image{std::move(name), size * size, size, 4, {}};
        image.pixels.assign(std::size_t(image.width) * std::size_t(size) * 4, 0.0f);
        for (int z = 0; z < size; ++z)
            for (int y = 0; y < size; ++y)
                for (int x = 0; x < size; ++x) {
                    const std::size_t src = std::size_t(x + size * (y + size * z));
                    const std::size_t dst = (std::size_t(size - 1 - y) * std::size_t(image.width) +
                                             std::size_t(z * size + x)) * 4;
                    for (int c = 0; c < 3; ++c)
                        image.pixels[dst + std::size_t(c)] = (*channels[std::size_t(c)])[src].x;
                    image.pixels[dst + 3] = 1.0f;
                }
        return image;
    };
    for (int k = 0; k < volumes_.cascades(); ++k) {
        const auto accum = readAccumulator(k);
        images.push_back(sliceImage("lpv-" + std::to_string(k) + "-accum", volumes_.gridSize(),
                                    {&accum[0], &accum[1], &accum[2]}));
        const auto gv = readGeometryVolume(k);
        images.push_back(sliceImage("lpv-" + std::to_string(k) + "-gv", volumes_.gridSize() + 1, {&gv, &gv, &gv}));
    }
    return images;
}

void LpvPass::addGpuMemory(GpuMemoryLedger& ledger) const {
    volumes_.addGpuMemory(ledger);
    for (const Texture& t : captureCopy_)
        ledger.addTexture("lpv.captureCopy", t.id());
}

} // namespace lpv::renderer
