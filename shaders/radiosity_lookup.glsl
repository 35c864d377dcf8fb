// gi.method = radiosity at shading (forward.frag's LPV_RADIOSITY variant):
// the radiosityIndirect pass drew the baked solution's incident light
// (irradiance / pi, the lights' direct light excluded) from this camera into
// a screen-sized target; the surface shaded here reads its own pixel.
uniform sampler2D uRadiosityIncident;

vec3 radiosityIncident() {
    return texelFetch(uRadiosityIncident, ivec2(gl_FragCoord.xy), 0).rgb;
}
