#pragma once
// How a shot is sampled into frames: frame k shows t = k / fps for every k with t < duration, so a
// shot of D seconds at F frames per second has D·F frames and plays for exactly D seconds, as long as
// its sound track.
//
// The movie's own timeline (MovieTimeline) is an edit list over the simulation: one segment for a
// plain shot, so that movie frame k shows t = k / fps as above; a game with a winner is cut as a
// broadcast cuts it (no waiting while balls only spin in place) and adds the winning shot again,
// slowed, filmed by the replay's camera. Every front end reads the movie's frames from it:
// the .pov frames, camera.csv, the sound track's length, the movie, the farm and the animatic.
#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

namespace bsim {

/// The number of frames: ceil(duration · fps), at least one (a shot of no length still has a picture).
inline int frame_count(double duration, int fps) {
  return std::max(1, static_cast<int>(std::ceil(duration * fps - 1e-9)));
}
inline double frame_time(int frame, int fps) { return static_cast<double>(frame) / fps; }

/// One stretch of the movie: the simulation from `start` to `end` played at `rate` simulation seconds
/// per movie second (1 as it happened, 0.5 at half speed), filmed by the main camera script or the
/// replay's.
struct MovieSegment {
  double start = 0, end = 0;  ///< s, simulation time
  double rate = 1;
  bool replay = false;  ///< filmed by the replay's camera (Shot::replay_camera)
  /// s of movie the segment lasts.
  double length() const { return (end - start) / rate; }
};

/// What one instant of the movie shows.
struct MovieFrame {
  double time = 0;      ///< s, the simulation time shown
  bool replay = false;  ///< the replay's: its camera, its slowed sound
  /// Simulation seconds per movie second there: a slowed frame's shutter covers less of the simulation.
  double rate = 1;
};

/// The movie's timeline: its segments, one after another.
class MovieTimeline {
 public:
  MovieTimeline() = default;
  /// The simulation as it plays, from 0 to `duration`: one segment at rate 1.
  explicit MovieTimeline(double duration) : segments_{{0.0, duration, 1.0, false}} {}

  /// Appends a segment after the others.
  void add(const MovieSegment& segment) { segments_.push_back(segment); }

  const std::vector<MovieSegment>& segments() const { return segments_; }
  /// s, the movie's length: the segments' lengths added up.
  double duration() const {
    double total = 0;
    for (const MovieSegment& s : segments_) total += s.length();
    return total;
  }
  /// s of movie before segment `index` starts.
  double segment_begin(std::size_t index) const {
    double begin = 0;
    for (std::size_t i = 0; i < index && i < segments_.size(); ++i) begin += segments_[i].length();
    return begin;
  }
  int frame_count(int fps) const { return bsim::frame_count(duration(), fps); }

  /// What the movie shows at `movie_time` s (clamped to the movie): the segment that holds it (a
  /// segment holds its start, the next one its end), the last one holding the movie's end.
  MovieFrame at(double movie_time) const {
    if (segments_.empty()) return {std::max(0.0, movie_time), false, 1.0};
    double begin = 0;
    for (std::size_t i = 0; i < segments_.size(); ++i) {
      const MovieSegment& s = segments_[i];
      if (movie_time < begin + s.length() || i + 1 == segments_.size()) {
        const double t = s.start + (std::max(movie_time, begin) - begin) * s.rate;
        return {std::min(t, s.end), s.replay, s.rate};
      }
      begin += s.length();
    }
    return {};
  }
  /// Movie frame k at `fps` frames per second: what the movie shows at k / fps.
  MovieFrame frame(int k, int fps) const { return at(frame_time(k, fps)); }

  /// s of movie where it shows simulation time `time` in the replay (`replay`) or in the plain
  /// movie: the first such segment holding it, else the nearest end of such a segment (a time cut
  /// out of the movie shows where the movie leaves or rejoins the simulation, whichever is nearer).
  double movie_time(double time, bool replay) const {
    double begin = 0;
    std::optional<double> nearest;
    double distance = 0;
    for (const MovieSegment& s : segments_) {
      if (s.replay == replay) {
        if (time >= s.start && time <= s.end) return begin + (time - s.start) / s.rate;
        const double off = time < s.start ? s.start - time : time - s.end;
        if (!nearest || off < distance) {
          nearest = begin + (std::clamp(time, s.start, s.end) - s.start) / s.rate;
          distance = off;
        }
      }
      begin += s.length();
    }
    return nearest.value_or(std::max(0.0, time));
  }

  /// The stretches of the simulation from 0 to `end` s that the plain segments leave out (each its
  /// start and end, s): the gaps between them and after the last.
  std::vector<std::pair<double, double>> cuts(double end) const {
    std::vector<std::pair<double, double>> gaps;
    std::optional<double> shown_until;
    for (const MovieSegment& s : segments_) {
      if (s.replay) continue;
      if (shown_until && s.start > *shown_until) gaps.emplace_back(*shown_until, s.start);
      shown_until = s.end;
    }
    if (shown_until && *shown_until < end) gaps.emplace_back(*shown_until, end);
    return gaps;
  }

  /// The replay's segment, if the movie has one.
  std::optional<MovieSegment> replay() const {
    for (const MovieSegment& s : segments_)
      if (s.replay) return s;
    return std::nullopt;
  }

 private:
  std::vector<MovieSegment> segments_;
};

}  // namespace bsim
