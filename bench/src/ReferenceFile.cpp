#include "lpv/bench/ReferenceFile.h"

#include "lpv/importers/ImageIO.h"

#include <algorithm>
#include <charconv>
#include <cstdio>

namespace lpv::bench {

namespace {

// A header value as a number; nullopt unless the whole text is one.
template <typename T> std::optional<T> headerNumber(const std::map<std::string, std::string>& attributes,
                                                  const char* key) {
    const auto it = attributes.find(key);
    if (it == attributes.end())
        return std::nullopt;
    const std::string& text = it->second;
    T value{};
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size())
        return std::nullopt;
    return value;
}

} // namespace

scene::Expected<void> writeReferenceExr(const std::filesystem::path& file,
                                        const reference::ReferenceImage& image,
                                        const std::map<std::string, std::string>& attributes) {
    const auto channels = reference::toChannels(image);
    importers::FloatChannels out;
    out.width = image.width;
    out.height = image.height;
    const std::size_t n = image.pixelCount();
    out.pixels.resize(n * channels.size());
    for (std::size_t c = 0; c < channels.size(); ++c) {
        out.names.push_back(channels[c].name);
        for (std::size_t i = 0; i < n; ++i)
            out.pixels[i * channels.size() + c] = channels[c].values[i];
    }
    return importers::writeImageChannels(file, out, {attributes.begin(), attributes.end()});
}

scene::Expected<LoadedReference> readReferenceExr(const std::filesystem::path& file) {
    auto in = importers::readImageChannels(file);
    if (!in)
        return std::unexpected(in.error());
    const std::size_t n = std::size_t(in->width) * std::size_t(in->height);
    const std::size_t stride = in->names.size();
    if (std::ranges::find(in->names, "indirect.R") == in->names.end())
        return scene::makeError(scene::ErrorCode::MissingField, file.string(), "channel indirect.R",
                                "not a reference image (write one with `lpv reference`)");
    std::vector<reference::Channel> channels;
    for (std::size_t c = 0; c < stride; ++c) {
        reference::Channel ch{in->names[c], std::vector<float>(n)};
        for (std::size_t i = 0; i < n; ++i)
            ch.values[i] = in->pixels[i * stride + c];
        channels.push_back(std::move(ch));
    }
    LoadedReference out;
    reference::fromChannels(channels, in->width, in->height, out.image);
    for (const auto& [k, v] : in->attributes)
        out.attributes[k] = v;
    out.image.samplesPerPixel = headerNumber<int>(out.attributes, "lpv:spp").value_or(0);
    out.image.seconds = headerNumber<double>(out.attributes, "lpv:seconds").value_or(0.0);
    return out;
}

std::optional<int> LoadedReference::bounces() const {
    return headerNumber<int>(attributes, "lpv:bounces");
}

std::string describeReferenceFile(const std::filesystem::path& file) {
    const auto ref = readReferenceExr(file);
    if (!ref)
        return "unreadable";
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.1f", ref->image.seconds);
    return std::to_string(ref->image.width) + "x" + std::to_string(ref->image.height) + ", " +
           std::to_string(ref->image.samplesPerPixel) + " spp in " + seconds + " s";
}

scene::Expected<RgbImage> readRgbExr(const std::filesystem::path& file) {
    auto in = importers::readImageChannels(file);
    if (!in)
        return std::unexpected(in.error());
    auto index = [&](const char* name) {
        return int(std::ranges::find(in->names, name) - in->names.begin());
    };
    const int r = index("R"), g = index("G"), b = index("B");
    if (r >= int(in->names.size()) || g >= int(in->names.size()) || b >= int(in->names.size()))
        return scene::makeError(scene::ErrorCode::MissingField, file.string(), "channels R, G, B",
                                "the image has no R, G and B channels");
    RgbImage out;
    out.width = in->width;
    out.height = in->height;
    const std::size_t n = std::size_t(in->width) * std::size_t(in->height), stride = in->names.size();
    out.pixels.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        out.pixels[i] = {in->pixels[i * stride + std::size_t(r)], in->pixels[i * stride + std::size_t(g)],
                         in->pixels[i * stride + std::size_t(b)]};
    for (const auto& [k, v] : in->attributes)
        if (k == "lpv:outputView")
            out.outputView = v;
    return out;
}

} // namespace lpv::bench
