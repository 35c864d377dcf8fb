#pragma once
// OBJ, 3DS and the other common formats through Assimp.
#include "lpv/importers/Importer.h"

namespace lpv::importers {

// True when Assimp has a reader for the file's extension.
bool assimpReads(const std::filesystem::path& file);

scene::Expected<ImportResult> importWithAssimp(const std::filesystem::path& file, const ImportOptions& options);

} // namespace lpv::importers
