#include "overlays.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include <imgui.h>

#include "camera_moment.h"
#include "labels.h"
#include "shot.h"
#include "table.h"

namespace bsim {

namespace {

constexpr double kPathStep = 1.0 / 240.0;  // s between path samples: smooth at any preview size

struct Projector {
  Eigen::Matrix4f view_projection;
  double width, height, left, top;
  bool operator()(const Vec3& p, ImVec2& out) const {
    double x = 0, y = 0;
    if (!project_to_pixels(view_projection, p, width, height, x, y)) return false;
    out = ImVec2(static_cast<float>(left + x), static_cast<float>(top + y));
    return true;
  }
};

Projector projector(const OverlayFrame& f) {
  const double aspect = f.width / std::max(f.height, 1.0);
  return {projection_matrix(f.camera, aspect) * view_matrix(f.camera), f.width, f.height, f.left, f.top};
}

float ui_scale(const OverlayFrame& f) { return static_cast<float>(std::clamp(f.height / 720.0, 0.5, 2.0)); }

// A polyline broken where points fall behind the camera.
void draw_projected_path(ImDrawList& list, const Projector& project, const std::vector<Vec3>& points, ImU32 color,
                         float thickness) {
  std::vector<ImVec2> run;
  const auto flush = [&] {
    if (run.size() >= 2) list.AddPolyline(run.data(), static_cast<int>(run.size()), color, ImDrawFlags_None, thickness);
    run.clear();
  };
  for (const Vec3& p : points) {
    ImVec2 s;
    if (project(p, s))
      run.push_back(s);
    else
      flush();
  }
  flush();
}

void text_with_shadow(ImDrawList& list, ImFont* font, float size, ImVec2 at, ImU32 color, const std::string& text) {
  list.AddText(font, size, ImVec2(at.x + 1, at.y + 1), IM_COL32(0, 0, 0, 200), text.c_str());
  list.AddText(font, size, at, color, text.c_str());
}

const Event* latest_event(const Timeline& timeline, double t) {
  const Event* latest = nullptr;
  for (const Event& e : timeline.events())
    if (e.time <= t + 1e-9) latest = &e;
  return latest;
}

const CameraShot* camera_shot_at(const Shot& shot, double t) {
  if (!shot.camera) return nullptr;
  const int i = shot.camera->shot_at(t + 1e-9);  // a frame at a description's event shows that one
  if (i < 0 || i >= static_cast<int>(shot.scene.camera.size())) return nullptr;
  return &shot.scene.camera[static_cast<std::size_t>(i)];
}

// One ball's path cut at the shot in play and at the current time: the shots before and after it
// (drawn faint), the part of this shot already travelled and the part still to come. The pieces
// join, so the path stays one line.
struct PathPieces {
  std::vector<Vec3> earlier, past, future, later;
};

PathPieces path_pieces(const std::vector<OverlayPaths::Point>& path, double begin, double t, double end,
                       const Vec3& now, bool gone) {
  PathPieces p;
  for (const auto& point : path) {
    if (point.time < begin)
      p.earlier.push_back(point.where);
    else if (point.time <= t)
      p.past.push_back(point.where);
    else if (point.time <= end)
      p.future.push_back(point.where);
    else
      p.later.push_back(point.where);
  }
  if (!gone) {
    if (t >= begin && t <= end) p.past.push_back(now);
    p.future.insert(p.future.begin(), p.past.empty() ? now : p.past.back());
  } else {
    p.future.clear();  // a pocketed ball goes nowhere after now
  }
  if (!p.earlier.empty() && !p.past.empty()) p.earlier.push_back(p.past.front());
  if (!p.later.empty()) {
    const std::vector<Vec3>& before = p.future.size() >= 2 ? p.future : p.past;
    if (!before.empty()) p.later.insert(p.later.begin(), before.back());
  }
  return p;
}

// The stretch of the timeline that belongs to the shot in play at t: from its start to the next
// shot's (the whole timeline for a scene of one shot).
void stretch_at(const Timeline& timeline, double t, double& begin, double& end) {
  begin = -INFINITY;
  end = INFINITY;
  if (timeline.shot_count() < 2) return;
  const ShotStretch stretch = shot_stretch(timeline, timeline.shot_at(t));
  if (stretch.shot > 0) begin = stretch.start;
  if (!stretch.last) end = stretch.end;
}

// On the cloth a path lies on the bed; in a pocket it follows the drop.
Vec3 path_point(const BallState& s, double radius) {
  Vec3 p = s.position;
  p.z() = std::min(p.z() - radius, 0.0) + 0.001;
  return p;
}

}  // namespace

OverlayPaths overlay_paths(const Shot& shot) {
  OverlayPaths paths;
  const Timeline& timeline = shot.timeline;
  const double duration = timeline.duration(), radius = timeline.physics().ball_radius;
  for (int i = 0; i < timeline.ball_count(); ++i) {
    std::vector<OverlayPaths::Point>& path = paths.balls.emplace_back();
    for (double t = 0;; t += kPathStep) {
      const double at = std::min(t, duration);
      const BallState s = timeline.state(i, at);
      if (s.motion == Motion::pocketed) break;
      const Vec3 p = path_point(s, radius);
      if (path.empty() || (p - path.back().where).norm() > 1e-4) path.push_back({at, p});
      if (at >= duration) break;
    }
  }
  if (shot.camera) {
    constexpr int kCameraSamples = 400;
    for (int k = 0; k <= kCameraSamples; ++k) {
      const double t = duration * k / kCameraSamples;
      const CameraPose pose = shot.camera->pose(t);
      paths.eyes.push_back({t, pose.location});
      paths.targets.push_back({t, pose.look_at});
    }
  }
  return paths;
}

void draw_ball_paths(ImDrawList& list, const OverlayFrame& f) {
  const OverlayPaths local = f.paths ? OverlayPaths{} : overlay_paths(f.shot);
  const OverlayPaths& paths = f.paths ? *f.paths : local;
  const Timeline& timeline = f.shot.timeline;
  const Projector project = projector(f);
  const float scale = ui_scale(f);
  // In a scene of several shots the shot in play is drawn as a shot of its own is; the paths of the
  // others are faint, so a break's fan of lines does not bury the shot that follows it.
  double begin = 0, end = 0;
  stretch_at(timeline, f.time, begin, end);
  for (int i = 0; i < timeline.ball_count() && i < static_cast<int>(paths.balls.size()); ++i) {
    const int number = f.shot.scene.balls[static_cast<std::size_t>(i)].number;
    const BallState now = timeline.state(i, f.time);
    const Vec3 here = path_point(now, timeline.physics().ball_radius);
    const PathPieces p =
        path_pieces(paths.balls[static_cast<std::size_t>(i)], begin, f.time, end, here, now.motion == Motion::pocketed);
    for (const std::vector<Vec3>* other : {&p.earlier, &p.later})
      draw_projected_path(list, project, *other, ball_ui_color(number, 50), 1.2f * scale);
    draw_projected_path(list, project, p.future, IM_COL32(0, 0, 0, 90), 3.5f * scale);
    draw_projected_path(list, project, p.future, ball_ui_color(number, 120), 1.5f * scale);
    draw_projected_path(list, project, p.past, IM_COL32(0, 0, 0, 150), 4.f * scale);
    draw_projected_path(list, project, p.past, ball_ui_color(number, 255), 2.2f * scale);
  }
}

void draw_event_markers(ImDrawList& list, const OverlayFrame& f) {
  const Projector project = projector(f);
  const float scale = ui_scale(f);
  const Event* current = latest_event(f.shot.timeline, f.time);
  for (const Event& e : f.shot.timeline.events()) {
    if (e.type == EventType::start || e.type == EventType::end) continue;
    ImVec2 s;
    if (!project(e.where, s)) continue;
    const bool is_current = &e == current;
    const bool past = e.time <= f.time;
    const ImU32 color = (event_color(e.type) & 0x00FFFFFFu) | (past ? 0xFF000000u : 0xB0000000u);
    const float r = (is_current ? 9.f : 6.f) * scale;
    list.AddCircle(s, r + 1.5f * scale, IM_COL32(0, 0, 0, 160), 24, 3.f * scale);
    list.AddCircle(s, r, color, 24, (is_current ? 2.5f : 1.6f) * scale);
    const std::string label = std::to_string(e.index);
    const float size = f.fonts.small_size;
    const ImVec2 extent = f.fonts.small->CalcTextSizeA(size, 1e9f, 0, label.c_str());
    const ImVec2 at(s.x + r + 2 * scale, s.y - r - extent.y + 2 * scale);
    list.AddRectFilled(ImVec2(at.x - 2, at.y), ImVec2(at.x + extent.x + 2, at.y + extent.y), IM_COL32(0, 0, 0, 150),
                       3.f);
    list.AddText(f.fonts.small, size, at, color, label.c_str());
  }
}

namespace {

// The camera map: the table and the camera's path seen from above, in a box at the view's top right.
struct CameraMap {
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;  ///< m, the area shown
  float pixels_per_m = 0;
  float w = 0, h = 0;  ///< px, the area's size on screen
  ImVec2 origin;       ///< px, its top left corner

  void grow(const Vec3& p, double margin) {
    x0 = std::min(x0, p.x() - margin);
    x1 = std::max(x1, p.x() + margin);
    y0 = std::min(y0, p.y() - margin);
    y1 = std::max(y1, p.y() + margin);
  }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  ImVec2 map(const Vec3& p) const {
    return ImVec2(origin.x + static_cast<float>(p.x() - x0) * pixels_per_m,
                  origin.y + static_cast<float>(y1 - p.y()) * pixels_per_m);
  }
};

// The area the map shows: the table with some room around it, and everywhere the camera goes.
CameraMap camera_map_area(const Scene& scene, const OverlayPaths& paths) {
  CameraMap m;
  for (const Rail& r : scene.rails) {
    m.grow(r.a, 0.25);
    m.grow(r.b, 0.25);
  }
  for (const Pocket& p : scene.pockets) m.grow(p.center, 0.25);
  for (const auto& e : paths.eyes) m.grow(e.where, 0.15);
  return m;
}

// Fits the area into a box at most 30% of the view wide and 45% high, in the top right corner.
void place_camera_map(CameraMap& m, const OverlayFrame& f, float scale) {
  const float margin = 10 * scale;
  const float box_w = static_cast<float>(f.width) * 0.3f;
  const float box_h =
      std::min(static_cast<float>(f.height) * 0.45f, box_w * static_cast<float>((m.y1 - m.y0) / (m.x1 - m.x0)));
  m.pixels_per_m = std::min(box_w / static_cast<float>(m.x1 - m.x0), box_h / static_cast<float>(m.y1 - m.y0));
  m.w = m.pixels_per_m * static_cast<float>(m.x1 - m.x0);
  m.h = m.pixels_per_m * static_cast<float>(m.y1 - m.y0);
  m.origin = ImVec2(static_cast<float>(f.left + f.width) - margin - m.w, static_cast<float>(f.top) + margin);
}

// The playing surface between the cushions, the cushions, the pockets, the balls now.
void draw_map_table(ImDrawList& list, const OverlayFrame& f, const CameraMap& m, float scale) {
  const Scene& scene = f.shot.scene;
  for (const Rail& r : scene.rails) {
    list.AddLine(m.map(r.a), m.map(r.b), IM_COL32(40, 150, 90, 255), 3.f * scale);
  }
  for (const Pocket& p : scene.pockets)
    list.AddCircleFilled(m.map(p.center), static_cast<float>(p.radius) * m.pixels_per_m, IM_COL32(0, 0, 0, 255), 20);
  const std::vector<BallState> balls = f.shot.timeline.states(f.time);
  const float ball_r = std::max(2.f, static_cast<float>(scene.physics.ball_radius) * m.pixels_per_m);
  for (std::size_t i = 0; i < balls.size() && i < scene.balls.size(); ++i) {
    if (balls[i].motion == Motion::pocketed) continue;
    list.AddCircleFilled(m.map(balls[i].position), ball_r, ball_ui_color(scene.balls[i].number), 12);
  }
}

// Path of the camera (bright up to now) and of what it looks at.
void draw_map_camera_paths(ImDrawList& list, const OverlayFrame& f, const OverlayPaths& paths, const CameraMap& m,
                           float scale) {
  std::vector<ImVec2> looked, past, future;
  for (const auto& p : paths.targets) looked.push_back(m.map(p.where));
  for (const auto& p : paths.eyes) (p.time <= f.time ? past : future).push_back(m.map(p.where));
  if (!past.empty()) future.insert(future.begin(), past.back());
  list.AddPolyline(looked.data(), static_cast<int>(looked.size()), IM_COL32(110, 200, 255, 110), ImDrawFlags_None,
                   1.2f * scale);
  if (future.size() >= 2)
    list.AddPolyline(future.data(), static_cast<int>(future.size()), IM_COL32(255, 214, 90, 110), ImDrawFlags_None,
                     1.5f * scale);
  if (past.size() >= 2)
    list.AddPolyline(past.data(), static_cast<int>(past.size()), IM_COL32(255, 214, 90, 255), ImDrawFlags_None,
                     2.f * scale);
}

// Where the camera is now, its horizontal field of view, and where it looks.
void draw_map_camera_now(ImDrawList& list, const OverlayFrame& f, const CameraMap& m, float scale) {
  const CameraPose now = f.shot.camera->pose(f.time);
  const ImVec2 eye = m.map(now.location), look = m.map(now.look_at);
  Vec3 dir = now.look_at - now.location;
  dir.z() = 0;
  if (dir.norm() > 1e-6) {
    dir.normalize();
    const double half = 0.5 * kCameraFovDeg * kDegToRad;
    const double reach = 0.6;
    for (double side : {-1.0, 1.0}) {
      const double c = std::cos(side * half), s = std::sin(side * half);
      const Vec3 edge(dir.x() * c - dir.y() * s, dir.x() * s + dir.y() * c, 0);
      list.AddLine(eye, m.map(now.location + edge * reach), IM_COL32(255, 255, 255, 150), 1.2f * scale);
    }
  }
  list.AddLine(eye, look, IM_COL32(110, 200, 255, 220), 1.2f * scale);
  list.AddCircleFilled(look, 3.f * scale, IM_COL32(110, 200, 255, 255), 12);
  list.AddCircleFilled(eye, 4.5f * scale, IM_COL32(255, 214, 90, 255), 16);
  list.AddCircle(eye, 4.5f * scale, IM_COL32(0, 0, 0, 255), 16, 1.f);
}

}  // namespace

void draw_camera_map(ImDrawList& list, const OverlayFrame& f) {
  if (!f.shot.camera) return;
  const OverlayPaths local = f.paths ? OverlayPaths{} : overlay_paths(f.shot);
  const OverlayPaths& paths = f.paths ? *f.paths : local;
  CameraMap m = camera_map_area(f.shot.scene, paths);
  if (m.empty()) return;
  const float scale = ui_scale(f);
  place_camera_map(m, f, scale);
  list.AddRectFilled(ImVec2(m.origin.x - 4, m.origin.y - 4), ImVec2(m.origin.x + m.w + 4, m.origin.y + m.h + 4),
                     IM_COL32(14, 16, 20, 215), 6.f);
  draw_map_table(list, f, m, scale);
  draw_map_camera_paths(list, f, paths, m, scale);
  draw_map_camera_now(list, f, m, scale);
  text_with_shadow(list, f.fonts.small, f.fonts.small_size,
                   ImVec2(m.origin.x + 2, m.origin.y + m.h - f.fonts.small_size - 1), IM_COL32(220, 220, 220, 230),
                   "camera from above");
}

namespace {

/// "t = 1.500 s  •  after event 3 (1.480 s): ball 0 – ball 5  •  camera: follow ball 0".
std::string status_text(const OverlayFrame& f) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "t = %.3f s", f.time);
  std::string text = buffer;
  const std::vector<int> painted = painted_numbers(f.shot.scene);
  if (const Event* e = latest_event(f.shot.timeline, f.time)) {
    std::snprintf(buffer, sizeof buffer, "  \xE2\x80\xA2  after event %d (%.3f s): ", e->index, e->time);
    text += buffer + event_label(*e, painted);
  }
  if (const CameraShot* c = camera_shot_at(f.shot, f.time)) {
    text += "  \xE2\x80\xA2  camera: " + camera_shot_label(*c, painted);
    if (f.shot.camera->pose(f.time).interpolating) text += " (interpolating)";
  }
  return text;
}

/// Below this many pixels high the status line takes the small font: it wraps onto fewer lines.
constexpr double kSmallStatusBelow = 400;

}  // namespace

StatusLine status_line_layout(const OverlayFrame& f, bool top) {
  StatusLine s;
  s.text = status_text(f);
  const bool small = f.height < kSmallStatusBelow;
  s.font = small ? f.fonts.small : f.fonts.regular;
  s.size = small ? f.fonts.small_size : f.fonts.regular_size;
  const float pad = small ? 3.f : 6.f, margin = small ? 2.f : 4.f;
  // Wrapped to the picture's width, so a small picture shows all of it.
  s.wrap = std::max(static_cast<float>(f.width) - 2 * (pad + margin), 20.f);
  const ImVec2 extent = s.font->CalcTextSizeA(s.size, 1e9f, s.wrap, s.text.c_str());
  const float left = static_cast<float>(f.left), picture_top = static_cast<float>(f.top);
  const float y =
      top ? picture_top + pad / 2 + margin : static_cast<float>(f.top + f.height) - extent.y - pad / 2 - margin;
  s.at = ImVec2(left + pad + margin, y);
  s.box = {s.at.x - pad, s.at.y - pad / 2, s.at.x + extent.x + pad, s.at.y + extent.y + pad / 2};
  s.top = top;
  return s;
}

void draw_status_line(ImDrawList& list, const StatusLine& s) {
  list.AddRectFilled(ImVec2(s.box.x0, s.box.y0), ImVec2(s.box.x1, s.box.y1), IM_COL32(0, 0, 0, 150), 4.f);
  list.AddText(s.font, s.size, s.at, IM_COL32(235, 235, 235, 255), s.text.c_str(), nullptr, s.wrap);
}

void draw_status_line(ImDrawList& list, const OverlayFrame& f) { draw_status_line(list, status_line_layout(f, false)); }

void draw_scripted_frustum(ImDrawList& list, const OverlayFrame& f, double aspect) {
  if (!f.shot.camera) return;
  const Projector project = projector(f);
  const OverlayPaths local = f.paths ? OverlayPaths{} : overlay_paths(f.shot);
  std::vector<Vec3> path;
  for (const auto& p : (f.paths ? *f.paths : local).eyes) path.push_back(p.where);
  draw_projected_path(list, project, path, IM_COL32(255, 214, 90, 150), 1.5f);

  const ViewCamera scripted = scripted_view(f.shot, f.time);
  const CameraView view = camera_view(scripted, aspect);
  const double depth = 0.35;  // m, how far the drawn frustum reaches
  const Vec3 centre = scripted.eye + view.forward() * depth;
  const Vec3 to_top = view.up() * (view.half_height() * depth);  // from the centre to the top edge
  // The picture's corners `depth` ahead: top right, top left, bottom left, bottom right.
  const PicturePoint at[4] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  Vec3 corners[4];
  for (int k = 0; k < 4; ++k)
    corners[k] =
        centre + depth * (at[k].x * view.half_width() * view.right() + at[k].y * view.half_height() * view.up());
  const ImU32 color = IM_COL32(255, 214, 90, 255);
  ImVec2 eye, c[4];
  bool ok = project(scripted.eye, eye);
  for (int k = 0; k < 4; ++k) ok = project(corners[k], c[k]) && ok;
  if (ok) {
    for (int k = 0; k < 4; ++k) {
      list.AddLine(eye, c[k], color, 1.5f);
      list.AddLine(c[k], c[(k + 1) % 4], color, 2.f);
    }
    ImVec2 top;
    if (project(centre + to_top * 1.3, top)) list.AddTriangleFilled(c[0], c[1], top, IM_COL32(255, 214, 90, 160));
  }
  ImVec2 from, to;
  if (project(scripted.eye, from) && project(scripted.target, to)) {
    list.AddLine(from, to, IM_COL32(110, 200, 255, 160), 1.f);
    list.AddCircleFilled(to, 4.f, IM_COL32(110, 200, 255, 255), 12);
  }
}

namespace {

/// The table overlay's labels: each centred on a point of the table, on a dark pill so it reads over
/// cloth and wood alike. Gathered before they are drawn, so that the status line can keep clear of
/// them or they of it.
class TableLabels {
 public:
  explicit TableLabels(const OverlayFrame& f) : f_(f), project_(projector(f)) {}

  void add(const Vec3& where, const std::string& text, ImU32 color) {
    ImVec2 at;
    if (!project_(where, at)) return;
    const ImVec2 extent = f_.fonts.regular->CalcTextSizeA(f_.fonts.regular_size, 1e9f, 0, text.c_str());
    ImVec2 corner(at.x - extent.x / 2, at.y - extent.y / 2);
    // A label whose place is in the picture stays whole in it: near an edge it slides inwards.
    const auto left = static_cast<float>(f_.left), top = static_cast<float>(f_.top);
    const auto right = static_cast<float>(f_.left + f_.width), bottom = static_cast<float>(f_.top + f_.height);
    if (at.x >= left && at.x <= right && at.y >= top && at.y <= bottom) {
      corner.x = std::clamp(corner.x, std::min(left + kPad, right - extent.x - kPad), right - extent.x - kPad);
      corner.y =
          std::clamp(corner.y, std::min(top + kPad / 2, bottom - extent.y - kPad / 2), bottom - extent.y - kPad / 2);
    }
    labels_.push_back({at, corner, extent, text, color});
  }

  /// The pills, where they would be drawn if nothing moved them.
  std::vector<OverlayBox> boxes() const {
    std::vector<OverlayBox> out;
    for (const Label& l : labels_) out.push_back(pill(l.corner, l.extent));
    return out;
  }

  /// Draws every label; one whose pill would fall under `keep_clear` moves out of it (up when the box
  /// is at the picture's bottom, down when at its top), tied to its place by a thin line.
  void draw(ImDrawList& list, const OverlayBox* keep_clear, bool clear_at_top) const {
    for (const Label& l : labels_) {
      ImVec2 corner = l.corner;
      if (keep_clear && pill(corner, l.extent).overlaps(*keep_clear)) {
        corner.y = clear_at_top ? keep_clear->y1 + kPad / 2 + 2 : keep_clear->y0 - kPad / 2 - 2 - l.extent.y;
        const float y = clear_at_top ? corner.y - kPad / 2 : corner.y + l.extent.y + kPad / 2;
        list.AddLine(l.at, ImVec2(l.at.x, y), IM_COL32(0, 0, 0, 170), 3.f);
        list.AddLine(l.at, ImVec2(l.at.x, y), l.color, 1.f);
      }
      const OverlayBox box = pill(corner, l.extent);
      list.AddRectFilled(ImVec2(box.x0, box.y0), ImVec2(box.x1, box.y1), IM_COL32(0, 0, 0, 170), 5.f);
      list.AddText(f_.fonts.regular, f_.fonts.regular_size, corner, l.color, l.text.c_str());
    }
  }

 private:
  static constexpr float kPad = 4;
  struct Label {
    ImVec2 at, corner, extent;
    std::string text;
    ImU32 color;
  };
  static OverlayBox pill(ImVec2 corner, ImVec2 extent) {
    return {corner.x - kPad, corner.y - kPad / 2, corner.x + extent.x + kPad, corner.y + extent.y + kPad / 2};
  }

  const OverlayFrame& f_;
  Projector project_;
  std::vector<Label> labels_;
};

/// The rails', pockets' and balls' labels of the frame's moment.
TableLabels table_labels(const OverlayFrame& f) {
  TableLabels labels(f);
  const Scene& scene = f.shot.scene;
  const TableLayout layout = table_layout(scene);
  // Rails on the wood beside their nose line: the playing side is on the right walking from a to b.
  const double onto_wood = kStandardTable.cushion.width + kStandardTable.rail.width / 2;
  for (std::size_t i = 0; i < scene.rails.size(); ++i) {
    const Rail& rail = scene.rails[i];
    const Vec3 along = rail.b - rail.a;
    const Vec3 outward = Vec3(-along.y(), along.x(), 0).normalized();
    const Vec3 mid = (rail.a + rail.b) / 2 + outward * onto_wood;
    labels.add(Vec3(mid.x(), mid.y(), layout.rail_top), "rail " + std::to_string(i), IM_COL32(255, 226, 140, 255));
  }
  // Pockets just outside their hole, away from the table's centre.
  const Vec3 centre((layout.noses.x0 + layout.noses.x1) / 2, (layout.noses.y0 + layout.noses.y1) / 2, 0);
  for (std::size_t i = 0; i < scene.pockets.size(); ++i) {
    const Pocket& pocket = scene.pockets[i];
    Vec3 away = pocket.center - centre;
    away.z() = 0;
    away = away.norm() > 0 ? away.normalized() : Vec3(0, 1, 0);
    const Vec3 at = pocket.center + away * (pocket.radius + 0.04);
    // Its number, and on the standard table the name `pot` takes for it: "pocket 0" over "top-left".
    const std::string number = "pocket " + std::to_string(i);
    labels.add(Vec3(at.x(), at.y(), layout.rail_top),
               standard_pocket_set(scene.pockets) ? number + "\n" + std::string(standard_pocket_words()[i]) : number,
               pocket_color());
  }
  // Each ball's index in file order (what `cue`, `look`, `follow` and `spin` refer to), with its
  // painted number beside it where the two differ, as the timeline writes it: "1 (3)".
  const std::vector<int> painted = painted_numbers(scene);
  for (int i = 0; i < f.shot.timeline.ball_count(); ++i) {
    const BallState s = f.shot.timeline.state(i, f.time);
    if (s.motion == Motion::pocketed) continue;
    const double r = scene.physics.ball_radius;  // the label just beyond the ball, leaving it in sight
    labels.add(s.position + Vec3(0, 3 * r, r), ball_index_text(i, painted), IM_COL32(255, 255, 255, 255));
  }
  return labels;
}

}  // namespace

void draw_table_numbering(ImDrawList& list, const OverlayFrame& f) { table_labels(f).draw(list, nullptr, false); }

namespace {

/// The first ball-ball event of shot `shot` (from 0) in which balls a and b both take part, or null.
const Event* first_meeting(const Timeline& timeline, int a, int b, int shot) {
  for (const Event& e : timeline.events()) {
    if (e.type != EventType::ball_ball || e.shot != shot) continue;
    const bool has_a = std::find(e.balls.begin(), e.balls.end(), a) != e.balls.end();
    if (has_a && std::find(e.balls.begin(), e.balls.end(), b) != e.balls.end()) return &e;
  }
  return nullptr;
}

/// A circle of radius r about `centre`, level with the bed, as a closed polyline.
void draw_ring(ImDrawList& list, const Projector& project, const Vec3& centre, double r, ImU32 color, float width) {
  constexpr int kSegments = 48;
  std::vector<Vec3> points;
  for (int k = 0; k <= kSegments; ++k) {
    const double a = 2 * std::numbers::pi * k / kSegments;
    points.push_back(centre + Vec3(r * std::cos(a), r * std::sin(a), 0));
  }
  draw_projected_path(list, project, points, color, width);
}

}  // namespace

void draw_aim(ImDrawList& list, const OverlayFrame& f) {
  const Scene& scene = f.shot.scene;
  const Timeline& timeline = f.shot.timeline;
  // The shot in play at this time: its cue, and the balls where that shot found them.
  const int shot = std::clamp(timeline.shot_at(f.time), 0, std::max(scene.shot_count() - 1, 0));
  if (scene.cues.empty() || !scene.cues[static_cast<std::size_t>(shot)].aims()) return;
  const Cue& cue = scene.cues[static_cast<std::size_t>(shot)];
  const int struck = cue.target, target = cue.pot_ball;
  const Event* meeting = first_meeting(timeline, struck, target, shot);
  if (!meeting || f.time >= meeting->time) return;
  const std::size_t k = static_cast<std::size_t>(std::find(meeting->balls.begin(), meeting->balls.end(), struck) -
                                                 meeting->balls.begin());
  const double R = scene.physics.ball_radius;
  const auto on_bed = [](Vec3 p, double z) { return Vec3(p.x(), p.y(), z); };
  // The first shot from the scene's own lines; a later one from where the shot before left the balls.
  const double strike = shot == 0 ? 0.0 : timeline.shots()[static_cast<std::size_t>(shot)].cue;
  const auto where = [&](int b) {
    return shot == 0 ? scene.ball(b).position : timeline.motion_state(b, strike).position;
  };
  const Vec3 ghost = on_bed(meeting->before[k].position, R);
  const Vec3 from = on_bed(where(struck), 0.002);
  const Vec3 ball = on_bed(where(target), 0.002);
  const Vec3 pocket = on_bed(scene.pockets[static_cast<std::size_t>(cue.pot_pocket)].center, 0.002);
  const Projector project = projector(f);
  const float scale = ui_scale(f);
  // The struck ball's way to the ghost ball as played (curving with swerve), then the ghost ball.
  std::vector<Vec3> way;
  if (f.paths)
    for (const auto& p : f.paths->balls[static_cast<std::size_t>(struck)])
      if (p.time >= strike && p.time <= meeting->time) way.push_back(on_bed(p.where, 0.002));
  if (way.empty()) way.push_back(from);
  way.push_back(on_bed(ghost, 0.002));
  draw_projected_path(list, project, way, IM_COL32(255, 255, 255, 200), 2.f * scale);
  draw_ring(list, project, ghost, R, IM_COL32(255, 255, 255, 230), 2.f * scale);
  draw_ring(list, project, on_bed(ghost, 0.002), R, IM_COL32(255, 255, 255, 110), 1.f * scale);
  // The ball's intended line to the pocket, and where it drops.
  draw_projected_path(list, project, {ball, pocket}, IM_COL32(255, 200, 60, 230), 2.f * scale);
  draw_ring(list, project, pocket, 0.01, IM_COL32(255, 200, 60, 255), 2.f * scale);
}

namespace {

/// The status line at the picture's bottom, or at its top when fewer of the table's labels are there
/// (never with the camera map, which has the top right corner).
StatusLine place_status_line(const OverlayFrame& f, const std::vector<OverlayBox>& labels, bool top_taken) {
  const auto covered = [&](const StatusLine& s) {
    return std::count_if(labels.begin(), labels.end(), [&](const OverlayBox& b) { return b.overlaps(s.box); });
  };
  StatusLine bottom = status_line_layout(f, false);
  if (top_taken || covered(bottom) == 0) return bottom;
  StatusLine top = status_line_layout(f, true);
  return covered(top) < covered(bottom) ? top : bottom;
}

}  // namespace

void draw_overlays(ImDrawList& list, const OverlayFrame& given, const PreviewOverlays& overlays) {
  const bool others = overlays.paths || overlays.events || overlays.camera || overlays.table;
  if (!others && !overlays.aim) return;
  OverlayPaths local;
  OverlayFrame frame = given;
  if (!frame.paths) {
    local = overlay_paths(frame.shot);
    frame.paths = &local;
  }
  if (overlays.paths) draw_ball_paths(list, frame);
  if (overlays.events) draw_event_markers(list, frame);
  if (overlays.camera) draw_camera_map(list, frame);
  // The status line never covers a label of the table: it goes where fewer are, and those it would
  // still cover move out of its way.
  const TableLabels labels = overlays.table ? table_labels(frame) : TableLabels(frame);
  const StatusLine status = place_status_line(frame, labels.boxes(), overlays.camera);
  labels.draw(list, others ? &status.box : nullptr, status.top);
  if (overlays.aim) draw_aim(list, frame);
  if (others) draw_status_line(list, status);
}

}  // namespace bsim
