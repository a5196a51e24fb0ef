#include "mesh.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "gl_api.h"

namespace bsim {

std::uint32_t MeshData::add_vertex(const Vec3& position, const Vec3& normal, const Vec3& color, double u, double v) {
  Vertex vertex{};
  for (int i = 0; i < 3; ++i) {
    vertex.position[i] = static_cast<float>(position[i]);
    vertex.normal[i] = static_cast<float>(normal[i]);
    vertex.color[i] = static_cast<float>(color[i]);
  }
  vertex.aux[0] = static_cast<float>(u);
  vertex.aux[1] = static_cast<float>(v);
  vertices.push_back(vertex);
  return static_cast<std::uint32_t>(vertices.size() - 1);
}

void MeshData::add_quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& color,
                        double max_cell) {
  Vec3 normal = (c - a).cross(d - b);
  if (normal.norm() < 1e-12) return;
  normal.normalize();
  const auto cells = [max_cell](double length) {
    return max_cell > 0 ? std::max(1, static_cast<int>(std::ceil(length / max_cell))) : 1;
  };
  const int nu = cells(std::max((b - a).norm(), (c - d).norm()));
  const int nv = cells(std::max((d - a).norm(), (c - b).norm()));
  const std::uint32_t first = static_cast<std::uint32_t>(vertices.size());
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const double u = static_cast<double>(i) / nu, v = static_cast<double>(j) / nv;
      add_vertex((1 - v) * ((1 - u) * a + u * b) + v * ((1 - u) * d + u * c), normal, color);
    }
  const auto at = [&](int i, int j) { return first + static_cast<std::uint32_t>(j * (nu + 1) + i); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i)
      indices.insert(indices.end(),
                     {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
}

void MeshData::add_triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& color) {
  Vec3 normal = (b - a).cross(c - a);
  if (normal.norm() < 1e-12) return;
  normal.normalize();
  const std::uint32_t i = add_vertex(a, normal, color);
  add_vertex(b, normal, color);
  add_vertex(c, normal, color);
  indices.insert(indices.end(), {i, i + 1, i + 2});
}

void MeshData::add_polygon(const std::vector<Vec3>& points, const Vec3& color) {
  if (points.size() < 3) return;
  // Newell's normal: robust for any planar polygon.
  Vec3 normal(0, 0, 0);
  for (std::size_t k = 0; k < points.size(); ++k) normal += points[k].cross(points[(k + 1) % points.size()]);
  if (normal.norm() < 1e-12) return;
  normal.normalize();
  const std::uint32_t first = static_cast<std::uint32_t>(vertices.size());
  for (const Vec3& p : points) add_vertex(p, normal, color);
  for (std::uint32_t k = 1; k + 1 < points.size(); ++k)
    indices.insert(indices.end(), {first, first + k, first + k + 1});
}

void MeshData::add_box(const Vec3& lo, const Vec3& hi, const Vec3& color) {
  const Vec3 p[8] = {{lo.x(), lo.y(), lo.z()}, {hi.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), lo.z()},
                     {lo.x(), hi.y(), lo.z()}, {lo.x(), lo.y(), hi.z()}, {hi.x(), lo.y(), hi.z()},
                     {hi.x(), hi.y(), hi.z()}, {lo.x(), hi.y(), hi.z()}};
  add_quad(p[0], p[3], p[2], p[1], color);  // bottom
  add_quad(p[4], p[5], p[6], p[7], color);  // top
  add_quad(p[0], p[1], p[5], p[4], color);
  add_quad(p[1], p[2], p[6], p[5], color);
  add_quad(p[2], p[3], p[7], p[6], color);
  add_quad(p[3], p[0], p[4], p[7], color);
}

void MeshData::append(const MeshData& other) {
  const auto base = static_cast<std::uint32_t>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  for (std::uint32_t i : other.indices) indices.push_back(base + i);
}

GpuMesh::~GpuMesh() { release(); }

void GpuMesh::release() {
  if (ebo_) glDeleteBuffers(1, &ebo_);
  if (vbo_) glDeleteBuffers(1, &vbo_);
  if (vao_) glDeleteVertexArrays(1, &vao_);
  vao_ = vbo_ = ebo_ = 0;
  count_ = 0;
}

void GpuMesh::upload(const MeshData& data) {
  release();
  if (data.indices.empty()) return;
  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  glGenBuffers(1, &vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.vertices.size() * sizeof(Vertex)), data.vertices.data(),
               GL_STATIC_DRAW);
  glGenBuffers(1, &ebo_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.indices.size() * sizeof(std::uint32_t)),
               data.indices.data(), GL_STATIC_DRAW);
  const auto attribute = [](GLuint index, GLint size, std::size_t offset) {
    glEnableVertexAttribArray(index);
    glVertexAttribPointer(index, size, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<const void*>(offset));
  };
  attribute(0, 3, offsetof(Vertex, position));
  attribute(1, 3, offsetof(Vertex, normal));
  attribute(2, 3, offsetof(Vertex, color));
  attribute(3, 2, offsetof(Vertex, aux));
  glBindVertexArray(0);
  count_ = static_cast<int>(data.indices.size());
}

void GpuMesh::draw() const {
  if (!count_) return;
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, count_, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

Vec3 srgb(int r, int g, int b) {
  const auto linear = [](int c) {
    const double s = c / 255.0;
    return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
  };
  return Vec3(linear(r), linear(g), linear(b));
}

}  // namespace bsim
