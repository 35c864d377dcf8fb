#pragma once
// Where the built-in sample projects (projects/NAME/NAME.lpvproj) are. An
// installed program finds them in <prefix>/share/lpvstudio/projects, relative
// to its own folder, so an installed tree works under any prefix; a program
// run from the build folder falls back to the source tree it was built from.
#include <filesystem>
#include <string_view>
#include <vector>

namespace lpv::app {

// The places tried, in order: installed beside the executable, then the source tree.
std::vector<std::filesystem::path> builtInProjectCandidates(std::string_view name,
                                                            const std::filesystem::path& executableDir);

// The first candidate that exists; empty when none does (the caller then
// builds the project from code, as the editor does for the Cornell box).
std::filesystem::path findBuiltInProject(std::string_view name, const std::filesystem::path& executableDir);

} // namespace lpv::app
