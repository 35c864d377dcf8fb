#pragma once
// What a project may hold, stated once for the reader and every writer
// (issue #42, docs/project-format.md, "What a save may write"): a write that
// the loader would refuse is refused before anything is written, so a
// command that succeeds never leaves a project, a camera path or an asset
// that cannot be opened again.
#include "lpv/scene/Error.h"
#include "lpv/scene/FileRead.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace lpv::scene {

// Materials in one project (and in one imported file). An import of more is
// refused before its material library is parsed; a project file with more
// is refused on load. A material takes about 1.3 KB of project JSON, so the
// limit keeps their part of a project file near 21 MiB of its 64 MiB.
inline constexpr std::size_t kMaxMaterials = 16384;

// Refuses `bytes` of a file that `limit` (the reader's) would not read back:
// "the project file would be 158.2 MiB, more than a project file can be
// (64.0 MiB, the most the loader reads); nothing was written".
Expected<void> checkWriteFits(std::uint64_t bytes, const ReadLimit& limit, const std::string& file);

// Refuses more than kMaxMaterials materials, naming `file` and `location`.
Expected<void> checkMaterialCount(std::size_t count, const std::string& file, const std::string& location);

} // namespace lpv::scene
