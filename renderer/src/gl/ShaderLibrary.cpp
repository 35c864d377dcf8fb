#include "lpv/renderer/ShaderLibrary.h"

#include "gl/EmbeddedShaders.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <regex>
#include <sstream>

namespace lpv::renderer {

using scene::ErrorCode;
using scene::makeError;

namespace {

// LPV_SHADER_DIR=<folder>: shaders read from that folder (the source tree's
// shaders/) in place of the embedded copies, so a shader edit shows without a
// rebuild. A developer's switch: each file is read once per process and kept
// (callers hold string_views); a file missing there falls back to the
// embedded one.
std::optional<std::string_view> shaderFromOverrideDir(std::string_view name) {
    static const char* dir = std::getenv("LPV_SHADER_DIR");
    if (dir == nullptr || *dir == '\0')
        return std::nullopt;
    static std::mutex mutex;
    static std::map<std::string, std::string, std::less<>> cache;
    std::lock_guard lock(mutex);
    if (auto it = cache.find(name); it != cache.end())
        return std::string_view(it->second);
    std::ifstream in(std::filesystem::path(dir) / std::string(name), std::ios::binary);
    if (!in)
        return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    return std::string_view(cache.emplace(std::string(name), text.str()).first->second);
}

} // namespace

std::optional<std::string_view> embeddedShader(std::string_view name) {
    if (auto overridden = shaderFromOverrideDir(name))
        return overridden;
    for (const EmbeddedShader& s : embeddedShaders())
        if (s.name == name)
            return s.source;
    return std::nullopt;
}

std::vector<std::string> embeddedShaderNames() {
    std::vector<std::string> out;
    for (const EmbeddedShader& s : embeddedShaders())
        out.emplace_back(s.name);
    return out;
}

std::string formatShaderLog(std::string_view log, std::string_view fileName) {
    return formatShaderLog(log, std::vector<std::string>{std::string(fileName)});
}

std::string formatShaderLog(std::string_view log, const std::vector<std::string>& fileNames) {
    // Mesa: "0:12(5): error: ...", NVIDIA: "0(12) : error C0000: ...". The
    // leading number is the source-string number that `#line N K` sets: 0 is
    // the stage file itself, K >= 1 the K-th file it includes.
    static const std::regex mesa(R"(^\s*(\d+):(\d+)\(\d+\):\s*(.*)$)");
    static const std::regex nvidia(R"(^\s*(\d+)\((\d+)\)\s*:\s*(.*)$)");
    const std::string fallback = fileNames.empty() ? std::string("shader") : fileNames.front();
    auto nameOf = [&](const std::string& number) -> const std::string& {
        const std::size_t k = std::size_t(std::stoul(number));
        return k < fileNames.size() ? fileNames[k] : fallback;
    };
    std::istringstream in{std::string(log)};
    std::ostringstream out;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty())
            continue;
        std::smatch m;
        if (std::regex_match(line, m, mesa) || std::regex_match(line, m, nvidia))
            out << nameOf(m[1]) << ":" << m[2] << ": " << m[3] << "\n";
        else
            out << fallback << ": " << line << "\n";
    }
    return out.str();
}

namespace {

std::string infoLog(GLuint object, bool isProgram) {
    GLint length = 0;
    isProgram ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length) : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(length > 0 ? length : 0), '\0');
    if (length > 0)
        isProgram ? glGetProgramInfoLog(object, length, nullptr, log.data())
                  : glGetShaderInfoLog(object, length, nullptr, log.data());
    while (!log.empty() && log.back() == '\0')
        log.pop_back();
    return log;
}

GLenum stageForFile(const std::string& name) {
    auto ends = [&](std::string_view ext) { return name.ends_with(ext); };
    if (ends(".vert")) return GL_VERTEX_SHADER;
    if (ends(".frag")) return GL_FRAGMENT_SHADER;
    if (ends(".geom")) return GL_GEOMETRY_SHADER;
    if (ends(".comp")) return GL_COMPUTE_SHADER;
    return GL_NONE;
}

} // namespace

scene::Expected<std::string> expandIncludes(std::string_view source, std::vector<std::string>& fileNames) {
    // One level of `#include "name.glsl"` from the embedded shaders. Each
    // included file gets its own source-string number, so errors inside it
    // name it; `#line` restores the including file's numbering after it.
    static const std::regex includeLine(R"re(^\s*#\s*include\s+"([^"]+)"\s*$)re");
    std::istringstream in{std::string(source)};
    std::ostringstream out;
    std::string line;
    int lineNumber = 0;
    while (std::getline(in, line)) {
        ++lineNumber;
        std::smatch m;
        if (!std::regex_match(line, m, includeLine)) {
            out << line << "\n";
            continue;
        }
        const std::string name = m[1];
        auto included = embeddedShader(name);
        if (!included)
            return makeError(ErrorCode::MissingAsset, fileNames.front() + ":" + std::to_string(lineNumber), "#include",
                             "no embedded shader named '" + name + "'");
        const std::string includedText(*included);
        if (std::regex_search(includedText, std::regex(R"re((^|\n)\s*#\s*include\s)re")))
            return makeError(ErrorCode::InvalidValue, "shaders/" + name, "#include",
                             "included files may not include others (one level only)");
        fileNames.push_back("shaders/" + name);
        out << "#line 1 " << fileNames.size() - 1 << "\n" << *included << "\n";
        out << "#line " << lineNumber + 1 << " 0\n";
    }
    return out.str();
}

scene::Expected<Program> buildProgram(const std::vector<ShaderStageSource>& stages) {
    Program program(glCreateProgram());
    std::vector<Shader> shaders;
    std::string names;
    for (const ShaderStageSource& s : stages) {
        std::vector<std::string> fileNames{s.fileName};
        auto expanded = expandIncludes(s.source, fileNames);
        if (!expanded)
            return std::unexpected(expanded.error());
        Shader shader(glCreateShader(s.stage));
        const char* src = expanded->c_str();
        glShaderSource(shader.id(), 1, &src, nullptr);
        glCompileShader(shader.id());
        GLint ok = GL_FALSE;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (!ok)
            return makeError(ErrorCode::InvalidValue, s.fileName, "compile",
                             "shader does not compile:\n" + formatShaderLog(infoLog(shader.id(), false), fileNames));
        glAttachShader(program.id(), shader.id());
        shaders.push_back(std::move(shader));
        names += (names.empty() ? "" : " + ") + s.fileName;
    }
    glLinkProgram(program.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok)
        return makeError(ErrorCode::InvalidValue, names, "link", "program does not link:\n" + infoLog(program.id(), true));
    return program;
}

scene::Expected<Program> buildEmbeddedProgram(const std::vector<std::string>& fileNames,
                                              const std::vector<std::string>& defines) {
    std::vector<ShaderStageSource> stages;
    for (const std::string& name : fileNames) {
        auto src = embeddedShader(name);
        const GLenum stage = stageForFile(name);
        if (!src || stage == GL_NONE)
            return makeError(ErrorCode::MissingAsset, "shaders/" + name, "", "no such embedded shader");
        std::string text(*src);
        if (!defines.empty()) {
            // After the #version line; #line keeps compiler messages on the file's own lines.
            std::string block;
            for (const std::string& d : defines)
                block += "#define " + d + "\n";
            const std::size_t eol = text.find('\n');
            text.insert(eol == std::string::npos ? text.size() : eol + 1, block + "#line 2\n");
        }
        stages.push_back({stage, "shaders/" + name, std::move(text)});
    }
    return buildProgram(stages);
}

} // namespace lpv::renderer
