#pragma once
// The one place that knows which Embree the build found (issue #49). Debian
// 12 has Embree 3, Debian 13 Embree 4; for what EmbreeScene.cpp uses they
// differ only in the header's folder and in how a single-ray query takes its
// context (Embree 3: an RTCIntersectContext the caller initialises; Embree 4:
// optional argument structs whose defaults are the same traversal, with the
// geometry's filter functions on). reference/CMakeLists.txt defines
// LPV_EMBREE_MAJOR from the package it found. Embree's types never leave
// EmbreeScene.cpp.
#if LPV_EMBREE_MAJOR >= 4
#include <embree4/rtcore.h>
#else
#include <embree3/rtcore.h>
#endif

namespace lpv::reference::embree {

inline constexpr int kMajorVersion = LPV_EMBREE_MAJOR;

// The closest hit along rayHit.ray, written into rayHit.hit (geomID stays
// RTC_INVALID_GEOMETRY_ID when there is none).
inline void intersect1(RTCScene scene, RTCRayHit& rayHit) {
#if LPV_EMBREE_MAJOR >= 4
    rtcIntersect1(scene, &rayHit);
#else
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcIntersect1(scene, &context, &rayHit);
#endif
}

// Whether anything blocks `ray`: its tfar becomes -inf when it is.
inline void occluded1(RTCScene scene, RTCRay& ray) {
#if LPV_EMBREE_MAJOR >= 4
    rtcOccluded1(scene, &ray);
#else
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded1(scene, &context, &ray);
#endif
}

} // namespace lpv::reference::embree
