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
  MeshData bed_holes;     ///< each hole in the slate on the bed plane (stencil masks; see build_table_model)
  MeshData top_holes;     ///< each throat, grown by its liner, at the frame's top height (stencil masks)
  double top_height = 0;  ///< m, the frame's (the wood's) top above the bed
};

/// Cloth colour (linear RGB), shared with the shadows and overlays that sit on it.
Vec3 cloth_color();

/// The table of `scene`. A standard pocket (cut) is the physics' own: its cushions end along the rounded
/// jaw points and the facings, then the hole's edge; the bed is cut at its hole (grown by the slate's
/// rounded lip), so it goes on between the facings as the shelf; the slate's lip, the hole's wall, the
/// liner through the wood and the cup's floor (where the physics leaves a pocketed ball) are its inside.
/// A bare pocket (a scene's own `pocket` line) is cut at its drop circle and its drawn throat.
TableModel build_table_model(const Scene& scene);

}  // namespace bsim
