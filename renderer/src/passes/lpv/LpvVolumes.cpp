#include "passes/lpv/LpvVolumes.h"

#include "frame/FrameResources.h"
#include "gl/GpuMemoryLedger.h"

#include <algorithm>
#include <string>

namespace lpv::renderer {

using scene::ErrorCode;
using scene::makeError;

namespace {

constexpr std::size_t kTexelBytes = 16; // RGBA32F

Texture makeVolume(int w, int h, int d) {
    Texture t = createTexture(GL_TEXTURE_3D);
    glTextureStorage3D(t.id(), 1, GL_RGBA32F, w, h, d);
    // Linear for the lookup's trilinear sample; the passes use texelFetch.
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTextureParameteri(t.id(), wrap, GL_CLAMP_TO_EDGE);
    return t;
}

Buffer makeZeroBuffer(std::size_t bytes) {
    Buffer b = createBuffer();
    glNamedBufferStorage(b.id(), GLsizeiptr(bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
    const GLuint zero = 0;
    glClearNamedBufferData(b.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    return b;
}

std::string mib(std::size_t bytes) { return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MiB"; }

} // namespace

std::size_t LpvVolumes::allocatedBytes() const {
    const std::size_t n = std::size_t(gridSize_), k = std::size_t(cascades_), m = n + 1;
    if (n == 0)
        return 0;
    const std::size_t directed = normals[0] ? 2 * n * n * n * k * kTexelBytes + 4 * n * n * n * k * 4 : 0;
    const std::size_t bounces = bounceTotal.channel[0] ? 3 * n * n * n * k * kTexelBytes : 0;
    const std::size_t planes = bands_ == 3 ? 7 : 3;
    const std::size_t interleavedBytes = interleaved[0] ? 2 * planes * n * n * n * k * kTexelBytes : 0;
    const std::size_t visibilityBytes = visibility ? 3 * n * n * n * k * kTexelBytes : 0;
    if (bands_ == 3) // the accumulator (3 + 4 planes), the face blocking (3 + 6), the GV (1 + 2), the sums
        return 16 * n * n * n * k * kTexelBytes + 3 * m * m * m * k * kTexelBytes + 27 * n * n * n * k * 4 +
               18 * m * m * m * k * 4 + 3 * k * 4 + directed + interleavedBytes;
    return 12 * n * n * n * k * kTexelBytes + m * m * m * k * kTexelBytes + 12 * n * n * n * k * 4 +
           8 * m * m * m * k * 4 + 3 * k * 4 + directed + bounces + interleavedBytes +
           visibilityBytes;
}

void LpvVolumes::ensureDirected(bool directed) {
    if (!directed || gridSize_ == 0) {
        for (Texture& t : normals)
            t.reset();
        normalSums.reset();
        return;
    }
    if (normals[0])
        return;
    for (Texture& t : normals)
        t = makeVolume(gridSize_, gridSize_, gridSize_ * cascades_);
    normalSums = makeZeroBuffer(4 * std::size_t(gridSize_) * std::size_t(gridSize_) * std::size_t(gridSize_) *
                                std::size_t(cascades_) * 4);
}

void LpvVolumes::ensureBounces(bool bounces) {
    if (!bounces || gridSize_ == 0) {
        for (Texture& t : bounceTotal.channel)
            t.reset();
        return;
    }
    if (bounceTotal.channel[0])
        return;
    for (Texture& t : bounceTotal.channel)
        t = makeVolume(gridSize_, gridSize_, gridSize_ * cascades_);
}

void LpvVolumes::ensureInterleaved(bool wanted) {
    if (!wanted || gridSize_ == 0) {
        for (Texture& t : interleaved)
            t.reset();
        return;
    }
    if (interleaved[0])
        return;
    const int planes = bands_ == 3 ? 7 : 3;
    for (Texture& t : interleaved)
        t = makeVolume(planes * gridSize_, gridSize_, gridSize_ * cascades_);
}

bool LpvVolumes::ensureVisibility(bool on) {
    if (!on || gridSize_ == 0) {
        visibility.reset();
        return false;
    }
    if (visibility)
        return false;
    visibility = makeVolume(3 * gridSize_, gridSize_, gridSize_ * cascades_);
    return true;
}

void LpvVolumes::release() {
    for (auto& set : volume)
        for (Texture& t : set.channel)
            t.reset();
    for (Texture& t : accumulator.channel)
        t.reset();
    geometry.reset();
    faceBlocking.reset();
    lpvSums.reset();
    gvSums.reset();
    scales.reset();
    for (Framebuffer& f : rasterTarget)
        f.reset();
    for (Texture& t : normals)
        t.reset();
    normalSums.reset();
    for (Texture& t : bounceTotal.channel)
        t.reset();
    for (Texture& t : interleaved)
        t.reset();
    visibility.reset();
    accumulatorHigh.reset();
    geometryHigh.reset();
    faceBlockingHigh.reset();
    gridSize_ = cascades_ = 0;
    bands_ = 2;
    ++generation_;
}

scene::Expected<void> LpvVolumes::ensure(int gridSize, int cascades, int bands) {
    if (gridSize == gridSize_ && cascades == cascades_ && bands == bands_)
        return {};
    release();
    const std::size_t n = std::size_t(gridSize), k = std::size_t(cascades), m = n + 1;
    GLint max3d = 0, maxBlock = 0;
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3d);
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
    const std::string layout = std::to_string(cascades) + " cascades of " + std::to_string(gridSize) + "^3";
    // The tallest texture is the stacked GV, the widest the face blocking (3N;
    // three bands: the interleaved volumes, 7N).
    const bool three = bands == 3;
    const std::size_t largestSide = std::max(m * k, (three ? 7 : 3) * n);
    if (std::size_t(max3d) < largestSide)
        return makeError(ErrorCode::OutOfRange, "render", "parameters.lpv.gridSize",
                         layout + " need " + std::to_string(largestSide) + " texels on a side, over GL_MAX_3D_TEXTURE_SIZE " +
                             std::to_string(max3d) + "; lower lpv.gridSize or lpv.cascades");
    const std::size_t coeffs = three ? 9 : 4;
    const std::size_t sumBytes = 3 * coeffs * n * n * n * k * 4, gvBytes = 2 * coeffs * m * m * m * k * 4;
    if (sumBytes > std::size_t(GLuint(maxBlock)) || gvBytes > std::size_t(GLuint(maxBlock)))
        return makeError(ErrorCode::OutOfRange, "render", "parameters.lpv.gridSize",
                         layout + " need a " + mib(std::max(sumBytes, gvBytes)) +
                             " storage buffer, over GL_MAX_SHADER_STORAGE_BLOCK_SIZE " +
                             mib(std::size_t(GLuint(maxBlock))) + "; lower lpv.gridSize or lpv.cascades");
    while (glGetError() != GL_NO_ERROR) {
    } // an earlier error must not be blamed on this allocation
    for (Texture& t : accumulator.channel)
        t = makeVolume(gridSize, gridSize, gridSize * cascades);
    geometry = makeVolume(int(m), int(m), int(m * k));
    faceBlocking = makeVolume(3 * gridSize, gridSize, gridSize * cascades);
    lpvSums = makeZeroBuffer(sumBytes);
    gvSums = makeZeroBuffer(gvBytes);
    scales = makeZeroBuffer(k * 3 * 4);
    if (three) {
        accumulatorHigh = makeVolume(4 * gridSize, gridSize, gridSize * cascades);
        geometryHigh = makeVolume(2 * int(m), int(m), int(m * k));
        faceBlockingHigh = makeVolume(6 * gridSize, gridSize, gridSize * cascades);
    } else {
        for (auto& set : volume)
            for (Texture& t : set.channel)
                t = makeVolume(gridSize, gridSize, gridSize * cascades);
    }
    for (int i = 0; i < 2 && !three; ++i) {
        rasterTarget[std::size_t(i)] = createFramebuffer();
        const GLuint fbo = rasterTarget[std::size_t(i)].id();
        for (int c = 0; c < 3; ++c) {
            glNamedFramebufferTexture(fbo, GLenum(GL_COLOR_ATTACHMENT0 + c), volume[std::size_t(i)].channel[std::size_t(c)].id(), 0);
            glNamedFramebufferTexture(fbo, GLenum(GL_COLOR_ATTACHMENT3 + c), accumulator.channel[std::size_t(c)].id(), 0);
        }
        const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                                  GL_COLOR_ATTACHMENT3, GL_COLOR_ATTACHMENT4, GL_COLOR_ATTACHMENT5};
        glNamedFramebufferDrawBuffers(fbo, 6, buffers);
    }
    gridSize_ = gridSize;
    cascades_ = cascades;
    bands_ = bands;
    if (glGetError() == GL_OUT_OF_MEMORY) {
        const std::size_t bytes = allocatedBytes();
        release();
        return makeError(ErrorCode::OutOfRange, "render", "parameters.lpv.gridSize",
                         "the GPU ran out of memory allocating " + layout + " (" + mib(bytes) +
                             "); lower lpv.gridSize or lpv.cascades");
    }
    return {};
}

void LpvVolumes::addGpuMemory(GpuMemoryLedger& ledger) const {
    auto addSet = [&](std::string_view name, const LpvVolumeSet& set) {
        for (const Texture& t : set.channel)
            ledger.addTexture(name, t.id());
    };
    for (const LpvVolumeSet& set : volume)
        addSet(resources::LpvVolumes.name(), set);
    addSet(resources::LpvAccumulator.name(), accumulator);
    ledger.addTexture(resources::LpvGeometry.name(), geometry.id());
    ledger.addTexture("lpv.faceBlocking", faceBlocking.id());
    ledger.addBuffer("lpv.lpvSums", lpvSums.id());
    ledger.addBuffer("lpv.gvSums", gvSums.id());
    ledger.addBuffer("lpv.scales", scales.id());
    for (const Texture& t : normals)
        ledger.addTexture(resources::LpvNormals.name(), t.id());
    ledger.addBuffer("lpv.normalSums", normalSums.id());
    addSet("lpv.bounceTotal", bounceTotal);
    for (const Texture& t : interleaved)
        ledger.addTexture("lpv.interleaved", t.id());
    ledger.addTexture("lpv.visibility", visibility.id());
    ledger.addTexture("lpv.accumulatorHigh", accumulatorHigh.id());
    ledger.addTexture("lpv.geometryHigh", geometryHigh.id());
    ledger.addTexture("lpv.faceBlockingHigh", faceBlockingHigh.id());
}

} // namespace lpv::renderer
