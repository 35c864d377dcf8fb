// Per-vertex tangents from uv derivatives (MeshCleanupDetail.h).
//
// Each triangle gives the directions of increasing u (T) and v (B) across it.
// Each corner projects T into the plane of its normal; a vertex (a group of
// corners with equal position, normal and uv) averages them, weighted by the
// corner angle, separately per handedness: where the uvs are mirrored the two
// sides disagree, and one vertex with an averaged tangent would be wrong on
// both, so the vertex gets one tangent per sign (the weld then makes two
// vertices of it).
#include "MeshCleanupDetail.h"

#include <cmath>
#include <optional>

namespace lpv::importers::detail {
namespace {

// UV triangles thinner than this (|uv cross| over the squared uv edges) have no
// usable derivative; float uvs of collinear points land around 1e-7.
constexpr double kMinRelativeUvArea = 1e-6;

struct UvFrame {
    glm::dvec3 tangent;   // d position / d u
    glm::dvec3 faceCross; // (p1 - p0) x (p2 - p0)
    double uvCross;       // signed: negative where the uvs are mirrored
};

bool isFinite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::optional<UvFrame> uvFrame(const TangentInput& in, std::size_t firstCorner) {
    if (in.uvs.empty())
        return std::nullopt;
    const glm::dvec3 p0(in.positions[firstCorner]);
    const glm::dvec3 e1 = glm::dvec3(in.positions[firstCorner + 1]) - p0;
    const glm::dvec3 e2 = glm::dvec3(in.positions[firstCorner + 2]) - p0;
    const glm::dvec2 w0(in.uvs[firstCorner]);
    const glm::dvec2 d1 = glm::dvec2(in.uvs[firstCorner + 1]) - w0;
    const glm::dvec2 d2 = glm::dvec2(in.uvs[firstCorner + 2]) - w0;
    const double r = d1.x * d2.y - d2.x * d1.y;
    if (!std::isfinite(r) || !(std::abs(r) > kMinRelativeUvArea * (glm::dot(d1, d1) + glm::dot(d2, d2))))
        return std::nullopt;
    const glm::dvec3 tangent = (e1 * d2.y - e2 * d1.y) / r;
    if (!isFinite(tangent))
        return std::nullopt;
    return UvFrame{tangent, glm::cross(e1, e2), r};
}

// The handedness w such that w * cross(n, T) points along increasing v. Since
// cross(T, B) = faceCross / uvCross, it is the sign of dot(n, faceCross) / uvCross.
float handedness(const UvFrame& f, const glm::vec3& n) {
    const double facing = glm::dot(glm::dvec3(n), f.faceCross);
    // A normal in the face's plane (facing == 0) leaves the decision to the uvs.
    const bool flipped = (f.uvCross < 0.0) != (facing < 0.0);
    return flipped ? -1.0f : 1.0f;
}

class TangentAccumulator {
public:
    explicit TangentAccumulator(const TangentInput& in)
        : in_(in), sums_(2 * std::size_t(in.groupCount), glm::dvec3(0.0)), signsSeen_(in.groupCount, 0),
          slotOfCorner_(in.positions.size(), 0) {}

    std::vector<glm::vec4> run() {
        std::vector<std::uint8_t> withoutFrame(in_.positions.size(), 0);
        for (std::size_t t = 0; t + 2 < in_.positions.size(); t += 3)
            accumulateTriangle(t, withoutFrame);
        // Corners without uv derivatives join a tangent their vertex already
        // has (preferring +1) rather than splitting it further.
        for (std::size_t c = 0; c < withoutFrame.size(); ++c)
            if (withoutFrame[c])
                slotOfCorner_[c] = slot(in_.groups[c], signsSeen_[in_.groups[c]] == 2 ? -1.0f : 1.0f);
        return finish();
    }

private:
    std::size_t slot(std::uint32_t group, float sign) const { return 2 * std::size_t(group) + (sign < 0 ? 1 : 0); }

    void accumulateTriangle(std::size_t t, std::vector<std::uint8_t>& withoutFrame) {
        const std::optional<UvFrame> frame = uvFrame(in_, t);
        for (std::size_t c = t; c < t + 3; ++c) {
            if (!in_.wanted[c])
                continue;
            if (!frame) {
                withoutFrame[c] = 1;
                continue;
            }
            const glm::dvec3 n(in_.normals[c]);
            const float sign = handedness(*frame, in_.normals[c]);
            const std::uint32_t group = in_.groups[c];
            signsSeen_[group] |= sign > 0 ? 1 : 2;
            slotOfCorner_[c] = slot(group, sign);
            // Project per corner (Gram-Schmidt) so that a steep T does not
            // outweigh the others after the projection.
            const glm::dvec3 projected = frame->tangent - n * glm::dot(n, frame->tangent);
            const double length = glm::length(projected);
            if (std::isfinite(length) && length > 0.0)
                sums_[slotOfCorner_[c]] += in_.angles[c] * (projected / length);
        }
    }

    // One tangent per slot, computed once, so that the corners of a slot share its bits.
    std::vector<glm::vec4> finish() const {
        std::vector<glm::vec4> slotTangent(sums_.size());
        std::vector<std::uint8_t> slotDone(sums_.size(), 0);
        std::vector<glm::vec4> out(in_.positions.size(), glm::vec4(0.0f));
        for (std::size_t c = 0; c < out.size(); ++c) {
            if (!in_.wanted[c])
                continue;
            const std::size_t s = slotOfCorner_[c];
            if (!slotDone[s]) {
                slotTangent[s] = orthonormalTangent(sums_[s], in_.normals[c], s % 2 == 1 ? -1.0f : 1.0f);
                slotDone[s] = 1;
            }
            out[c] = slotTangent[s];
        }
        return out;
    }

    static glm::vec4 orthonormalTangent(const glm::dvec3& sum, const glm::vec3& normal, float sign) {
        const glm::dvec3 n(normal);
        const glm::dvec3 t = sum - n * glm::dot(n, sum);
        const double length = glm::length(t);
        // Degenerate uvs (or none): any tangent in the plane still gives a valid frame.
        const glm::vec3 xyz = std::isfinite(length) && length > 1e-12 ? glm::vec3(t / length) : anyPerpendicular(normal);
        return {xyz, sign};
    }

    const TangentInput& in_;
    std::vector<glm::dvec3> sums_;         // two slots per group: w = +1, w = -1
    std::vector<std::uint8_t> signsSeen_;  // per group: bit 0 = +1 seen, bit 1 = -1 seen
    std::vector<std::size_t> slotOfCorner_;
};

} // namespace

std::vector<glm::vec4> generateCornerTangents(const TangentInput& input) {
    return TangentAccumulator(input).run();
}

} // namespace lpv::importers::detail
