#pragma once
// What a ball, the stick and a contact shadow look like: colours, stripes, the number discs, meshes.
#include <cstdint>
#include <vector>

#include "ball_look.h"
#include "mesh.h"

namespace bsim {

/// The core's standard pool colours (ball_look.h: ball_srgb) as linear RGB for the shaders; whether
/// a ball is striped is ball_look.h's ball_striped().
Vec3 ball_color(int number);
/// The ivory white of the cue ball, the stripes' ground and the number discs (kBallIvory), linear.
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
