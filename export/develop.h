#pragma once
// Developing a frame, as a camera's image pipeline does: POV-Ray renders linear light with no upper
// limit (a Radiance .hdr), and this turns it into the 8-bit sRGB PNG of the movie: a fixed exposure,
// the lens's natural vignetting, a soft glare round over-bright points, a filmic tone curve that
// rolls highlights off instead of clipping them, a film's less pure colour, and the sRGB encoding.
//
// Everything is deterministic and uses only IEEE arithmetic (no libm call whose last bit may differ
// between CPUs): the same .hdr gives the same PNG bytes on every machine, so a frame rendered on a
// render farm's node is byte for byte the frame a local run makes.
#include <cstdint>
#include <string>
#include <vector>

namespace bsim {

struct FrameCaption;

/// The one exposure of the look, a factor on POV-Ray's linear light before the tone curve. A constant,
/// never measured from the frame: auto-exposure would pump and flicker as balls move.
inline constexpr float kExposure = 1.6f;

/// Light (after the exposure) that the tone curve makes white; brighter light stays white.
inline constexpr float kToneWhite = 6.0f;

/// Light above this (after the exposure) is over-bright and scatters in the lens as glare: what the
/// tone curve shows at sRGB 210 of 255 and brighter, the glints of the lamp and a white ball's
/// brightest part, not the lit cloth or a ball's body, so glare is a halo round highlights, not a haze.
inline constexpr float kGlareThreshold = 1.5f;
/// The share of the over-bright light the lens scatters into its wide point-spread function.
inline constexpr float kGlareShare = 0.2f;

/// The film's colour: what saturation of the tone-mapped colours is kept round each pixel's luma
/// (the ASC CDL's saturation operator, with the Rec. 709 luma weights). Rendered colours come out
/// purer than a photograph's, whose film or sensor and lens mix a little of every colour into the
/// others: the cloth reads as paint, the walls as a poster, until they are drawn in a little.
inline constexpr float kSaturation = 0.85f;

/// The field angle of the picture's corners for the cos^4 vignetting: gentler than the camera's
/// real 31 degrees (55 degrees across), as a lens whose fall-off is partly corrected; corners keep
/// cos^4(20 degrees) = 78 % of their light.
inline constexpr double kVignetteCornerTan = 0.36397023426620234;  // tan(20 degrees)

/// A linear-light RGB picture: width x height pixels of three floats, rows from the top.
struct HdrImage {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;
};

/// A text that changes whenever the develop stage's output would: its version and constants. The
/// frame store folds it into every picture's key.
std::string develop_signature();

/// Reads a Radiance .hdr picture. False, with `error` naming the file and the reason, when it is
/// missing, not a Radiance picture, truncated or otherwise cannot be decoded.
bool read_hdr(const std::string& path, HdrImage& image, std::string& error);

/// The filmic tone curve: scene-linear light (after the exposure) to display-linear light in [0, 1],
/// monotone, 0 at 0, rolling off towards 1 instead of clipping.
float tone_curve(float x);

/// Draws display-linear r, g, b towards their Rec. 709 luma by kSaturation; the luma is kept, and no
/// value goes below 0.
void saturate(float& r, float& g, float& b);

/// Display-linear light in [0, 1] to its 8-bit sRGB code, rounded to the nearest (IEC 61966-2-1).
std::uint8_t encode_srgb8(float linear);

/// The cos^4 vignetting factor at pixel (x, y) of a width x height picture: 1 at the centre,
/// cos^4(atan(kVignetteCornerTan)) at the corners.
float vignette(int x, int y, int width, int height);

/// Multiplies every pixel by kExposure and its vignetting factor.
void expose(HdrImage& image);

/// Adds the lens's glare: kGlareShare of the light above kGlareThreshold is spread by a wide
/// point-spread function and added back, so the total light is kept (less what spreads off the
/// picture's edges). A picture with nothing over-bright is left exactly as it was.
void add_glare(HdrImage& image);

/// The tone curve, the film colour and the sRGB encoding of an exposed-and-glared picture: 8-bit sRGB,
/// three bytes a pixel.
std::vector<std::uint8_t> tone_map(const HdrImage& image);

/// The whole pipeline on a picture: exposure and vignetting, glare, tone curve, film colour, sRGB.
std::vector<std::uint8_t> develop(HdrImage image);

/// Develops `image` into the PNG at `png_path`, with `caption` (a game movie's, lower_third.h) drawn
/// over it when given. False, with `error` naming the file, when it cannot be written (or the
/// caption's fonts are not installed); no half-written PNG is left behind.
bool develop_to_png(HdrImage image, const std::string& png_path, std::string& error,
                    const FrameCaption* caption = nullptr);

/// Develops the .hdr at `hdr_path` into the PNG at `png_path`. False, with `error` saying why (the
/// file and the reason), when the .hdr cannot be read or the PNG cannot be written; no half-written
/// PNG is left behind.
bool develop_file(const std::string& hdr_path, const std::string& png_path, std::string& error);

}  // namespace bsim
