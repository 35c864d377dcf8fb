// Camera path playback; the method is described in CameraSpline.h and
// docs/camera-paths.md.
#include "lpv/scene/CameraSpline.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>

namespace lpv::scene {
namespace {

// Arc-length table resolution for constant speed; each interval is also
// integrated with 3-point Gauss-Legendre, so the table is exact to about 1e-7.
constexpr int kArcSamplesPerSegment = 64;
// Knot interval of two keys at the same position: keeps the centripetal
// tangents finite (they go to zero with the distance anyway).
constexpr float kMinKnotInterval = 1e-6f;
// Fields of view outside this give a degenerate projection.
constexpr float kMinFov = 1e-4f;
constexpr float kMaxFov = std::numbers::pi_v<float> - 1e-4f;

// Cubic Hermite basis on [0, 1] and its derivative.
struct Hermite {
    float h00, h10, h01, h11;
};
Hermite hermite(float t) {
    const float t2 = t * t, t3 = t2 * t;
    return {2 * t3 - 3 * t2 + 1, t3 - 2 * t2 + t, -2 * t3 + 3 * t2, t3 - t2};
}
Hermite hermiteDerivative(float t) {
    const float t2 = t * t;
    return {6 * t2 - 6 * t, 3 * t2 - 4 * t + 1, -6 * t2 + 6 * t, 3 * t2 - 2 * t};
}

// Slope at a key of the monotone piecewise cubic (PCHIP, Fritsch-Butland):
// the weighted harmonic mean of the two neighbouring secants, zero at a local
// extremum. Never overshoots, and continuous in the first derivative.
float pchipSlope(float hIn, float secantIn, float hOut, float secantOut) {
    if (secantIn * secantOut <= 0.0f)
        return 0.0f;
    const float w1 = 2.0f * hOut + hIn;
    const float w2 = hOut + 2.0f * hIn;
    return (w1 + w2) / (w1 / secantIn + w2 / secantOut);
}

// Quaternion logarithm of a unit quaternion with w >= 0 (half the rotation
// vector) and its inverse.
glm::vec3 logOf(const glm::quat& q) {
    const glm::vec3 v(q.x, q.y, q.z);
    const float s = glm::length(v);
    if (s < 1e-7f)
        return v;
    return v * (std::atan2(s, q.w) / s);
}
glm::quat expOf(const glm::vec3& v) {
    const float angle = glm::length(v);
    if (angle < 1e-7f)
        return glm::normalize(glm::quat(1.0f, v.x, v.y, v.z));
    const glm::vec3 axis = v * (std::sin(angle) / angle);
    return glm::quat(std::cos(angle), axis.x, axis.y, axis.z);
}

// Geodesic between a and b exactly as given (no sign flip: the Bezier
// control points are already in one hemisphere, and flipping inside De
// Casteljau would break continuity).
glm::quat slerpAsGiven(const glm::quat& a, const glm::quat& b, float t) {
    const float cosTheta = std::clamp(glm::dot(a, b), -1.0f, 1.0f);
    if (cosTheta > 0.9995f)
        return glm::normalize(a * (1.0f - t) + b * t);
    const float theta = std::acos(cosTheta);
    const float sinTheta = std::sin(theta);
    if (sinTheta < 1e-6f)
        return a;
    return a * (std::sin((1.0f - t) * theta) / sinTheta) + b * (std::sin(t * theta) / sinTheta);
}

glm::quat normalisedOrIdentity(const glm::quat& q) {
    const float len = glm::length(q);
    if (!(len > 0.0f) || !std::isfinite(len))
        return glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    return q / len;
}

} // namespace

glm::vec3 forwardOf(const glm::quat& orientation) {
    return orientation * glm::vec3(0.0f, 0.0f, -1.0f);
}
glm::vec3 upOf(const glm::quat& orientation) {
    return orientation * glm::vec3(0.0f, 1.0f, 0.0f);
}

CameraSpline::CameraSpline(const CameraPath& path)
    : keys_(path.keyframes), closed_(path.closed), constantSpeed_(path.constantSpeed) {
    const std::size_t n = keys_.size();
    if (n == 0)
        return;
    // Each key in the hemisphere of the one before: the output is then sign-
    // continuous, and every segment interpolates the short way.
    keys_[0].orientation = normalisedOrIdentity(keys_[0].orientation);
    for (std::size_t i = 1; i < n; ++i) {
        glm::quat q = normalisedOrIdentity(keys_[i].orientation);
        if (glm::dot(keys_[i - 1].orientation, q) < 0.0f)
            q = -q;
        keys_[i].orientation = q;
    }
    start_ = keys_[0].time;
    if (n == 1)
        return;

    // --- segments and their durations ---
    const std::size_t count = closed_ ? n : n - 1;
    const float closingDuration =
        std::max(0.0f, (keys_[n - 1].time - keys_[0].time) / static_cast<float>(n - 1));
    segments_.resize(count);
    std::vector<float> knot(count);         // centripetal knot intervals
    std::vector<glm::vec3> rotation(count); // log of the relative rotation of each segment
    for (std::size_t i = 0; i < count; ++i) {
        Segment& s = segments_[i];
        s.from = i;
        s.to = (i + 1) % n;
        s.start = keys_[i].time;
        s.duration = i + 1 < n ? std::max(0.0f, keys_[i + 1].time - keys_[i].time) : closingDuration;
        duration_ += s.duration;
        knot[i] = std::max(std::sqrt(glm::distance(keys_[s.from].position, keys_[s.to].position)),
                           kMinKnotInterval);
        s.q0 = keys_[s.from].orientation;
        s.q3 = keys_[s.to].orientation;
        if (glm::dot(s.q0, s.q3) < 0.0f) // only the closing segment can need this
            s.q3 = -s.q3;
        rotation[i] = logOf(glm::conjugate(s.q0) * s.q3);
    }

    // A key's neighbouring segments, if they are connected (a cut is an end).
    const auto incoming = [&](std::size_t k) -> std::optional<std::size_t> {
        if (k == 0 && !closed_)
            return std::nullopt;
        const std::size_t s = k == 0 ? count - 1 : k - 1;
        return segments_[s].duration > 0.0f ? std::optional(s) : std::nullopt;
    };
    const auto outgoing = [&](std::size_t k) -> std::optional<std::size_t> {
        if (k >= count)
            return std::nullopt;
        return segments_[k].duration > 0.0f ? std::optional(k) : std::nullopt;
    };

    // --- per-key derivatives ---
    std::vector<glm::vec3> tangent(n, glm::vec3(0.0f));     // dP/ds, s the centripetal curve parameter
    std::vector<float> curveRate(n, 0.0f);                  // ds/dt
    std::vector<glm::vec3> angularRate(n, glm::vec3(0.0f)); // d log(q) / dt, body frame
    std::vector<float> fovRate(n, 0.0f);                    // dfov/dt
    for (std::size_t k = 0; k < n; ++k) {
        const auto in = incoming(k);
        const auto out = outgoing(k);
        const glm::vec3 p = keys_[k].position;
        if (in && out) {
            const Segment& a = segments_[*in];
            const Segment& b = segments_[*out];
            const glm::vec3 prev = keys_[a.from].position;
            const glm::vec3 next = keys_[b.to].position;
            const float da = knot[*in], db = knot[*out];
            const float ha = a.duration, hb = b.duration;
            // Barry-Goldman: the tangent of the Catmull-Rom curve with knots da, db.
            tangent[k] = (p - prev) / da - (next - prev) / (da + db) + (next - p) / db;
            curveRate[k] = pchipSlope(ha, da / ha, hb, db / hb);
            angularRate[k] = (rotation[*in] / ha * hb + rotation[*out] / hb * ha) / (ha + hb);
            fovRate[k] = pchipSlope(ha, (keys_[k].fovY - keys_[a.from].fovY) / ha, hb,
                                    (keys_[b.to].fovY - keys_[k].fovY) / hb);
        } else if (out) {
            // Reflected phantom key before the first: the tangent is the chord.
            const Segment& b = segments_[*out];
            tangent[k] = (keys_[b.to].position - p) / knot[*out];
            curveRate[k] = knot[*out] / b.duration;
            angularRate[k] = rotation[*out] / b.duration;
            fovRate[k] = (keys_[b.to].fovY - keys_[k].fovY) / b.duration;
        } else if (in) {
            const Segment& a = segments_[*in];
            tangent[k] = (p - keys_[a.from].position) / knot[*in];
            curveRate[k] = knot[*in] / a.duration;
            angularRate[k] = rotation[*in] / a.duration;
            fovRate[k] = (keys_[k].fovY - keys_[a.from].fovY) / a.duration;
        }
    }

    // --- per-segment coefficients ---
    for (std::size_t i = 0; i < count; ++i) {
        Segment& s = segments_[i];
        s.tangentFrom = tangent[s.from] * knot[i];
        s.tangentTo = tangent[s.to] * knot[i];
        if (s.duration > 0.0f) {
            const float secant = knot[i] / s.duration;
            s.uSlopeFrom = curveRate[s.from] / secant;
            s.uSlopeTo = curveRate[s.to] / secant;
        }
        // Spherical Bezier: its derivative at each end is 3 log(q0^-1 q1) / duration = the key's angular
        // rate.
        s.q1 = s.q0 * expOf(angularRate[s.from] * (s.duration / 3.0f));
        s.q2 = s.q3 * expOf(-angularRate[s.to] * (s.duration / 3.0f));
        s.fovSlopeFrom = fovRate[s.from] * s.duration;
        s.fovSlopeTo = fovRate[s.to] * s.duration;
    }
    buildArcTable();
}

glm::vec3 CameraSpline::positionAt(const Segment& s, float tau) const {
    const Hermite ht = hermite(tau);
    const float u = ht.h10 * s.uSlopeFrom + ht.h01 + ht.h11 * s.uSlopeTo;
    const Hermite hu = hermite(u);
    return hu.h00 * keys_[s.from].position + hu.h10 * s.tangentFrom + hu.h01 * keys_[s.to].position +
           hu.h11 * s.tangentTo;
}

namespace {

// |dP/dtau| of the segment's position: the chain rule through u(tau).
struct SpeedOf {
    const glm::vec3& p0;
    const glm::vec3& t0;
    const glm::vec3& p1;
    const glm::vec3& t1;
    float uSlopeFrom, uSlopeTo;

    float operator()(float tau) const {
        const Hermite ht = hermite(tau);
        const Hermite dt = hermiteDerivative(tau);
        const float u = ht.h10 * uSlopeFrom + ht.h01 + ht.h11 * uSlopeTo;
        const float dudtau = dt.h10 * uSlopeFrom + dt.h01 + dt.h11 * uSlopeTo;
        const Hermite du = hermiteDerivative(u);
        return glm::length(du.h00 * p0 + du.h10 * t0 + du.h01 * p1 + du.h11 * t1) * dudtau;
    }
    // Arc length from a to b, 3-point Gauss-Legendre.
    float length(float a, float b) const {
        constexpr float x = 0.7745966692f; // sqrt(3/5)
        const float mid = 0.5f * (a + b), half = 0.5f * (b - a);
        return half * ((5.0f / 9.0f) * ((*this)(mid - half * x) + (*this)(mid + half * x)) +
                       (8.0f / 9.0f) * (*this)(mid));
    }
};

} // namespace

void CameraSpline::buildArcTable() {
    float total = 0.0f;
    for (std::size_t i = 0; i < segments_.size(); ++i) {
        const Segment& s = segments_[i];
        // A cut takes no time, so it has no place on the constant-speed clock either.
        if (s.duration <= 0.0f)
            continue;
        const SpeedOf speed{keys_[s.from].position, s.tangentFrom, keys_[s.to].position, s.tangentTo,
                            s.uSlopeFrom,           s.uSlopeTo};
        arcTable_.push_back({total, i, 0.0f});
        for (int k = 1; k <= kArcSamplesPerSegment; ++k) {
            const float a = static_cast<float>(k - 1) / kArcSamplesPerSegment;
            const float b = static_cast<float>(k) / kArcSamplesPerSegment;
            total += speed.length(a, b);
            arcTable_.push_back({total, i, b});
        }
    }
    length_ = total;
}

CameraKeyframe CameraSpline::evaluate(std::size_t segment, float tau) const {
    const Segment& s = segments_[segment];
    CameraKeyframe k;
    if (tau <= 0.0f) {
        k = keys_[s.from];
        k.orientation = s.q0;
        return k;
    }
    if (tau >= 1.0f) {
        k = keys_[s.to];
        k.orientation = s.q3;
        return k;
    }
    k.position = positionAt(s, tau);
    // De Casteljau on the sphere.
    const glm::quat a = slerpAsGiven(s.q0, s.q1, tau);
    const glm::quat b = slerpAsGiven(s.q1, s.q2, tau);
    const glm::quat c = slerpAsGiven(s.q2, s.q3, tau);
    const glm::quat d = slerpAsGiven(a, b, tau);
    const glm::quat e = slerpAsGiven(b, c, tau);
    k.orientation = glm::normalize(slerpAsGiven(d, e, tau));
    const Hermite h = hermite(tau);
    const float fov =
        h.h00 * keys_[s.from].fovY + h.h10 * s.fovSlopeFrom + h.h01 * keys_[s.to].fovY + h.h11 * s.fovSlopeTo;
    k.fovY = std::clamp(fov, kMinFov, kMaxFov);
    return k;
}

CameraKeyframe CameraSpline::sample(float time) const {
    CameraKeyframe out;
    if (keys_.empty()) {
        out.time = time;
        return out;
    }
    if (segments_.empty() || !std::isfinite(time)) {
        out = keys_.front();
        out.time = time;
        return out;
    }

    // Clamp (open) or wrap (closed) into [start, end].
    float t = time;
    if (closed_ && duration_ > 0.0f) {
        t = std::fmod(time - start_, duration_);
        if (t < 0.0f)
            t += duration_;
        t += start_;
    } else {
        t = std::clamp(time, start_, endTime());
    }

    std::size_t segment = 0;
    float tau = 0.0f;
    if (constantSpeed_ && length_ > 0.0f && duration_ > 0.0f && !arcTable_.empty()) {
        // Distance along the path grows linearly with time.
        const float target = std::clamp((t - start_) / duration_, 0.0f, 1.0f) * length_;
        const auto hi = std::lower_bound(arcTable_.begin(), arcTable_.end(), target,
                                         [](const ArcSample& a, float v) { return a.length < v; });
        if (hi == arcTable_.begin() || hi == arcTable_.end()) {
            const ArcSample& a = hi == arcTable_.end() ? arcTable_.back() : *hi;
            segment = a.segment;
            tau = a.tau;
        } else {
            const ArcSample& lo = *(hi - 1);
            segment = hi->segment;
            tau = hi->tau;
            if (lo.segment == hi->segment && hi->length > lo.length) {
                // Linear guess, then Newton steps on the integrated length.
                const Segment& s = segments_[segment];
                const SpeedOf speed{keys_[s.from].position, s.tangentFrom, keys_[s.to].position, s.tangentTo,
                                    s.uSlopeFrom,           s.uSlopeTo};
                tau = lo.tau + (hi->tau - lo.tau) * (target - lo.length) / (hi->length - lo.length);
                for (int iteration = 0; iteration < 2; ++iteration) {
                    const float v = speed(tau);
                    if (!(v > 0.0f))
                        break;
                    tau = std::clamp(tau - (lo.length + speed.length(lo.tau, tau) - target) / v, lo.tau,
                                     hi->tau);
                }
            }
        }
    } else {
        // The last segment that starts at or before t (at a cut, the later one).
        const auto next = std::upper_bound(segments_.begin(), segments_.end(), t,
                                           [](float v, const Segment& s) { return v < s.start; });
        segment = next == segments_.begin() ? 0 : static_cast<std::size_t>(next - segments_.begin()) - 1;
        const Segment& s = segments_[segment];
        tau = s.duration > 0.0f ? std::clamp((t - s.start) / s.duration, 0.0f, 1.0f) : 1.0f;
    }
    out = evaluate(segment, tau);
    out.time = time;
    return out;
}

Camera CameraSpline::cameraAt(float time, const Camera& base) const {
    if (keys_.empty())
        return base;
    const CameraKeyframe k = sample(time);
    Camera c = base;
    c.position = k.position;
    c.target = k.position + forwardOf(k.orientation);
    c.up = upOf(k.orientation);
    c.fovY = k.fovY;
    return c;
}

CameraKeyframe keyframeFromCamera(const Camera& camera, float time) {
    glm::vec3 forward = camera.target - camera.position;
    forward = glm::length(forward) > 0.0f ? glm::normalize(forward) : glm::vec3(0.0f, 0.0f, -1.0f);
    glm::vec3 up = camera.up;
    if (!(glm::length(glm::cross(forward, up)) > 1e-6f * glm::length(up)))
        up = std::abs(forward.y) < 0.99f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f);
    const glm::vec3 right = glm::normalize(glm::cross(forward, up));
    const glm::vec3 trueUp = glm::cross(right, forward);
    // Columns: where the camera's local X, Y and Z axes point (it looks down -Z).
    const glm::mat3 basis(right, trueUp, -forward);
    CameraKeyframe k;
    k.time = time;
    k.position = camera.position;
    k.orientation = glm::normalize(glm::quat_cast(basis));
    k.fovY = camera.fovY;
    return k;
}

} // namespace lpv::scene
