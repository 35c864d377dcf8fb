#include "VisualizerOverlay.h"

#include "lpv/renderer/lpv/Sh.h"

#include <QImage>
#include <QPainter>
#include <QPolygonF>

#include <algorithm>
#include <cmath>

namespace lpv::editor {

namespace {

// One colour per cascade, finest first.
QColor cascadeColour(int k) {
    static const QColor colours[] = {QColor(255, 90, 90),  QColor(90, 220, 90),  QColor(90, 150, 255),
                                     QColor(255, 210, 60), QColor(220, 90, 255), QColor(80, 230, 230)};
    return colours[std::size_t(k) % 6];
}

// World to widget pixels, with lines and polygons clipped to the view
// frustum (with a guard band): the cascades surround the camera, so most of
// their edges pass behind it or far outside the view, where QPainter would
// drop them (it refuses coordinates beyond +-32767).
struct Projector {
    glm::mat4 viewProj;
    QSizeF size;

    glm::vec4 clip(const glm::vec3& p) const { return viewProj * glm::vec4(p, 1.0f); }
    // Signed distances to the near plane and the four side planes (guard band 2x): >= 0 inside.
    static float plane(int i, const glm::vec4& c) {
        switch (i) {
        case 0:
            return c.z + c.w;
        case 1:
            return 2.0f * c.w + c.x;
        case 2:
            return 2.0f * c.w - c.x;
        case 3:
            return 2.0f * c.w + c.y;
        default:
            return 2.0f * c.w - c.y;
        }
    }
    QPointF toScreen(const glm::vec4& c) const {
        return QPointF((c.x / c.w * 0.5 + 0.5) * size.width(), (0.5 - c.y / c.w * 0.5) * size.height());
    }
    std::optional<QPointF> operator()(const glm::vec3& p) const {
        const glm::vec4 c = clip(p);
        for (int i = 0; i < 5; ++i)
            if (plane(i, c) < 0.0f)
                return std::nullopt;
        return toScreen(c);
    }
    void line(QPainter& painter, const glm::vec3& a, const glm::vec3& b) const {
        glm::vec4 ca = clip(a), cb = clip(b);
        for (int i = 0; i < 5; ++i) {
            const float da = plane(i, ca), db = plane(i, cb);
            if (da < 0.0f && db < 0.0f)
                return;
            if (da < 0.0f)
                ca = glm::mix(ca, cb, da / (da - db));
            else if (db < 0.0f)
                cb = glm::mix(ca, cb, da / (da - db));
        }
        if (ca.w <= 1e-6f || cb.w <= 1e-6f)
            return;
        painter.drawLine(toScreen(ca), toScreen(cb));
    }
    // Sutherland-Hodgman against the same planes.
    QPolygonF polygon(const std::vector<glm::vec3>& corners) const {
        std::vector<glm::vec4> in;
        for (const glm::vec3& p : corners)
            in.push_back(clip(p));
        for (int i = 0; i < 5 && !in.empty(); ++i) {
            std::vector<glm::vec4> out;
            for (std::size_t j = 0; j < in.size(); ++j) {
                const glm::vec4 &a = in[j], &b = in[(j + 1) % in.size()];
                const float da = plane(i, a), db = plane(i, b);
                if (da >= 0.0f)
                    out.push_back(a);
                if ((da < 0.0f) != (db < 0.0f))
                    out.push_back(glm::mix(a, b, da / (da - db)));
            }
            in = std::move(out);
        }
        QPolygonF polygon;
        for (const glm::vec4& c : in)
            if (c.w > 1e-6f)
                polygon << toScreen(c);
        return polygon;
    }
};

void drawBox(QPainter& painter, const Projector& project, const glm::vec3& lo, const glm::vec3& hi) {
    auto corner = [&](int i) {
        return glm::vec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
    };
    for (int i = 0; i < 8; ++i)
        for (int bit : {1, 2, 4})
            if (!(i & bit))
                project.line(painter, corner(i), corner(i | bit));
}

void drawSlicePlane(QPainter& painter, const Projector& project, const renderer::LpvGridFrame& g,
                    const SlicePlane& plane) {
    // The plane through the centres of the slice's cells (GV: through its cell centres, the LPV corners).
    const int axis = int(plane.axis);
    const float offset = plane.geometryVolume ? float(plane.index) : float(plane.index) + 0.5f;
    const float at = g.origin[axis] + offset * g.cellSize;
    const int u = axis == 0 ? 2 : 0, v = axis == 1 ? 2 : 1;
    std::vector<glm::vec3> corners;
    for (const glm::vec2 c : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(1, 1), glm::vec2(0, 1)}) {
        glm::vec3 p(0.0f);
        p[axis] = at;
        p[u] = g.origin[u] + c.x * g.extent();
        p[v] = g.origin[v] + c.y * g.extent();
        corners.push_back(p);
    }
    const QPolygonF polygon = project.polygon(corners);
    if (polygon.size() < 3)
        return;
    QColor fill = cascadeColour(plane.cascade);
    fill.setAlpha(60);
    painter.setBrush(fill);
    painter.setPen(QPen(cascadeColour(plane.cascade), 1.5));
    painter.drawPolygon(polygon);
    painter.setBrush(Qt::NoBrush);
}

// Spheres shaded per pixel by the SH of their cell: the irradiance on a
// surface with the sphere's normal there, as shading would compute it.
void drawProbes(QPainter& painter, const Projector& project, const scene::Camera& camera,
                const renderer::LpvSnapshot& lpv, int stride) {
    const renderer::LpvGridFrame& g = lpv.frame;
    const int n = g.gridSize;
    const auto& accum = lpv.accumulatedToStep;
    if (n <= 0 || accum[0].size() != std::size_t(n) * std::size_t(n) * std::size_t(n))
        return;
    const glm::mat4 inverseView = glm::inverse(camera.view());
    const glm::vec3 right(inverseView[0]), up(inverseView[1]), back(inverseView[2]);
    struct Probe {
        std::size_t cell;
        QPointF centre;
        float radius;
        float depth;
    };
    std::vector<Probe> probes;
    float brightest = 0.0f;
    const int step = std::max(stride, 1);
    for (int z = step / 2; z < n; z += step)
        for (int y = step / 2; y < n; y += step)
            for (int x = step / 2; x < n; x += step) {
                const glm::vec3 centre = g.origin + (glm::vec3(x, y, z) + 0.5f) * g.cellSize;
                const auto c = project(centre);
                const auto edge = project(centre + right * (0.3f * g.cellSize * float(step)));
                if (!c || !edge)
                    continue;
                const float radius =
                    std::clamp(float(std::hypot(edge->x() - c->x(), edge->y() - c->y())), 2.0f, 14.0f);
                const std::size_t cell =
                    std::size_t(x) + std::size_t(n) * (std::size_t(y) + std::size_t(n) * std::size_t(z));
                probes.push_back({cell, *c, radius, glm::length(centre - camera.position)});
                for (int ch = 0; ch < 3; ++ch)
                    brightest =
                        std::max(brightest, accum[std::size_t(ch)][cell].x * renderer::sh::kCos0 * 2.0f);
            }
    if (brightest <= 0.0f)
        return;
    // Cells with next to no light would be black dots over the scene: left out.
    std::erase_if(probes, [&](const Probe& p) {
        float dc = 0.0f;
        for (int ch = 0; ch < 3; ++ch)
            dc = std::max(dc, accum[std::size_t(ch)][p.cell].x * renderer::sh::kCos0 * 2.0f);
        return dc < 0.01f * brightest;
    });
    // Far probes first, so near ones cover them.
    std::sort(probes.begin(), probes.end(), [](const Probe& a, const Probe& b) { return a.depth > b.depth; });
    for (const Probe& p : probes) {
        const int r = int(std::ceil(p.radius)), side = 2 * r + 1;
        QImage sphere(side, side, QImage::Format_ARGB32_Premultiplied);
        sphere.fill(Qt::transparent);
        for (int py = 0; py < side; ++py)
            for (int px = 0; px < side; ++px) {
                const float sx = (float(px - r)) / p.radius, sy = -(float(py - r)) / p.radius;
                const float rr = sx * sx + sy * sy;
                if (rr > 1.0f)
                    continue;
                const glm::vec3 normal = glm::normalize(right * sx + up * sy + back * std::sqrt(1.0f - rr));
                int rgb[3];
                for (int ch = 0; ch < 3; ++ch) {
                    const float e =
                        renderer::sh::irradiance(accum[std::size_t(ch)][p.cell], normal) / brightest;
                    // Gamma so that dim probes still read; the same scale for every probe.
                    rgb[ch] = int(std::lround(std::pow(std::clamp(e, 0.0f, 1.0f), 1.0f / 2.2f) * 255.0f));
                }
                sphere.setPixel(px, py, qRgba(rgb[0], rgb[1], rgb[2], 255));
            }
        painter.drawImage(QPointF(p.centre.x() - r, p.centre.y() - r), sphere);
    }
}

} // namespace

void drawVisualizerOverlay(QPainter& painter, const VisualizerRequest& request, const VisualizerFrame* frame,
                           const scene::Camera& camera, const QSizeF& size) {
    if (!frame || !request.active())
        return;
    const Projector project{
        camera.projection(float(size.width() / std::max(size.height(), 1.0))) * camera.view(), size};
    painter.save();
    if (request.cascadeBounds)
        for (std::size_t k = 0; k < frame->cascades.size(); ++k) {
            const renderer::LpvGridFrame& g = frame->cascades[k];
            painter.setPen(QPen(cascadeColour(int(k)), 1.5, Qt::DashLine));
            drawBox(painter, project, g.origin, g.origin + glm::vec3(g.extent()));
        }
    if (request.slicePlane && request.slicePlane->cascade >= 0 &&
        std::size_t(request.slicePlane->cascade) < frame->cascades.size())
        drawSlicePlane(painter, project, frame->cascades[std::size_t(request.slicePlane->cascade)],
                       *request.slicePlane);
    if (request.probes && frame->lpv)
        drawProbes(painter, project, camera, *frame->lpv, request.probeStride);
    painter.restore();
}

} // namespace lpv::editor
