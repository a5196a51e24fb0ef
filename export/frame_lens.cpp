#include "frame_lens.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "frame_cache.h"
#include "frames.h"
#include "number_format.h"
#include "pov_format.h"
#include "pov_frame.h"
#include "scene_file.h"
#include "shot.h"
#include "text_words.h"

namespace bsim {

namespace {

constexpr const char* kLensHeader =
    "# billiards-export: each frame's lens and what it sees, for the develop stage's depth of field\n"
    "# (README, \"The lens\"): the fixed scene, then one line a frame\n";

/// The simulation time the stretch of the movie holding movie time `movie_time` starts at.
double stretch_start(const MovieTimeline& movie, double movie_time) {
  double begin = 0;
  const std::vector<MovieSegment>& segments = movie.segments();
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (movie_time < begin + segments[i].length() || i + 1 == segments.size()) return segments[i].start;
    begin += segments[i].length();
  }
  return 0;
}

/// A number as the frame's .pov file writes it (to the micrometre), so the depth is cast from what
/// POV-Ray traces.
void put_pov(std::string& out, const Vec3& v) {
  for (int i = 0; i < 3; ++i) out += " " + pov_number(v[i]);
}

}  // namespace

std::vector<FrameLens> frame_lenses(const Shot& shot, int fps) {
  std::vector<CameraPose> poses;
  const int count = shot.movie.frame_count(fps);
  for (int k = 0; k < count; ++k) poses.push_back(frame_content(shot, k, fps).camera_pose);
  return frame_lenses(shot, fps, poses);
}

std::vector<FrameLens> frame_lenses(const Shot& shot, int fps, const std::vector<CameraPose>& poses) {
  std::vector<FrameLens> frames;
  const int count = std::min(shot.movie.frame_count(fps), static_cast<int>(poses.size()));
  for (int k = 0; k < count; ++k) {
    const MovieFrame shown = shot.movie.frame(k, fps);
    FrameLens f;
    f.frame = k;
    f.pose = poses[static_cast<std::size_t>(k)];
    f.lens = frame_lens(shot.camera_at(shown), shown.time, stretch_start(shot.movie, frame_time(k, fps)), shown.rate);
    for (int i = 0; i < shot.timeline.ball_count(); ++i)
      f.moving.balls.push_back(shot.timeline.state(i, shown.time).position);
    const CuePose cue = shot.cue->pose(shown.time);
    if (cue.visible) f.moving.stick = cue;
    frames.push_back(std::move(f));
  }
  return frames;
}

std::string lens_text(const DepthScene& scene, const std::vector<FrameLens>& frames) {
  std::string text = kLensHeader + depth_scene_text(scene) + "\n";
  for (const FrameLens& f : frames) {
    text += "frame " + std::to_string(f.frame) + " camera";
    put_pov(text, f.pose.location);
    put_pov(text, f.pose.look_at);
    text += " lens";
    for (double v : {f.lens.focal_mm, f.lens.aperture, f.lens.focus}) {
      text += ' ';
      append_number(text, v);
    }
    text += " balls " + std::to_string(f.moving.balls.size());
    for (const Vec3& b : f.moving.balls) put_pov(text, b);
    text += " stick";
    if (f.moving.stick) {
      put_pov(text, f.moving.stick->tip);
      put_pov(text, f.moving.stick->axis);
    } else {
      text += " -";
    }
    text += "\n";
  }
  return text;
}

LensFile read_lens_file(const std::string& frames_dir) {
  return lens_file(read_text_file(frames_dir + "/" + kLensName));
}

LensFile lens_file(const std::string& text) {
  LensFile file;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (line.rfind("frame ", 0) == 0) {
      const std::size_t end = line.find(' ', 6);
      const std::string number = line.substr(6, end == std::string::npos ? std::string::npos : end - 6);
      if (number.empty() || number.size() > 9 || number.find_first_not_of("0123456789") != std::string::npos) continue;
      file.frames[std::stoi(number)] = line;
      continue;
    }
    file.scene += line + "\n";
  }
  return file;
}

bool parse_frame_lens(const std::string& line, FrameLens& f) {
  f = {};
  std::istringstream in(line);
  double frame = 0, count = 0;
  if (!word_is(in, "frame") || !take(in, frame) || frame < 0 || frame != std::floor(frame) || frame > 1e9) return false;
  f.frame = static_cast<int>(frame);
  if (!word_is(in, "camera") || !take(in, f.pose.location) || !take(in, f.pose.look_at)) return false;
  if (!word_is(in, "lens") || !take(in, f.lens.focal_mm) || !take(in, f.lens.aperture) || !take(in, f.lens.focus))
    return false;
  if (f.lens.focal_mm <= 0 || f.lens.aperture <= 0 || f.lens.focus * 1e3 <= f.lens.focal_mm) return false;
  if (!word_is(in, "balls") || !take(in, count) || count < 0 || count > 1e4 || count != std::floor(count)) return false;
  f.moving.balls.resize(static_cast<std::size_t>(count));
  for (Vec3& b : f.moving.balls)
    if (!take(in, b)) return false;
  if (!word_is(in, "stick")) return false;
  std::string rest;
  if (in >> rest && rest != "-") {
    std::istringstream stick(rest + " " + std::string(std::istreambuf_iterator<char>(in), {}));
    CuePose cue;
    cue.visible = true;
    if (!take(stick, cue.tip) || !take(stick, cue.axis) || cue.axis.norm() < 1e-9 || stick >> rest) return false;
    f.moving.stick = cue;
    return true;
  }
  return !(in >> rest);
}

void add_lens_keys(const std::string& frames_dir, std::vector<std::uint64_t>& keys) {
  add_lens_keys(read_lens_file(frames_dir), keys);
}

void add_lens_keys(const LensFile& file, std::vector<std::uint64_t>& keys) {
  if (file.frames.empty()) return;
  const std::uint64_t scene = fnv1a(file.scene);
  for (const auto& [frame, line] : file.frames)
    if (frame >= 0 && frame < static_cast<int>(keys.size()))
      keys[static_cast<std::size_t>(frame)] =
          fnv1a(line, fnv1a(std::to_string(scene), keys[static_cast<std::size_t>(frame)]));
}

}  // namespace bsim
