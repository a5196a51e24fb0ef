#pragma once
// Triangle meshes: built on the CPU in world or object space, then uploaded once.
#include <cstdint>
#include <vector>

#include "vec.h"

namespace bsim {

struct Vertex {
  float position[3];
  float normal[3];
  float color[3];  ///< linear RGB
  float aux[2];    ///< per-material: the cue's distance from the tip, a shadow's disc coordinates
};

struct MeshData {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;

  std::uint32_t add_vertex(const Vec3& position, const Vec3& normal, const Vec3& color, double u = 0, double v = 0);
  /// A flat quad a-b-c-d in order, either winding: the shader lights whichever side faces the eye.
  /// With `max_cell` > 0 (m) it is split into a grid of cells no longer than that, for per-vertex lighting.
  void add_quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& color, double max_cell = 0);
  void add_triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& color);
  /// A flat convex polygon, points in order.
  void add_polygon(const std::vector<Vec3>& points, const Vec3& color);
  /// A box between two corners, all six faces.
  void add_box(const Vec3& low, const Vec3& high, const Vec3& color);
  void append(const MeshData& other);
};

/// A mesh on the GPU (a vertex array with its buffers). Needs a current GL context for its whole life.
class GpuMesh {
 public:
  GpuMesh() = default;
  ~GpuMesh();
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;

  void upload(const MeshData& data);
  void draw() const;
  bool empty() const { return count_ == 0; }

 private:
  void release();
  unsigned vao_ = 0, vbo_ = 0, ebo_ = 0;
  int count_ = 0;
};

/// sRGB colour (0-255) to linear RGB, for colours chosen by eye.
Vec3 srgb(int r, int g, int b);

}  // namespace bsim
