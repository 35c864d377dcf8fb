#include "lpv/bench/FlickerSweep.h"

#include "Pixels.h"
#include "SceneRenderer.h"

#include "lpv/importers/SceneTextures.h"
#include "lpv/reference/Flicker.h"
#include "lpv/reference/Metrics.h"
#include "lpv/renderer/ForwardRenderer.h"
#include "lpv/scene/CameraSpline.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace lpv::bench {

namespace {

// Directional lights turned by `degrees` about +y, from their directions in `lights`.
std::vector<scene::Light> turnedSun(const std::vector<scene::Light>& lights, float degrees) {
    std::vector<scene::Light> out = lights;
    const glm::mat4 r = glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0, 1, 0));
    for (scene::Light& l : out)
        if (l.type == scene::LightType::Directional)
            l.direction = glm::vec3(r * glm::vec4(l.direction, 0.0f));
    return out;
}

} // namespace

std::string flickerLabel(const std::vector<Setting>& settings) {
    std::string s;
    for (const auto& [key, value] : settings)
        s += (s.empty() ? "" : " ") + key + "=" + value;
    return s.empty() ? "defaults" : s;
}

std::string describeMotion(const FlickerSpec& spec) {
    if (spec.path)
        return "camera path '" + spec.path->name + "', " + std::to_string(spec.frames) + " frames at " +
               std::to_string(spec.fps) + " fps from its start";
    char buf[160];
    std::snprintf(buf, sizeof buf,
                  "fixed camera, sun turning %g degrees about the vertical in %d frames (%.3g per frame)",
                  double(spec.sunDegrees), spec.frames, double(spec.sunDegrees) / double(spec.frames - 1));
    return buf;
}

scene::Expected<FlickerResult> runFlicker(const FlickerSpec& spec, const reference::ReferenceImage* ref,
                                          const FlickerCallbacks& callbacks) {
    auto invalid = [](const std::string& message) {
        return scene::makeError(scene::ErrorCode::InvalidValue, "", "flicker", message);
    };
    if (spec.frames < 2)
        return invalid("flicker needs at least 2 frames (1 pair)");
    if (ref && (ref->width != spec.width || ref->height != spec.height))
        return invalid("the reference is " + std::to_string(ref->width) + "x" + std::to_string(ref->height) +
                       "; give the same size");
    if (!spec.path && std::ranges::none_of(spec.project.scene.lights, [](const scene::Light& l) {
            return l.type == scene::LightType::Directional;
        }))
        return invalid("turning the sun needs a directional light");
    scene::Scene scene = spec.project.scene; // the sun turns in this copy
    auto opened = openSceneRenderer(scene, spec.projectDir, callbacks.warning);
    if (!opened)
        return std::unexpected(opened.error());
    renderer::HeadlessContext* context = &(*opened)->context;
    renderer::ForwardRenderer* forward = &(*opened)->renderer;
    std::optional<scene::CameraSpline> spline;
    if (spec.path)
        spline.emplace(*spec.path);

    const std::vector<std::vector<Setting>> combinations =
        spec.combinations.empty() ? std::vector<std::vector<Setting>>{{}} : spec.combinations;
    const float aspect = float(spec.width) / float(spec.height);
    FlickerResult result;
    result.gl = context->info();
    for (std::size_t c = 0; c < combinations.size(); ++c) {
        FlickerRun run;
        run.settings = spec.fixed;
        run.settings.insert(run.settings.end(), combinations[c].begin(), combinations[c].end());
        if (callbacks.progress && !callbacks.progress(int(c), int(combinations.size()), flickerLabel(run.settings)))
            return scene::makeError(scene::ErrorCode::Cancelled, "", "", "stopped");
        scene::ParameterSet parameters = spec.project.parameters;
        for (const auto& [key, value] : combinations[c])
            (void)parameters.setFromText(key, value, "--set");
        (void)parameters.setFromText("output.view", "indirect", "flicker");
        scene::Camera camera = spec.camera;
        auto placeFrame = [&](int i) {
            if (spline)
                camera = spline->cameraAt(spline->startTime() + float(i) / float(spec.fps), spec.camera);
            else
                scene.lights = turnedSun(spec.project.scene.lights, spec.sunDegrees * float(i) / float(spec.frames - 1));
        };
        auto frame = [&]() -> scene::Expected<void> {
            if (auto ok = forward->render(scene, parameters, camera, spec.width, spec.height); !ok)
                return std::unexpected(ok.error());
            forward->timer().resolveAll();
            return {};
        };
        // Warm-up at the first frame: the geometry volume also reads the previous frame's G-buffer.
        placeFrame(0);
        for (int w = 0; w < 2; ++w)
            if (auto ok = frame(); !ok)
                return std::unexpected(ok.error());
        forward->timer().clearHistory();
        std::vector<glm::vec3> indirect[2], position[2], normal[2];
        reference::FlickerFrame frames[2];
        int pairs = 0;
        for (int i = 0; i < spec.frames; ++i) {
            placeFrame(i);
            if (auto ok = frame(); !ok)
                return std::unexpected(ok.error());
            const int k = i % 2;
            indirect[k] = rgbOf(forward->readHdr());
            normal[k] = rgbOf(forward->readGBufferNormal());
            const glm::mat4 viewProjection = camera.projection(aspect) * camera.view();
            position[k] = reference::positionsFromDepth(forward->readDepth(), spec.width, spec.height,
                                                        glm::inverse(viewProjection));
            frames[k] = {spec.width, spec.height, &indirect[k], &position[k], &normal[k], viewProjection,
                         camera.position};
            if (i == 0 && ref)
                run.mare = reference::compareImages({spec.width, spec.height, &indirect[0]},
                                                    {ref->width, ref->height, &ref->indirectMulti},
                                                    &ref->indirectMultiVariance, &ref->coverage)
                               .mare;
            if (i == 0)
                continue;
            const reference::FlickerResult f = reference::measureFlicker(frames[1 - k], frames[k]);
            run.meanFlicker += f.meanRelativeChange;
            run.worstFlicker = std::max(run.worstFlicker, f.meanRelativeChange);
            run.p95Flicker += f.p95RelativeChange;
            run.keptFraction += f.candidates ? double(f.pixels) / double(f.candidates) : 0.0;
            ++pairs;
        }
        run.meanFlicker /= pairs;
        run.p95Flicker /= pairs;
        run.keptFraction /= pairs;
        for (const auto& p : forward->timer().table())
            if (p.samples > 0)
                run.totalMs += p.medianMs;
        if (callbacks.runDone)
            callbacks.runDone(run);
        result.runs.push_back(std::move(run));
    }
    return result;
}

std::string flickerMarkdown(const std::vector<FlickerRun>& runs, const std::string& command,
                            const std::string& machine, const std::string& motion) {
    std::ostringstream out;
    char buf[512];
    out << "# Flicker of the indirect light\n\n`" << command << "`\n\nMachine: " << machine
        << "\n\nMotion: " << motion
        << "\n\n| settings | flicker mean | worst pair | p95 | pixels kept | total GPU ms | indirect "
        << "MARE |\n|---|---:|---:|---:|---:|---:|---:|\n";
    for (const FlickerRun& r : runs) {
        std::snprintf(buf, sizeof buf, "| %s | %.2f%% | %.2f%% | %.2f%% | %.0f%% | %.3f | %s |\n",
                      flickerLabel(r.settings).c_str(), 100.0 * r.meanFlicker, 100.0 * r.worstFlicker,
                      100.0 * r.p95Flicker, 100.0 * r.keptFraction, r.totalMs,
                      r.mare ? (std::to_string(100.0 * *r.mare).substr(0, 5) + "%").c_str() : "-");
        out << buf;
    }
    return out.str();
}

std::string flickerCsv(const std::vector<FlickerRun>& runs) {
    std::ostringstream out;
    out << "settings,flicker_mean,flicker_worst_pair,flicker_p95,kept_fraction,total_ms,indirect_mare\n";
    for (const FlickerRun& r : runs)
        out << '"' << flickerLabel(r.settings) << "\"," << r.meanFlicker << "," << r.worstFlicker << ","
            << r.p95Flicker << "," << r.keptFraction << "," << r.totalMs << ","
            << (r.mare ? std::to_string(*r.mare) : "") << "\n";
    return out.str();
}

} // namespace lpv::bench
