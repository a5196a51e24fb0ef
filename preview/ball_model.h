#pragma once
// What a ball, the stick and a contact shadow look like: colours, stripes, the number discs, meshes.
#include <cstdint>
#include <vector>

#include "mesh.h"

namespace bsim {

/// The standard pool colours (linear RGB): 1 yellow, 2 blue, 3 red, 4 purple, 5 orange, 6 green,
/// 7 maroon, 8 black; 9-15 repeat 1-7 as stripes; 0 is the white cue ball.
Vec3 ball_color(int number);
bool ball_striped(int number);
/// The ivory white of the cue ball, the stripes' ground and the number discs.
Vec3 ball_ivory();

/// A unit sphere; its object-space position doubles as the ball-frame direction the shader paints by.
MeshData make_sphere_mesh(int slices, int stacks);
/// The stick along +x from its tip at the origin; aux.x is the distance from the tip (m).
MeshData make_cue_mesh();
/// A unit square in the xy plane, aux = corner in [-1, 1]^2 (for soft round contact shadows).
MeshData make_shadow_quad();

/// The digits 1-15 in a 4 x 4 grid of `cell` pixel squares, one byte of coverage per pixel, row 0 at top.
/// Cell k holds the number k (cell 0 is empty).
std::vector<std::uint8_t> make_number_atlas(int cell);

}  // namespace bsim
