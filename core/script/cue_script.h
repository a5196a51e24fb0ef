#pragma once
// The scripted cue stick: approach, two practice strokes, the strike, retraction (the seed's four phases).
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
};

class CueScript {
 public:
  /// `scene`, `timeline` and `camera` must outlive the script.
  CueScript(const Scene& scene, const Timeline& timeline, const CameraScript& camera);

  CuePose pose(double t) const;
  /// Approach, preflight (two strokes and the back-swing), impact (forward stroke and follow-through),
  /// retraction (ends when the stick is removed). Empty when the shot has no cue strike.
  const std::vector<CuePhaseSpan>& phases() const { return phases_; }

  /// m, where the tip meets the struck ball: where the stick's axis enters its surface.
  const Vec3& contact_point() const { return contact_; }
  /// deg the butt is raised above the horizontal: from the stroke's (or 5 without one) up, the least that
  /// clears the cushions and balls.
  double elevation_deg() const;
  /// m/s, the tip's speed at the strike: the stroke's speed when the scene has a stroke.
  double tip_speed() const { return tip_speed_; }
  /// Whether the stick's stroke keeps clear of every ball and cushion at elevation_deg(): the stroke's
  /// elevation, or the least above it that clears (a level stroke is drawn raised over the cushion;
  /// the strike keeps the stroke's elevation); false when no elevation clears.
  bool clears() const { return clears_; }

 private:
  /// The stick `behind` m behind the contact point along its axis, swung `lift` rad up about it.
  CuePose place(double behind, double lift) const;
  /// The lowest elevation from `lowest_deg` (whole degrees above it) that clears, else the one that
  /// comes closest.
  void choose_elevation(double lowest_deg);
  /// m, where the tip's face centre meets the ball: on the axis through the centre, or with a stroke at
  /// its offsets across the stick.
  Vec3 tip_contact(const Vec3& centre, double radius) const;
  /// The plan for one elevation: back-swing, forward stroke and follow-through.
  void plan_stroke(double elevation);
  /// m, the least gap to the balls at rest and the cushions over the stroke, at the planned elevation.
  double stroke_clearance() const;
  /// Whether the tip stays off the struck ball as it leaves.
  bool follow_through_clear() const;
  CuePose path(double t) const;

  const Scene* scene_ = nullptr;
  const Timeline* timeline_ = nullptr;
  const CameraScript* camera_ = nullptr;
  std::vector<CuePhaseSpan> phases_;
  Vec3 contact_{0, 0, 0};     ///< m
  Vec3 heading_{1, 0, 0};     ///< unit, horizontal: the direction the stick pushes
  double elevation_ = 0;      ///< rad
  double cue_time_ = 0;       ///< s
  double ball_speed_ = 0;     ///< m/s the strike gives the ball
  double tip_speed_ = 0;      ///< m/s at contact
  double backswing_ = 0;      ///< m behind the contact point where the forward stroke starts
  double follow_ = 0;         ///< m past the contact point where the tip stops
  double accel_time_ = 0;     ///< s of the forward stroke
  double follow_time_ = 0;    ///< s of the follow-through
  double approach_from_ = 0;  ///< m behind the contact point at the start (swung up, out of view)
  double retract_to_ = 0;     ///< m behind the contact point at the end of retraction
  double hide_time_ = 0;      ///< s, the stick is removed from here on
  double amplitude_ = 0;      ///< m, reach of the practice strokes
  bool clears_ = true;
};

}  // namespace bsim
