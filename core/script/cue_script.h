#pragma once
// The scripted cue stick: for every shot of the scene, approach, two practice strokes, the strike and
// retraction (the seed's four phases), the stick leaving after each stroke and coming back for the next.
#include <optional>
#include <vector>

#include "camera_script.h"
#include "cue_pose.h"
#include "scene.h"
#include "timeline.h"

namespace bsim {

enum class CuePhase { approach, preflight, impact, retraction };

struct CuePhaseSpan {
  CuePhase phase = CuePhase::approach;
  double begin = 0;  ///< s
  double end = 0;    ///< s
  int shot = 0;      ///< the shot whose stroke it is, from 0 (Timeline::shots())
};

/// One shot's stroke as the stick plays it: where and how it strikes and the timing of its phases.
struct CueStroke {
  int shot = 0;              ///< from 0 (Timeline::shots(), Scene::cues)
  int target = 0;            ///< file-order index of the struck ball
  double start = 0;          ///< s, the shot's start: the stick comes in from here
  double cue_time = 0;       ///< s, the strike
  double next_start = -1;    ///< s, the next shot's start (the stick is gone by then); -1 for the last shot
  Vec3 contact{0, 0, 0};     ///< m, where the tip meets the struck ball (the ball as it stands at the strike)
  Vec3 heading{1, 0, 0};     ///< unit, horizontal: the direction the stick pushes
  double elevation = 0;      ///< rad
  double ball_speed = 0;     ///< m/s the strike gives the ball
  double tip_speed = 0;      ///< m/s at contact
  double backswing = 0;      ///< m behind the contact point where the forward stroke starts
  double follow = 0;         ///< m past the contact point where the tip stops
  double accel_time = 0;     ///< s of the forward stroke
  double follow_time = 0;    ///< s of the follow-through
  double retract_time = 0;   ///< s of the retraction at most (shorter when the next shot starts sooner)
  double approach_from = 0;  ///< m behind the contact point at the start (swung up, out of view)
  double retract_to = 0;     ///< m behind the contact point at the end of retraction
  /// rad the stick is swung up about the contact point at the start, and at the end of retraction:
  /// 60 degrees, or less when that swing would sweep across the camera's picture (0: it slides).
  double approach_lift = 0, retract_lift = 0;
  double hide_time = 0;  ///< s, the stick is removed from here on
  double amplitude = 0;  ///< m, reach of the practice strokes
  bool clears = true;    ///< see CueScript::clears()
  double elevation_deg() const;
};

/// Shot `shot`'s stroke as the stick plays it, all but what keeps the stick out of a camera's view
/// (approach_from, retract_to, retract_time and hide_time are left unset): where it strikes, at what
/// elevation (the stroke's, raised as far as the cushions and balls need), its timing. The same pose
/// the CueScript of any camera plays; none when the stick does not play that shot.
std::optional<CueStroke> plan_stroke(const Scene& scene, const Timeline& timeline, int shot);

/// s, the stretch of a stroke when the stick is at the ball: from the end of its approach (the tip
/// addressed) through the practice strokes and the strike to the end of the follow-through. Its pose
/// then is the same whatever camera films it (the approach before and the retraction after keep out
/// of the camera's view).
struct AtBall {
  double begin = 0, end = 0;
};
AtBall at_ball(const CueStroke& stroke);

/// The stick of `stroke` at t within at_ball(stroke) (clamped to it): as CueScript::pose draws it.
CuePose stroke_pose(const CueStroke& stroke, double t);

/// A second camera that films a stretch of the timeline again (a game's replay of its winning shot).
struct AlsoFilmed {
  const CameraScript* camera = nullptr;  ///< none: only the movie's camera films the stick
  double begin = 0, end = 0;             ///< s of the timeline it films
};

class CueScript {
 public:
  /// `scene`, `timeline` and `camera` (and `also`'s camera) must outlive the script. The stick comes in
  /// and leaves out of view of `camera`, and over `also`'s stretch out of view of its camera too; its
  /// swing sweeps across neither picture.
  CueScript(const Scene& scene, const Timeline& timeline, const CameraScript& camera, const AlsoFilmed& also = {});

  /// The stick at time t: the pose of the stroke of the shot under way (Timeline::shot_at), hidden
  /// between one stroke's removal and the next shot's start.
  CuePose pose(double t) const;
  /// Every shot's approach, preflight (two strokes and the back-swing), impact (forward stroke and
  /// follow-through), retraction (ends when the stick is removed), in time order, four per stroke.
  /// Empty when the scene has no cue strike.
  const std::vector<CuePhaseSpan>& phases() const { return phases_; }
  /// The strokes, one per shot the stick plays, in shot order.
  const std::vector<CueStroke>& strokes() const { return strokes_; }

  /// The first shot's stroke (the one-shot accessors below read it); a default one without strokes.
  const CueStroke& first() const;
  /// m, where the tip meets the struck ball: where the stick's axis enters its surface.
  const Vec3& contact_point() const { return first().contact; }
  /// deg the butt is raised above the horizontal: from the stroke's (or 5 without one) up, the least that
  /// clears the cushions and balls.
  double elevation_deg() const { return first().elevation_deg(); }
  /// m/s, the tip's speed at the strike: the stroke's speed when the scene has a stroke.
  double tip_speed() const { return first().tip_speed; }
  /// Whether the stick's stroke keeps clear of every ball and cushion at elevation_deg(): the stroke's
  /// elevation, or the least above it that clears (a level stroke is drawn raised over the cushion;
  /// the strike keeps the stroke's elevation); false when no elevation clears.
  bool clears() const { return first().clears; }

 private:
  const Timeline* timeline_ = nullptr;
  std::vector<CuePhaseSpan> phases_;
  std::vector<CueStroke> strokes_;
  std::vector<int> stroke_of_shot_;  ///< per shot, its index in strokes_, or -1 when the stick does not play it
};

}  // namespace bsim
