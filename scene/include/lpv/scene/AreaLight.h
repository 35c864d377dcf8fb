#pragma once
// Area lights' geometry and the irradiance they cast (Light.h has the model).
//
// The irradiance of a Lambertian polygon of radiance L at a point p with
// normal n is E = L * F, where F is the cosine-weighted solid angle of the
// polygon clipped to p's upper hemisphere (Lambert 1760):
//     F = 1/2 * sum over edges (v_i, v_i+1) of theta_i * (n . g_i),
// with v_i the unit vectors from p to the vertices, theta_i the angle between
// consecutive ones and g_i the unit normal of the plane through p, v_i, v_i+1.
// This is also the diffuse term of Linearly Transformed Cosines (Heitz et al.
// 2016) with the identity transform. `polygonCosineSolidAngle` is it in double
// precision (the closed form the tests and the path tracer use);
// `areaLightIrradianceFactor` is the float twin of shaders/area_light.glsl.
#include "lpv/scene/Light.h"

#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace lpv::scene {

// A disc is drawn and shaded as a regular polygon of this many sides whose
// area equals the disc's (its irradiance is within 0.3% of the disc's).
inline constexpr int kAreaLightDiscSides = 24;

struct AreaLightFrame {
    glm::vec3 center{0.0f};
    glm::vec3 normal{0.0f, -1.0f, 0.0f}; // the front side's normal (unit)
    glm::vec3 halfU{0.5f, 0.0f, 0.0f};   // half the width along the tangent
    glm::vec3 halfV{0.0f, 0.0f, 0.5f};   // half the height along normal x tangent
};

// The light's plane and extent; a disc's half axes are its radius.
AreaLightFrame areaLightFrame(const Light& light);
// The emitting area in m^2 (one side).
float areaLightArea(const Light& light);
// The radiance (W/(m^2 sr), per colour channel, colour included) leaving an
// emitting side: intensity itself, or the power spread over pi * area per side.
glm::vec3 areaLightRadiance(const Light& light);
// The outline, counter-clockwise seen from the front: 4 corners or the disc's polygon.
std::vector<glm::vec3> areaLightPolygon(const Light& light);

// Lambert's formula (above) for a polygon given by its vertices, clipped to
// the hemisphere around n at p; orientation does not matter. Double precision.
double polygonCosineSolidAngle(const glm::dvec3& p, const glm::dvec3& n, std::span<const glm::dvec3> polygon);

// The irradiance factor F of an area light at p with normal n, as the shader
// computes it: 0 behind a one-sided light; a light smaller than 1e-3 of its
// distance treated as a point (A cos cos / d^2), where float angles lose
// their digits. E = areaLightRadiance(light) * F.
float areaLightIrradianceFactor(const Light& light, const glm::vec3& p, const glm::vec3& n);

// Whether any of `lights` is an area light.
bool hasAreaLight(std::span<const Light> lights);

// Whether the triangle (world positions) lies in the plane and within the
// outline of one of `lights`' area lights: the lamp's visible surface (the
// Cornell light quad), which the LPV's emissive VPLs and the reference's
// emitter sampling leave out, so a lamp modelled both ways counts once.
// `worldMagnitude`: for positions moved near the origin from far away (the
// renderer's render space), how far from the origin they were rounded to
// float: the slack covers that rounding too.
bool liesOnAnAreaLight(std::span<const Light> lights, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                       float worldMagnitude = 0.0f);

} // namespace lpv::scene
