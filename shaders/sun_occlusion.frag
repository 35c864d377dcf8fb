#version 450 core
// Sun rays, pass 1 (the thesis' occlusion pre-pass): the sun's disc bright,
// the rest of the sky mid-grey, geometry black, from the camera's depth.
in vec2 vUv;
out float outOcclusion;

uniform sampler2D uDepth;    // window-space depth, 1 = background
uniform mat4 uInvViewProj;
uniform vec3 uTowardSun;     // unit vector from the scene towards the sun
uniform float uSkyLevel;     // brightness of open sky away from the sun
uniform vec2 uDiscCos;       // cosines of the disc's outer and inner angular radius

void main() {
    // texelFetch: the depth texture's own filtering state is the forward pass's business.
    ivec2 texel = min(ivec2(vUv * vec2(textureSize(uDepth, 0))), textureSize(uDepth, 0) - 1);
    if (texelFetch(uDepth, texel, 0).r < 1.0) {
        outOcclusion = 0.0;
        return;
    }
    vec4 nearPoint = uInvViewProj * vec4(vUv * 2.0 - 1.0, -1.0, 1.0);
    vec4 farPoint = uInvViewProj * vec4(vUv * 2.0 - 1.0, 1.0, 1.0);
    vec3 dir = normalize(farPoint.xyz / farPoint.w - nearPoint.xyz / nearPoint.w);
    float disc = smoothstep(uDiscCos.x, uDiscCos.y, dot(dir, uTowardSun));
    outOcclusion = uSkyLevel + disc;
}
