#pragma once
// Developing a frame, as a camera's image pipeline does: POV-Ray renders linear light with no upper
// limit (a Radiance .hdr), and this turns it into the 8-bit sRGB PNG of the movie: a fixed exposure,
// the lens's vignetting, its depth of field and lateral chromatic aberration (for a frame whose lens is
// known: frame_lens.h), a soft glare round over-bright points, the sensor's noise, a filmic tone curve
// that rolls highlights off instead of clipping them, a film's less pure colour, and the sRGB encoding.
//
// Everything is deterministic and uses only IEEE arithmetic (no libm call whose last bit may differ
// between CPUs): the same .hdr gives the same PNG bytes on every machine, so a frame rendered on a
// render farm's node is byte for byte the frame a local run makes.
#include <cstdint>
#include <string>
#include <vector>

namespace bsim {

struct FrameCaption;
struct FrameLens;
struct DepthScene;

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

/// Optical vignetting of a lens wide open: at kOpenAperture (lens.h) the corners lose this share of
/// their light besides the cos^4 law's, as a fast lens's corners do (lensfun's EF 35mm f/1.4L wide open:
/// 78 %; at f/2.8 about half of that); it fades to nothing as the lens is stopped down to
/// kClearVignetteAperture, where the cos^4 law alone remains.
inline constexpr double kOpenVignette = 0.35;
inline constexpr double kClearVignetteAperture = 5.6;

/// Lateral chromatic aberration: the red picture is this much larger than the green one and the blue
/// this much smaller, about the centre: lensfun's measurement of the Nikon AF-S 35mm f/1.8G ED
/// (data/db/slr-nikon.xml, tca poly3 vr 1.000618, vb 0.999651), 0.45 pixels of red and 0.26 of blue
/// at the corners of a 1280x720 picture, in proportion for other sizes.
inline constexpr double kRedScale = 1.000618;
inline constexpr double kBlueScale = 0.999651;

/// The sensor's noise, Poissonian-Gaussian in linear light (Foi, Trimeche, Katkovnik & Egiazarian 2008,
/// "Practical Poissonian-Gaussian noise modeling and fitting for single-image raw-data", IEEE TIP): a
/// value v (after the exposure) gets noise of variance kGrainShot v + kGrainFloor, different in every
/// pixel and every frame. Its luma part is shared by the three channels, its chroma part (half as
/// strong) is each channel's own.
inline constexpr double kGrainShot = 2.4e-4;
inline constexpr double kGrainFloor = 1.6e-6;
inline constexpr double kGrainChroma = 0.5;

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

/// The vignetting of a lens at f-number `aperture`: vignette()'s cos^4 law, times the optical
/// vignetting, 1 - k r^2 with r 1 at the corners and k kOpenVignette at kOpenAperture, fading to 0 at
/// kClearVignetteAperture.
float vignette(int x, int y, int width, int height, double aperture);

/// Multiplies every pixel by kExposure and its vignetting factor (of a lens at f-number `aperture`;
/// stopped down when none is given).
void expose(HdrImage& image);
void expose(HdrImage& image, double aperture);

/// Lateral chromatic aberration: the red picture scaled by kRedScale and the blue by kBlueScale about
/// the picture's centre (sampled bilinearly), the green left as it is.
void chromatic_aberration(HdrImage& image);

/// Pixels the red (`red`) or blue picture is moved at pixel (x, y) of a width x height picture, away
/// from the centre (negative: towards it).
double chromatic_shift(double x, double y, int width, int height, bool red);

/// The sensor's noise (kGrainShot, kGrainFloor) for movie frame `frame`: its pattern is drawn from a
/// hash of the frame number and the pixel, so each frame's is its own and the same on every run.
void add_grain(HdrImage& image, int frame);

/// Adds the lens's glare: kGlareShare of the light above kGlareThreshold is spread by a wide
/// point-spread function and added back, so the total light is kept (less what spreads off the
/// picture's edges). A picture with nothing over-bright is left exactly as it was.
void add_glare(HdrImage& image);

/// The tone curve, the film colour and the sRGB encoding of an exposed-and-glared picture: 8-bit sRGB,
/// three bytes a pixel.
std::vector<std::uint8_t> tone_map(const HdrImage& image);

/// What the develop stage knows of a frame's lens: the frame's line of lens.txt and the fixed scene
/// its depth is cast from (frame_lens.h).
struct DevelopLens {
  const FrameLens* frame = nullptr;
  const DepthScene* scene = nullptr;
};

/// The whole pipeline on a picture: exposure and vignetting, then for a frame whose lens is given its
/// depth of field (depth_of_field.h, from the depth cast_depth() casts) and chromatic aberration, then
/// glare, the sensor's noise (with the lens), tone curve, film colour, sRGB.
std::vector<std::uint8_t> develop(HdrImage image, const DevelopLens& lens = {});

/// Develops `image` into the PNG at `png_path`, with `caption` (a game movie's, lower_third.h) drawn
/// over it when given. False, with `error` naming the file, when it cannot be written (or the
/// caption's fonts are not installed); no half-written PNG is left behind.
bool develop_to_png(HdrImage image, const std::string& png_path, std::string& error,
                    const FrameCaption* caption = nullptr, const DevelopLens& lens = {});

/// Develops the .hdr at `hdr_path` into the PNG at `png_path`. False, with `error` saying why (the
/// file and the reason), when the .hdr cannot be read or the PNG cannot be written; no half-written
/// PNG is left behind.
bool develop_file(const std::string& hdr_path, const std::string& png_path, std::string& error);

}  // namespace bsim
