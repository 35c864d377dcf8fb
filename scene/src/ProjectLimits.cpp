#include "lpv/scene/ProjectLimits.h"

namespace lpv::scene {

Expected<void> checkWriteFits(std::uint64_t bytes, const ReadLimit& limit, const std::string& file) {
    if (bytes <= limit.maxBytes)
        return {};
    return makeError(ErrorCode::OutOfRange, file, "",
                     "the " + limit.what + " would be " + formatBytes(bytes) + ", more than a " + limit.what +
                         " can be (" + formatBytes(limit.maxBytes) +
                         ", the most the loader reads); nothing was written");
}

Expected<void> checkMaterialCount(std::size_t count, const std::string& file, const std::string& location) {
    if (count <= kMaxMaterials)
        return {};
    return makeError(ErrorCode::OutOfRange, file, location,
                     std::to_string(count) + " materials, more than a project can hold (" +
                         std::to_string(kMaxMaterials) + ")");
}

} // namespace lpv::scene
