#include "lpv/app/BuiltInProjects.h"

#include <string>
#include <system_error>

namespace lpv::app {

std::vector<std::filesystem::path> builtInProjectCandidates(std::string_view name,
                                                            const std::filesystem::path& executableDir) {
    const std::string file = std::string(name) + "/" + std::string(name) + ".lpvproj";
    std::vector<std::filesystem::path> out;
    if (!executableDir.empty())
        out.push_back((executableDir / LPV_PROJECTS_FROM_BINDIR / file).lexically_normal());
    out.push_back(std::filesystem::path(LPV_SOURCE_PROJECTS_DIR) / file);
    return out;
}

std::filesystem::path findBuiltInProject(std::string_view name, const std::filesystem::path& executableDir) {
    for (const auto& candidate : builtInProjectCandidates(name, executableDir)) {
        std::error_code ec;
        if (std::filesystem::is_regular_file(candidate, ec))
            return candidate;
    }
    return {};
}

} // namespace lpv::app
