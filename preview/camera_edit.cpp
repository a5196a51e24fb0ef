#include "camera_edit.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <numbers>
#include <utility>

#include "atomic_file.h"
#include "ball_track.h"
#include "camera_key.h"
#include "camera_script.h"
#include "scene_file.h"
#include "scene_lexer.h"
#include "shot.h"

namespace bsim {

namespace fs = std::filesystem;

namespace {

/// A number to the millimetre (or millisecond), without trailing zeros: "1.25", "-0.4", "2".
std::string fixed3(double value) {
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.3f", value);
  std::string text = buffer;
  while (!text.empty() && text.back() == '0') text.pop_back();
  if (!text.empty() && text.back() == '.') text.pop_back();
  if (text == "-0") text = "0";
  return text;
}

/// "" for the first, "second " to "fifth ", "last " for the last of more than five; nothing when
/// the k-th (1-based) of n has no name.
std::optional<std::string> ordinal_word(std::size_t k, std::size_t n) {
  static const char* const kWords[] = {"", "second ", "third ", "fourth ", "fifth "};
  if (k >= 1 && k <= 5) return std::string(kWords[k - 1]);
  if (k == n) return std::string("last ");
  return std::nullopt;
}

struct Instant {
  double time = 0;
  int event = -1;
};

/// Every moment a key can name, in the order the events list them.
std::vector<NamedMoment> nameable_moments(const Timeline& timeline) {
  std::vector<NamedMoment> moments;
  std::map<std::pair<int, int>, std::vector<Instant>> hits;
  std::map<int, std::vector<Instant>> cushions;
  bool cue_named = false;
  for (const Event& e : timeline.events()) {
    switch (e.type) {
      case EventType::start: moments.push_back({"start", e.time, e.index}); break;
      case EventType::end: moments.push_back({"end", e.time, e.index}); break;
      case EventType::cue:
        if (!cue_named) moments.push_back({"cue", e.time, e.index});
        cue_named = true;
        break;
      case EventType::ball_ball:
        if (e.contacts.empty() && e.balls.size() == 2) hits[{e.balls[0], e.balls[1]}].push_back({e.time, e.index});
        for (const Contact& c : e.contacts) hits[{std::min(c.a, c.b), std::max(c.a, c.b)}].push_back({c.time, e.index});
        break;
      case EventType::ball_rail:
        if (!e.balls.empty()) cushions[e.balls[0]].push_back({e.time, e.index});
        break;
    }
  }
  // Counted in time order, as the keys resolve (camera_key.cpp).
  for (auto& [pair, found] : hits) {
    std::stable_sort(found.begin(), found.end(), [](const Instant& x, const Instant& y) { return x.time < y.time; });
    for (std::size_t k = 0; k < found.size(); ++k)
      if (const auto word = ordinal_word(k + 1, found.size()))
        moments.push_back({*word + "hit " + std::to_string(pair.first) + " " + std::to_string(pair.second),
                           found[k].time, found[k].event});
  }
  for (const auto& [ball, found] : cushions)
    for (std::size_t k = 0; k < found.size(); ++k)
      if (const auto word = ordinal_word(k + 1, found.size()))
        moments.push_back({*word + "cushion " + std::to_string(ball), found[k].time, found[k].event});
  std::vector<int> dropped;
  for (const PocketDrop& d : timeline.pocket_drops()) {
    if (std::find(dropped.begin(), dropped.end(), d.ball) != dropped.end()) continue;
    dropped.push_back(d.ball);
    moments.push_back({"pocket " + std::to_string(d.ball), d.time, -1});
  }
  return moments;
}

Vec3 rounded(const Vec3& v) {
  const auto mm = [](double x) { return std::strtod(fixed3(x).c_str(), nullptr); };
  return {mm(v.x()), mm(v.y()), mm(v.z())};
}

std::size_t offset_of(std::string_view text, const Token& token) {
  return static_cast<std::size_t>(token.text.data() - text.data());
}

std::size_t token_end(std::string_view text, const Token& token) { return offset_of(text, token) + token.text.size(); }

std::size_t line_start(std::string_view text, std::size_t offset) {
  const std::size_t nl = offset == 0 ? std::string_view::npos : text.rfind('\n', offset - 1);
  return nl == std::string_view::npos ? 0 : nl + 1;
}

bool only_blanks(std::string_view text, std::size_t from, std::size_t to) {
  for (std::size_t i = from; i < to; ++i)
    if (text[i] != ' ' && text[i] != '\t' && text[i] != '\r') return false;
  return true;
}

/// The spaces and tabs a line starts with.
std::string indent_of(std::string_view text, std::size_t offset) {
  const std::size_t start = line_start(text, offset);
  std::size_t end = start;
  while (end < text.size() && (text[end] == ' ' || text[end] == '\t')) ++end;
  return std::string(text.substr(start, end - start));
}

int line_at(std::string_view text, std::size_t offset) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

std::size_t token_count(const CameraKey& key) {
  if (key.kind == CameraKeyKind::event) return 1;
  return 1 + static_cast<std::size_t>(std::count(key.text.begin(), key.text.end(), ' '));
}

bool same_loc(const SourceLoc& a, const SourceLoc& b) { return a.line == b.line && a.column == b.column; }

/// The camera the placement asks for, given the description that already starts at the moment.
CameraShot placed_shot(const CameraPlacement& placement, const CameraShot* existing, const Scene& scene,
                       const Timeline& timeline, double t) {
  CameraShot shot;
  if (placement.kind == CameraPlacement::Kind::hover) {
    shot.mode = CameraMode::hover;
    shot.location = rounded(placement.eye);
    shot.target = rounded(placement.look_at);
    return shot;
  }
  shot.ball = placement.ball;
  const bool looking = existing && existing->mode == CameraMode::look && existing->ball == placement.ball;
  if (!looking) {
    shot.mode = CameraMode::look;
    shot.location = rounded(placement.eye);
    return shot;
  }
  // The eye as the follow camera's offset: ahead, left and up in the ball's frame at time t.
  std::optional<double> heading;
  if (placement.ball == scene.cue.target) heading = scene.cue.heading_deg * std::numbers::pi / 180;
  const BallTrack track(timeline, placement.ball, heading);
  const Vec3 ahead = track.heading(t), left(-ahead.y(), ahead.x(), 0), from = placement.eye - track.position(t);
  shot.mode = CameraMode::follow;
  shot.location = rounded(Vec3(from.dot(ahead), from.dot(left), from.z()));
  if (shot.location.norm() == 0) shot.location = Vec3(0, 0, 0.001);  // a follow camera never sits on its ball
  return shot;
}

/// The part of a description after its windows: "hover 1 2 3 0 0 0", "look 1 2 3 5", "follow 5 -1 0 0.5".
std::string mode_text(const CameraShot& c) {
  const auto vec = [](const Vec3& v) { return fixed3(v.x()) + " " + fixed3(v.y()) + " " + fixed3(v.z()); };
  switch (c.mode) {
    case CameraMode::hover: return "hover " + vec(c.location) + " " + vec(c.target);
    case CameraMode::look: return "look " + vec(c.location) + " " + std::to_string(c.ball);
    case CameraMode::follow: return "follow " + std::to_string(c.ball) + " " + vec(c.location);
  }
  return "";
}

std::string first_error(const std::vector<Diagnostic>& diagnostics, const std::string& shown_path) {
  for (const Diagnostic& d : diagnostics)
    if (d.severity == Severity::error) return format_diagnostic(d, shown_path);
  return shown_path + ": error: the scene does not load";
}

std::string system_error(const std::string& what, const std::string& path) {
  return path + ": error: cannot " + what + ": " + std::strerror(errno);
}

}  // namespace

NamedMoment name_moment(const Timeline& timeline, double t) {
  const std::vector<NamedMoment> moments = nameable_moments(timeline);
  const NamedMoment* nearest = nullptr;
  for (const NamedMoment& m : moments)
    if (!nearest || std::abs(m.time - t) < std::abs(nearest->time - t)) nearest = &m;
  if (nearest && std::abs(nearest->time - t) <= kKeySnap) return *nearest;
  // `at T` counts from the start of the shot; T rounded down to the millisecond stays in the shot.
  const double start = timeline.events().empty() ? 0.0 : timeline.events().front().time;
  const double seconds = std::max(0.0, std::floor((t - start) * 1000 + 1e-6) / 1000);
  NamedMoment at{"at " + fixed3(seconds), 0, -1};
  at.time = start + std::strtod(fixed3(seconds).c_str(), nullptr);
  return at;
}

std::string format_description(const std::string& key, double pre, double post, const CameraShot& camera) {
  return "event " + key + " " + fixed3(pre) + " " + fixed3(post) + " " + mode_text(camera);
}

CameraEdit place_camera(std::string_view text, const std::string& shown_path, double t,
                        const CameraPlacement& placement) {
  CameraEdit edit;
  ShotResult loaded = load_shot(text, fs::path(shown_path).stem().string());
  const Shot* shot = loaded.shot ? loaded.shot.get() : loaded.unscripted.get();
  if (!shot) {
    edit.error = "the camera was not written: the scene file has errors; fix them first (" +
                 first_error(loaded.diagnostics, shown_path) + ")";
    return edit;
  }
  const Scene& scene = shot->scene;
  const Timeline& timeline = shot->timeline;
  if (placement.kind == CameraPlacement::Kind::ball &&
      (placement.ball < 0 || placement.ball >= static_cast<int>(scene.balls.size()))) {
    edit.error = "the camera was not written: the scene file has no ball " + std::to_string(placement.ball);
    return edit;
  }
  t = std::clamp(t, 0.0, timeline.duration());
  const NamedMoment moment = name_moment(timeline, t);

  // Each description's instant, and the one (if any) already at this moment.
  std::vector<std::optional<KeyInstant>> instants;
  const CameraShot* existing = nullptr;
  for (std::size_t i = 0; i < scene.camera.size(); ++i) {
    instants.push_back(resolve_camera_key(scene.camera[i], scene, timeline).instant);
    const auto& at = instants.back();
    if (!existing && at && at->time == moment.time && at->event == moment.event) existing = &scene.camera[i];
  }
  const CameraShot camera = placed_shot(placement, existing, scene, timeline, t);

  const LexedText lexed = lex_scene(text);
  const std::vector<Token>& tokens = lexed.tokens;
  const auto token_at = [&](const SourceLoc& loc) -> std::optional<std::size_t> {
    for (std::size_t k = 0; k < tokens.size(); ++k)
      if (same_loc(tokens[k].loc, loc)) return k;
    return std::nullopt;
  };
  // The tokens of description i: from its `event` to before the next `event` or `endcamera`.
  const auto description_end = [&](std::size_t first) {
    std::size_t last = first;
    while (last + 1 < tokens.size() && tokens[last + 1].text != "event" && tokens[last + 1].text != "endcamera") ++last;
    return last;
  };

  std::string out(text);
  const std::string nl = text.find("\r\n") != std::string_view::npos ? "\r\n" : "\n";  // the file's line ends
  std::size_t at = 0;      // where the description starts in `out`
  std::size_t at_end = 0;  // where it ends
  if (existing) {
    const std::optional<std::size_t> first = token_at(existing->loc);
    const std::size_t mode_token = first ? *first + 1 + token_count(existing->key) + 2 : tokens.size();
    if (!first || mode_token >= tokens.size()) {
      edit.error =
          "the camera was not written: cannot find the description on line " + std::to_string(existing->loc.line);
      return edit;
    }
    const std::size_t from = offset_of(text, tokens[mode_token]);
    const std::size_t to = token_end(text, tokens[description_end(*first)]);
    const std::string replacement = mode_text(camera);
    out.replace(from, to - from, replacement);
    at = offset_of(text, tokens[*first]);
    at_end = from + replacement.size();
    edit.replaced = true;
  } else {
    const std::string line = format_description(moment.key, kWrittenPre, kWrittenPost, camera);
    // Before the first description that starts later.
    std::optional<std::size_t> before;
    for (std::size_t i = 0; i < scene.camera.size() && !before; ++i) {
      const auto& instant = instants[i];
      if (!instant) continue;
      const bool later = instant->time > moment.time || (instant->time == moment.time && instant->event >= 0 &&
                                                         moment.event >= 0 && instant->event > moment.event);
      if (later) before = i;
    }
    const std::optional<std::size_t> camera_token =
        scene.camera_loc.known() ? token_at(scene.camera_loc) : std::optional<std::size_t>{};
    std::optional<std::size_t> end_token;
    if (camera_token)
      for (std::size_t k = *camera_token + 1; k < tokens.size() && !end_token; ++k)
        if (tokens[k].text == "endcamera") end_token = k;

    if (before) {
      const std::optional<std::size_t> first = token_at(scene.camera[*before].loc);
      if (!first) {
        edit.error = "the camera was not written: cannot find the description on line " +
                     std::to_string(scene.camera[*before].loc.line);
        return edit;
      }
      const std::size_t o = offset_of(text, tokens[*first]);
      const std::size_t start = line_start(text, o);
      if (only_blanks(text, start, o)) {
        out.insert(start, indent_of(text, o) + line + nl);
        at = start + indent_of(text, o).size();
      } else {
        out.insert(o, line + nl);
        at = o;
      }
      at_end = at + line.size();
    } else if (end_token) {
      const std::size_t e = offset_of(text, tokens[*end_token]);
      const std::size_t start = line_start(text, e);
      // Indented like the last description, or like `endcamera` in an empty block.
      std::string indent = indent_of(text, e);
      if (!scene.camera.empty())
        if (const auto last = token_at(scene.camera.back().loc))
          indent = indent_of(text, offset_of(text, tokens[*last]));
      if (only_blanks(text, start, e)) {
        out.insert(start, indent + line + nl);
        at = start + indent.size();
      } else {
        // `camera endcamera` or a description and `endcamera` on one line: break the line there.
        const std::size_t p = token_end(text, tokens[*end_token - 1]);
        out.replace(p, e - p, nl + indent + line + nl);
        at = p + nl.size() + indent.size();
      }
      at_end = at + line.size();
    } else {
      // No camera block: one at the end of the file.
      if (!out.empty() && out.back() != '\n') out += nl;
      out += "camera" + nl;
      at = out.size();
      out += line + nl + "endcamera" + nl;
      at_end = at + line.size();
    }
  }
  edit.text = std::move(out);
  edit.description = edit.text.substr(at, at_end - at);
  edit.line = line_at(edit.text, at);
  return edit;
}

std::optional<int> ball_at_pixel(const Timeline& timeline, double t, const ViewCamera& camera, double width,
                                 double height, double x, double y) {
  if (width <= 0 || height <= 0) return std::nullopt;
  // The ray through the pixel, in the frame view_matrix() and projection_matrix() use.
  const Vec3 forward = (camera.target - camera.eye).normalized();
  const Vec3 right = forward.cross(view_up(camera)).normalized();
  const Vec3 up = right.cross(forward);
  const double aspect = width / height;
  const double half_w = std::tan(camera.hfov_deg * std::numbers::pi / 360);
  const double half_h = std::tan(vertical_fov_deg(camera.hfov_deg, aspect) * std::numbers::pi / 360);
  const double nx = 2 * x / width - 1, ny = 1 - 2 * y / height;
  const Vec3 ray = (forward + nx * half_w * right + ny * half_h * up).normalized();
  const double radius = timeline.physics().ball_radius * 1.25;
  std::optional<int> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int ball = 0; ball < timeline.ball_count(); ++ball) {
    const Vec3 centre = timeline.motion_state(ball, t).position;
    if (centre.z() < 0) continue;  // dropped into a pocket, out of sight
    const Vec3 to = centre - camera.eye;
    const double along = to.dot(ray);
    if (along <= 0) continue;
    const double miss2 = to.squaredNorm() - along * along;
    if (miss2 > radius * radius) continue;
    const double hit = along - std::sqrt(radius * radius - miss2);
    if (hit < best_distance) {
      best_distance = hit;
      best = ball;
    }
  }
  return best;
}

std::string backup_path(const std::string& path) { return path + ".bak"; }

std::string replace_scene_file(const std::string& path, const std::string& previous, const std::string& text) {
  std::error_code ec;
  fs::path target = path;
  if (fs::is_symlink(target, ec)) {
    target = fs::canonical(target, ec);
    if (ec) return path + ": error: cannot follow the link: " + ec.message();
  }
  struct stat st {};
  if (::stat(target.c_str(), &st) != 0) return system_error("read", path);
  const mode_t mode = st.st_mode & 07777;
  std::string error;
  if (!write_file_atomically(backup_path(target.string()), previous, error, mode)) return error;
  if (!write_file_atomically(target.string(), text, error, mode)) return error;
  return "";
}

void SceneEdits::record(std::string before, std::string after) {
  changes_.push_back({std::move(before), std::move(after)});
}

std::string SceneEdits::undo(const std::string& path) {
  if (changes_.empty()) return "nothing to undo: the window has not changed " + path;
  std::string error;
  const std::optional<std::string> now = read_scene_file(path, error);
  if (!now) return error;
  if (*now != changes_.back().after)
    return "not undone: " + path +
           " has changed since the window wrote it (the version before the window's change is in " + backup_path(path) +
           ")";
  if (std::string failed = replace_scene_file(path, *now, changes_.back().before); !failed.empty()) return failed;
  changes_.pop_back();
  return "";
}

}  // namespace bsim
