#include "passes/lpv/EmissiveVplBuffer.h"

#include <cmath>
#include <string>

namespace lpv::renderer {

void EmissiveVplBuffer::upload(const std::vector<lpvref::Vpl>& vpls) {
    count_ = int(vpls.size());
    size_ = count_ > 0 ? int(std::ceil(std::sqrt(double(count_)))) : 0;
    position_.reset();
    normal_.reset();
    flux_.reset();
    if (count_ == 0)
        return;
    const std::size_t texels = std::size_t(size_) * std::size_t(size_);
    std::vector<glm::vec4> p(texels, glm::vec4(0.0f)), n(texels, glm::vec4(0.0f)), f(texels, glm::vec4(0.0f));
    for (std::size_t i = 0; i < vpls.size(); ++i) {
        p[i] = glm::vec4(vpls[i].position, 1.0f);
        n[i] = glm::vec4(vpls[i].normal, 1.0f);
        f[i] = glm::vec4(vpls[i].flux, 1.0f);
    }
    auto make = [&](Texture& t, const std::vector<glm::vec4>& data) {
        t = createTexture(GL_TEXTURE_2D_ARRAY);
        glTextureStorage3D(t.id(), 1, GL_RGBA32F, size_, size_, 1);
        glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTextureSubImage3D(t.id(), 0, 0, 0, 0, size_, size_, 1, GL_RGBA, GL_FLOAT, data.data());
    };
    make(position_, p);
    make(normal_, n);
    make(flux_, f);
}

LpvLocalInput EmissiveVplBuffer::input() const {
    return {position_.id(), normal_.id(),       flux_.id(),
            size_,          count_ > 0 ? 1 : 0, std::to_string(count_) + " emissive VPLs"};
}

} // namespace lpv::renderer
