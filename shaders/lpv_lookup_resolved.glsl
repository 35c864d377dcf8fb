// The LPV's diffuse irradiance at reduced resolution, resolved to this pixel
// (forward.frag's LPV_LOOKUP_RESOLVED variant; the lpvLookupResolve pass,
// LpvLookupResolvePass.cpp, upsampled it and looked up at full resolution
// where the upsampling had no neighbour): the opaque surface shaded here
// reads its own texel, with no LPV lookup of its own.
uniform sampler2D uLpvResolved;

vec3 lpvIrradianceResolved() {
    return texelFetch(uLpvResolved, ivec2(gl_FragCoord.xy), 0).rgb;
}
