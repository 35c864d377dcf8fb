#include "gl/ProgramCache.h"

#include "lpv/renderer/ShaderLibrary.h"

namespace lpv::renderer {

GLint CachedProgram::uniform(std::string_view name) const {
    if (const auto it = locations_.find(name); it != locations_.end())
        return it->second;
    const std::string key(name);
    const GLint location = glGetUniformLocation(program_.id(), key.c_str());
    locations_.emplace(key, location);
    return location;
}

scene::Expected<const CachedProgram*> ProgramCache::get(const ProgramVariant& variant) {
    if (const auto it = programs_.find(variant); it != programs_.end())
        return it->second.get();
    auto built = buildEmbeddedProgram(variant.files, variant.defines);
    if (!built)
        return std::unexpected(built.error());
    auto& slot = programs_[variant];
    slot = std::make_unique<CachedProgram>(std::move(*built));
    return slot.get();
}

} // namespace lpv::renderer
