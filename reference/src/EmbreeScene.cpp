#include "lpv/reference/EmbreeScene.h"
#include "lpv/scene/WorldMatrices.h"

#include "lpv/scene/AreaLight.h"

#include "lpv/reference/SurfaceLookup.h"

#include "EmbreeApi.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lpv::reference {

namespace {

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

struct EmbreeScene::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    // Flattened world-space streams; triangle i uses vertices 3i..3i+2.
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<int> triangleMaterial;
    std::vector<scene::Material> materials;
    std::vector<MaterialTextures> textures;
    std::vector<bool> maybeCutOut; // per material: needs the alpha filter
    // Emissive triangles: corners, material, and the running sum of
    // area x luminance that picks one.
    struct Emitter {
        glm::vec3 p0, p1, p2;
        unsigned prim;
        float area;
    };
    std::vector<Emitter> emitters;
    std::vector<float> emitterCdf;
    glm::dvec3 origin{0.0};
    float extent = 0.0f;

    ~Impl() {
        if (scene)
            rtcReleaseScene(scene);
        if (device)
            rtcReleaseDevice(device);
    }

    glm::vec2 uvAt(unsigned prim, float u, float v) const {
        const std::size_t i = std::size_t(prim) * 3;
        return (1.0f - u - v) * uvs[i] + u * uvs[i + 1] + v * uvs[i + 2];
    }
};

EmbreeScene::EmbreeScene() : impl_(std::make_unique<Impl>()) {}
EmbreeScene::EmbreeScene(EmbreeScene&&) noexcept = default;
EmbreeScene& EmbreeScene::operator=(EmbreeScene&&) noexcept = default;
EmbreeScene::~EmbreeScene() = default;

Expected<EmbreeScene> EmbreeScene::build(const scene::Scene& s, const scene::TextureImages& images) {
    EmbreeScene out;
    Impl& d = *out.impl_;
    d.device = rtcNewDevice(nullptr);
    if (!d.device)
        return scene::makeError(scene::ErrorCode::InvalidValue, "", "Embree",
                                "rtcNewDevice failed (error " +
                                    std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    d.materials = s.materials;
    for (const scene::Material& m : s.materials) {
        d.textures.push_back(lookUpTextures(m, images));
        d.maybeCutOut.push_back(m.additive || m.alphaMode != scene::AlphaMode::Opaque || m.colorKey ||
                                !m.alphaTexture.empty());
    }

    // World corners in double first: the frame's origin comes from their bounds.
    std::vector<glm::dvec3> corners;
    const std::vector<glm::mat4> worlds = scene::worldMatrices(s); // linear in any parent chain
    for (std::size_t o = 0; o < s.objects.size(); ++o) {
        const scene::Object& object = s.objects[o];
        if (!object.visible || object.mesh < 0 || std::size_t(object.mesh) >= s.meshes.size())
            continue;
        const scene::Mesh& mesh = s.meshes[std::size_t(object.mesh)];
        const glm::mat4 world = worlds[o];
        const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(world));
        auto addRange = [&](std::uint32_t first, std::uint32_t count, int material) {
            for (std::uint32_t k = first; k + 3 <= std::size_t(first) + count && k + 3 <= mesh.indices.size();
                 k += 3) {
                glm::vec3 p[3]; // world, for the area-light test
                glm::dvec3 pd[3];
                glm::vec3 n[3];
                glm::vec2 uv[3];
                bool ok = true;
                for (int c = 0; c < 3; ++c) {
                    const std::uint32_t vi = mesh.indices[k + std::uint32_t(c)];
                    if (vi >= mesh.positions.size()) {
                        ok = false;
                        break;
                    }
                    p[c] = glm::vec3(world * glm::vec4(mesh.positions[vi], 1.0f));
                    pd[c] = glm::dvec3(glm::dmat4(world) * glm::dvec4(glm::dvec3(mesh.positions[vi]), 1.0));
                    n[c] = vi < mesh.normals.size() ? normalMatrix * mesh.normals[vi] : glm::vec3(0.0f);
                    uv[c] = vi < mesh.uvs.size() ? mesh.uvs[vi] : glm::vec2(0.0f);
                    ok = ok && finite(p[c]);
                }
                // Non-finite or degenerate triangles are left out rather than poisoning the BVH.
                // Edges in double: far from the origin the float corners are
                // rounded to millimetres and a small triangle would collapse.
                const glm::dvec3 cross = glm::cross(pd[1] - pd[0], pd[2] - pd[0]);
                if (!ok || !(glm::length(glm::vec3(cross)) > 0.0f))
                    continue;
                const glm::vec3 face = glm::vec3(glm::normalize(cross));
                for (int c = 0; c < 3; ++c) {
                    corners.push_back(pd[c]);
                    const float len = glm::length(n[c]);
                    d.normals.push_back(std::isfinite(len) && len > 0.0f ? n[c] / len : face);
                    d.uvs.push_back(uv[c]);
                }
                d.triangleMaterial.push_back(material < int(s.materials.size()) ? material : -1);
                if (const int m = d.triangleMaterial.back(); m >= 0) {
                    const scene::Material& mat = s.materials[std::size_t(m)];
                    const float luminance =
                        0.2126f * mat.emissive.r + 0.7152f * mat.emissive.g + 0.0722f * mat.emissive.b;
                    const float area = float(0.5 * glm::length(cross));
                    // An area light's visible surface is sampled as that light, not again as an emitter.
                    if (luminance > 0.0f && std::isfinite(luminance) && std::isfinite(area) &&
                        !scene::liesOnAnAreaLight(s.lights, p[0], p[1], p[2])) {
                        // Corners are filled in once the frame is known.
                        d.emitters.push_back({{}, {}, {}, unsigned(d.triangleMaterial.size() - 1), area});
                        d.emitterCdf.push_back((d.emitterCdf.empty() ? 0.0f : d.emitterCdf.back()) +
                                               area * luminance);
                    }
                }
            }
        };
        if (mesh.submeshes.empty())
            addRange(0, std::uint32_t(mesh.indices.size()), -1);
        for (const scene::Submesh& sub : mesh.submeshes)
            addRange(sub.firstIndex, sub.indexCount, int(sub.materialIndex));
    }

    // The frame: for a scene farther from the world origin than its own size,
    // the bounds' centre snapped to a grid of the power of two at or above
    // that size, so it is moved by an exact amount (100 km for a box 100 km
    // away). A scene within its size of the origin keeps origin 0, bit for
    // bit the coordinates it always had: they are already as small as it is.
    if (!corners.empty()) {
        glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
        for (const glm::dvec3& c : corners) {
            lo = glm::min(lo, c);
            hi = glm::max(hi, c);
        }
        const double side = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
        const double grid = side > 0.0 ? std::exp2(std::ceil(std::log2(side))) : 1.0;
        const glm::dvec3 centre = 0.5 * (lo + hi);
        if (std::max({std::abs(centre.x), std::abs(centre.y), std::abs(centre.z)}) > side)
            d.origin = glm::round(centre / grid) * grid;
        d.extent = float(side);
    }
    std::vector<glm::vec3> positions(corners.size());
    for (std::size_t i = 0; i < corners.size(); ++i)
        positions[i] = glm::vec3(corners[i] - d.origin);
    for (Impl::Emitter& e : d.emitters) {
        e.p0 = positions[3 * std::size_t(e.prim)];
        e.p1 = positions[3 * std::size_t(e.prim) + 1];
        e.p2 = positions[3 * std::size_t(e.prim) + 2];
    }

    d.scene = rtcNewScene(d.device);
    rtcSetSceneFlags(d.scene, RTC_SCENE_FLAG_ROBUST);
    if (!d.triangleMaterial.empty()) {
        RTCGeometry g = rtcNewGeometry(d.device, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), positions.size()));
        auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), d.triangleMaterial.size()));
        if (!v || !idx) {
            rtcReleaseGeometry(g);
            return scene::makeError(scene::ErrorCode::InvalidValue, "", "Embree",
                                    "could not allocate " + std::to_string(d.triangleMaterial.size()) +
                                        " triangles");
        }
        for (std::size_t i = 0; i < positions.size(); ++i) {
            v[3 * i] = positions[i].x;
            v[3 * i + 1] = positions[i].y;
            v[3 * i + 2] = positions[i].z;
            idx[i] = unsigned(i);
        }
        rtcSetGeometryUserData(g, &d);
        // Masked texels are holes for every ray, as the renderer discards them in every pass.
        RTCFilterFunctionN alphaFilter = [](const RTCFilterFunctionNArguments* args) {
            const auto* impl = static_cast<const Impl*>(args->geometryUserPtr);
            for (unsigned i = 0; i < args->N; ++i) {
                if (args->valid[i] != -1)
                    continue;
                const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
                const int m = impl->triangleMaterial[prim];
                if (m < 0 || !impl->maybeCutOut[std::size_t(m)])
                    continue;
                const glm::vec2 uv =
                    impl->uvAt(prim, RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i));
                if (materialCutOut(impl->materials[std::size_t(m)], impl->textures[std::size_t(m)], uv))
                    args->valid[i] = 0;
            }
        };
        rtcSetGeometryIntersectFilterFunction(g, alphaFilter);
        rtcSetGeometryOccludedFilterFunction(g, alphaFilter);
        rtcCommitGeometry(g);
        rtcAttachGeometry(d.scene, g);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(d.scene);
    if (const RTCError e = rtcGetDeviceError(d.device); e != RTC_ERROR_NONE)
        return scene::makeError(scene::ErrorCode::InvalidValue, "", "Embree",
                                "building the BVH failed (error " + std::to_string(int(e)) + ")");
    return out;
}

bool embreeAcceptsRay(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax) {
    constexpr float kFltLarge = 1.844e18f; // Embree's FLT_LARGE
    for (int i = 0; i < 3; ++i)
        if (!(std::abs(origin[i]) <= kFltLarge) || !(std::abs(dir[i]) <= kFltLarge))
            return false;
    return !std::isnan(tMin) && !std::isnan(tMax) && tMin >= 0.0f;
}

std::optional<Hit> EmbreeScene::intersect(const glm::vec3& origin, const glm::vec3& dir, float tMin,
                                          float tMax) const {
    if (!embreeAcceptsRay(origin, dir, tMin, tMax))
        return std::nullopt;
    RTCRayHit rh{};
    rh.ray.org_x = origin.x;
    rh.ray.org_y = origin.y;
    rh.ray.org_z = origin.z;
    rh.ray.dir_x = dir.x;
    rh.ray.dir_y = dir.y;
    rh.ray.dir_z = dir.z;
    rh.ray.tnear = tMin;
    rh.ray.tfar = tMax;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    embree::intersect1(impl_->scene, rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID)
        return std::nullopt;
    const Impl& d = *impl_;
    const std::size_t i = std::size_t(rh.hit.primID) * 3;
    Hit hit;
    hit.distance = rh.ray.tfar;
    hit.position = origin + dir * rh.ray.tfar;
    glm::vec3 ng = glm::normalize(glm::vec3(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z));
    if (glm::dot(ng, dir) > 0.0f)
        ng = -ng;
    const float u = rh.hit.u, v = rh.hit.v;
    glm::vec3 ns = (1.0f - u - v) * d.normals[i] + u * d.normals[i + 1] + v * d.normals[i + 2];
    const float len = glm::length(ns);
    ns = len > 1e-12f ? ns / len : ng;
    // Seen from behind: both normals face the viewer (the renderer draws without culling).
    if (glm::dot(ns, ng) < 0.0f)
        ns = -ns;
    hit.geometricNormal = ng;
    hit.shadingNormal = ns;
    hit.uv = d.uvAt(rh.hit.primID, u, v);
    hit.material = d.triangleMaterial[rh.hit.primID];
    return hit;
}

bool EmbreeScene::occluded(const glm::vec3& origin, const glm::vec3& dir, float tMin, float tMax) const {
    if (!embreeAcceptsRay(origin, dir, tMin, tMax))
        return true;
    RTCRay ray{};
    ray.org_x = origin.x;
    ray.org_y = origin.y;
    ray.org_z = origin.z;
    ray.dir_x = dir.x;
    ray.dir_y = dir.y;
    ray.dir_z = dir.z;
    ray.tnear = tMin;
    ray.tfar = tMax;
    ray.mask = 0xFFFFFFFFu;
    embree::occluded1(impl_->scene, ray);
    return ray.tfar == -std::numeric_limits<float>::infinity();
}

SurfaceSample EmbreeScene::surface(const Hit& hit) const {
    if (hit.material < 0)
        return SurfaceSample{}; // the renderer's default material: grey 0.8 Lambert
    const std::size_t m = std::size_t(hit.material);
    return materialSurface(impl_->materials[m], impl_->textures[m], hit.uv);
}

std::size_t EmbreeScene::triangleCount() const {
    return impl_->triangleMaterial.size();
}

const glm::dvec3& EmbreeScene::frameOrigin() const {
    return impl_->origin;
}

glm::vec3 EmbreeScene::toFrame(const glm::vec3& world) const {
    return glm::vec3(glm::dvec3(world) - impl_->origin);
}

float EmbreeScene::extent() const {
    return impl_->extent;
}

glm::vec3 EmbreeScene::offsetOrigin(const glm::vec3& p, const glm::vec3& n) const {
    // 2e-5 is about 170 float ulps of the scale: far above the rounding of a
    // hit, far below the thickness of real walls (a 1 mm gap 50 m from the
    // frame's centre is still not jumped). The extent / 8 floor covers hits
    // near the frame's centre, whose rounding comes from the ray's length.
    const float scale = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 0.125f * impl_->extent});
    return p + n * (2e-5f * scale);
}

glm::vec3 EmbreeScene::offsetWorldPoint(const glm::vec3& world, const glm::vec3& n) const {
    const glm::vec3 p = toFrame(world);
    const float frameScale = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 0.125f * impl_->extent});
    const float worldScale = std::max({std::abs(world.x), std::abs(world.y), std::abs(world.z)});
    const float lift =
        std::max(2e-5f * frameScale, 2.0f * std::numeric_limits<float>::epsilon() * worldScale);
    return p + n * lift;
}

bool EmbreeScene::hasEmitters() const {
    return !impl_->emitters.empty() && impl_->emitterCdf.back() > 0.0f;
}

EmitterSample EmbreeScene::sampleEmitter(float pick, float u1, float u2) const {
    const Impl& d = *impl_;
    EmitterSample out;
    if (!hasEmitters())
        return out;
    const float total = d.emitterCdf.back();
    const auto it = std::upper_bound(d.emitterCdf.begin(), d.emitterCdf.end(), pick * total);
    const std::size_t k = std::min(std::size_t(it - d.emitterCdf.begin()), d.emitters.size() - 1);
    const Impl::Emitter& e = d.emitters[k];
    const float weight = d.emitterCdf[k] - (k > 0 ? d.emitterCdf[k - 1] : 0.0f);
    // Uniform on the triangle (square-root warp of the unit square).
    const float r = std::sqrt(u1);
    const float b0 = 1.0f - r, b1 = r * (1.0f - u2), b2 = r * u2;
    out.position = b0 * e.p0 + b1 * e.p1 + b2 * e.p2;
    out.normal = glm::normalize(glm::cross(e.p1 - e.p0, e.p2 - e.p0));
    const std::size_t m = std::size_t(d.triangleMaterial[e.prim]);
    const glm::vec2 uv = b0 * d.uvs[3 * e.prim] + b1 * d.uvs[3 * e.prim + 1] + b2 * d.uvs[3 * e.prim + 2];
    out.radiance = materialSurface(d.materials[m], d.textures[m], uv).emissive;
    out.twoSided = d.materials[m].twoSided;
    out.pdfArea = (weight / total) / e.area;
    return out;
}

} // namespace lpv::reference
