// `lpv dump`: the editor's visualizers from the command line. The pictures
// come from the same code as the Visualizers dock (renderer/viz), so a dump
// and the dock show the same pixels for the same choices.
#include "Cli.h"
#include "RenderSetup.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/renderer/viz/LpvViews.h"
#include "lpv/renderer/viz/TileImages.h"

#include <cstdio>
#include <iostream>

namespace lpv::cli {

void printDumpHelp() {
    std::cout << R"(Usage: lpv dump PROJECT.lpvproj --what VIEW -o OUT.png [options]

Renders the project headless and writes one visualizer image, exactly as the
editor's Visualizers dock shows it (slice, false colour, legend).

  --what VIEW           lpv       a slice of a cascade's light (see --source)
                        gv        a slice of a cascade's geometry volume (blocking potential)
                        leak      heat map of the flux that crosses faces the GV marks as walls
                        backside  irradiance arriving on the back side of GV walls
                        rsm       the RSM tiles (position, normal, flux) of --cascade
                        shadow    the shadow-map depth tiles (every sun cascade, spot and point map)
  -o, --output FILE     Image to write (.png), required
  --cascade N           LPV / RSM cascade, 0 = finest (default 0)
  --axis x|y|z          Slice axis (default z); the image shows (z,y), (x,z) or (x,y), second axis up
  --slice K             Slice index along the axis (default: the middle)
  --source S            For --what lpv: injected, step (the s-th step's light alone) or
                        accumulated (steps 0..s summed; default)
  --step S              Propagation step, 0 = injection (default: the last)
  --quantity Q          band0 (default), coefficient, directional (irradiance facing --direction;
                        for gv: the fraction of light travelling along --direction it blocks)
  --coefficient K       SH coefficient 0..3 for --quantity coefficient
  --direction X,Y,Z     Direction for --quantity directional (default 0,1,0)
  --channel C           red, green, blue, luminance (default) or rgb (true colour)
  --scale linear|log    Colour scale (default linear); log spans 4 decades below the maximum
  --max V               Fix the top of the colour range (default: the slice's maximum)
  --grey                Grey ramp instead of false colour
  --cell-pixels N       Pixels per cell (default 12)
  --max-tile N          rsm, shadow: shrink each tile to at most N pixels across (default: full size)
  --wall-threshold T    Leak views: blocking from which a face is a wall (default 0.3)
  --width N --height N  Camera image size; the camera decides the cascades (default 1280x720)
  --camera NAME         Named camera of the project (default: the first)
  --set KEY=VALUE       Override a registry parameter; repeatable
  --frames N            Frames rendered before the read-back (default 2: the geometry
                        volume uses the previous frame's camera G-buffer, as in the editor)
)";
}

namespace {

bool writePng(const std::filesystem::path& path, const scene::Image8& image) {
    if (auto ok = importers::writeImage(path, image); !ok) {
        std::cerr << "lpv: " << ok.error().describe() << "\n";
        return false;
    }
    std::printf("wrote %s (%dx%d)\n", path.string().c_str(), image.width, image.height);
    return true;
}

} // namespace

int runDump(Args args) {
    const auto output = args.option("--output", "-o");
    const auto what = args.choice("--what", {"lpv", "gv", "leak", "backside", "rsm", "shadow"});
    const int cascade = args.integer("--cascade", 0, {0});
    const auto axisName = args.choice("--axis", {"x", "y", "z"});
    const auto slice = args.optionalInteger("--slice");
    const auto sourceName = args.choice("--source", {"injected", "step", "accumulated"});
    const auto step = args.optionalInteger("--step", {0});
    const auto quantityName = args.choice("--quantity", {"band0", "coefficient", "directional"});
    const auto coefficient = args.optionalInteger("--coefficient", {0, 3});
    const auto direction = args.realList("--direction", 3);
    const auto channelName = args.choice("--channel", {"red", "green", "blue", "luminance", "rgb"});
    const auto scaleName = args.choice("--scale", {"linear", "log"});
    const auto rangeMax = args.optionalReal("--max", RealRange::above(0.0));
    const auto cellPixels = args.optionalInteger("--cell-pixels", {1, 64});
    const int maxTile = args.integer("--max-tile", 0, {0});
    const auto threshold = args.optionalReal("--wall-threshold", {0.0, 1.0});
    const int width = args.integer("--width", 1280, {1});
    const int height = args.integer("--height", 720, {1});
    const int frames = args.integer("--frames", 2, {1});
    const bool grey = args.flag("--grey");
    RenderRequest request = renderRequestOptions(args);
    args.require(output.has_value(), "missing -o OUT.png");
    args.require(what.has_value(), "missing --what lpv|gv|leak|backside|rsm|shadow");
    const auto pos = args.expectPositionals(1, "expected exactly one project file");
    if (pos.empty())
        return usageError(*args.error(), "dump");
    const std::string view = *what;
    const bool isSlice = view == "lpv" || view == "gv" || view == "leak" || view == "backside";

    renderer::viz::LpvViewSpec spec;
    spec.colour.pixelsPerCell = cellPixels.value_or(12);
    spec.cascade = cascade;
    if (view == "gv")
        spec.source = renderer::viz::LpvSource::Geometry;
    else if (view == "leak")
        spec.source = renderer::viz::LpvSource::LeakHeat;
    else if (view == "backside")
        spec.source = renderer::viz::LpvSource::Backside;
    if (sourceName) {
        if (view != "lpv")
            return usageError("--source is injected, step or accumulated, with --what lpv", "dump");
        spec.source = *renderer::viz::sourceFromName(*sourceName);
    }
    if (step)
        spec.step = *step;
    if (axisName)
        spec.slice.axis = *renderer::viz::axisFromName(*axisName);
    if (quantityName)
        spec.slice.quantity = *renderer::viz::quantityFromName(*quantityName);
    if (coefficient)
        spec.slice.coefficient = *coefficient;
    if (direction) {
        const glm::vec3 d{float((*direction)[0]), float((*direction)[1]), float((*direction)[2])};
        if (glm::length(d) < 1e-6f)
            return usageError("--direction: all zero is no direction", "dump");
        spec.slice.direction = d;
    }
    if (channelName)
        spec.slice.channel = *renderer::viz::channelFromName(*channelName);
    if (scaleName)
        spec.colour.scale = *scaleName == "log" ? renderer::viz::Scale::Log : renderer::viz::Scale::Linear;
    if (rangeMax)
        spec.colour.rangeMax = float(*rangeMax);
    if (threshold)
        spec.wallThreshold = float(*threshold);
    spec.colour.falseColour = !grey;

    request.projectFile = pos.front();
    int exitCode = kOk;
    auto setup = prepareRender(request, "dump", exitCode);
    if (!setup)
        return exitCode;
    if (isSlice)
        setup->renderer->setLpvCapture(renderer::viz::captureFor(spec));
    if (!renderFrames(*setup, width, height, frames))
        return kFailure;
    std::printf("%s\n", setup->renderer->lpvNote().c_str());

    if (view == "shadow") {
        const auto images = setup->renderer->debugImages("shadowMaps");
        if (images.empty()) {
            std::cerr << "lpv: " << pos.front()
                      << ": no shadow maps (the scene has no light that casts shadows)\n";
            return kFailure;
        }
        return writePng(*output, renderer::viz::tileRow(images, maxTile)) ? kOk : kFailure;
    }
    if (view == "rsm") {
        const auto all = setup->renderer->debugImages("rsm");
        if (all.empty()) {
            std::cerr << "lpv: " << pos.front() << ": no RSM (the scene has no directional light)\n";
            return kFailure;
        }
        const auto tiles = renderer::viz::imagesNamed(all, "rsm-" + std::to_string(spec.cascade) + "-");
        if (tiles.empty())
            return usageError("--cascade " + std::to_string(spec.cascade) + " is outside 0.." +
                                  std::to_string(int(all.size() / 3) - 1) + " (the RSM tiles of this frame)",
                              "dump");
        return writePng(*output, renderer::viz::tileRow(tiles, maxTile)) ? kOk : kFailure;
    }

    const auto frames3d = setup->renderer->lpvCascadeFrames();
    if (frames3d.empty()) {
        std::cerr << "lpv: " << pos.front() << ": nothing to show: " << setup->renderer->lpvNote() << "\n";
        return kFailure;
    }
    if (spec.cascade >= int(frames3d.size()))
        return usageError("--cascade " + std::to_string(spec.cascade) + " is outside 0.." +
                              std::to_string(int(frames3d.size()) - 1) + " (lpv.cascades of this frame)",
                          "dump");
    const renderer::LpvSnapshot* snapshot = setup->renderer->lpvSnapshot();
    if (!snapshot) {
        std::cerr << "lpv: the renderer returned no read-back of cascade " << spec.cascade << "\n";
        return kFailure;
    }
    const int count = renderer::viz::sliceCount(*snapshot, spec.source);
    spec.slice.index = slice.value_or(count / 2);
    if (spec.slice.index < 0 || spec.slice.index >= count)
        return usageError("--slice " + std::to_string(spec.slice.index) + " is outside 0.." +
                              std::to_string(count - 1),
                          "dump");
    renderer::viz::SliceRange range;
    auto image = renderer::viz::renderLpvView(*snapshot, spec, &range);
    if (!image) {
        std::cerr << "lpv: " << image.error().describe() << "\n";
        return kFailure;
    }
    std::printf("%s\ncolour range %g .. %g\n", renderer::viz::viewTitle(*snapshot, spec).c_str(),
                double(range.low), double(range.high));
    return writePng(*output, *image) ? kOk : kFailure;
}

} // namespace lpv::cli
