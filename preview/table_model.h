#pragma once
// The table as meshes, built from the scene's cushions and pockets and the table description
// (table.h: the cushion profile, the wood, the sights): cloth, cushions at nose height, the wooden
// frame with its sights, the pockets (table.h's PocketMouth: jaws, throat, cup), and a floor and legs for context.
#include <vector>

#include "mesh.h"
#include "scene.h"

namespace bsim {

struct TableModel {
  MeshData cloth;         ///< the bed, z = 0 (pocket holes are cut out of it with the stencil)
  MeshData tops;          ///< the frame's top faces at top_height (the throats cut out likewise)
  MeshData body;          ///< cushions (ending on their jaws' facings), frame sides, legs, floor
  MeshData pockets;       ///< inside of each pocket: liner, slate edge, cup floor, seen through the holes
  MeshData bed_holes;     ///< each pocket's drop circle and throat on the bed plane (stencil masks)
  MeshData top_holes;     ///< each throat, grown by its liner, at the frame's top height (stencil masks)
  double top_height = 0;  ///< m, the frame's (the wood's) top above the bed
};

/// Cloth colour (linear RGB), shared with the shadows and overlays that sit on it.
Vec3 cloth_color();

TableModel build_table_model(const Scene& scene);

}  // namespace bsim
