#pragma once
// Depth of field in the develop stage: each pixel of the exposed linear picture spread over its
// circle of confusion (lens.h) from the frame's depth picture (depth_scene.h), as a lens spreads a
// point off its focus, before the glare and the tone curve so a bright glint off focus becomes a
// bright disc.
//
// Scatter as gather (Gustafsson 2018, "Bokeh depth of field in a single pass", blog.tuxedolabs.com;
// Jimenez 2014, "Next generation post processing in Call of Duty: Advanced Warfare", SIGGRAPH): each
// pixel gathers taps on a golden-angle (Vogel) spiral round it, each tap counting where its own circle
// reaches the pixel. The picture is cut into tiles; a tile whose neighbourhood's largest circle reaches
// no tap is copied as it is (a wide shot's sharp table costs nothing), and elsewhere the spiral goes only
// as far as that largest circle. Occlusion, so an edge keeps its place:
// - a tap behind the pixel spreads at most twice the pixel's own circle, so a blurred background never
//   bleeds over a sharp foreground's edge (no halo);
// - a tap in front of the pixel and more blurred than it lies over it: the foreground's taps cover the
//   pixel by the share of their circles' light that reaches it, and what they leave uncovered is the
//   pixel's own layer;
// - what a pixel's own layer lacks (a sharp foreground's taps reach nothing) is filled with its own
//   layer's light: the pixel itself where it is sharp, and round a blurred foreground's edge the
//   background it shows through its blur.
// Deterministic: IEEE arithmetic, taps in one fixed order, no threads.
#include <vector>

#include "depth_scene.h"
#include "develop.h"
#include "lens.h"

namespace bsim {

/// Pixels (of a 1280-pixel-wide picture; in proportion for other widths): the largest radius of a circle
/// of confusion, as far as a lens's blur is drawn. Farther off its focus everything is this soft.
inline constexpr double kMaxBlurRadius = 16.0;
/// Pixels^2 of the picture each tap of the spiral stands for: about one tap every two pixels.
inline constexpr double kTapArea = 2.0;
/// Pixels, the side of a tile (at least the largest radius).
inline constexpr int kBlurTile = 16;

/// The depth with each pixel taking the nearest of itself and its eight neighbours. A pixel on an
/// object's outline is antialiased, a mixture of the object and what lies behind it; so it is taken as
/// the object's, and a sharp object keeps its whole outline sharp instead of spreading the light of its
/// edge into a blurred background round it.
DepthPicture nearest_of_neighbours(const DepthPicture& depth);

/// Pixels, each pixel's radius of its circle of confusion through `lens` in `depth`'s picture, at
/// most kMaxBlurRadius in proportion to its width.
std::vector<float> blur_radii(const DepthPicture& depth, const Lens& lens);

/// Spreads each pixel of `image` over its circle of radius `radii` (pixels), with `depth` (the same
/// size) deciding what lies in front of what. A picture whose circles are all under a third of a
/// pixel is left exactly as it was.
void gather_blur(HdrImage& image, const DepthPicture& depth, const std::vector<float>& radii);

}  // namespace bsim
