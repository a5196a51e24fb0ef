#include "ball_model.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <imgui.h>

#include "cue_pose.h"
#include "fonts.h"

namespace bsim {

namespace {
Vec3 linear(const SrgbColor& c) { return srgb(c.r, c.g, c.b); }
}  // namespace

Vec3 ball_ivory() { return linear(kBallIvory); }

Vec3 ball_color(int number) { return linear(ball_srgb(number)); }

MeshData make_sphere_mesh(int slices, int stacks) {
  MeshData mesh;
  for (int i = 0; i <= stacks; ++i) {
    const double theta = std::numbers::pi * i / stacks;  // from +z down to -z
    for (int j = 0; j <= slices; ++j) {
      const double phi = 2 * std::numbers::pi * j / slices;
      const Vec3 p(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      mesh.add_vertex(p, p, Vec3(1, 1, 1));
    }
  }
  const auto index = [slices](int i, int j) { return static_cast<std::uint32_t>(i * (slices + 1) + j); };
  for (int i = 0; i < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      if (i > 0) mesh.indices.insert(mesh.indices.end(), {index(i, j), index(i + 1, j), index(i, j + 1)});
      if (i + 1 < stacks)
        mesh.indices.insert(mesh.indices.end(), {index(i, j + 1), index(i + 1, j), index(i + 1, j + 1)});
    }
  return mesh;
}

MeshData make_cue_mesh() {
  MeshData mesh;
  constexpr int kSides = 32;
  // Rings where the colour changes (tip, ferrule, shaft, joint, wrap, butt), so bands stay crisp.
  const double stations[] = {0, 0.009, 0.010, 0.034, 0.035, 0.80, 0.82, 1.02, 1.30, 1.44, kCueLength};
  const auto radius = [](double s) { return kCueTipRadius + (kCueButtRadius - kCueTipRadius) * s / kCueLength; };
  const double slope = (kCueButtRadius - kCueTipRadius) / kCueLength;
  std::uint32_t previous = 0;
  bool first = true;
  for (double s : stations) {
    const std::uint32_t ring = static_cast<std::uint32_t>(mesh.vertices.size());
    for (int k = 0; k <= kSides; ++k) {
      const double a = 2 * std::numbers::pi * k / kSides;
      const Vec3 radial(0, std::cos(a), std::sin(a));
      const Vec3 normal = (radial - Vec3(slope, 0, 0)).normalized();
      mesh.add_vertex(Vec3(s, 0, 0) + radial * radius(s), normal, Vec3(1, 1, 1), s);
    }
    if (!first)
      for (std::uint32_t k = 0; k < kSides; ++k)
        mesh.indices.insert(mesh.indices.end(),
                            {previous + k, ring + k, previous + k + 1, previous + k + 1, ring + k, ring + k + 1});
    previous = ring;
    first = false;
  }
  for (double s : {0.0, kCueLength}) {
    const Vec3 normal(s == 0 ? -1 : 1, 0, 0);
    const std::uint32_t centre = mesh.add_vertex(Vec3(s, 0, 0), normal, Vec3(1, 1, 1), s);
    for (int k = 0; k <= kSides; ++k) {
      const double a = 2 * std::numbers::pi * k / kSides;
      mesh.add_vertex(Vec3(s, std::cos(a) * radius(s), std::sin(a) * radius(s)), normal, Vec3(1, 1, 1), s);
    }
    for (std::uint32_t k = 0; k < kSides; ++k)
      mesh.indices.insert(mesh.indices.end(), {centre, centre + 1 + k, centre + 2 + k});
  }
  return mesh;
}

MeshData make_shadow_quad() {
  MeshData mesh;
  const Vec3 up(0, 0, 1), black(0, 0, 0);
  mesh.add_vertex(Vec3(-1, -1, 0), up, black, -1, -1);
  mesh.add_vertex(Vec3(1, -1, 0), up, black, 1, -1);
  mesh.add_vertex(Vec3(1, 1, 0), up, black, 1, 1);
  mesh.add_vertex(Vec3(-1, 1, 0), up, black, -1, 1);
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

std::vector<std::uint8_t> make_number_atlas(int cell) {
  std::vector<std::uint8_t> atlas(static_cast<std::size_t>(cell) * cell * 16, 0);
  ImFontAtlas fonts;
  ImFontConfig config;
  config.OversampleH = 1;
  config.OversampleV = 1;
  config.PixelSnapH = true;
  static const ImWchar kDigits[] = {'0', '9', 0};
  const std::string path = find_dejavu("DejaVuSansCondensed-Bold.ttf");
  const std::string fallback = find_dejavu("DejaVuSans-Bold.ttf");
  const float px = static_cast<float>(cell) * 0.70f;
  ImFont* font = nullptr;
  if (!path.empty() || !fallback.empty())
    font = fonts.AddFontFromFileTTF((path.empty() ? fallback : path).c_str(), px, &config, kDigits);
  else
    font = fonts.AddFontDefault();
  unsigned char* pixels = nullptr;
  int width = 0, height = 0;
  fonts.GetTexDataAsAlpha8(&pixels, &width, &height);
  for (int number = 1; number <= 15; ++number) {
    const std::string text = std::to_string(number);
    // Ink extent of the digits laid out on one line, to centre them in the cell.
    double pen = 0, ink_x0 = 1e9, ink_x1 = -1e9, ink_y0 = 1e9, ink_y1 = -1e9;
    struct Placed {
      const ImFontGlyph* glyph;
      double x;
    };
    std::vector<Placed> placed;
    for (char c : text) {
      const ImFontGlyph* g = font->FindGlyph(static_cast<ImWchar>(c));
      if (!g) continue;
      placed.push_back({g, pen});
      ink_x0 = std::min(ink_x0, pen + g->X0);
      ink_x1 = std::max(ink_x1, pen + g->X1);
      ink_y0 = std::min<double>(ink_y0, g->Y0);
      ink_y1 = std::max<double>(ink_y1, g->Y1);
      pen += g->AdvanceX * 0.92;  // a little tighter than text, as on real balls
    }
    if (placed.empty()) continue;
    // Two-digit numbers are squeezed to fit the disc.
    const double scale = std::min(1.0, 0.74 * cell / (ink_x1 - ink_x0));
    const int cell_x = (number % 4) * cell, cell_y = (number / 4) * cell;
    const double off_x = cell / 2.0 - (ink_x0 + ink_x1) / 2 * scale;
    const double off_y = cell / 2.0 - (ink_y0 + ink_y1) / 2;
    for (const Placed& p : placed) {
      const ImFontGlyph* g = p.glyph;
      const int gw = static_cast<int>(std::lround((g->U1 - g->U0) * width));
      const int gh = static_cast<int>(std::lround((g->V1 - g->V0) * height));
      const int u0 = static_cast<int>(std::lround(g->U0 * width)), v0 = static_cast<int>(std::lround(g->V0 * height));
      for (int y = 0; y < gh; ++y)
        for (int x = 0; x < gw; ++x) {
          const int tx = cell_x + static_cast<int>(std::lround(off_x + (p.x + g->X0 + x) * scale));
          const int ty = cell_y + static_cast<int>(std::lround(off_y + g->Y0 + y));
          if (tx < cell_x || tx >= cell_x + cell || ty < cell_y || ty >= cell_y + cell) continue;
          std::uint8_t& out = atlas[static_cast<std::size_t>(ty) * cell * 4 + tx];
          out = std::max(out, pixels[static_cast<std::size_t>(v0 + y) * width + u0 + x]);
        }
    }
  }
  return atlas;
}

}  // namespace bsim
