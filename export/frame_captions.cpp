#include "frame_captions.h"

#include <algorithm>
#include <sstream>

#include "frame_cache.h"
#include "frames.h"
#include "scene_file.h"
#include "shot.h"

namespace bsim {

namespace {

constexpr const char* kHeader =
    "# billiards-export: each frame's caption, drawn on it by the develop stage (README, \"Games\")\n";

/// A field of the file: tabs and line ends would break it, so they become spaces.
std::string field(std::string text) {
  std::replace_if(
      text.begin(), text.end(), [](char c) { return c == '\t' || c == '\n' || c == '\r'; }, ' ');
  return text;
}

std::string numbers_field(const std::vector<int>& numbers) {
  std::string text;
  for (int n : numbers) text += (text.empty() ? "" : ",") + std::to_string(n);
  return text.empty() ? "-" : text;
}

bool read_numbers(const std::string& text, std::vector<int>& numbers) {
  numbers.clear();
  if (text == "-") return true;
  std::istringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    if (item.empty() || item.find_first_not_of("0123456789") != std::string::npos || item.size() > 2) return false;
    numbers.push_back(std::stoi(item));
  }
  return true;
}

const char* rules_word(RackGame rules) {
  return rules == RackGame::eight_ball ? "8ball" : rules == RackGame::ten_ball ? "10ball" : "9ball";
}

const char* kind_word(CaptionCall::Kind kind) {
  switch (kind) {
    case CaptionCall::Kind::foul: return "foul";
    case CaptionCall::Kind::push_out: return "push-out";
    case CaptionCall::Kind::winner: return "winner";
    case CaptionCall::Kind::stopped: return "stopped";
  }
  return "";
}

std::string caption_line(const FrameCaption& f) {
  const Caption& c = f.caption;
  std::string line = std::string(f.right ? "right" : "left") + "\t" + rules_word(c.rules) + "\t" +
                     std::to_string(c.at_table) + "\t" + std::to_string(c.shot);
  for (std::size_t p = 0; p < 2; ++p) line += "\t" + field(p < c.players.size() ? c.players[p] : "");
  line += "\t" + numbers_field(c.rack) + "\t" + numbers_field(c.on_table) + "\t" + (c.replay ? "replay" : "-");
  for (const CaptionCall& call : c.calls)
    line += std::string("\t") + kind_word(call.kind) + "\t" + field(call.title) + "\t" + field(call.text);
  return line;
}

/// How often, over `frames` of one shot, its cue ball or the ball it is played at is seen in the
/// caption's column in the lower corner given.
int covered(const Shot& shot, const std::vector<FrameMoment>& moments, const std::vector<int>& frames,
            const std::vector<int>& balls, int width, int height, bool right, int rack) {
  const CaptionBox box = lower_third_column(rack, width, height, right);
  int count = 0;
  for (int k : frames) {
    const FrameMoment& m = moments[static_cast<std::size_t>(k)];
    const CameraView view(m.pose, kCameraFovDeg, static_cast<double>(width) / height);
    for (int ball : balls) {
      const Vec3 at = shot.timeline.motion_state(ball, m.time).position;
      const auto point = view.project(at);
      if (!point) continue;
      const double x = 0.5 * width * (1 + point->x), y = 0.5 * height * (1 - point->y);
      const double r = shot.scene.physics.ball_radius / (view.depth(at) * view.half_width()) * 0.5 * width;
      if (x + r > box.x0 && x - r < box.x1 && y + r > box.y0 && y - r < box.y1) ++count;
    }
  }
  return count;
}

/// The file-order indices of shot k's cue ball and the ball it is played at.
std::vector<int> balls_that_matter(const Shot& shot, int k) {
  std::vector<int> numbers = {0};
  const std::vector<GameTurn>& turns = shot.game->turns;
  if (k >= 0 && k < static_cast<int>(turns.size()) && turns[static_cast<std::size_t>(k)].planned.ball > 0)
    numbers.push_back(turns[static_cast<std::size_t>(k)].planned.ball);
  std::vector<int> balls;
  for (std::size_t i = 0; i < shot.scene.balls.size(); ++i)
    if (std::find(numbers.begin(), numbers.end(), shot.scene.balls[i].number) != numbers.end())
      balls.push_back(static_cast<int>(i));
  return balls;
}

}  // namespace

std::vector<FrameMoment> movie_frame_moments(const Shot& shot, int fps) {
  std::vector<FrameMoment> moments;
  const int frames = shot.movie.frame_count(fps);
  for (int k = 0; k < frames; ++k) {
    const MovieFrame f = shot.movie.frame(k, fps);
    moments.push_back({f.time, f.replay, shot.camera ? shot.camera_at(f).pose(f.time) : CameraPose{}});
  }
  return moments;
}

std::vector<FrameCaption> frame_captions(const Shot& shot, const std::vector<FrameMoment>& moments, int width,
                                         int height) {
  std::vector<FrameCaption> captions;
  if (!shot.game) return captions;
  std::map<std::pair<int, bool>, std::vector<int>> groups;  // (the game's shot, replay) -> its frames
  for (const FrameMoment& m : moments) {
    captions.push_back({caption_at(*shot.game, shot.timeline, shot.scene, m.time, m.replay), false});
    groups[{captions.back().caption.shot, m.replay}].push_back(static_cast<int>(captions.size()) - 1);
  }
  for (const auto& [group, frames] : groups) {
    const std::vector<int> balls = balls_that_matter(shot, group.first);
    const int rack = static_cast<int>(captions[static_cast<std::size_t>(frames.front())].caption.rack.size());
    const bool right = covered(shot, moments, frames, balls, width, height, true, rack) <
                       covered(shot, moments, frames, balls, width, height, false, rack);
    for (int k : frames) captions[static_cast<std::size_t>(k)].right = right;
  }
  return captions;
}

std::string captions_text(const std::vector<FrameCaption>& captions) {
  std::string text = kHeader;
  for (std::size_t k = 0; k < captions.size(); ++k) text += std::to_string(k) + "\t" + caption_line(captions[k]) + "\n";
  return text;
}

std::map<int, std::string> read_caption_lines(const std::string& frames_dir) {
  return caption_lines(read_text_file(frames_dir + "/" + kCaptionsName));
}

std::map<int, std::string> caption_lines(const std::string& text) {
  std::map<int, std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    const std::size_t tab = line.find('\t');
    if (line.empty() || line[0] == '#' || tab == std::string::npos || tab > 9) continue;
    if (line.find_first_not_of("0123456789") != tab) continue;
    lines[std::stoi(line.substr(0, tab))] = line.substr(tab + 1);
  }
  return lines;
}

bool parse_caption(const std::string& line, FrameCaption& f) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string item; std::getline(in, item, '\t');) fields.push_back(item);
  if (fields.size() < 9 || (fields.size() - 9) % 3 != 0) return false;
  f = {};
  Caption& c = f.caption;
  f.right = fields[0] == "right";
  c.rules = fields[1] == "8ball"    ? RackGame::eight_ball
            : fields[1] == "10ball" ? RackGame::ten_ball
                                    : RackGame::nine_ball;
  if (fields[2] != "0" && fields[2] != "1") return false;
  c.at_table = fields[2] == "1" ? 1 : 0;
  if (fields[3].empty() || fields[3].size() > 6 || fields[3].find_first_not_of("0123456789") != std::string::npos)
    return false;
  c.shot = std::stoi(fields[3]);
  c.players = {fields[4], fields[5]};
  if (!read_numbers(fields[6], c.rack) || !read_numbers(fields[7], c.on_table)) return false;
  c.replay = fields[8] == "replay";
  for (std::size_t i = 9; i + 2 < fields.size(); i += 3) {
    CaptionCall call{CaptionCall::Kind::foul, fields[i + 1], fields[i + 2]};
    for (const auto kind :
         {CaptionCall::Kind::foul, CaptionCall::Kind::push_out, CaptionCall::Kind::winner, CaptionCall::Kind::stopped})
      if (fields[i] == kind_word(kind)) call.kind = kind;
    c.calls.push_back(call);
  }
  return true;
}

void add_caption_keys(const std::string& frames_dir, std::vector<std::uint64_t>& keys) {
  add_caption_keys(read_caption_lines(frames_dir), keys);
}

void add_caption_keys(const std::map<int, std::string>& lines, std::vector<std::uint64_t>& keys) {
  if (lines.empty()) return;
  const std::string drawing = lower_third_signature();
  for (const auto& [frame, line] : lines)
    if (frame >= 0 && frame < static_cast<int>(keys.size()))
      keys[static_cast<std::size_t>(frame)] = fnv1a(drawing + "\n" + line, keys[static_cast<std::size_t>(frame)]);
}

}  // namespace bsim
