#pragma once
// The frame graph's resources that several passes share, declared once:
// passes read, write and look up their GL objects through these handles,
// and the name in quotes is the one reports, `lpv render --dump` and the
// GPU memory table print. A resource only one pass writes may instead be
// declared in that pass's header (its kOutputs, frame/PassList.h), as
// radiosity's are.
#include "graph/ResourceHandle.h"

#include <array>

namespace lpv::renderer::resources {

using graph::ResourceHandle;

// The camera's targets (FramePasses.cpp): shading writes the G-buffer beside
// the HDR image; the geometry volume reads last frame's.
inline constexpr ResourceHandle CameraHdr{"camera.hdr"};
inline constexpr ResourceHandle CameraNormal{"camera.normal"};
inline constexpr ResourceHandle CameraAlbedo{"camera.albedo"};
inline constexpr ResourceHandle CameraDepth{"camera.depth"};
inline constexpr ResourceHandle Display{"display"};
inline constexpr ResourceHandle ShadowMaps{"shadowMaps"};
// The sun's RSM tiles and the local lights' RSM faces.
inline constexpr ResourceHandle RsmPosition{"rsm.position"};
inline constexpr ResourceHandle RsmNormal{"rsm.normal"};
inline constexpr ResourceHandle RsmFlux{"rsm.flux"};
inline constexpr ResourceHandle LocalRsmPosition{"localRsm.position"};
inline constexpr ResourceHandle LocalRsmNormal{"localRsm.normal"};
inline constexpr ResourceHandle LocalRsmFlux{"localRsm.flux"};
inline constexpr ResourceHandle EmissiveVpls{"emissiveVpls"};
inline constexpr ResourceHandle SkyHeight{"skyHeight"};
// The LPV's volumes, updated in place by its stages.
inline constexpr ResourceHandle LpvVolumes{"lpv.volumes"};
inline constexpr ResourceHandle LpvAccumulator{"lpv.accumulator"};
inline constexpr ResourceHandle LpvGeometry{"lpv.geometry"};
inline constexpr ResourceHandle LpvNormals{"lpv.normals"};
// lpv.lookupResolution = half|quarter: the LPV's lookup at reduced resolution
// (rgb irradiance, a distance), the normals it was looked up with, their depth.
inline constexpr ResourceHandle LpvLookup{"lpv.lookup"};
inline constexpr ResourceHandle LpvLookupNormal{"lpv.lookupNormal"};
inline constexpr ResourceHandle LpvLookupDepth{"lpv.lookupDepth"};
inline constexpr ResourceHandle SubsurfaceAccumulator{"subsurface.accumulator"};
inline constexpr ResourceHandle SunRaysOcclusion{"sunRays.occlusion"};
inline constexpr ResourceHandle Exposure{"exposure"};

// In the order --dump's error lists them, before those the passes declare (PassTable.cpp).
inline constexpr std::array shared{CameraHdr,       CameraNormal,     CameraAlbedo,     CameraDepth,
                                Display,         ShadowMaps,       RsmPosition,      RsmNormal,
                                RsmFlux,         LocalRsmPosition, LocalRsmNormal,   LocalRsmFlux,
                                EmissiveVpls,    SkyHeight,        LpvVolumes,       LpvAccumulator,
                                LpvGeometry,     LpvNormals,       LpvLookup,        LpvLookupNormal,
                                LpvLookupDepth,  SubsurfaceAccumulator, SunRaysOcclusion, Exposure};

} // namespace lpv::renderer::resources
