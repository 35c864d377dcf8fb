#pragma once
// Material textures on the GPU: full mip chains, trilinear filtering (plus
// anisotropic filtering where the driver has it, output.anisotropy), repeat wrapping. Colour
// textures are stored as sRGB so sampling returns linear values; data
// textures (normals, roughness, masks) are stored as they are.
#include "lpv/renderer/GlHandle.h"
#include "lpv/scene/Image.h"

#include <map>
#include <string>
#include <utility>

namespace lpv::renderer {

enum class TextureUsage {
    Color, // diffuse/base colour, emissive, specular colour: GL_SRGB8_ALPHA8
    Data,  // normal, height-derived normal, metallic-roughness, occlusion, alpha: GL_RGBA8
};

// One immutable 2D texture of `image` (rows top to bottom; uploaded flipped
// so that UV (0,0) is the image's bottom-left corner, the scene's convention).
Texture uploadTexture(const scene::Image8& image, TextureUsage usage);

// The driver's anisotropy limit; 1 without GL 4.6 or the anisotropic extensions.
float maxSupportedAnisotropy();

// Uploads each (image key, usage) once however many materials use it.
class TextureCache {
public:
    // The texture of `images[key]`, 0 when the key is empty or absent.
    GLuint get(const scene::TextureImages& images, const std::string& key, TextureUsage usage);
    std::size_t uploadedCount() const { return uploaded_.size(); }
    // Anisotropic filtering of every texture, clamped to 1..maxSupportedAnisotropy()
    // (cheap on GPUs; llvmpipe's textured frames take about 3x as long at 8x).
    void setAnisotropy(float samples);
    float anisotropy() const { return anisotropy_; }

private:
    float anisotropy_ = 1.0f;
    std::map<std::pair<std::string, TextureUsage>, Texture> uploaded_;
};

} // namespace lpv::renderer
