#version 450 core
// Geometry-volume injection (docs/lpv.md): surfels from the RSM tiles
// (GV_FROM_RSM) or from the camera G-buffer of the previous frame
// (GV_FROM_CAMERA) add min(A / s^2, 1) times a clamped cosine lobe around
// their normal to the GV cell nearest to them, in fixed point (2^16 per unit),
// each source into its own half of the buffer; lpv_gv_merge.comp keeps the
// larger of the two per cell.
#include "sh.glsl"
#include "sh3.glsl"
#include "lpv_common.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

const float GV_FIXED_SCALE = 65536.0;

uniform vec3 uOrigin[6];
uniform float uCellSize[6];
layout(std430, binding = 2) buffer GvFixedPoint { int gvSums[]; }; // [source][cascade][cell] * B^2

void addSurfel(int source, int k, vec3 p, vec3 n, float area) {
    // floor(x + 0.5), not round(): GLSL leaves the direction of halves to the driver.
    vec3 gf = floor((p - uOrigin[k]) / uCellSize[k] + 0.5);
    // Range-checked as floats: converting a far-away coordinate to int is undefined.
    if (any(lessThan(gf, vec3(0.0))) || any(greaterThan(gf, vec3(uGridSize))))
        return;
    ivec3 g = ivec3(gf);
    float s = uCellSize[k];
    int m = uGridSize + 1;
#if LPV_SH_BANDS == 3
    Sh9 v9 = sh9Scale(sh9CosineLobe(n), min(area / (s * s), 1.0) * GV_FIXED_SCALE);
    int base9 = (source * uCascades * m * m * m + gvCellIndex(k, g)) * 9;
    for (int j = 0; j < 9; ++j)
        atomicAdd(gvSums[base9 + j], int(round(lpvCoeff(v9, j))));
    return;
#endif
    vec4 v = shCosineLobe(n) * (min(area / (s * s), 1.0) * GV_FIXED_SCALE);
    int base = (source * uCascades * m * m * m + gvCellIndex(k, g)) * 4;
    for (int j = 0; j < 4; ++j)
        atomicAdd(gvSums[base + j], int(round(v[j])));
}

#ifdef GV_FROM_RSM
uniform sampler2DArray uRsmPosition;
uniform sampler2DArray uRsmNormal;
uniform float uTexelArea[6];
uniform vec3 uToSun;

void main() {
    ivec3 texel = ivec3(gl_GlobalInvocationID);
    ivec3 size = textureSize(uRsmPosition, 0);
    if (texel.z >= uCascades || any(greaterThanEqual(texel.xy, size.xy)))
        return;
    vec4 position = texelFetch(uRsmPosition, texel, 0);
    if (position.w <= 0.0)
        return;
    vec3 rawNormal = texelFetch(uRsmNormal, texel, 0).xyz;
    if (!lpvUsableTexel(position.xyz, rawNormal, vec3(0.0)))
        return;
    vec3 n = normalize(rawNormal);
    float area = uTexelArea[texel.z] / max(dot(n, uToSun), 0.2);
    addSurfel(0, texel.z, position.xyz, n, area);
}
#endif

#ifdef GV_FROM_CAMERA
uniform sampler2D uDepth;
uniform sampler2D uNormal;
uniform mat4 uInvViewProj;   // of the frame that wrote the G-buffer
uniform vec3 uCameraPos;     // of that frame
uniform float uPixelAngle;   // 2 tan(fovY / 2) / height: a pixel's size at distance 1
uniform int uStride;         // lpv.gvCameraStride: one surfel per uStride^2 pixels

void main() {
    // The middle pixel of each uStride x uStride block stands for the block.
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy) * uStride + uStride / 2;
    if (any(greaterThanEqual(pixel, textureSize(uDepth, 0))))
        return;
    vec4 normal = texelFetch(uNormal, pixel, 0);
    if (normal.w <= 0.0)
        return;
    float depth = texelFetch(uDepth, pixel, 0).r;
    vec2 ndc = (vec2(pixel) + 0.5) / vec2(textureSize(uDepth, 0)) * 2.0 - 1.0;
    vec4 world = uInvViewProj * vec4(ndc, depth * 2.0 - 1.0, 1.0);
    vec3 p = world.xyz / world.w;
    if (!lpvUsableTexel(p, normal.xyz, vec3(0.0)))
        return;
    vec3 n = normalize(normal.xyz);
    vec3 toCamera = uCameraPos - p;
    float dist = length(toCamera);
    float side = dist * uPixelAngle * float(uStride);
    float area = side * side / max(abs(dot(n, toCamera / max(dist, 1e-6))), 0.2);
    for (int k = 0; k < uCascades; ++k)
        addSurfel(1, k, p, n, area);
}
#endif
