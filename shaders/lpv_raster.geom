#version 450 core
// Routes a primitive to the layer (slice of the stacked LPV textures) its
// vertex shader chose: geometry shaders may write gl_Layer in core OpenGL.
#ifdef LPV_POINTS
layout(points) in;
layout(points, max_vertices = 1) out;
in int vSlice[];
flat in vec4 vR[];
flat in vec4 vG[];
flat in vec4 vB[];
flat out vec4 gR;
flat out vec4 gG;
flat out vec4 gB;
void main() {
    if (vSlice[0] < 0)
        return; // the destination is outside the cascade
    gl_Position = gl_in[0].gl_Position;
    gl_PointSize = 1.0;
    gl_Layer = vSlice[0];
    gR = vR[0];
    gG = vG[0];
    gB = vB[0];
    EmitVertex();
}
#else
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in int vSlice[];
flat out int gSlice;
void main() {
    for (int v = 0; v < 3; ++v) {
        gl_Position = gl_in[v].gl_Position;
        gl_Layer = vSlice[0];
        gSlice = vSlice[0];
        EmitVertex();
    }
}
#endif
