#pragma once
// GLSL sources from shaders/, embedded into the library at build time, and
// program building with compile errors that name the file and line.
#include "lpv/renderer/GlHandle.h"
#include "lpv/scene/Error.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lpv::renderer {

struct ShaderStageSource {
    GLenum stage;          // GL_VERTEX_SHADER, ...
    std::string fileName;  // shown in errors, e.g. "shaders/forward.frag"
    std::string source;
};

// The embedded source of `shaders/<name>`, or nullopt. With LPV_SHADER_DIR set,
// the file of that name in that folder wins (shader iteration without a rebuild).
std::optional<std::string_view> embeddedShader(std::string_view name);
std::vector<std::string> embeddedShaderNames();

// Compiles and links; on failure the error lists "file:line: message" per
// diagnostic, translated from the driver's log format (Mesa or NVIDIA).
scene::Expected<Program> buildProgram(const std::vector<ShaderStageSource>& stages);
// Convenience: stages from embedded files, chosen by extension (.vert, .frag, .geom, .comp).
// Shared code lives in shaders/*.glsl and is pulled in with #include "name.glsl".
// `defines` ("NAME VALUE" each) become #define lines after every stage's
// #version line, e.g. a geometry shader's invocation count.
scene::Expected<Program> buildEmbeddedProgram(const std::vector<std::string>& fileNames,
                                              const std::vector<std::string>& defines = {});

// Rewrites a driver info log ("0:12(5): error: ..." or "0(12) : error ...")
// into "file:12: error: ..." lines. Exposed for tests.
std::string formatShaderLog(std::string_view log, std::string_view fileName);
// The same with one name per GLSL source-string number (0 = the stage file,
// K = the K-th file it #includes).
std::string formatShaderLog(std::string_view log, const std::vector<std::string>& fileNames);

// Replaces each `#include "name.glsl"` line with that embedded file, appending
// its name to `fileNames` (whose first entry names the including file).
scene::Expected<std::string> expandIncludes(std::string_view source, std::vector<std::string>& fileNames);

} // namespace lpv::renderer
