#include "lpv/bench/ContentHash.h"

#include "lpv/scene/FileRead.h"
#include "lpv/scene/MeshAsset.h"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace lpv::bench {

namespace {

std::string hex64(std::uint64_t v) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
    return buf;
}

} // namespace

scene::Expected<std::string> fileContentHash(const std::filesystem::path& file) {
    auto bytes = scene::readFileBytes(file);
    if (!bytes)
        return std::unexpected(bytes.error());
    return hex64(scene::contentHash64(*bytes));
}

std::string parametersHash(const scene::ParameterSet& parameters) {
    std::vector<std::string> lines;
    for (const auto& [key, value] : parameters.overrides())
        lines.push_back(key + "=" + scene::formatValue(value));
    std::ranges::sort(lines);
    std::string text;
    for (const std::string& l : lines)
        text += l + "\n";
    return hex64(scene::contentHash64(text));
}

} // namespace lpv::bench
