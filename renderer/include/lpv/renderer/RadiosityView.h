#pragma once
// Draws a radiosity solution as it is: each patch's radiance (or unshot /
// shot radiance), smoothed to the corners, optionally with Cohen's ambient
// term and the patch wireframe, tonemapped like the forward renderer (ACES,
// output.exposure). Used by `lpv radiosity --image` and the tests; the
// forward renderer shows a solution as its indirect light with gi.method =
// radiosity (the radiosityIndirect pass, docs/renderer.md).
#include "lpv/radiosity/PatchMesh.h"
#include "lpv/renderer/GlHandle.h"
#include "lpv/scene/Camera.h"
#include "lpv/scene/Error.h"

#include <cstdint>
#include <span>
#include <vector>

namespace lpv::renderer {

class RadiosityView {
  public:
    static scene::Expected<RadiosityView> create();

    // Uploads the patches with one value per patch (radiance to show).
    void setPatches(const radiosity::PatchMesh& mesh, std::span<const glm::vec3> perPatch, bool smooth);

    // Renders into the internal RGBA8 target (sRGB-encoded) and an RGBA32F
    // target of linear radiance.
    void render(const scene::Camera& camera, int width, int height, float exposureEv, bool wireframe);

    // Rows top to bottom, RGBA8.
    std::vector<std::uint8_t> readDisplay() const;
    // Rows top to bottom, RGBA32F: radiance (W/(m^2 sr)) at each pixel centre, 0 where no patch.
    std::vector<float> readRadiance() const;
    void blitTo(GLuint framebuffer, int width, int height) const;

  private:
    RadiosityView() = default;
    Program program_;
    Buffer triangles_;
    Buffer lines_;
    VertexArray triangleVao_;
    VertexArray lineVao_;
    GLsizei triangleVertices_ = 0;
    GLsizei lineVertices_ = 0;
    Texture color_;
    Texture radiance_;
    Texture depth_;
    Framebuffer fbo_;
    int width_ = 0;
    int height_ = 0;
};

} // namespace lpv::renderer
