#pragma once
// Shader programs built on first use and kept, keyed by their files and
// #defines (the typed flags of a pass name a variant; LpvPass's LpvKernel),
// with uniform locations asked of GL once per program and name. A variant
// that does not compile is an error value naming shaders/file:line, as
// buildEmbeddedProgram reports it, and is tried again when asked again.
#include "lpv/renderer/GlHandle.h"
#include "lpv/scene/Error.h"

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace lpv::renderer {

struct ProgramVariant {
    std::vector<std::string> files;   // embedded shaders/ files, one per stage
    std::vector<std::string> defines; // "NAME VALUE" each
    auto operator<=>(const ProgramVariant&) const = default;
};

class CachedProgram {
  public:
    explicit CachedProgram(Program program) : program_(std::move(program)) {}
    GLuint id() const { return program_.id(); }
    // The uniform's location (-1: not active), asked of GL the first time only.
    GLint uniform(std::string_view name) const;

  private:
    Program program_;
    mutable std::map<std::string, GLint, std::less<>> locations_;
};

class ProgramCache {
  public:
    // The variant's program, compiled and linked the first time it is asked for.
    scene::Expected<const CachedProgram*> get(const ProgramVariant& variant);
    // Programs built so far (a variant never asked for is never compiled).
    std::size_t size() const { return programs_.size(); }

  private:
    std::map<ProgramVariant, std::unique_ptr<CachedProgram>> programs_;
};

} // namespace lpv::renderer
