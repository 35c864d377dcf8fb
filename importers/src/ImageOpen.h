#pragma once
// The one way our readers open an image with OpenImageIO: after the file's
// own header passed the budget (ImageBudget.h), with OpenImageIO's header
// checked again, and with whatever the library throws turned into an error.
#include "lpv/importers/ImageBudget.h"

#include <OpenImageIO/imageio.h>

#include <memory>

namespace lpv::importers {

struct OpenedImage {
    std::unique_ptr<OIIO::ImageInput> input;
    ImageHeader header; // from OpenImageIO's spec, weighed like the sniffed one
};

// The file's size; refuses what is not a regular file (FileNotFound when absent).
scene::Expected<std::uint64_t> fileSize(const std::filesystem::path& file);

// Straight alpha (oiio:UnassociatedAlpha) when `straightAlpha`: textures keep the file's values.
scene::Expected<OpenedImage> openWithinBudget(const std::filesystem::path& file, bool straightAlpha);

// Call inside a catch block: the exception in flight as an error value
// naming the file ("could not decode: out of memory (std::bad_alloc)").
std::unexpected<scene::Error> libraryThrew(const std::filesystem::path& file);

} // namespace lpv::importers
