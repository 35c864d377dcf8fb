#pragma once
// Our own reading of the canvas a file claims, for the formats whose
// libraries allocate from the header before we could check it (GIF, JPEG)
// or whose headers are simple enough to read safely ourselves (PNG, BMP,
// TGA, OpenEXR). Nothing here allocates more than a header's worth.
#include "lpv/importers/ImageBudget.h"

#include <filesystem>
#include <optional>

namespace lpv::importers {

// nullopt: not one of these formats (OpenImageIO's header reader decides).
// An error: the signature is one of them but the header cannot be read.
scene::Expected<std::optional<ImageHeader>> sniffImageHeader(const std::filesystem::path& file);

} // namespace lpv::importers
