#pragma once
// Images stored inside a model file (glTF data: URIs and .glb buffer views)
// have no path of their own, but the scene model refers to textures by path
// and `lpv import` copies textures into the project from paths. They are
// therefore written once to a content-addressed cache folder:
// $LPV_CACHE_DIR, else $XDG_CACHE_HOME/lpvstudio, else ~/.cache/lpvstudio,
// under embedded-images/<content hash>.<png|jpg|...>.
#include "lpv/scene/Error.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

namespace lpv::importers {

std::filesystem::path embeddedImageFolder();

// The file holding `bytes` (written if it is not there yet). The extension
// comes from the MIME type, else from the bytes' signature.
scene::Expected<std::filesystem::path> storeEmbeddedImage(std::span<const std::uint8_t> bytes,
                                                          const std::string& mimeType);

} // namespace lpv::importers
