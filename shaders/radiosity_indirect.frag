#version 450 core
// The light that reached a patch through form factors (irradiance / pi),
// for shading to read at the same pixel (LPV_SCREEN_INDIRECT in forward.frag).
in vec3 vWorldPos;
in vec3 vIncident;
flat in vec3 vNormal;
uniform vec3 uCameraPos;
// With the depth pre-pass: the depth of the surface shading lights at this
// pixel. A patch further than uDepthTolerance (relative) from it belongs to
// something else: a masked leaf's patch covers the holes in the leaf, where
// the wall behind is what is shaded.
uniform bool uTestSceneDepth;
uniform sampler2D uSceneDepth;
uniform float uDepthTolerance;
uniform vec2 uProjectionZ; // projection[2][2], projection[3][2]: window depth to view distance
layout(location = 0) out vec4 outIncident;

float viewDistance(float windowDepth) {
    return uProjectionZ.y / (2.0 * windowDepth - 1.0 + uProjectionZ.x);
}

void main() {
    if (uTestSceneDepth) {
        float surface = viewDistance(texelFetch(uSceneDepth, ivec2(gl_FragCoord.xy), 0).r);
        if (abs(viewDistance(gl_FragCoord.z) - surface) > uDepthTolerance * surface)
            discard;
    }
    // The solver gives a patch's back nothing (it blocks, it does not
    // receive), so a patch seen from behind adds no light.
    bool front = dot(vNormal, uCameraPos - vWorldPos) > 0.0;
    outIncident = vec4(front ? max(vIncident, vec3(0.0)) : vec3(0.0), 1.0);
}
