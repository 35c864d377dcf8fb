#include "lpv/renderer/GpuHemicube.h"

#include "lpv/radiosity/Hemicube.h"
#include "lpv/renderer/ShaderLibrary.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace lpv::renderer {
namespace {

struct HemicubeVertex {
    glm::vec3 position;
    std::uint32_t patch;
};

constexpr double kFixedPointScale = 2147483648.0; // 2^31, as in hemicube_accumulate.comp

// Any unit vector perpendicular to n.
glm::vec3 perpendicular(const glm::vec3& n) {
    const glm::vec3 a = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    return glm::normalize(glm::cross(n, a));
}

} // namespace

GpuHemicube::~GpuHemicube() = default;

scene::Expected<std::unique_ptr<GpuHemicube>> GpuHemicube::create(const radiosity::PatchMesh& mesh,
                                                                  int resolution, int maxBatch) {
    std::unique_ptr<GpuHemicube> h(new GpuHemicube());
    h->mesh_ = &mesh;
    h->resolution_ = std::max(2, (resolution + 1) / 2 * 2);
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
    GLint maxFbHeight = 0;
    glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &maxFbHeight);
    const int limit = std::min(maxSize, maxFbHeight);
    if (3 * h->resolution_ > limit)
        return scene::makeError(scene::ErrorCode::OutOfRange, "", "radiosity.hemicubeResolution",
                                "a hemicube of " + std::to_string(h->resolution_) + " px needs textures " +
                                    std::to_string(3 * h->resolution_) + " wide; this GPU allows " +
                                    std::to_string(limit));
    h->maxBatch_ = std::clamp(maxBatch, 1, std::max(1, limit / h->resolution_));

    auto raster = buildEmbeddedProgram({"hemicube.vert", "hemicube.frag"});
    if (!raster)
        return std::unexpected(raster.error());
    auto accumulate = buildEmbeddedProgram({"hemicube_accumulate.comp"});
    if (!accumulate)
        return std::unexpected(accumulate.error());
    h->raster_ = std::move(*raster);
    h->accumulate_ = std::move(*accumulate);

    // Every patch as its own triangles (IDs are per vertex, so no sharing),
    // in Morton order of their centres, cut into clusters for culling.
    scene::Bounds bounds;
    for (const radiosity::Patch& p : mesh.patches)
        for (int k = 0; k < p.cornerCount; ++k)
            bounds.extend(p.corners[std::size_t(k)]);
    if (!bounds.empty()) {
        const glm::vec3 c = bounds.center();
        if (std::max({std::abs(c.x), std::abs(c.y), std::abs(c.z)}) > glm::length(bounds.size()))
            h->frame_ = c;
    }
    const glm::vec3 frame = h->frame_;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> order;
    order.reserve(mesh.size());
    // A float guard only (a flat axis divides): the Morton order needs no length.
    const glm::vec3 size = glm::max(bounds.size(), glm::vec3(std::numeric_limits<float>::min()));
    for (std::uint32_t i = 0; i < mesh.size(); ++i) {
        const glm::vec3 q = glm::clamp((mesh.patches[i].center - bounds.min) / size, 0.0f, 1.0f) * 1023.0f;
        std::uint64_t code = 0;
        for (int b = 9; b >= 0; --b)
            code = (code << 3) | (std::uint64_t((std::uint32_t(q.x) >> b) & 1u) << 2) |
                   (std::uint64_t((std::uint32_t(q.y) >> b) & 1u) << 1) |
                   std::uint64_t((std::uint32_t(q.z) >> b) & 1u);
        order.emplace_back(code, i);
    }
    std::sort(order.begin(), order.end());
    constexpr std::size_t kClusterPatches = 256;
    std::vector<HemicubeVertex> verts;
    verts.reserve(mesh.size() * 6);
    for (std::size_t start = 0; start < order.size(); start += kClusterPatches) {
        Cluster cluster;
        cluster.first = GLint(verts.size());
        scene::Bounds cb;
        for (std::size_t k = start; k < std::min(order.size(), start + kClusterPatches); ++k) {
            const std::uint32_t i = order[k].second;
            const radiosity::Patch& p = mesh.patches[i];
            std::array<glm::vec3, 4> c{};
            for (int j = 0; j < p.cornerCount; ++j)
                c[std::size_t(j)] = p.corners[std::size_t(j)] - frame;
            verts.push_back({c[0], i});
            verts.push_back({c[1], i});
            verts.push_back({c[2], i});
            if (p.cornerCount == 4) {
                verts.push_back({c[0], i});
                verts.push_back({c[2], i});
                verts.push_back({c[3], i});
            }
            for (int j = 0; j < p.cornerCount; ++j)
                cb.extend(c[std::size_t(j)]);
        }
        cluster.count = GLsizei(verts.size()) - cluster.first;
        cluster.min = cb.min;
        cluster.max = cb.max;
        h->clusters_.push_back(cluster);
    }
    // A float guard only: a mesh of one point has no extent to scale with.
    const float diagonal = bounds.empty() ? 0.0f : glm::length(bounds.size());
    const float extent = diagonal > 0.0f && std::isfinite(diagonal) ? diagonal : 1.0f;
    // The near plane must be closer than the thinnest gap the scene has (the
    // Cornell light hangs 1 mm under the ceiling, 0.2% of the box).
    h->near_ = extent * 1e-5f;
    h->far_ = extent * 2.0f;
    h->vertexCount_ = GLsizei(verts.size());
    h->vertices_ = createBuffer();
    glNamedBufferStorage(h->vertices_.id(),
                         GLsizeiptr(std::max<std::size_t>(verts.size(), 1) * sizeof(HemicubeVertex)),
                         verts.empty() ? nullptr : verts.data(), 0);
    h->vao_ = createVertexArray();
    const GLuint vao = h->vao_.id();
    glVertexArrayVertexBuffer(vao, 0, h->vertices_.id(), 0, sizeof(HemicubeVertex));
    glEnableVertexArrayAttrib(vao, 0);
    glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE, offsetof(HemicubeVertex, position));
    glVertexArrayAttribBinding(vao, 0, 0);
    glEnableVertexArrayAttrib(vao, 1);
    glVertexArrayAttribIFormat(vao, 1, 1, GL_UNSIGNED_INT, offsetof(HemicubeVertex, patch));
    glVertexArrayAttribBinding(vao, 1, 0);

    const int w = 3 * h->resolution_, hgt = h->resolution_ * h->maxBatch_;
    h->ids_ = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(h->ids_.id(), 1, GL_R32UI, w, hgt);
    h->depth_ = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(h->depth_.id(), 1, GL_DEPTH_COMPONENT32F, w, hgt);
    h->fbo_ = createFramebuffer();
    glNamedFramebufferTexture(h->fbo_.id(), GL_COLOR_ATTACHMENT0, h->ids_.id(), 0);
    glNamedFramebufferTexture(h->fbo_.id(), GL_DEPTH_ATTACHMENT, h->depth_.id(), 0);
    if (glCheckNamedFramebufferStatus(h->fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        return scene::makeError(scene::ErrorCode::InvalidValue, "", "radiosity",
                                "the hemicube framebuffer (R32UI + depth) is incomplete");

    const std::vector<float> dff = radiosity::deltaFormFactors(h->resolution_);
    h->deltaFF_ = createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(h->deltaFF_.id(), 1, GL_R32F, w, h->resolution_);
    glTextureSubImage2D(h->deltaFF_.id(), 0, 0, 0, w, h->resolution_, GL_RED, GL_FLOAT, dff.data());
    for (GLuint t : {h->ids_.id(), h->deltaFF_.id()}) {
        glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }

    h->sums_ = createBuffer();
    glNamedBufferStorage(h->sums_.id(),
                         GLsizeiptr(std::max<std::size_t>(mesh.size(), 1) * std::size_t(h->maxBatch_) * 4),
                         nullptr, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
    return h;
}

void GpuHemicube::renderShooter(const radiosity::Patch& shooter, int row) const {
    const glm::vec3 n = shooter.normal;
    const glm::vec3 t = perpendicular(n);
    const glm::vec3 b = glm::cross(n, t);
    // Just off the surface, so the shooter's own plane falls behind the near
    // plane, and past the float rounding of the patch's world position (8 mm
    // 100 km out), which may have put its centre behind its own wall.
    const glm::vec3& c = shooter.center;
    const float rounding = 2.0f * std::numeric_limits<float>::epsilon() *
                           std::max({std::abs(c.x), std::abs(c.y), std::abs(c.z)});
    const glm::vec3 eye = (c - frame_) + n * std::max(near_ * 0.5f, rounding);
    const radiosity::HemicubeLayout layout{resolution_};
    const GLint loc = glGetUniformLocation(raster_.id(), "uViewProj");
    for (const radiosity::HemicubeFace& face : layout.faces()) {
        const glm::vec3 forward = face.forward.x * t + face.forward.y * b + face.forward.z * n;
        const glm::vec3 up = face.up.x * t + face.up.y * b + face.up.z * n;
        const glm::mat4 view = glm::lookAt(eye, eye + forward, up);
        // 90-degree frustum; side faces keep only the half above the horizon.
        // Reversed depth (near -> 1, far -> 0) into a float buffer keeps the
        // relative precision constant, so a near plane 1e-5 of the scene does
        // not cost the far walls their depth resolution.
        glm::mat4 reverse(1.0f);
        reverse[2][2] = -1.0f;
        reverse[3][2] = 1.0f;
        const glm::mat4 proj =
            reverse * glm::frustumRH_ZO(-near_, near_, face.side ? 0.0f : -near_, near_, near_, far_);
        const glm::mat4 viewProj = proj * view;
        glProgramUniformMatrix4fv(raster_.id(), loc, 1, GL_FALSE, glm::value_ptr(viewProj));
        glViewport(face.x, row * resolution_ + face.y, face.width, face.height);
        // Frustum planes (Gribb-Hartmann) in clip space -w<=x,y<=w, 0<=z<=w.
        std::array<glm::vec4, 6> planes;
        const glm::vec4 r0(viewProj[0][0], viewProj[1][0], viewProj[2][0], viewProj[3][0]);
        const glm::vec4 r1(viewProj[0][1], viewProj[1][1], viewProj[2][1], viewProj[3][1]);
        const glm::vec4 r2(viewProj[0][2], viewProj[1][2], viewProj[2][2], viewProj[3][2]);
        const glm::vec4 r3(viewProj[0][3], viewProj[1][3], viewProj[2][3], viewProj[3][3]);
        planes = {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r2, r3 - r2};
        firsts_.clear();
        counts_.clear();
        for (const Cluster& cluster : clusters_) {
            bool outside = false;
            for (const glm::vec4& pl : planes) {
                const glm::vec3 far(pl.x >= 0 ? cluster.max.x : cluster.min.x,
                                    pl.y >= 0 ? cluster.max.y : cluster.min.y,
                                    pl.z >= 0 ? cluster.max.z : cluster.min.z);
                if (glm::dot(glm::vec3(pl), far) + pl.w < 0.0f) {
                    outside = true;
                    break;
                }
            }
            if (outside)
                continue;
            // Neighbouring clusters merge into one range.
            if (!firsts_.empty() && firsts_.back() + counts_.back() == cluster.first)
                counts_.back() += cluster.count;
            else {
                firsts_.push_back(cluster.first);
                counts_.push_back(cluster.count);
            }
        }
        if (!firsts_.empty())
            glMultiDrawArrays(GL_TRIANGLES, firsts_.data(), counts_.data(), GLsizei(firsts_.size()));
    }
}

scene::Expected<void> GpuHemicube::compute(std::span<const std::uint32_t> shooters,
                                           std::vector<float>& factors) {
    const std::size_t n = mesh_->size();
    factors.assign(shooters.size() * n, 0.0f);
    for (std::size_t first = 0; first < shooters.size(); first += std::size_t(maxBatch_)) {
        const int count = int(std::min<std::size_t>(std::size_t(maxBatch_), shooters.size() - first));
        const GLuint zero = 0;
        const float farDepth = 0.0f;
        glClearNamedFramebufferuiv(fbo_.id(), GL_COLOR, 0, &zero);
        glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &farDepth);
        glClearNamedBufferSubData(sums_.id(), GL_R32UI, 0, GLsizeiptr(n * std::size_t(count) * 4),
                                  GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);

        glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_GREATER);
        glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
        glDepthMask(GL_TRUE);
        glDisable(GL_CULL_FACE); // back faces must occlude
        glDisable(GL_BLEND);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glUseProgram(raster_.id());
        glBindVertexArray(vao_.id());
        for (int s = 0; s < count; ++s)
            renderShooter(mesh_->patches[shooters[first + std::size_t(s)]], s);
        glBindVertexArray(0);
        glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
        glDepthFunc(GL_LESS);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);

        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
        glUseProgram(accumulate_.id());
        glProgramUniform1ui(accumulate_.id(), glGetUniformLocation(accumulate_.id(), "uPatchCount"),
                            GLuint(n));
        glProgramUniform1i(accumulate_.id(), glGetUniformLocation(accumulate_.id(), "uResolution"),
                           resolution_);
        glProgramUniform1i(accumulate_.id(), glGetUniformLocation(accumulate_.id(), "uShooters"), count);
        glBindTextureUnit(0, ids_.id());
        glBindTextureUnit(1, deltaFF_.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, sums_.id());
        glDispatchCompute(GLuint((3 * resolution_ + 15) / 16), GLuint((resolution_ * count + 15) / 16), 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        glUseProgram(0);

        std::vector<std::uint32_t> sums(n * std::size_t(count));
        if (!sums.empty())
            glGetNamedBufferSubData(sums_.id(), 0, GLsizeiptr(sums.size() * 4), sums.data());
        for (std::size_t k = 0; k < sums.size(); ++k)
            factors[first * n + k] = float(double(sums[k]) / kFixedPointScale);
        lastBatch_ = count;
    }
    if (const GLenum err = glGetError(); err != GL_NO_ERROR)
        return scene::makeError(scene::ErrorCode::InvalidValue, "", "radiosity",
                                "OpenGL error " + std::to_string(err) +
                                    " while computing hemicube form factors");
    return {};
}

std::vector<std::uint32_t> GpuHemicube::readHemicube(int index) const {
    if (index < 0 || index >= lastBatch_)
        return {};
    const int w = 3 * resolution_;
    std::vector<std::uint32_t> out(std::size_t(w * resolution_));
    glGetTextureSubImage(ids_.id(), 0, 0, index * resolution_, 0, w, resolution_, 1, GL_RED_INTEGER,
                         GL_UNSIGNED_INT, GLsizei(out.size() * 4), out.data());
    return out;
}

} // namespace lpv::renderer
