// The subsurface LPV's volumes (docs/lpv.md, "Subsurface LPV"): one RGBA32F
// 3D texture per volume with the three colour channels side by side along x,
// so the forward pass reads the accumulator through one sampler. Channel c of
// cell (x, y, z) of cascade k is texel (x + c N, y, k N + z).
// Needs lpv_common.glsl included before it (includes are one level deep).

ivec3 sssTexel(int channel, int k, ivec3 cell) {
    return ivec3(cell.x + channel * uGridSize, cell.y, k * uGridSize + cell.z);
}
