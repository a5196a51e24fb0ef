#pragma once
// The automatic director's rules and its judge: where its camera may stand, which side of a line of
// action it keeps, and how a candidate script is filmed with the real camera (CameraScript::pose)
// over the simulated shot and scored against those rules. The candidates (director_candidates.h)
// come in order; the judge picks among them, so the same candidates always give the same pick.
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include "camera_script.h"
#include "cue_script.h"
#include "director.h"
#include "scene.h"
#include "table.h"
#include "timeline.h"

namespace bsim::directing {

/// m/s the director plans to: a margin under the bound, for what falls between samples.
inline constexpr double kPlanSpeed = 0.85 * kCameraCarrySpeed;
/// The share of the picture's width and height a watched ball keeps from its edges.
inline constexpr double kPlanMargin = 0.05;
/// m from the line of action within which a camera counts as on it (neutral).
inline constexpr double kOnLine = 0.05;

/// The simulated shot as the director sees it, sampled on a fixed grid of times.
struct ShotSamples {
  std::vector<double> times;             ///< s, the grid
  std::vector<std::vector<Vec3>> where;  ///< per sample, per ball: its centre, m
  /// Per sample, per ball: whether it is on view (not pocketed nor sunk below the bed), and whether it
  /// travels (moving on the table, not yet dropping into a pocket).
  std::vector<std::vector<char>> shown, moving;
  /// Per shot (Timeline::shots(), its stretch up to the next shot's start), per ball: s when it first
  /// drops into a pocket in that shot (infinity if it does not), and m/s, the fastest it travels then,
  /// horizontally. A ball that drops travels no more in that shot, though a later one may put it back.
  std::vector<std::vector<double>> drop_time, peak_speed;
};

/// The simulated shot sampled at 120 Hz, for the judge and the beats; `radius`: the balls' (m).
ShotSamples sample_shot(const Timeline& timeline, double radius);

/// Where the director never puts its camera, whatever the balls do: low over the table, in the lamp,
/// out of the room.
bool clear_of_room(const TableLayout& layout, const Vec3& p);

/// The side of `line` a camera at `previous` stands on, to be kept by the next description: +1 left,
/// -1 right, 0 when it stands on the line (either side will do).
double side_to_keep(const LineOfAction& line, const Vec3& previous);

/// Whether a camera at `p` is on the `wanted` side of `line` (or on the line).
bool keeps_side(const LineOfAction& line, double wanted, const Vec3& p);

/// The descriptions after `placed` hold its camera, each keeping its own key (and no blend: pre and
/// post 0), until they are placed themselves.
void hold_after(std::vector<CameraShot>& shots, std::size_t placed);

/// s, the shortest blend between two descriptions of one shot: a quicker one reads as a jump.
inline constexpr double kMinBlendSeconds = 0.3;

/// What a candidate script does over the shot (up to a time limit).
struct Verdict {
  /// Clear of everything, on the right side of every line of action, the stick at the cue ball covering
  /// no more than kDirectorStickShare of the picture.
  bool ok = false;
  bool hurried = false;  ///< a blend within a shot shorter than kMinBlendSeconds (another timing may do)
  double max_speed = std::numeric_limits<double>::infinity();
  double shortfall = std::numeric_limits<double>::infinity();  ///< summed share below the targets
  bool good() const { return ok && max_speed <= kPlanSpeed && shortfall <= 0; }
  bool usable() const { return ok && max_speed <= kPlanSpeed; }
};

/// The blend of a description: its `pre` and `post` fractions.
struct Timing {
  double pre = 0, post = 0;
};

/// A beat's timings, tried in order: the usual ones, then, if no place meets every target with them,
/// the early ones (blends that start sooner).
struct Timings {
  std::vector<Timing> usual, early;
};

class Judge {
 public:
  /// Judges the stretch of shot `shot` (from its start): watches the balls pocketed in it and its
  /// struck ball, and keeps in the picture every knock on a pocket's jaw by one of them or by
  /// `subject` (the ball that matters: a rattle is watched where it happens). `scene`, `timeline` and
  /// `samples` must outlive it.
  Judge(const Scene& scene, const Timeline& timeline, const ShotSamples& samples, int shot, int subject = -1);

  /// Films `shots` (the real CameraScript) from the shot's start up to `limit` and judges it; `lines`
  /// are the descriptions' lines of action.
  Verdict evaluate(const std::vector<CameraShot>& shots, const std::vector<LineOfAction>& lines, double limit) const;

  /// The shot's stroke as the stick will play it (CueScript); none when the stick plays none.
  const std::optional<CueStroke>& stroke() const { return stroke_; }

  /// The camera of the script `shots` at t; nullopt when they do not make a script.
  std::optional<CameraPose> pose(const std::vector<CameraShot>& shots, double t) const;

  /// The place for description `slot` of `shots`: the first candidate (in order) that is good with
  /// one of the usual timings (tried in order), else the usable one that misses the targets least;
  /// if that misses any, the same with the early timings, and the better of the two. Candidates are
  /// complete descriptions but for their key and windows: the key is `slot`'s, the windows the
  /// timing's. The descriptions after the slot hold its camera. Nullopt when none is usable.
  std::optional<CameraShot> choose(const std::vector<CameraShot>& shots, const std::vector<LineOfAction>& lines,
                                   std::size_t slot, const std::vector<CameraShot>& candidates, const Timings& timings,
                                   double limit) const;

 private:
  struct Watched {
    int ball = 0;
    double target = 0;
  };
  /// A knock on a pocket's jaw: when, and where the ball meets the jaw.
  struct Knock {
    double time = 0;
    Vec3 where{0, 0, 0};
  };
  struct Choice {
    CameraShot shot;
    double shortfall = 0;  ///< 0: it meets every target
  };

  std::optional<CameraScript> film(const std::vector<CameraShot>& shots) const;
  /// clear_of_room(), and room around every ball on view at `sample`.
  bool clear(const Vec3& p, std::size_t sample) const;
  /// Whether at t the stick, at the cue ball, covers more than kDirectorStickShare of `pose`'s picture.
  bool stick_blocks(const CameraPose& pose, double t) const;
  std::optional<Choice> choose_with(std::vector<CameraShot> shots, const std::vector<LineOfAction>& lines,
                                    std::size_t slot, const std::vector<CameraShot>& candidates,
                                    const std::vector<Timing>& timings, double limit) const;

  const Scene& scene_;
  const Timeline& timeline_;
  const ShotSamples& samples_;
  TableLayout layout_;
  double radius_ = 0;
  double from_ = 0;  ///< s, the shot's start: what comes before it is judged already
  std::vector<Watched> watched_;
  std::vector<Knock> knocks_;        ///< every one wanted in the picture
  std::optional<CueStroke> stroke_;  ///< the shot's stroke as the stick plays it; none when it plays none
};

}  // namespace bsim::directing
