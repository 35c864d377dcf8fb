#version 450 core
// Raster scatter: the point's payload into the step's result (0-2) and the
// accumulator (3-5), both with additive blending.
flat in vec4 gR;
flat in vec4 gG;
flat in vec4 gB;
layout(location = 0) out vec4 outR;
layout(location = 1) out vec4 outG;
layout(location = 2) out vec4 outB;
layout(location = 3) out vec4 accumR;
layout(location = 4) out vec4 accumG;
layout(location = 5) out vec4 accumB;
void main() {
    outR = gR;
    outG = gG;
    outB = gB;
    accumR = gR;
    accumG = gG;
    accumB = gB;
}
