#include "lpv/importers/ImageIO.h"

#include "lpv/scene/FileRead.h"
#include "lpv/scene/ProcessId.h"
#include "lpv/scene/Project.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <atomic>

namespace lpv::importers {

using scene::ErrorCode;
using scene::makeError;

namespace {

// Formats whose writer cannot write to memory: written to a temporary file
// by OpenImageIO, then read back, synced and renamed. OpenImageIO's file
// writers do not report a failed write (a full disk gave "wrote out.png" and
// a 0-byte file), so the read-back is what proves the file whole.
scene::Expected<void> writeThroughTemporary(const std::filesystem::path& file, const OIIO::ImageSpec& spec,
                                            OIIO::TypeDesc type, const void* pixels) {
    static std::atomic<unsigned> counter{0};
    // The temporary keeps the real extension last so OpenImageIO picks the same format.
    std::filesystem::path tmp = file;
    tmp.replace_filename("." + file.stem().string() + ".tmp-" + std::to_string(scene::processId()) + "-" +
                         std::to_string(counter++) + file.extension().string());
    auto fail = [&](const std::string& why) {
        std::error_code ec;
        std::filesystem::remove(tmp, ec);
        return makeError(ErrorCode::IoError, file.string(), "", why);
    };
    auto out = OIIO::ImageOutput::create(tmp.string());
    if (!out)
        return fail("no image writer for this extension: " + OIIO::geterror());
    if (!out->open(tmp.string(), spec) || !out->write_image(type, pixels) || !out->close())
        return fail("could not write image: " + out->geterror());
    out.reset();
    auto in = OIIO::ImageInput::open(tmp.string());
    std::vector<float> back;
    if (in && in->spec().width == spec.width && in->spec().height == spec.height &&
        in->spec().nchannels == spec.nchannels)
        back.resize(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
    if (back.empty() || !in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, back.data()))
        return fail("the image written to " + tmp.string() +
                    " does not read back whole (is the disk full?); nothing was written");
    in.reset();
    if (auto synced = scene::syncFileToDisk(tmp); !synced)
        return fail(synced.error().message);
    std::error_code ec;
    std::filesystem::rename(tmp, file, ec);
    if (ec)
        return fail("could not move the image into place: " + ec.message());
    return {};
}

// Encodes into memory (OpenImageIO's I/O proxy) and writes the bytes with
// scene::writeFileAtomically: every write checked, flushed, synced, closed
// and renamed over the target, so a full disk is an error ("No space left
// on device") and never a short image at `file`.
scene::Expected<void> writeAtomically(const std::filesystem::path& file, int width, int height, int channels,
                                      OIIO::TypeDesc type, const void* pixels,
                                      const std::vector<std::string>& channelNames = {},
                                      const std::vector<std::pair<std::string, std::string>>& attributes = {}) {
    OIIO::ImageSpec spec(width, height, channels, type);
    // Our pixels are straight (not premultiplied) alpha; say so, or formats
    // with associated alpha (TGA, TIFF) would change the colours.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!channelNames.empty()) {
        spec.channelnames = channelNames;
        spec.alpha_channel = -1; // named layers: none of them is coverage alpha
    }
    for (const auto& [name, value] : attributes)
        spec.attribute(name, value);
    auto out = OIIO::ImageOutput::create(file.string());
    if (!out)
        return makeError(ErrorCode::IoError, file.string(), "",
                         "no image writer for this extension: " + OIIO::geterror());
    if (!out->supports("ioproxy"))
        return writeThroughTemporary(file, spec, type, pixels);
    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput memory(encoded);
    if (!out->set_ioproxy(&memory) || !out->open(file.string(), spec) || !out->write_image(type, pixels) ||
        !out->close())
        return makeError(ErrorCode::IoError, file.string(), "", "could not encode image: " + out->geterror());
    out.reset();
    return scene::writeFileAtomically(
        file, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}

} // namespace

scene::Expected<void> writeImage(const std::filesystem::path& file, const Image8& image) {
    if (image.width <= 0 || image.height <= 0 ||
        image.pixels.size() != std::size_t(image.width) * std::size_t(image.height) * std::size_t(image.channels))
        return makeError(ErrorCode::InvalidValue, file.string(), "", "image size and pixel count disagree");
    return writeAtomically(file, image.width, image.height, image.channels, OIIO::TypeDesc::UINT8,
                           image.pixels.data());
}

scene::Expected<void> writeImageFloat(const std::filesystem::path& file, int width, int height, int channels,
                                      const std::vector<float>& pixels) {
    if (width <= 0 || height <= 0 || channels <= 0 ||
        pixels.size() != std::size_t(width) * std::size_t(height) * std::size_t(channels))
        return makeError(ErrorCode::InvalidValue, file.string(), "", "image size and pixel count disagree");
    return writeAtomically(file, width, height, channels, OIIO::TypeDesc::FLOAT, pixels.data());
}

scene::Expected<void> writeImageChannels(const std::filesystem::path& file, const FloatChannels& image,
                                         const std::vector<std::pair<std::string, std::string>>& attributes) {
    const std::size_t channels = image.names.size();
    if (image.width <= 0 || image.height <= 0 || channels == 0 ||
        image.pixels.size() != std::size_t(image.width) * std::size_t(image.height) * channels)
        return makeError(ErrorCode::InvalidValue, file.string(), "", "image size and pixel count disagree");
    return writeAtomically(file, image.width, image.height, int(channels), OIIO::TypeDesc::FLOAT,
                           image.pixels.data(), image.names, attributes);
}

} // namespace lpv::importers
