#include "Cli.h"
#include "lpv/app/ImportDefaults.h"

#include "lpv/importers/ImportUnits.h"
#include "lpv/importers/Importer.h"
#include "lpv/scene/Project.h"
#include "lpv/scene/ProjectTextures.h"
#include "lpv/scene/SaveCleanup.h"
#include "lpv/scene/SceneMerge.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

namespace lpv::cli {

namespace fs = std::filesystem;

void printImportHelp() {
    std::cout << R"(Usage: lpv import FILE... -o PROJECT.lpvproj [options]

Imports scene files into a project: creates PROJECT.lpvproj, or adds to it
when it exists. Formats: Mafia .4ds (version 29), glTF 2.0 (.gltf, .glb), and
what Assimp reads (.obj, .3ds, .fbx, .dae, .ply, ...), chosen by content, then
by extension. Every mesh is cleaned (duplicate vertices welded, degenerate
triangles dropped, normals and tangents generated where missing), textures
are copied into PROJECT.assets/textures/, and a missing texture is reported
and drawn as a placeholder instead of failing the import.

  -o, --output FILE         The project to create or add to (required)
  --texture-path DIR        Also look for textures in DIR (and DIR/maps); repeatable
  --allow-path DIR          Let the scene (and an existing PROJECT) name files in
                            DIR too; repeatable (see "What a scene may read")
  --unit mm|cm|m|in|ft      The unit the files are in; every length is scaled into
                            metres (vertices, translations, lights, cameras, paths)
  --scale S                 The same as metres per unit (S > 0), e.g. --scale 0.01
                            for centimetres; --unit and --scale exclude each other
  --no-sun                  Do not add a sun when the project ends up without lights
  --verbose                 Print every warning (default: the first 20)

Units: without --unit or --scale a file is read in the unit it states (glTF
and Mafia 4ds: metres; FBX: its UnitScaleFactor; Collada: its <unit>), and
in metres when it states none; the scale is printed with the file's line.
When the size of a scene without a stated unit suggests another (over 1,000
units along a side, at least 100 along every side, or under 0.05), a note
says which --unit to try. The new files' lengths are scaled only, never a
project's earlier content. Meshes far from their origin compared with their
size are stored relative to their centre, the offset moved into their
objects' translations, which keeps float precision 100 km away.

What a scene may read: files it names (textures, glTF buffers) are read
only from the scene file's folder, its maps/ and ../maps/ folders, each
--texture-path (and its maps/), each --allow-path and the folders in
LPV_ALLOW_PATH (':'-separated), after resolving "..", %-escapes and symbolic
links. Anything else (an absolute system path, an escape, a folder, a FIFO)
is a missing texture with a warning that names it, or an error for a glTF
buffer. Copies in the project are never more widely readable than rw-r--r--.

Prints per file: objects, triangles, materials, textures found/missing,
degenerate triangles dropped, time. Exit code 1 when a file cannot be
imported or the project cannot be saved; the project is then unchanged.
Saves of one project take turns (a lock file beside it): when another
process saved the project while this import read its files, this import
saves nothing and says so (exit code 1); run it again to add to that project.
)";
}

namespace {

std::string withCommas(std::size_t n) {
    std::string digits = std::to_string(n), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0)
            out += ',';
        out += digits[i];
    }
    return out;
}

std::string factorText(double f) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", f);
    return text;
}

std::string seconds(double s) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f s", s);
    return text;
}

void printSummary(const fs::path& file, const importers::ImportResult& r, bool verbose) {
    const auto& s = r.stats;
    std::cout << file.string() << ": " << withCommas(s.objects) << " objects, " << withCommas(s.triangles)
              << " triangles, " << s.materials << " materials, textures " << s.texturesFound << " found / "
              << s.texturesMissing << " missing, " << s.degenerateTrianglesDropped
              << " degenerate triangles dropped, " << seconds(s.seconds);
    // The scale into metres, when there was one or the user named the unit.
    const importers::AppliedScale& scale = s.lengthScale;
    if (scale.factor != 1.0 || scale.knew == importers::UnitKnowledge::GivenByUser)
        std::cout << "; lengths x" << factorText(scale.factor) << " into metres (" << scale.source << ")";
    std::cout << "\n";
    for (const std::string& note : r.notes)
        std::cout << "  " << note << "\n";
    const std::size_t shown = verbose ? r.warnings.size() : std::min<std::size_t>(r.warnings.size(), 20);
    for (std::size_t i = 0; i < shown; ++i)
        std::cerr << "  warning: " << r.warnings[i] << "\n";
    if (shown < r.warnings.size())
        std::cerr << "  ... and " << r.warnings.size() - shown << " more warnings (--verbose shows them)\n";
}

// An imported scene without lights would render black; scenes such as
// Sponza ship none. The sun comes from where it lights the most of what the
// scene's camera (or the framing camera) sees (reference::chooseSunDirection),
// the old fixed direction when nothing beats it. Returns what to print.
std::string addDefaultSun(scene::Scene& s) {
    app::DefaultSun sun = app::chooseDefaultSun(s);
    sun.light.name = "sun (added by lpv import)";
    s.lights.push_back(sun.light);
    return sun.how;
}

} // namespace

int runImport(Args args) {
    const auto output = args.option("--output", "-o");
    importers::ImportOptions options;
    for (const std::string& dir : args.options("--texture-path"))
        options.textureSearchPaths.emplace_back(dir);
    for (const std::string& dir : args.options("--allow-path"))
        options.allowPaths.emplace_back(dir);
    const auto unit = args.option("--unit");
    if (unit && !importers::metresPerUnit(*unit))
        args.reject("--unit", *unit, std::string("one of ") + importers::unitNames());
    std::string scaleText;
    const auto scale = args.optionalReal("--scale", RealRange::above(0.0), &scaleText);
    const bool noSun = args.flag("--no-sun");
    const bool verbose = args.flag("--verbose");
    if (auto e = args.error())
        return usageError(*e, "import");
    if (unit && scale)
        return usageError("--unit and --scale both say what a unit of the file is: give one", "import");
    if (unit) {
        options.metresPerUnit = importers::metresPerUnit(*unit);
        options.unitSource = "--unit " + *unit;
    }
    if (scale) {
        options.metresPerUnit = *scale;
        options.unitSource = "--scale " + scaleText;
    }
    const auto inputs = args.positionals();
    if (inputs.empty())
        return usageError("no file to import", "import");
    if (!output)
        return usageError("-o PROJECT.lpvproj is required", "import");
    const fs::path projectFile = *output;
    if (projectFile.extension() != ".lpvproj")
        return usageError("the project file must end in .lpvproj", "import");

    const auto start = std::chrono::steady_clock::now();
    // The project as this import found it: another process that saves it
    // while the inputs are read wins, and this import says it lost.
    const scene::ProjectFileIdentity found = scene::projectFileIdentity(projectFile);
    scene::Project project;
    const bool adding = found.exists;
    if (adding) {
        auto loaded = scene::loadProject(projectFile, options.allowPaths);
        if (!loaded) {
            std::cerr << "lpv: cannot add to it: " << loaded.error().describe() << "\n";
            return kFailure;
        }
        printLoadWarnings(projectFile.string(), loaded->loadWarnings);
        project = std::move(*loaded);
    } else {
        project.name = projectFile.stem().string();
    }

    for (const std::string& input : inputs) {
        auto imported = importers::importScene(input, options);
        if (!imported) {
            std::cerr << "lpv: " << imported.error().describe() << "\n";
            std::cerr << "lpv: nothing was saved" << (adding ? "; " + projectFile.string() + " is unchanged" : "")
                      << "\n";
            return kFailure;
        }
        printSummary(input, *imported, verbose);
        scene::appendScene(project.scene, std::move(imported->scene));
    }
    if (project.scene.lights.empty() && !noSun) {
        const std::string how = addDefaultSun(project.scene);
        std::cout << "no lights in the scene: added a sun " << how << " (--no-sun to leave it dark)\n";
    }

    // The lock spans the texture copies too: another save's clean-up would
    // take copies that no project file names yet for orphans.
    auto lock = scene::ProjectLock::acquire(projectFile);
    if (!lock) {
        std::cerr << "lpv: " << lock.error().describe() << "\n";
        return kFailure;
    }
    if (scene::projectFileIdentity(projectFile) != found) {
        std::cerr << "lpv: " << scene::projectChangedError(projectFile, "import").describe() << "\n";
        return kFailure;
    }

    // Texture copies go in before the project that names them; if either
    // step fails (a full disk), the copies this import made go again.
    scene::SaveRollback rollback;
    rollback.watchTextureCopies(scene::assetsFolderOf(projectFile) / "textures");
    auto textures = scene::copyTexturesIntoProject(project.scene, projectFile);
    if (!textures) {
        rollback.undo();
        std::cerr << "lpv: " << textures.error().describe() << "\n";
        return kFailure;
    }
    scene::SaveOptions saveOptions;
    saveOptions.heldLock = &*lock;
    saveOptions.unchangedSince = found;
    saveOptions.operation = "import";
    if (auto saved = scene::saveProject(project, projectFile, saveOptions); !saved) {
        rollback.undo();
        std::cerr << "lpv: " << saved.error().describe() << "\n";
        std::cerr << "lpv: nothing was saved" << (adding ? "; " + projectFile.string() + " is unchanged" : "")
                  << "\n";
        return kFailure;
    }
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << (adding ? "added to " : "created ") << projectFile.string() << ": "
              << withCommas(project.scene.objects.size()) << " objects, "
              << withCommas(project.scene.triangleCount()) << " triangles, " << project.scene.materials.size()
              << " materials; textures " << textures->copied << " copied, " << textures->alreadyThere
              << " already there, " << textures->missing << " missing (placeholder); " << seconds(total) << "\n";
    return kOk;
}

} // namespace lpv::cli
