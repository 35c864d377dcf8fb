// libFuzzer target fuzz_image: texture and image loading (issue #42) through
// the public functions of importers/include/lpv/importers/ImageIO.h, i.e.
// OpenImageIO behind our header checks and decode budget: loadTextureOrPlaceholder
// (readTextureRgba8, what every material texture goes through) and
// readImageChannels (the float path of `lpv compare` and `lpv merge`).
//
// The input is the file's bytes, written into the work folder as
// `texture.<ext>` with the extension its magic bytes call for (PNG, JPEG,
// GIF, BMP, EXR; anything else is `.tga`, which has no magic): OpenImageIO
// picks its reader by extension first, so a file named like what it looks
// like reaches the right decoder, as a user's texture would. A file that
// reader refuses still goes through OpenImageIO's fallback to every other
// format it knows.
//
// Promises checked (a broken one aborts, so libFuzzer saves the input):
// a texture is the placeholder with a warning, or RGBA8 with both sides in
// 1..kMaxImageSide and exactly width * height * 4 bytes; float channels hold
// width * height * channels values with at least one named channel. Header
// bombs (a 65535x65535 GIF screen, an EXR with 64 channels of 16384^2)
// must be refused before they allocate: every run uses
// -malloc_limit_mb=1024 and -rss_limit_mb=2048, so an allocation the budget
// should have stopped is a crash.
#include "WorkFolder.h"

#include "lpv/importers/ImageIO.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>

namespace {

namespace fs = std::filesystem;

fs::path gFolder;

[[noreturn]] void broken(const std::string& what) {
    std::fprintf(stderr, "==fuzz== invariant broken: %s\n", what.c_str());
    std::abort();
}

// The extension OpenImageIO should try first for these bytes.
const char* extensionFor(std::string_view bytes) {
    const auto startsWith = [&](std::string_view magic) { return bytes.substr(0, magic.size()) == magic; };
    if (startsWith("\x89PNG"))
        return ".png";
    if (startsWith("\xff\xd8"))
        return ".jpg";
    if (startsWith("GIF")) // giflib checks no more of the signature
        return ".gif";
    if (startsWith("BM"))
        return ".bmp";
    if (startsWith(std::string_view("\x76\x2f\x31\x01", 4)))
        return ".exr";
    return ".tga";
}

void checkSides(int width, int height, const std::string& what) {
    if (width < 1 || height < 1 || width > lpv::importers::kMaxImageSide ||
        height > lpv::importers::kMaxImageSide)
        broken(what + " has sides " + std::to_string(width) + "x" + std::to_string(height));
}

void checkTexture(const lpv::importers::LoadedTexture& t) {
    if (t.placeholder && t.warning.empty())
        broken("a placeholder texture without a warning");
    checkSides(t.image.width, t.image.height, "the texture");
    if (t.image.channels != 4)
        broken("the texture has " + std::to_string(t.image.channels) + " channels, not RGBA");
    const std::size_t expected = std::size_t(t.image.width) * std::size_t(t.image.height) * 4;
    if (t.image.pixels.size() != expected)
        broken("the texture holds " + std::to_string(t.image.pixels.size()) + " bytes, not " +
               std::to_string(expected));
}

void checkChannels(const lpv::importers::FloatChannels& c) {
    checkSides(c.width, c.height, "the float image");
    if (c.names.empty())
        broken("a float image without channels");
    const std::size_t expected = std::size_t(c.width) * std::size_t(c.height) * c.names.size();
    if (c.pixels.size() != expected)
        broken("the float image holds " + std::to_string(c.pixels.size()) + " values, not " +
               std::to_string(expected));
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    gFolder = lpv::fuzz::makeWorkFolder("image");
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    const fs::path file = gFolder / (std::string("texture") + extensionFor(bytes));
    lpv::fuzz::writeInput(file, bytes);
    checkTexture(lpv::importers::loadTextureOrPlaceholder(file));
    if (const auto channels = lpv::importers::readImageChannels(file))
        checkChannels(*channels);
    else if (channels.error().describe().empty())
        broken("readImageChannels failed without a message");
    std::error_code ignored;
    fs::remove(file, ignored); // the next input may pick another extension
    return 0;
}
