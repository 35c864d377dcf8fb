#pragma once
// The first forward pass (issue #2): direct light with one shadow map for the
// first shadow-casting light, HDR accumulation, exposure and tonemapping to
// sRGB. Later passes (CSM, RSM, LPV) slot in around it.
#include "lpv/renderer/GpuTimer.h"
#include "lpv/renderer/SceneGpu.h"
#include "lpv/scene/ParameterRegistry.h"
#include "lpv/scene/Scene.h"

#include <memory>
#include <vector>

namespace lpv::renderer {

using scene::Expected;

class ForwardRenderer {
public:
    // Compiles every program; a shader that does not compile is an error value naming file and line.
    static Expected<ForwardRenderer> create();

    ForwardRenderer(ForwardRenderer&&) noexcept;
    ForwardRenderer& operator=(ForwardRenderer&&) noexcept;
    ~ForwardRenderer();

    // Uploads the scene's geometry; call again after the scene changes.
    void setScene(const scene::Scene& scene);

    // Renders one frame into the internal HDR and display targets.
    Expected<void> render(const scene::Scene& scene, const scene::ParameterSet& params, const scene::Camera& camera,
                          int width, int height);

    // Copies the last display image into `framebuffer` (e.g. a QOpenGLWidget's).
    void blitTo(GLuint framebuffer, int width, int height) const;

    // Read-backs for tests and PNG output: rows top to bottom, RGBA.
    std::vector<float> readHdr() const;
    std::vector<std::uint8_t> readDisplay() const;
    int width() const;
    int height() const;

    GpuTimer& timer();

private:
    ForwardRenderer();
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace lpv::renderer
