// `lpv path export` and `lpv path import`: camera paths in and out of a
// project as our JSON schema, or out as a per-frame CSV (docs/camera-paths.md).
#include "Cli.h"

#include "lpv/scene/CameraPathFile.h"
#include "lpv/scene/CameraSpline.h"
#include "lpv/scene/Project.h"
#include "lpv/scene/ValueChecks.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace lpv::cli {

namespace fs = std::filesystem;

void printPathHelp() {
    std::cout << R"(Usage: lpv path export PROJECT.lpvproj --path NAME -o FILE.json|FILE.csv [--fps N]
       lpv path import PROJECT.lpvproj FILE.json [--name NEW]

export: writes the camera path NAME of the project
  .json   our schema ("lpvstudio-camera-path", version 1): name, closed,
          constantSpeed, keyframes of time, position, orientation (x, y, z, w)
          and fovYDegrees; it imports again unchanged
  .csv    time,px,py,pz,qx,qy,qz,qw,fovY_deg: the camera as played back, one
          row per frame at --fps (default 30) from the first key's time to the
          last, both included
import: adds the path in FILE.json to the project, or replaces the path of
  the same name (--name NEW renames it first), and saves the project
  atomically (a failed save leaves it as it was)

The file is validated first: a bad field is reported with its location
(keyframes[2].orientation) and nothing is written.
)";
}

namespace {

std::string lowerExtension(const fs::path& p) {
    std::string e = p.extension().string();
    for (char& c : e)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return e;
}

const scene::CameraPath* findPath(const scene::Project& project, const std::string& name) {
    for (const scene::CameraPath& p : project.scene.cameraPaths)
        if (p.name == name)
            return &p;
    return nullptr;
}

std::string pathNames(const scene::Project& project) {
    std::string names;
    for (const scene::CameraPath& p : project.scene.cameraPaths)
        names += (names.empty() ? "'" : ", '") + p.name + "'";
    return names.empty() ? "none" : names;
}

int exportPath(Args& args) {
    const auto output = args.option("--output", "-o");
    const auto name = args.option("--path");
    const auto givenFps = args.optionalReal("--fps", RealRange::above(0.0));
    args.require(name.has_value(), "missing --path NAME");
    args.require(output.has_value(), "missing -o FILE.json or FILE.csv");
    const auto pos = args.expectPositionals(2, "expected one project file after 'export'");
    if (pos.empty())
        return usageError(*args.error(), "path");
    const std::string extension = lowerExtension(*output);
    if (extension != ".json" && extension != ".csv")
        return usageError("-o must end in .json or .csv, got '" + *output + "'", "path");
    if (givenFps && extension != ".csv")
        return usageError("--fps applies to CSV export only", "path");
    const double fps = givenFps.value_or(30.0);

    const auto project = scene::loadProject(pos[1]);
    if (!project) {
        std::cerr << "lpv: " << project.error().describe() << "\n";
        return kFailure;
    }
    const scene::CameraPath* path = findPath(*project, *name);
    if (!path) {
        std::cerr << "lpv: " << pos[1] << ": no camera path named '" << *name
                  << "' (paths: " << pathNames(*project) << ")\n";
        return kFailure;
    }
    if (extension == ".json") {
        if (auto ok = scene::saveCameraPathFile(*path, *output); !ok) {
            std::cerr << "lpv: " << ok.error().describe() << "\n";
            return kFailure;
        }
        std::printf("wrote %s (%zu keyframes)\n", output->c_str(), path->keyframes.size());
        return kOk;
    }
    const scene::CameraSpline spline(*path);
    if (auto why = scene::checkPlannedFrames(double(spline.duration()), fps)) {
        std::cerr << "lpv: " << pos[1] << ": path '" << *name << "': " << *why << "; nothing was written\n";
        return kFailure;
    }
    if (auto ok = scene::writeFileAtomically(*output, scene::cameraPathToCsv(spline, fps)); !ok) {
        std::cerr << "lpv: " << ok.error().describe() << "\n";
        return kFailure;
    }
    std::printf("wrote %s (%d rows at %g fps over %g s)\n", output->c_str(),
                scene::cameraPathCsvRows(spline.duration(), fps), fps, double(spline.duration()));
    return kOk;
}

int importPath(Args& args) {
    const auto rename = args.option("--name");
    const auto pos = args.expectPositionals(3, "expected a project file and a path file after 'import'");
    if (pos.empty())
        return usageError(*args.error(), "path");
    auto path = scene::loadCameraPathFile(pos[2]);
    if (!path) {
        std::cerr << "lpv: " << path.error().describe() << "\n";
        return kFailure;
    }
    if (rename)
        path->name = *rename;
    // Another process that saves the project before this one does wins (issue #42).
    const scene::ProjectFileIdentity found = scene::projectFileIdentity(pos[1]);
    auto project = scene::loadProject(pos[1]);
    if (!project) {
        std::cerr << "lpv: " << project.error().describe() << "\n";
        return kFailure;
    }
    auto& paths = project->scene.cameraPaths;
    const auto existing =
        std::find_if(paths.begin(), paths.end(), [&](const auto& p) { return p.name == path->name; });
    const bool replaced = existing != paths.end();
    if (replaced)
        *existing = *path;
    else
        paths.push_back(*path);
    scene::SaveOptions saveOptions;
    saveOptions.unchangedSince = found;
    saveOptions.operation = "path import";
    if (auto ok = scene::saveProject(*project, pos[1], saveOptions); !ok) {
        std::cerr << "lpv: " << ok.error().describe() << "\n";
        return kFailure;
    }
    std::printf("%s path '%s' (%zu keyframes) in %s\n", replaced ? "replaced" : "added", path->name.c_str(),
                path->keyframes.size(), pos[1].c_str());
    return kOk;
}

} // namespace

int runPath(Args args) {
    const auto pos = args.positionals();
    if (pos.empty())
        return usageError("which action? (export, import)", "path");
    if (pos.front() == "export")
        return exportPath(args);
    if (pos.front() == "import")
        return importPath(args);
    return usageError("unknown action '" + pos.front() + "' (export, import)", "path");
}

} // namespace lpv::cli
