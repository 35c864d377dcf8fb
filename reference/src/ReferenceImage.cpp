#include "lpv/reference/ReferenceImage.h"

#include <map>

namespace lpv::reference {

void ReferenceImage::resize(int w, int h) {
    width = w;
    height = h;
    const std::size_t n = pixelCount();
    for (auto* v :
         {&image, &indirectOne, &indirectMulti, &imageVariance, &indirectOneVariance, &indirectMultiVariance})
        v->assign(n, glm::vec3(0.0f));
    coverage.assign(n, 0.0f);
}

namespace {

// Layer name prefix and the member it maps to, in file order.
template <class Image> auto layers(Image& r) {
    return std::vector<std::pair<std::string, decltype(&r.image)>>{
        {"", &r.image},
        {"indirect1.", &r.indirectOne},
        {"indirect.", &r.indirectMulti},
        {"variance.", &r.imageVariance},
        {"indirect1.variance.", &r.indirectOneVariance},
        {"indirect.variance.", &r.indirectMultiVariance},
    };
}

} // namespace

std::vector<Channel> toChannels(const ReferenceImage& r) {
    std::vector<Channel> out;
    const std::size_t n = r.pixelCount();
    for (const auto& [prefix, data] : layers(r))
        for (int c = 0; c < 3; ++c) {
            Channel ch{prefix + "RGB"[c], std::vector<float>(n)};
            for (std::size_t i = 0; i < n; ++i)
                ch.values[i] = (*data)[i][c];
            out.push_back(std::move(ch));
        }
    out.push_back(Channel{"coverage.Y", r.coverage});
    return out;
}

bool fromChannels(const std::vector<Channel>& channels, int width, int height, ReferenceImage& out) {
    out.resize(width, height);
    const std::size_t n = out.pixelCount();
    std::map<std::string, const std::vector<float>*> byName;
    for (const Channel& c : channels) {
        if (c.values.size() != n)
            return false;
        byName[c.name] = &c.values;
    }
    for (const auto& [prefix, data] : layers(out))
        for (int c = 0; c < 3; ++c)
            if (auto it = byName.find(prefix + "RGB"[c]); it != byName.end())
                for (std::size_t i = 0; i < n; ++i)
                    (*data)[i][c] = (*it->second)[i];
    if (auto it = byName.find("coverage.Y"); it != byName.end())
        out.coverage = *it->second;
    else
        out.coverage.assign(n, 1.0f);
    return true;
}

} // namespace lpv::reference
