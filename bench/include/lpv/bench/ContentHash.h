#pragma once
// What ties pieces made apart together (reference shards, sweep shards), as
// 16 hex digits of XXH3: of a file's bytes (a reference shard's project file,
// which names every mesh asset by its checksum; the reference a sweep shard
// measured against), and of the effective parameter overrides (the
// project's and --set's, sorted, so their order does not matter).
#include "lpv/scene/Error.h"
#include "lpv/scene/ParameterRegistry.h"

#include <filesystem>
#include <string>

namespace lpv::bench {

scene::Expected<std::string> fileContentHash(const std::filesystem::path& file);
std::string parametersHash(const scene::ParameterSet& parameters);

} // namespace lpv::bench
