#pragma once
// The automatic director's candidates: for each of its beats, the places a camera could stand (in
// the order they are tried) and the blends into it. They only propose; the judge
// (director_judge.h) films each candidate with the real camera and picks, and the director
// (director.cpp) decides the beats, their moments and their order.
#include <vector>

#include "director.h"
#include "director_judge.h"
#include "scene.h"
#include "table.h"

namespace bsim::directing {

/// One stroke as the director films it: the cue ball, the way it is sent, and the span of time its
/// descriptions cover. A scene has one per shot, each over its shot's stretch of the timeline, and
/// the beats run once for each.
struct FilmedStroke {
  int shot = 0;                   ///< from 0 (Scene::cues, Timeline::shots())
  double begin = 0;               ///< s, its first description's key
  double end = 0;                 ///< s, where its last description ends
  double cue_time = 0;            ///< s, the stick strikes
  int cue_ball = 0;               ///< file-order index
  Vec3 cue_at{0, 0, 0};           ///< m, where the cue ball rests before the stroke
  Vec3 aim{1, 0, 0};              ///< unit, horizontal: the line of aim
  int first_object = -1;          ///< the cue ball's first object ball, -1 when it meets none
  Vec3 first_object_at{0, 0, 0};  ///< m, where that ball rests before the stroke
  /// The pocket the shot is played at (its `pot` line's, else the one its first object ball drops
  /// into, not counting a break's group collision), -1 for none.
  int pocket = -1;
  Vec3 pocket_at{0, 0, 0};  ///< m, that pocket's centre
};

/// Beat 1, the approach and the stroke: hovers behind and above the cue ball, looking down the line of
/// aim at a point between it and its first object ball; the nearest and lowest first, on the line and
/// then 0.3 m to its right and to its left, those clear of the room only.
std::vector<CameraShot> stroke_places(const FilmedStroke& stroke, double radius, const TableLayout& layout);

/// Beat 2, the ball that matters (`subject`) on its run, about `middle`: `look`s from high places
/// around it, cranes up from the camera before it (at `previous`), and `follow`s beside a ball slow
/// enough to walk with (its fastest: `peak_speed`); the closest framing and the shortest walk first,
/// those clear of the room and on the side of `line` the camera before stands on only.
std::vector<CameraShot> ball_places(int subject, const Vec3& middle, double peak_speed, const Vec3& previous,
                                    const LineOfAction& line, const Vec3& aim, const TableLayout& layout);

/// Beat 2's blends, for its key at `key_time` after the one before it at `previous_time`: from the
/// strike (`cue_time`) at the earliest.
Timings ball_timings(double key_time, double previous_time, double cue_time);

/// Beat 3, wide: hovers that frame the whole cloth from the room around it, for each direction the
/// nearest that does; the shortest walk from the camera before it (at `previous`) first, those clear
/// of the room and on the side of `line` it stands on only.
std::vector<CameraShot> wide_places(const TableLayout& layout, const Vec3& previous, const LineOfAction& line);

/// Beat 3's blends, for its key `since` s after the one before it: from its key, or up to 0.8 s
/// before it.
Timings wide_timings(double since);

}  // namespace bsim::directing
