// The indirect light as an image of the frame (forward.frag's
// LPV_SCREEN_INDIRECT variant, frame/IndirectLight.h's ScreenIncident): a
// pass drew the diffuse light arriving at each pixel's surface, as irradiance
// / pi, into a screen-sized target (gi.method = radiosity: radiosityIndirect
// draws a baked solution's, the lights' direct light excluded); the surface
// shaded here reads its own pixel.
uniform sampler2D uIndirectIncident;

vec3 indirectIncident() {
    return texelFetch(uIndirectIncident, ivec2(gl_FragCoord.xy), 0).rgb;
}
