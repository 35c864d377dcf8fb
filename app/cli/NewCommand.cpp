#include "Cli.h"

#include "lpv/scene/CornellBox.h"
#include "lpv/scene/Project.h"

#include <iostream>

namespace lpv::cli {

void printNewHelp() {
    std::cout << R"(Usage: lpv new FILE.lpvproj [--template cornell-box|empty] [--force]

Creates a project: FILE.lpvproj plus its FILE.assets/ folder.
  --template NAME   cornell-box (default): the Cornell box from its published
                    measurements; empty: a scene with no objects
  --force           Overwrite an existing project
)";
}

int runNew(Args args) {
    const std::string templ = args.option("--template").value_or("cornell-box");
    const bool force = args.flag("--force");
    const auto pos = args.expectPositionals(1, "expected exactly one project file");
    if (pos.empty())
        return usageError(*args.error(), "new");
    const std::filesystem::path file = pos.front();
    if (file.extension() != ".lpvproj")
        return usageError("the project file must end in .lpvproj", "new");
    if (std::filesystem::exists(file) && !force) {
        std::cerr << "lpv: " << file.string() << " exists; use --force to overwrite it\n";
        return kFailure;
    }
    scene::Project project;
    if (templ == "cornell-box")
        project = scene::makeCornellBoxProject();
    else if (templ == "empty")
        project.name = file.stem().string();
    else
        return usageError("unknown template '" + templ + "' (cornell-box, empty)", "new");
    project.name = file.stem().string();
    if (auto saved = scene::saveProject(project, file); !saved) {
        std::cerr << "lpv: " << saved.error().describe() << "\n";
        return kFailure;
    }
    std::cout << "created " << file.string() << " (" << project.scene.triangleCount() << " triangles)\n";
    return kOk;
}

} // namespace lpv::cli
