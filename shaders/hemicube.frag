#version 450 core
// 0 = nothing; a patch seen from behind blocks the view but receives nothing.
flat in uint vPatchId;
layout(location = 0) out uint outId;
void main() { outId = gl_FrontFacing ? vPatchId + 1u : 0u; }
