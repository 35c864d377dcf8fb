// `lpv dump`: the editor's visualizers from the command line. The pictures
// come from the same code as the Visualizers dock (renderer/viz), so a dump
// and the dock show the same pixels for the same choices.
#include "Cli.h"
#include "RenderSetup.h"

#include "lpv/importers/ImageIO.h"
#include "lpv/renderer/viz/LpvViews.h"
#include "lpv/renderer/viz/TileImages.h"

#include <charconv>
#include <cstdio>
#include <iostream>
#include <sstream>

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

std::optional<int> parseInt(const std::string& s) {
    int v = 0;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size())
        return std::nullopt;
    return v;
}

std::optional<float> parseFloat(const std::string& s) {
    float v = 0.0f;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size())
        return std::nullopt;
    return v;
}

std::optional<glm::vec3> parseDirection(const std::string& s) {
    std::vector<float> parts;
    std::stringstream in(s);
    std::string item;
    while (std::getline(in, item, ','))
        if (auto v = parseFloat(item))
            parts.push_back(*v);
        else
            return std::nullopt;
    if (parts.size() != 3)
        return std::nullopt;
    return glm::vec3(parts[0], parts[1], parts[2]);
}

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
    auto output = args.option("--output");
    if (auto o = args.option("-o"))
        output = o;
    const auto what = args.option("--what");
    const auto cascadeText = args.option("--cascade");
    const auto axisText = args.option("--axis");
    const auto sliceText = args.option("--slice");
    const auto sourceText = args.option("--source");
    const auto stepText = args.option("--step");
    const auto quantityText = args.option("--quantity");
    const auto coefficientText = args.option("--coefficient");
    const auto directionText = args.option("--direction");
    const auto channelText = args.option("--channel");
    const auto scaleText = args.option("--scale");
    const auto maxText = args.option("--max");
    const auto cellPixelsText = args.option("--cell-pixels");
    const auto maxTileText = args.option("--max-tile");
    const auto thresholdText = args.option("--wall-threshold");
    const auto widthText = args.option("--width");
    const auto heightText = args.option("--height");
    const auto framesText = args.option("--frames");
    const bool grey = args.flag("--grey");
    RenderRequest request;
    request.cameraName = args.option("--camera");
    request.sets = args.options("--set");
    if (!args.missingValue().empty())
        return usageError(args.missingValue() + " needs a value", "dump");
    if (auto unknown = args.unknownOption())
        return usageError("unknown option '" + *unknown + "'", "dump");
    const auto pos = args.positionals();
    if (pos.size() != 1)
        return usageError("expected exactly one project file", "dump");
    if (!output)
        return usageError("missing -o OUT.png", "dump");
    if (!what)
        return usageError("missing --what lpv|gv|leak|backside|rsm|shadow", "dump");
    const std::string view = *what;
    const bool isSlice = view == "lpv" || view == "gv" || view == "leak" || view == "backside";
    if (!isSlice && view != "rsm" && view != "shadow")
        return usageError("--what: unknown view '" + view + "' (lpv, gv, leak, backside, rsm, shadow)",
                          "dump");

    renderer::viz::LpvViewSpec spec;
    spec.colour.pixelsPerCell = 12;
    const auto cascade = parseInt(cascadeText.value_or("0"));
    if (!cascade || *cascade < 0)
        return usageError("--cascade must be a non-negative integer", "dump");
    spec.cascade = *cascade;
    if (view == "gv")
        spec.source = renderer::viz::LpvSource::Geometry;
    else if (view == "leak")
        spec.source = renderer::viz::LpvSource::LeakHeat;
    else if (view == "backside")
        spec.source = renderer::viz::LpvSource::Backside;
    if (sourceText) {
        const auto source = renderer::viz::sourceFromName(*sourceText);
        if (view != "lpv" || !source || int(*source) > int(renderer::viz::LpvSource::Accumulated))
            return usageError("--source is injected, step or accumulated, with --what lpv", "dump");
        spec.source = *source;
    }
    if (stepText) {
        const auto step = parseInt(*stepText);
        if (!step || *step < 0)
            return usageError("--step must be a non-negative integer", "dump");
        spec.step = *step;
    }
    if (axisText) {
        const auto axis = renderer::viz::axisFromName(*axisText);
        if (!axis)
            return usageError("--axis must be x, y or z", "dump");
        spec.slice.axis = *axis;
    }
    std::optional<int> slice;
    if (sliceText) {
        slice = parseInt(*sliceText);
        if (!slice)
            return usageError("--slice must be an integer", "dump");
    }
    if (quantityText) {
        const auto q = renderer::viz::quantityFromName(*quantityText);
        if (!q)
            return usageError("--quantity must be band0, coefficient or directional", "dump");
        spec.slice.quantity = *q;
    }
    if (coefficientText) {
        const auto k = parseInt(*coefficientText);
        if (!k || *k < 0 || *k > 3)
            return usageError("--coefficient must be 0, 1, 2 or 3", "dump");
        spec.slice.coefficient = *k;
    }
    if (directionText) {
        const auto d = parseDirection(*directionText);
        if (!d || glm::length(*d) < 1e-6f)
            return usageError("--direction must be X,Y,Z, not all zero", "dump");
        spec.slice.direction = *d;
    }
    if (channelText) {
        const auto c = renderer::viz::channelFromName(*channelText);
        if (!c)
            return usageError("--channel must be red, green, blue, luminance or rgb", "dump");
        spec.slice.channel = *c;
    }
    if (scaleText) {
        if (*scaleText != "linear" && *scaleText != "log")
            return usageError("--scale must be linear or log", "dump");
        spec.colour.scale = *scaleText == "log" ? renderer::viz::Scale::Log : renderer::viz::Scale::Linear;
    }
    if (maxText) {
        const auto m = parseFloat(*maxText);
        if (!m || *m <= 0.0f)
            return usageError("--max must be a positive number", "dump");
        spec.colour.rangeMax = *m;
    }
    if (cellPixelsText) {
        const auto p = parseInt(*cellPixelsText);
        if (!p || *p < 1 || *p > 64)
            return usageError("--cell-pixels must be 1..64", "dump");
        spec.colour.pixelsPerCell = *p;
    }
    if (thresholdText) {
        const auto t = parseFloat(*thresholdText);
        if (!t || *t < 0.0f || *t > 1.0f)
            return usageError("--wall-threshold must be in 0..1", "dump");
        spec.wallThreshold = *t;
    }
    const auto maxTile = parseInt(maxTileText.value_or("0"));
    if (!maxTile || *maxTile < 0)
        return usageError("--max-tile must be a non-negative integer", "dump");
    spec.colour.falseColour = !grey;
    const auto width = parseInt(widthText.value_or("1280"));
    const auto height = parseInt(heightText.value_or("720"));
    const auto frames = parseInt(framesText.value_or("2"));
    if (!width || !height || *width <= 0 || *height <= 0)
        return usageError("--width and --height must be positive integers", "dump");
    if (!frames || *frames <= 0)
        return usageError("--frames must be a positive integer", "dump");

    request.projectFile = pos.front();
    int exitCode = kOk;
    auto setup = prepareRender(request, "dump", exitCode);
    if (!setup)
        return exitCode;
    if (isSlice)
        setup->renderer->setLpvCapture(renderer::viz::captureFor(spec));
    if (!renderFrames(*setup, *width, *height, *frames))
        return kFailure;
    std::printf("%s\n", setup->renderer->lpvNote().c_str());

    if (view == "shadow") {
        const auto images = setup->renderer->debugImages("shadowMaps");
        if (images.empty()) {
            std::cerr << "lpv: " << pos.front()
                      << ": no shadow maps (the scene has no light that casts shadows)\n";
            return kFailure;
        }
        return writePng(*output, renderer::viz::tileRow(images, *maxTile)) ? kOk : kFailure;
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
        return writePng(*output, renderer::viz::tileRow(tiles, *maxTile)) ? kOk : kFailure;
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
