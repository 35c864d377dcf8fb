#version 450 core
// Raster gather (lpv.variant = rasterGather): one full-screen triangle per
// slice of the stacked volume; the instance is the slice (lpv_raster.geom
// routes it to that layer).
out int vSlice;
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
    vSlice = gl_InstanceID;
}
