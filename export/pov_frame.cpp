#include "pov_frame.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <vector>

#include "camera_view.h"
#include "cue_pose.h"
#include "frames.h"
#include "pov_format.h"
#include "pov_table.h"
#include "shot.h"

namespace bsim {

namespace {

/// A POV-Ray `matrix`: the images of x, y and z, then the translation.
std::string pov_matrix(const Vec3& x, const Vec3& y, const Vec3& z, const Vec3& at) {
  std::string text = "matrix <";
  const Vec3* rows[] = {&x, &y, &z, &at};
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 3; ++c) text += (r || c ? ", " : "") + pov_number((*rows[r])[c]);
  }
  return text + ">";
}

/// POV-Ray cannot orient a camera looking along its sky vector (z). A camera on its look point (closer
/// than the files' micrometre) is the straight-down camera, 1 m over its look point; a view that the
/// core counts as vertical (picture_up() is +y) is turned a hair towards +y so that POV-Ray puts the
/// table's +y at the top of its picture, as the preview does.
void steady_camera(Vec3& location, Vec3& look_at) {
  if ((look_at - location).norm() < 1e-6) look_at = location + straight_down();
  const Vec3 d = look_at - location;
  if (picture_up(d) == Vec3::UnitY()) look_at = location + d.norm() * Vec3(0, 1e-4, d.z() > 0 ? 1 : -1);
}

/// The camera POV-Ray draws from at one pose (steady_camera()'s).
CameraView steady_view(const CameraPose& pose) {
  CameraPose steady = pose;
  steady_camera(steady.location, steady.look_at);
  return CameraView(steady);
}

/// Where points land in the picture of one camera pose, in pixels of a 1280-pixel-wide picture.
class PictureProjection {
 public:
  explicit PictureProjection(const CameraPose& pose) : view_(steady_view(pose)), scale_(640.0 / view_.half_width()) {}
  /// Whether the point is in front of the camera (else it has no place in the picture).
  bool in_front(const Vec3& p) const { return view_.depth(p) > 0.05; }
  /// Whether a place is in the picture (a 16:9 one), or near enough that its blur would show.
  static bool in_picture(const Eigen::Vector2d& at) { return std::abs(at.x()) < 700 && std::abs(at.y()) < 400; }
  /// The point's place in the picture (pixels from its centre).
  Eigen::Vector2d at(const Vec3& p) const {
    const Vec3 d = p - view_.eye();
    const double ahead = std::max(d.dot(view_.forward()), 1e-3);
    return {d.dot(view_.right()) / ahead * scale_, d.dot(view_.up()) / ahead * scale_};
  }
  /// Pixels a length `size` at `p` spans across the picture.
  double size_at(const Vec3& p, double size) const { return size / std::max(view_.depth(p), 1e-3) * scale_; }

 private:
  CameraView view_;
  double scale_;
};

/// Sub-frame instants the blur measures a path at and draws its copies at, across the open shutter.
constexpr int kMeasureSteps = 8;
constexpr int kMaxCopies = 24;
/// How much of the background the copies together still let through where they all overlap.
constexpr double kStreakLeak = 0.04;

/// Instant k of `steps` steps across the open shutter of the frame at t, within the shot.
double shutter_instant(const Shot& shot, double t, double shutter, int k, int steps) {
  return std::clamp(t + shutter * (static_cast<double>(k) / steps - 0.5), 0.0, shot.timeline.duration());
}

/// The open shutter of the frame at t as the blur measures it: its kMeasureSteps + 1 sub-frame
/// instants and the camera's projection at each.
struct ShutterViews {
  std::vector<double> instants;
  std::vector<PictureProjection> views;
};

ShutterViews shutter_views(const Shot& shot, const CameraScript& camera, double t, double shutter) {
  ShutterViews s;
  for (int k = 0; k <= kMeasureSteps; ++k) {
    s.instants.push_back(shutter_instant(shot, t, shutter, k, kMeasureSteps));
    s.views.emplace_back(camera.pose(s.instants.back()));
  }
  return s;
}

/// Pixels `point(u)` travels across the picture while the shutter is open, the camera moving too
/// (u runs over the shutter's sub-frame instants).
template <class PointAt>
double picture_travel(const ShutterViews& shutter, PointAt&& point) {
  double travel = 0;
  Eigen::Vector2d last = Eigen::Vector2d::Zero();
  bool seen_last = false;
  for (int k = 0; k <= kMeasureSteps; ++k) {
    const PictureProjection& view = shutter.views[static_cast<std::size_t>(k)];
    const Vec3 p = point(shutter.instants[static_cast<std::size_t>(k)]);
    // What is behind the camera or outside the picture does not count.
    const Eigen::Vector2d at = view.at(p);
    const bool seen = view.in_front(p) && view.in_picture(at);
    const Eigen::Vector2d here = seen ? at : Eigen::Vector2d::Zero();
    if (k > 0 && seen && seen_last) travel += (here - last).norm();
    last = here;
    seen_last = seen;
  }
  return travel;
}

/// The copies of the stick a streak of `travel` pixels needs: close enough (at most `spacing` pixels
/// apart) to read as one streak; 1 below the threshold.
int copies_for(double travel, double spacing) {
  if (travel < kBlurPixels) return 1;
  return std::clamp(static_cast<int>(std::ceil(travel / std::max(spacing, 1.0))) + 1, 3, kMaxCopies);
}

/// What each of `copies` copies of the stick lets through so that where they all cover a point
/// together they let through kStreakLeak: 1 - a, with (1 - a)^copies = kStreakLeak.
double copy_transmit(int overlap) { return std::pow(kStreakLeak, 1.0 / std::max(overlap, 1)); }

/// The stick model's placement (its x along the axis, tip at the origin) for a pose, as a POV-Ray
/// `matrix`.
std::string stick_place(const CuePose& cue) {
  const Vec3 along = cue.axis.normalized();
  Vec3 side = Vec3::UnitZ().cross(along);
  if (side.norm() < 1e-9) side = Vec3::UnitY();
  side.normalize();
  return pov_matrix(along, side, along.cross(side), cue.tip);
}

/// Sub-frame instants the stick's way along its axis is measured at across the open shutter.
constexpr int kStickSteps = 16;

/// How the stick is drawn: once (copies 1, no way), swept along its axis (its way), or as copies.
struct StickBlur {
  int copies = 1;
  std::vector<StickTravel> travel;  ///< the pieces of its way; empty: not swept
  std::vector<double> along;        ///< its tip's place along its axis at each seen instant
  double front = 0, back = 0;       ///< the least and the most of `along`
};

struct FrameBlur {
  std::vector<int> ball_segments;  ///< per ball, 0: drawn once, else the straight pieces of its streak
  StickBlur stick;
};

/// The stick's way along its axis over the open shutter, when it goes (nearly) along its axis: where
/// the stick at each of kStickSteps + 1 instants lies, along the axis of the stick `cue` at the
/// frame's instant; nothing (copies instead) when its tip or butt strays more than kStickSidePixels
/// from that line in the picture.
StickBlur sweep_stick(const Shot& shot, const CameraScript& camera, double t, double shutter, const CuePose& cue) {
  StickBlur blur;
  const PictureProjection view(camera.pose(t));
  const Vec3 axis = cue.axis.normalized(), butt = cue.tip + kCueLength * axis;
  std::vector<double> along;
  std::vector<bool> seen;
  for (int k = 0; k <= kStickSteps; ++k) {
    const CuePose p = shot.cue->pose(shutter_instant(shot, t, shutter, k, kStickSteps));
    seen.push_back(p.visible);
    const Vec3 tip = p.tip - cue.tip, end = p.tip + kCueLength * p.axis.normalized() - butt;
    const double s = tip.dot(axis);
    along.push_back(s);
    if (!p.visible) continue;
    const double side = std::max(view.size_at(cue.tip, (tip - s * axis).norm()),
                                 view.size_at(butt, (end - end.dot(axis) * axis).norm()));
    if (side > kStickSidePixels) return blur;
  }
  // The pieces between instants where the stick is seen; the others are time it is not there.
  std::vector<double> run;
  auto close_run = [&] {
    if (run.size() >= 2) {
      const double share = static_cast<double>(run.size() - 1) / kStickSteps;
      for (StickTravel piece : stick_travel(run)) {
        piece.share *= share;
        blur.travel.push_back(piece);
      }
    }
    run.clear();
  };
  for (int k = 0; k <= kStickSteps; ++k) {
    if (seen[static_cast<std::size_t>(k)]) {
      run.push_back(along[static_cast<std::size_t>(k)]);
      blur.along.push_back(along[static_cast<std::size_t>(k)]);
    } else {
      close_run();
    }
  }
  close_run();
  if (blur.travel.empty()) return {};
  blur.front = *std::min_element(blur.along.begin(), blur.along.end());
  blur.back = *std::max_element(blur.along.begin(), blur.along.end());
  return blur;
}

/// The straight pieces a ball's path during the open shutter is drawn as: one when the path is
/// straight (within a tenth of the radius), else kMeasureSteps (a collision within the shutter).
int streak_segments(const Shot& shot, int ball, double t, double shutter, double radius) {
  std::vector<Vec3> at;
  for (int k = 0; k <= kMeasureSteps; ++k)
    at.push_back(shot.timeline.motion_state(ball, shutter_instant(shot, t, shutter, k, kMeasureSteps)).position);
  const Vec3 chord = at.back() - at.front();
  if (chord.norm() < 1e-9) return 1;
  const Vec3 along = chord.normalized();
  for (const Vec3& p : at) {
    const Vec3 d = p - at.front();
    if ((d - d.dot(along) * along).norm() > 0.1 * radius) return kMeasureSteps;
  }
  return 1;
}

/// The blur of the frame at t whose shutter is open `shutter` s of the simulation, filmed by `camera`.
FrameBlur plan_blur(const Shot& shot, const CameraScript& camera, double t, double shutter) {
  FrameBlur blur;
  const double radius = shot.scene.physics.ball_radius;
  const ShutterViews views = shutter_views(shot, camera, t, shutter);
  for (int i = 0; i < shot.timeline.ball_count(); ++i) {
    const double travel = picture_travel(views, [&](double u) { return shot.timeline.motion_state(i, u).position; });
    blur.ball_segments.push_back(travel < kBlurPixels ? 0 : streak_segments(shot, i, t, shutter, radius));
  }
  const CuePose cue = shot.cue->pose(t);
  if (cue.visible) {
    double travel = 0;
    for (double along : {0.0, kCueLength}) {
      travel = std::max(travel, picture_travel(views, [&](double u) {
                          // Where the stick is out of the scene, it counts as where it is now.
                          const CuePose at = shot.cue->pose(u);
                          const CuePose& p = at.visible ? at : cue;
                          return Vec3(p.tip + along * p.axis.normalized());
                        }));
    }
    if (travel >= kBlurPixels) blur.stick = sweep_stick(shot, camera, t, shutter, cue);
    if (blur.stick.travel.empty()) blur.stick.copies = copies_for(travel, 4.0);
  }
  return blur;
}

/// Writes the stick `cue` (at the frame's instant) swept along its axis over `blur`'s way (CueSweep),
/// and its shadow as one unseen stick at the frame's instant.
void write_stick_sweep(const CuePose& cue, const StickBlur& blur, std::ostream& out) {
  const std::string place = stick_place(cue);
  out << "#declare StickCover = function(X) {";
  for (std::size_t i = 0; i < blur.travel.size(); ++i) {
    const StickTravel& piece = blur.travel[i];
    out << (i ? " +" : "") << " StickPiece(X, " << pov_number(piece.from) << ", " << pov_number(piece.to) << ", "
        << pov_number(piece.share) << ")";
  }
  out << " }\n";
  // The colours are averaged over the instants, the first and last counting half (the trapezoid rule).
  const std::size_t n = blur.along.size();
  out << "#declare StickShift = array[" << n << "] {";
  for (std::size_t k = 0; k < n; ++k) out << (k ? ", " : " ") << pov_number(blur.along[k]);
  out << " }\n#declare StickShiftWeight = array[" << n << "] {";
  for (std::size_t k = 0; k < n; ++k) out << (k ? ", " : " ") << (k == 0 || k + 1 == n ? "0.5" : "1.0");
  out << " }\n";
  out << "object { CueSweep(" << pov_number(blur.front) << ", " << pov_number(blur.back) << ") " << place
      << " }  // blurred: swept along its axis, " << blur.travel.size()
      << (blur.travel.size() == 1 ? " piece" : " pieces") << "\n";
  out << "object { CueShadow " << place << " }  // the stick's shadow\n";
}

/// Writes ball i's streak over the open shutter as `segments` straight pieces (BallStreak), each
/// laid out with its x along the piece as the camera at `eye` sees it and its z towards the camera,
/// and weighted by the share of the shutter's time it takes over its length; false (nothing
/// written) when the ball hardly moves in the world (the camera's own motion blurs it, which the
/// frames do not draw).
bool write_streak(const Shot& shot, int i, double t, double shutter, int segments, const Vec3& eye, std::ostream& out) {
  const double radius = shot.scene.physics.ball_radius;
  std::vector<Vec3> at;
  for (int k = 0; k <= segments; ++k)
    at.push_back(shot.timeline.state(i, shutter_instant(shot, t, shutter, k, segments)).position);
  if ((at.back() - at.front()).norm() < 0.05 * radius) return false;
  const int number = shot.scene.ball(i).number;
  out << "object { BallShadow translate " << pov_vector(shot.timeline.state(i, t).position) << " }  // ball " << i
      << "'s shadow\n";
  for (int k = 0; k < segments; ++k) {
    const Vec3 piece = at[static_cast<std::size_t>(k) + 1] - at[static_cast<std::size_t>(k)];
    const Vec3 toward = (eye - at[static_cast<std::size_t>(k)] - 0.5 * piece).normalized();
    const Vec3 across_view = piece - piece.dot(toward) * toward;
    Vec3 x = across_view.norm() > 1e-9 ? Vec3(across_view.normalized()) : toward.unitOrthogonal();
    const Vec3 y = toward.cross(x);
    const double length = std::max(across_view.norm(), kStreakLeast);
    const double weight = 1.0 / (segments * length);
    // The ball's orientation and centre half-way through the piece, in the piece's frame.
    const BallState mid = shot.timeline.state(i, shutter_instant(shot, t, shutter, 2 * k + 1, 2 * segments));
    Eigen::Matrix3d frame;
    frame << x, y, toward;
    const Eigen::Matrix3d turn = frame.transpose() * mid.orientation.normalized().toRotationMatrix();
    const Vec3 centre = frame.transpose() * (mid.position - at[static_cast<std::size_t>(k)]);
    out << "object { BallStreak(" << number << ", " << pov_number(across_view.norm()) << ", "
        << pov_number(piece.dot(toward)) << ", " << pov_number(length) << ", " << pov_number(weight) << ", transform { "
        << pov_matrix(turn.col(0), turn.col(1), turn.col(2), centre) << " }) "
        << pov_matrix(x, y, toward, at[static_cast<std::size_t>(k)]) << " }  // ball " << i << ", streak " << k + 1
        << "/" << segments << "\n";
  }
  return true;
}

}  // namespace

std::vector<StickTravel> stick_travel(const std::vector<double>& along) {
  std::vector<StickTravel> pieces;
  if (along.size() < 2) return pieces;
  const double share = 1.0 / static_cast<double>(along.size() - 1);
  for (std::size_t k = 0; k + 1 < along.size(); ++k) {
    const double step = along[k + 1] - along[k];
    if (!pieces.empty()) {
      StickTravel& last = pieces.back();
      const double speed = (last.to - last.from) / last.share * share;  // its way a step
      if (std::abs(step - speed) <= 0.03 * std::abs(speed) + 1e-9) {
        last.to = along[k + 1];
        last.share += share;
        continue;
      }
    }
    pieces.push_back({along[k], along[k + 1], share});
  }
  return pieces;
}

std::string frame_name(int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d", frame);
  return name;
}

namespace {

/// The stick at `cue`, from `front` to `back` m along its axis from the tip (its butt kCueLength
/// further), as a capsule that holds it.
BoundCapsule stick_bound(const CuePose& cue, double front, double back) {
  const Vec3 axis = cue.axis.normalized();
  const double r = kCueButtRadius + kBoundSlack;
  return {{cue.tip + front * axis, r}, {cue.tip + (back + kCueLength) * axis, r}};
}

/// Ball i at the frame's instant, drawn once or as its streak.
FramePart ball_part(const Shot& shot, const FrameBlur& blur, int i, double t, double shutter, const Vec3& eye) {
  FramePart part;
  part.mirrors = true;
  const double r = shot.scene.physics.ball_radius + kBoundSlack;
  const BallState state = shot.timeline.state(i, t);
  const BoundSphere now{state.position, r};
  part.casts.push_back({now, now});
  const int segments = blur.ball_segments[static_cast<std::size_t>(i)];
  std::ostringstream out;
  if (segments > 0 && write_streak(shot, i, t, shutter, segments, eye, out)) {
    // Each piece of the streak is the capsule between two instants (write_streak).
    BoundSphere from{shot.timeline.state(i, shutter_instant(shot, t, shutter, 0, segments)).position, r};
    for (int k = 1; k <= segments; ++k) {
      const BoundSphere to{shot.timeline.state(i, shutter_instant(shot, t, shutter, k, segments)).position, r};
      part.seen.push_back({from, to});
      from = to;
    }
  } else {
    // A pocketed ball lies in its pocket's cup.
    const Eigen::Matrix3d m = state.orientation.normalized().toRotationMatrix();
    out << "object { Ball(" << shot.scene.ball(i).number << ") "
        << pov_matrix(m.col(0), m.col(1), m.col(2), state.position) << " }  // ball " << i << "\n";
    part.seen.push_back({now, now});
  }
  part.text = out.str();
  return part;
}

/// The stick at the frame's instant: none, once, swept along its axis, or as copies.
FramePart stick_part(const Shot& shot, const FrameBlur& blur, double t, double shutter) {
  FramePart part;
  std::ostringstream out;
  const CuePose now = shot.cue->pose(t);
  if (!blur.stick.travel.empty()) {
    write_stick_sweep(now, blur.stick, out);
    part.seen = {stick_bound(now, blur.stick.front, blur.stick.back)};
    part.casts = {stick_bound(now, 0, 0)};
    part.text = out.str();
    return part;
  }
  const int stick_copies = blur.stick.copies;
  if (stick_copies == 1) {
    if (now.visible) {
      out << "object { CueStick " << stick_place(now) << " }\n";
      part.seen = part.casts = {stick_bound(now, 0, 0)};
    }
    part.text = out.str();
    return part;
  }
  // The copies cast no shadow: one unseen stick at the frame's instant does, as for the balls and the
  // swept stick (shadow rays through a couple of dozen see-through copies cost more than the frame).
  if (now.visible) {
    out << "object { CueShadow " << stick_place(now) << " }  // the stick's shadow\n";
    part.casts = {stick_bound(now, 0, 0)};
  }
  const std::string transmit = pov_number(copy_transmit(stick_copies));
  for (int k = 0; k < stick_copies; ++k) {
    const CuePose cue = shot.cue->pose(shutter_instant(shot, t, shutter, 2 * k + 1, 2 * stick_copies));
    if (!cue.visible) continue;
    out << "object { CueStickT(" << transmit << ") " << stick_place(cue) << " no_shadow }  // blurred " << k + 1 << "/"
        << stick_copies << "\n";
    part.seen.push_back(stick_bound(cue, 0, 0));
  }
  part.text = out.str();
  return part;
}

}  // namespace

namespace {
std::atomic<long> g_contents_computed{0};
}  // namespace

long frame_contents_computed() { return g_contents_computed.load(std::memory_order_relaxed); }

FrameContent frame_content(const Shot& shot, int frame, int fps) {
  g_contents_computed.fetch_add(1, std::memory_order_relaxed);
  FrameContent content;
  // The movie's frame k: the simulation time it shows and the camera filming it (frames.h); a slowed
  // frame's shutter is open for as little of the simulation as the frame lasts of it.
  const MovieFrame shown = shot.movie.frame(frame, fps);
  const double t = shown.time, shutter = kShutter / fps * shown.rate;
  const CameraScript& script = shot.camera_at(shown);
  const CameraPose camera = script.pose(t);
  Vec3 location = camera.location, look_at = camera.look_at;
  steady_camera(location, look_at);
  // The include's cloth fades its weave with the distance from the camera (materials.inc), so the
  // camera's place comes before it.
  content.header = "// " + frame_name(frame) + " of " + shot.scene.name + ": t = " + pov_number(t) + " s" +
                   (shown.replay ? " (replay)" : "") + "\n#version 3.7;\n#declare CamPos = " + pov_vector(location) +
                   ";\n#include \"" + std::string(kPovIncludeName) + "\"\n\n";
  content.camera_pose = {location, look_at, false};
  // right is -x for z-up right-handed coordinates; angle is the horizontal field of view.
  std::ostringstream cam;
  cam << "camera {\n  perspective\n  location " << pov_vector(location) << "\n  sky z\n  up z\n"
      << "  right -x * image_width / image_height\n  angle " << pov_number(kCameraFovDeg) << "\n  look_at "
      << pov_vector(look_at) << "\n}\n\n";
  content.camera = cam.str();

  const FrameBlur blur = plan_blur(shot, script, t, shutter);
  for (int i = 0; i < shot.timeline.ball_count(); ++i)
    content.parts.push_back(ball_part(shot, blur, i, t, shutter, camera.location));
  content.parts.push_back(stick_part(shot, blur, t, shutter));
  return content;
}

std::string pov_frame_text(const FrameContent& content) {
  std::size_t size = content.header.size() + content.camera.size() + 64;
  for (const FramePart& part : content.parts) size += part.text.size();
  std::string text;
  text.reserve(size);
  // The lamp lights the balls and the stick from a light group of their own, as it does the table
  // (the include's LampLight says why).
  text += content.header;
  text += content.camera;
  text += "light_group {\n";
  for (const FramePart& part : content.parts) text += part.text;
  text += "  LampLight()\n  global_lights on\n}\n";
  return text;
}

void write_pov_frame(const Shot& shot, int frame, int fps, std::ostream& out) {
  out << pov_frame_text(frame_content(shot, frame, fps));
}

}  // namespace bsim
