#pragma once
// Meshes the editor's Create menu adds: unit-sized, centred on the origin,
// with normals, tangents and uvs, one submesh using material 0 (the caller
// points it at the material it adds).
#include "lpv/scene/Mesh.h"

namespace lpv::scene {

// A square of side 1 in the XZ plane facing +Y, `divisions` quads per side
// (more quads give the LPV's geometry volume and the shadows finer detail).
Mesh makePlane(int divisions = 1);
// A cube of side 1, 4 vertices per face so faces keep flat normals.
Mesh makeBox();
// A UV sphere of radius 0.5.
Mesh makeSphere(int segments = 32, int rings = 16);

} // namespace lpv::scene
