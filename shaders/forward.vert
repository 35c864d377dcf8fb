#version 450 core
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec4 inTangent; // xyz tangent, w handedness (0 vector: none)
layout(location = 3) in vec2 inUv;

uniform mat4 uModel;
uniform mat3 uNormalMatrix;
uniform mat4 uViewProj;

out vec3 vWorldPos;
out vec3 vNormal;
out vec4 vTangent;
out vec2 vUv;
// The depth pre-pass and shading run this shader in two programs: their
// depths must agree bit for bit for shading's depth test to pass.
invariant gl_Position;

void main() {
    vec4 world = uModel * vec4(inPosition, 1.0);
    vWorldPos = world.xyz;
    vNormal = uNormalMatrix * inNormal;
    // Tangents follow the surface (model matrix), normals its inverse
    // transpose; a mirroring transform flips the bitangent's handedness.
    mat3 linear = mat3(uModel);
    vTangent = vec4(linear * inTangent.xyz, inTangent.w * (determinant(linear) < 0.0 ? -1.0 : 1.0));
    vUv = inUv;
    gl_Position = uViewProj * world;
}
