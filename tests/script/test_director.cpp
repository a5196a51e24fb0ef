// The automatic director: its script, filmed with the real camera (CameraScript::pose) and judged
// with the preview's own projection, over every shipped scene and 50 seeded random breaks. Physics
// and camera only: nothing is rendered.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "aim.h"
#include "builtin_scene.h"
#include "camera_clearance.h"
#include "camera_key_text.h"
#include "cue_geometry.h"
#include "director.h"
#include "files.h"
#include "number_format.h"
#include "play.h"
#include "random_scenes.h"
#include "scene_parse.h"
#include "shot.h"
#include "support.h"
#include "table.h"
#include "view.h"

using namespace bsim;
using bsim::test::quoted;
namespace fs = std::filesystem;

namespace {

/// The share of a picture's width and height a watched ball's centre keeps inside its edges.
constexpr double kMargin = 0.02;
/// Hz at which the camera's speed is measured (and every blend's ends besides).
constexpr double kSpeedHz = 240.0;
/// Hz at which the picture is judged.
constexpr double kPictureHz = 60.0;

struct Named {
  std::string name;
  Scene scene;
};

/// Every scene in scenes/ (parsed; their own cameras are replaced) and 50 seeded random breaks.
std::vector<Named> all_scenes() {
  std::vector<Named> out;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(test::source_path("scenes")))
    if (entry.path().extension() == ".scn") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    ParseResult parsed = parse_scene(test::require_file(file), file.stem().string());
    REQUIRE(parsed.scene);
    if (parsed.scene->game && test::kSanitizedBuild) continue;  // a whole game: Release builds only
    out.push_back({file.filename().string(), *parsed.scene});
  }
  for (std::uint64_t seed = 1; seed <= 50; ++seed)
    out.push_back({"random break " + std::to_string(seed), scenes::random_break(seed)});
  return out;
}

/// `scene` played as load_shot plays it (every shot, `pot` aimed; a game by its players, as its explicit
/// scene): the scene to film and its timeline.
/// `notes`, when given, gets what load_shot tells the director of a game.
void play_as_loaded(Scene& scene, Timeline& timeline, FilmingNotes* notes = nullptr) {
  if (scene.game) {
    GameResult game = play_game(scene);
    REQUIRE(!game.failure);
    scene = std::move(game.scene);
    timeline = std::move(game.timeline);
    if (notes) *notes = game_filming_notes(scene, game.record);
    return;
  }
  PlayResult played = play(scene);
  REQUIRE(!played.failure);
  write_found(scene, played.found);
  timeline = std::move(played.timeline);
}

/// The shot filmed by the director, built as load_shot builds it.
std::unique_ptr<Shot> directed(const Scene& scene, DirectedCamera* script = nullptr) {
  auto shot = std::make_unique<Shot>();
  shot->scene = scene;
  FilmingNotes notes;
  play_as_loaded(shot->scene, shot->timeline, &notes);
  const DirectedCamera camera = direct_camera(shot->scene, shot->timeline, notes);
  shot->scene.camera = camera.shots;
  if (script) *script = camera;
  std::vector<Diagnostic> diagnostics;
  shot->camera = CameraScript::build(shot->scene, shot->timeline, diagnostics);
  REQUIRE(shot->camera);
  shot->cue.emplace(shot->scene, shot->timeline, *shot->camera);
  check_camera_clearance(shot->scene, shot->timeline, *shot->camera, diagnostics);
  for (const Diagnostic& d : diagnostics) CHECK_MESSAGE(false, format_diagnostic(d, shot->scene.name));
  return shot;
}

/// Whether the ball is travelling: moving on the table, not yet dropping into a pocket.
bool moving(const Timeline& timeline, int ball, double t, double drop) {
  const BallState s = timeline.motion_state(ball, t);
  const double speed = std::hypot(s.velocity.x(), s.velocity.y());
  return speed > 1e-3 && s.motion != Motion::falling && s.motion != Motion::pocketed && t < drop;
}

/// Whether `point` is in the picture the preview and POV-Ray draw at t (16:9, kCameraFovDeg).
bool in_frame(const Shot& shot, double t, const Vec3& point) {
  const ViewCamera view = scripted_view(shot, t);
  const Eigen::Matrix4f vp = projection_matrix(view, 16.0 / 9.0) * view_matrix(view);
  double x = 0, y = 0;
  const double w = 1280, h = 720;
  if (!project_to_pixels(vp, point, w, h, x, y)) return false;
  return x >= kMargin * w && x <= (1 - kMargin) * w && y >= kMargin * h && y <= (1 - kMargin) * h;
}

/// Whether description `k` of the script is the cut to a later shot: keyed at that shot's start, with
/// no blend.
bool cut_between_shots(const DirectedCamera& script, int k) {
  const CameraShot& s = script.shots[static_cast<std::size_t>(k)];
  if (s.pre != 0 || s.post != 0) return false;
  // A game's opening wide shot cuts to the breaker's view kOpeningSeconds in.
  const bool after_opening = k == 1 && script.comments[0].starts_with("opening") && s.key.kind == CameraKeyKind::at &&
                             s.key.seconds == kOpeningSeconds;
  return (s.key.kind == CameraKeyKind::start && s.key.shot > 0) || after_opening;
}

/// No description shorter than about a second; within a shot every change a blend, none a cut (a
/// cut only to a later shot's start). Never across the line of action from one description to the
/// next: the camera where the blend leaves the old description and where it arrives at the new one are
/// on one side of the new description's line (or on the line).
void check_descriptions(const DirectedCamera& script, const Timeline& timeline, const CameraScript& camera) {
  REQUIRE(!camera.segments().empty());
  for (const CameraSegment& s : camera.segments()) {
    const double begin = s.shot == 0 ? 0.0 : s.begin;
    CHECK(s.end - begin >= kMinDescriptionSeconds - 1e-9);
  }
  for (const CameraWindow& w : camera.windows())
    if (!cut_between_shots(script, w.shot)) CHECK(w.end - w.begin >= 0.3);

  REQUIRE(script.lines.size() == script.shots.size());
  REQUIRE(script.subjects.size() == script.shots.size());
  for (const CameraWindow& w : camera.windows()) {
    if (cut_between_shots(script, w.shot)) continue;
    const LineOfAction& line = script.lines[static_cast<std::size_t>(w.shot)];
    // The line runs through the description's subject at its key, level.
    const int subject = script.subjects[static_cast<std::size_t>(w.shot)];
    REQUIRE(subject >= 0);
    CHECK((line.point - timeline.motion_state(subject, w.event_time).position).norm() < 1e-3);
    CHECK(std::abs(line.direction.norm() - 1) < 1e-9);
    CHECK(line.direction.z() == 0);
    const double a = line.side(camera.pose(w.begin).location), b = line.side(camera.pose(w.end).location);
    CHECK_MESSAGE(!((a > 0.05 && b < -0.05) || (a < -0.05 && b > 0.05)), "crosses the line into description ", w.shot);
  }
}

/// Speed, clearance and the room, sampled finely, with every blend's ends.
void check_path(const Shot& shot) {
  const Timeline& timeline = shot.timeline;
  const CameraScript& camera = *shot.camera;
  const double radius = shot.scene.physics.ball_radius;
  const TableLayout layout = table_layout(shot.scene);
  std::vector<double> times;
  for (int k = 0; k / kSpeedHz <= timeline.duration(); ++k) times.push_back(k / kSpeedHz);
  for (const CameraWindow& w : camera.windows()) {
    times.push_back(w.begin);
    times.push_back(w.end);
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  double fastest = 0, nearest = std::numeric_limits<double>::infinity(), lowest_over_table = 10, lowest = 10;
  Vec3 previous = camera.pose(0).location;
  // The cuts (between shots, at the later shots' starts, and a game's opening) are not walked;
  // check_descriptions holds them to those places.
  const auto cut_in = [&](double from, double to) {
    for (const CameraWindow& w : camera.windows())
      if (w.begin == w.end && w.event_time > from && w.event_time <= to) return true;
    return false;
  };
  for (std::size_t i = 0; i < times.size(); ++i) {
    const double t = times[i];
    const Vec3 p = camera.pose(t).location;
    if (i > 0 && t > times[i - 1] + 1e-6 && !cut_in(times[i - 1], t))
      fastest = std::max(fastest, (p - previous).norm() / (t - times[i - 1]));
    previous = p;
    for (int b = 0; b < timeline.ball_count(); ++b) {
      const Vec3 centre = timeline.motion_state(b, t).position;
      if (centre.z() >= -radius) nearest = std::min(nearest, (p - centre).norm());
    }
    const TableRect& r = layout.wood_outer;
    if (p.x() >= r.x0 && p.x() <= r.x1 && p.y() >= r.y0 && p.y() <= r.y1)
      lowest_over_table = std::min(lowest_over_table, p.z());
    lowest = std::min(lowest, p.z());
  }
  CHECK(fastest <= kCameraCarrySpeed);
  CHECK(nearest >= radius + kDirectorBallRoom);
  CHECK(lowest_over_table > layout.rail_top);
  CHECK(lowest > layout.rail_top);  // nowhere below the rails' top, over the table or beside it
}

/// The balls that matter in the picture while they move between `begin` and `end` (one shot's
/// stretch): those pocketed then and the struck ball.
void check_watched_in(const Shot& shot, int struck, double begin, double end) {
  const Timeline& timeline = shot.timeline;
  std::vector<double> drop(static_cast<std::size_t>(timeline.ball_count()), std::numeric_limits<double>::infinity());
  for (const PocketDrop& d : timeline.pocket_drops())
    if (d.time >= begin && d.time <= end)
      drop[static_cast<std::size_t>(d.ball)] = std::min(drop[static_cast<std::size_t>(d.ball)], d.time);
  for (int b = 0; b < timeline.ball_count(); ++b) {
    const double dropped = drop[static_cast<std::size_t>(b)];
    const bool pocketed = std::isfinite(dropped);
    if (!pocketed && b != struck) continue;
    int travelling = 0, seen = 0;
    for (int k = static_cast<int>(std::ceil(begin * kPictureHz)); k / kPictureHz <= end; ++k) {
      const double t = k / kPictureHz;
      if (!moving(timeline, b, t, dropped)) continue;
      ++travelling;
      if (in_frame(shot, t, timeline.motion_state(b, t).position)) ++seen;
    }
    if (travelling == 0) continue;
    const double share = double(seen) / travelling;
    CAPTURE(b);
    CAPTURE(share);
    CHECK(share >= (pocketed ? 0.8 : 0.6));
  }
}

/// The balls that matter in the picture while they move, shot by shot: those pocketed in the shot and
/// its struck ball.
void check_watched(const Shot& shot) {
  const Timeline& timeline = shot.timeline;
  for (int k = 0; k < timeline.shot_count(); ++k) {
    CAPTURE(k);
    const double begin = timeline.shots()[static_cast<std::size_t>(k)].start;
    const double end =
        k + 1 < timeline.shot_count() ? timeline.shots()[static_cast<std::size_t>(k) + 1].start : timeline.duration();
    check_watched_in(shot, shot.scene.cues[static_cast<std::size_t>(k)].target, begin, end);
  }
}

/// While the stick is at the cue ball (from its address to its follow-through), it covers no more than
/// kDirectorStickShare of the picture, as drawn (CueScript::pose) and filmed (CameraScript::pose).
void check_stick_share(const Shot& shot) {
  REQUIRE(shot.cue);
  for (const CueStroke& stroke : shot.cue->strokes()) {
    const AtBall at = at_ball(stroke);
    double most = 0;
    for (double t = at.begin; t <= at.end; t += 1.0 / kPictureHz)
      most = std::max(most, stick_picture_share(shot.cue->pose(t), shot.camera->pose(t)));
    CAPTURE(stroke.shot);
    // The director looks at 30 Hz: a little more may fall between its looks.
    CHECK(most <= kDirectorStickShare + 0.005);
  }
}

/// Every check of the director's script for one shot.
void check_shot(const std::string& name, const Scene& scene) {
  CAPTURE(name);
  DirectedCamera script;
  const std::unique_ptr<Shot> shot = directed(scene, &script);
  check_descriptions(script, shot->timeline, *shot->camera);
  check_path(*shot);
  check_stick_share(*shot);
  check_watched(*shot);
}

/// The scene's text with its camera block replaced by `camera` (or appended when it has none).
std::string with_camera(const std::string& text, const std::string& camera) {
  const auto begin = text.find("\ncamera\n");
  const auto end = text.find("endcamera\n");
  if (begin == std::string::npos || end == std::string::npos) return text + camera;
  return text.substr(0, begin + 1) + camera + text.substr(end + std::string("endcamera\n").size());
}

bool same_shot(const CameraShot& a, const CameraShot& b) {
  return a.event == b.event && a.key.kind == b.key.kind && a.key.shot == b.key.shot && a.key.ordinal == b.key.ordinal &&
         a.key.a == b.key.a && a.key.b == b.key.b && a.key.seconds == b.key.seconds && a.pre == b.pre &&
         a.post == b.post && a.mode == b.mode && a.location == b.location && a.target == b.target && a.ball == b.ball;
}

}  // namespace

TEST_SUITE("director") {
  TEST_CASE("the director films every shipped scene and 50 random breaks within its rules") {
    for (const Named& named : all_scenes()) check_shot(named.name, named.scene);
  }

  TEST_CASE("the director shoots in beats: the stroke from behind, the ball that matters, then wide") {
    const ParseResult parsed = parse_scene(test::require_file(test::source_path("scenes/break.scn")), "break");
    REQUIRE(parsed.scene);
    DirectedCamera script;
    const std::unique_ptr<Shot> shot = directed(*parsed.scene, &script);
    REQUIRE(script.shots.size() == 3);
    // The stroke: behind the cue ball (against its aim) and above it, looking the way it goes.
    const CameraShot& stroke = script.shots[0];
    CHECK(camera_key_text(stroke.key) == "start");
    const Vec3 cue = shot->scene.balls[0].position;
    const double heading = shot->scene.cue().heading_deg * kDegToRad;  // the break is a stroke along it
    const Vec3 aim(std::cos(heading), std::sin(heading), 0);
    CHECK((stroke.location - cue).dot(aim) < -0.5);
    CHECK(stroke.location.z() > cue.z() + 0.3);
    CHECK((stroke.target - stroke.location).dot(aim) > 0);
    // The 10 (ball 10), the last ball down, watched from the contact that sets it going; then wide as it drops.
    CHECK(script.shots[1].ball == 10);
    CHECK(script.shots[1].mode != CameraMode::hover);
    CHECK(camera_key_text(script.shots[2].key) == "drop 10");
    CHECK(script.shots[2].mode == CameraMode::hover);
  }

  TEST_CASE("the director writes a script that fits any shot: a crowded odd table, a lone ball, a ball at rest") {
    Scene lone = scenes::standard_table();
    lone.balls.push_back(scenes::ball_at(0, 0, 0, lone.physics, Vec3(1, 0.5, 0)));
    Scene still = scenes::standard_table();
    still.balls.push_back(scenes::ball_at(0, -0.5, 0.2, still.physics));
    still.balls.push_back(scenes::ball_at(1, 0.5, 0.2, still.physics));
    for (const Scene& scene :
         {scenes::stress_table(40, 3), lone, still, scenes::tight_break(), scenes::two_ball_shot()}) {
      Scene copy = scene;
      const Timeline timeline = simulate(copy);
      const DirectedCamera script = direct_camera(copy, timeline);
      REQUIRE(!script.shots.empty());
      CHECK(camera_key_text(script.shots.front().key) == "start");
      copy.camera = script.shots;
      std::vector<Diagnostic> diagnostics;
      CHECK(CameraScript::build(copy, timeline, diagnostics));
      CHECK(diagnostics.empty());
    }
  }

  TEST_CASE("README shows the script the director writes for the break") {
    const std::string readme = test::require_file(test::source_path("README.md"));
    const std::string lead = "The first prints the break's script:\n\n```\n";
    const auto begin = readme.find(lead);
    REQUIRE(begin != std::string::npos);
    const auto end = readme.find("```", begin + lead.size());
    REQUIRE(end != std::string::npos);
    const std::string shown = readme.substr(begin + lead.size(), end - begin - lead.size());
    const ParseResult parsed = parse_scene(test::require_file(test::source_path("scenes/break.scn")), "break");
    REQUIRE(parsed.scene);
    const Timeline timeline = simulate(*parsed.scene);
    CHECK(shown == camera_script_text(direct_camera(*parsed.scene, timeline), "break"));
  }

  TEST_CASE("the script's text parses back to the same descriptions") {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(test::source_path("scenes")))
      if (entry.path().extension() == ".scn") files.push_back(entry.path());
    for (const fs::path& file : files) {
      const std::string name = file.filename().string();
      CAPTURE(name);
      const std::string text = test::require_file(file);
      ParseResult parsed = parse_scene(text, "scene");
      REQUIRE(parsed.scene);
      if (parsed.scene->game && test::kSanitizedBuild) continue;  // a whole game: Release builds only
      Timeline timeline;
      FilmingNotes notes;
      play_as_loaded(*parsed.scene, timeline, &notes);  // a scene aimed by `pot` is played at the headings found
      const DirectedCamera script = direct_camera(*parsed.scene, timeline, notes);
      const std::string camera = camera_script_text(script, "scene");
      CHECK(camera.starts_with("camera\n"));
      CHECK(camera.ends_with("endcamera\n"));
      // Deterministic: the same again, to the byte.
      CHECK(camera_script_text(direct_camera(*parsed.scene, timeline, notes), "scene") == camera);
      const ParseResult again = parse_scene(with_camera(text, camera), "scene");
      REQUIRE(again.scene);
      CHECK(again.diagnostics.empty());
      REQUIRE(again.scene->camera.size() == script.shots.size());
      for (std::size_t k = 0; k < script.shots.size(); ++k) CHECK(same_shot(again.scene->camera[k], script.shots[k]));
      // Loaded with --camera auto, the shot is filmed with exactly these descriptions.
      const ShotResult automatic = load_shot(text, "scene", {}, CameraChoice::automatic);
      REQUIRE(automatic.shot);
      CHECK(automatic.diagnostics.empty());
      REQUIRE(automatic.shot->scene.camera.size() == script.shots.size());
      for (std::size_t k = 0; k < script.shots.size(); ++k)
        CHECK(same_shot(automatic.shot->scene.camera[k], script.shots[k]));
    }
  }

  TEST_CASE("a scene of several shots: every shot filmed as one, its keys counting within it") {
    const std::string text = test::require_file(test::source_path("tests/scene/three_shots.scn"));
    ParseResult parsed = parse_scene(text, "three_shots");
    REQUIRE(parsed.scene);
    check_shot("three_shots.scn", *parsed.scene);
    // Loaded with --camera auto: no error, no warning.
    const ShotResult automatic = load_shot(text, "three_shots", {}, CameraChoice::automatic);
    REQUIRE(automatic.scripted());
    for (const Diagnostic& d : automatic.diagnostics) CHECK_MESSAGE(false, format_diagnostic(d, "three_shots.scn"));
    const Shot& shot = *automatic.shot;
    REQUIRE(shot.timeline.shot_count() == 3);
    const DirectedCamera& script = *shot.directed;
    // Each shot's descriptions are keyed within it (`shot K ...`), in order, the first at its start.
    int shot_before = 0;
    for (const CameraShot& d : script.shots) {
      CAPTURE(camera_key_text(d.key));
      CHECK(d.key.shot >= shot_before);
      CHECK(camera_key_text(d.key).starts_with("shot " + std::to_string(d.key.shot + 1) + " "));
      if (d.key.shot > shot_before) CHECK(d.key.kind == CameraKeyKind::start);
      shot_before = d.key.shot;
    }
    CHECK(shot_before == 2);
    // Every strike is filmed from behind the struck ball, which is in the picture as the stick meets it
    // (and from the stroke's start: the approach).
    for (int k = 0; k < 3; ++k) {
      CAPTURE(k);
      const ShotSpan& span = shot.timeline.shots()[static_cast<std::size_t>(k)];
      const int struck = shot.scene.cues[static_cast<std::size_t>(k)].target;
      const Vec3 ball = shot.timeline.motion_state(struck, span.cue).position;
      const int at_cue = shot.camera->shot_at(span.cue);
      REQUIRE(at_cue >= 0);
      const CameraShot& filming = script.shots[static_cast<std::size_t>(at_cue)];
      CHECK(filming.key.shot == k);
      CHECK(camera_key_text(filming.key) == "shot " + std::to_string(k + 1) + " start");
      const double heading = shot.scene.cues[static_cast<std::size_t>(k)].heading_deg * kDegToRad;
      CHECK((filming.location - ball).dot(Vec3(std::cos(heading), std::sin(heading), 0)) < -0.5);
      for (double t : {span.start, span.cue, span.cue + 0.1}) CHECK(in_frame(shot, t, ball));
    }
    // The text parses back to the same descriptions.
    const ParseResult again = parse_scene(with_camera(text, camera_script_text(script, "three_shots")), "three_shots");
    REQUIRE(again.scene);
    CHECK(again.diagnostics.empty());
    REQUIRE(again.scene->camera.size() == script.shots.size());
    for (std::size_t k = 0; k < script.shots.size(); ++k) CHECK(same_shot(again.scene->camera[k], script.shots[k]));
  }

  TEST_CASE("--camera auto replaces a scene's camera script, even one that does not fit the shot") {
    const std::string text = std::string(builtin_scene_text());
    const std::string broken = with_camera(text, "camera\nevent fifth hit 0 1 0 0 hover 0 -3 2 0 0 0\nendcamera\n");
    CHECK(!load_shot(broken, "break").scripted());
    const ShotResult automatic = load_shot(broken, "break", {}, CameraChoice::automatic);
    REQUIRE(automatic.shot);
    CHECK(automatic.diagnostics.empty());
    CHECK(camera_key_text(automatic.shot->scene.camera.front().key) == "start");
  }

  TEST_CASE("--camera and --write-camera on the command lines") {
    test::TempDir tmp;
    const std::string scene = test::source_path("scenes/bank.scn").string();
    const std::string preview = quoted(test::bin("billiards-preview")) + " " + quoted(scene);
    const std::string exporter = quoted(test::bin("billiards-export")) + " " + quoted(scene);

    for (const std::string& program : {preview, exporter}) {
      const test::CommandResult bad = test::run_command(program + " --camera director");
      CHECK(bad.exit_code == 2);
      CHECK_MESSAGE(bad.err.find("bad value 'director' for --camera: expected auto (the automatic director's script) "
                                 "or scene (the scene's own)") != std::string::npos,
                    bad.err);
      const test::CommandResult typo = test::run_command(program + " --camer auto");
      CHECK(typo.exit_code == 2);
      CHECK_MESSAGE(typo.err.find("did you mean '--camera'?") != std::string::npos, typo.err);
      const test::CommandResult help = test::run_command(program + " --help");
      CHECK(help.out.find("--camera auto|scene") != std::string::npos);
    }

    // To standard output, and to a file (only that: no window, no picture).
    const test::CommandResult out = test::run_command(preview + " --write-camera -");
    CHECK(out.exit_code == 0);
    CHECK(out.out.starts_with("camera\n"));
    CHECK(out.out.find("\nevent start ") != std::string::npos);
    CHECK(out.out.ends_with("endcamera\n"));
    const std::string file = (tmp.path / "camera.txt").string();
    const test::CommandResult written = test::run_command(preview + " --write-camera " + quoted(file));
    CHECK(written.exit_code == 0);
    CHECK(written.err == "wrote " + file + "\n");
    CHECK(test::require_file(file) == out.out);
    CHECK(test::leftovers(tmp.path).empty());
    // --quiet: the file, and no closing line.
    const test::CommandResult quiet = test::run_command(preview + " --quiet --write-camera " + quoted(file));
    CHECK(quiet.exit_code == 0);
    CHECK(quiet.err.empty());
    CHECK(test::require_file(file) == out.out);
    // With a picture: the script first, then the timeline of the director's camera.
    const std::string both = (tmp.path / "both.txt").string(), picture = (tmp.path / "timeline.png").string();
    const test::CommandResult timeline =
        test::run_command(preview + " --write-camera " + quoted(both) + " --timeline -o " + quoted(picture));
    CHECK_MESSAGE(timeline.exit_code == 0, timeline.err);
    CHECK(test::require_file(both) == out.out);
    CHECK(fs::file_size(picture) > 1000);
    const test::CommandResult clash = test::run_command(preview + " --camera scene --write-camera -");
    CHECK(clash.exit_code == 2);
    const test::CommandResult nowhere =
        test::run_command(preview + " --write-camera " + quoted((tmp.path / "no/such/dir/c.txt").string()));
    CHECK(nowhere.exit_code == 1);
    CHECK(test::leftovers(tmp.path).empty());

    // billiards-export films with it: camera.csv follows the director's script, and run.json says so.
    const std::string dir = (tmp.path / "auto").string();
    const test::CommandResult exported = test::run_command(exporter + " --camera auto --events-only -o " + quoted(dir));
    CHECK(exported.exit_code == 0);
    CHECK_MESSAGE(exported.err.find("warning") == std::string::npos, exported.err);
    const std::string plain = (tmp.path / "scene").string();
    CHECK(test::run_command(exporter + " --events-only -o " + quoted(plain)).exit_code == 0);
    CHECK(test::require_file(fs::path(dir) / "camera.csv") != test::require_file(fs::path(plain) / "camera.csv"));
  }
}

TEST_SUITE("director: a pocket's jaws") {
  /// The 1, sent along the table, comes off the top cushion into the top-right corner and rattles in
  /// its jaws, three knocks in 0.43 s, and stays out.
  const std::string kBankRattle =
      "cue 0 25\n"
      "ball 0 -0.9625 -0.3690 0.028575 1.8126 0.8452 0 1 0 0 0\n"
      "ball 1 -0.6000 -0.2000 0.028575 0 0 0 1 0 0 0\n";

  std::vector<const Event*> jaw_events(const Timeline& timeline, int ball) {
    std::vector<const Event*> out;
    for (const Event& e : timeline.events())
      if (e.type == EventType::ball_jaw && e.balls.at(0) == ball) out.push_back(&e);
    return out;
  }

  TEST_CASE("a ball rattling in a pocket's jaws is watched to its last knock, and only then the camera goes wide") {
    const ParseResult parsed = parse_scene(kBankRattle, "bank rattle");
    REQUIRE(parsed.scene);
    DirectedCamera script;
    const std::unique_ptr<Shot> shot = directed(*parsed.scene, &script);
    const std::vector<const Event*> jaws = jaw_events(shot->timeline, 1);
    REQUIRE(jaws.size() == 3);
    REQUIRE(shot->timeline.pocket_drops().empty());
    // Its cushion comes first, over a second after the hit that sets it going: a moment the wide shot
    // could start at, with the rattle still to come.
    double cushion = -1;
    for (const Event& e : shot->timeline.events())
      if (e.type == EventType::ball_rail && e.balls[0] == 1) cushion = e.time;
    REQUIRE(cushion > shot->timeline.events().at(2).time + kMinDescriptionSeconds);
    REQUIRE(cushion < jaws.front()->time);

    REQUIRE(script.shots.size() == 3);
    CHECK(script.shots[1].ball == 1);
    CHECK(script.shots[1].mode != CameraMode::hover);
    CHECK(script.comments[1].find("the 1 (ball 1) rattling in the jaws of the top-right corner (pocket 2)") !=
          std::string::npos);
    CHECK(camera_key_text(script.shots[2].key) == "last jaw 1");
    // Up to the last knock the camera is the one on the 1 (holding it, or still arriving at it), never
    // on its way to the wide shot, which leaves only from the last knock; every knock's jaw is in the picture.
    for (const Event* e : jaws) {
      CAPTURE(e->time);
      int in_charge = shot->camera->shot_at(e->time);
      for (const CameraWindow& w : shot->camera->windows())
        if (e->time >= w.begin && e->time < w.end) in_charge = w.shot;
      if (e != jaws.back()) CHECK(in_charge == 1);
      CHECK(in_frame(*shot, e->time, e->where));
    }
    for (const CameraWindow& w : shot->camera->windows())
      if (w.shot == 2) CHECK(w.begin >= jaws.back()->time);
    check_shot("bank rattle", *parsed.scene);
  }

  TEST_CASE("with no ball pocketed, the ball that met a pocket's jaw matters more than a faster one") {
    // The 1 rattles in the top-right corner's jaws and stays out; the 2, rolling across the table on its
    // own, is the fastest object ball.
    const ParseResult parsed = parse_scene(
        "cue 0 45\n"
        "ball 0 0.5176 -0.1683 0.028575 1.7678 1.7678 0 1 0 0 0\n"
        "ball 1 0.9419 0.2560 0.028575 0 0 0 1 0 0 0\n"
        "ball 2 -1.0 -0.45 0.028575 2.6 0 0 1 0 0 0\n",
        "rattle and a runner");
    REQUIRE(parsed.scene);
    DirectedCamera script;
    const std::unique_ptr<Shot> shot = directed(*parsed.scene, &script);
    REQUIRE(shot->timeline.pocket_drops().empty());
    REQUIRE(jaw_events(shot->timeline, 1).size() >= 3);
    REQUIRE(jaw_events(shot->timeline, 2).empty());
    double fastest[3] = {0, 0, 0};
    for (double t = 0; t < shot->timeline.duration(); t += 0.01)
      for (int b = 1; b <= 2; ++b) {
        const Vec3 v = shot->timeline.motion_state(b, t).velocity;
        fastest[b] = std::max(fastest[b], std::hypot(v.x(), v.y()));
      }
    REQUIRE(fastest[2] > fastest[1]);
    REQUIRE(script.shots.size() >= 2);
    CHECK(script.subjects[1] == 1);
    CHECK(script.shots[1].ball == 1);
    check_shot("rattle and a runner", *parsed.scene);
  }

  TEST_CASE("in 50 random breaks every knock on a jaw by the ball the camera is on is in the picture") {
    int followed = 0;
    for (std::uint64_t seed = 1; seed <= 50; ++seed) {
      CAPTURE(seed);
      DirectedCamera script;
      const std::unique_ptr<Shot> shot = directed(scenes::random_break(seed), &script);
      for (const Event& e : shot->timeline.events()) {
        if (e.type != EventType::ball_jaw) continue;
        // The description in charge: the one being blended into, else the one that holds.
        int in_charge = shot->camera->shot_at(e.time);
        for (const CameraWindow& w : shot->camera->windows())
          if (e.time >= w.begin && e.time < w.end) in_charge = w.shot;
        const auto k = static_cast<std::size_t>(in_charge);
        if (script.subjects[k] != e.balls[0] || script.shots[k].mode == CameraMode::hover) continue;
        ++followed;
        CAPTURE(e.time);
        CHECK(in_frame(*shot, e.time, e.where));
      }
    }
    CHECK(followed >= 10);
  }
}

TEST_SUITE("director") {
  TEST_CASE(
      "a game with no camera block is filmed by the director: it opens wide on the table, then cuts to the breaker") {
    // Both players without noise: the break wins at once; the whole game is one shot.
    const std::string text = "game 9ball seed 11\nplayer Ann noise 0\nplayer Bo noise 0\n";
    const ShotResult loaded = load_shot(text, "opening");
    REQUIRE(loaded.scripted());
    const Shot& shot = *loaded.shot;
    REQUIRE(shot.directed);  // the default `--camera scene`, yet the director's script
    const std::vector<CameraShot>& script = shot.directed->shots;
    REQUIRE(script.size() >= 2);
    // The opening: a still wide view from the start, the whole bed and the rack in the picture.
    CHECK(script[0].key.kind == CameraKeyKind::start);
    CHECK(script[0].mode == CameraMode::hover);
    const TableRect bed = table_layout(shot.scene).noses;
    for (const Vec3& corner :
         {Vec3(bed.x0, bed.y0, 0), Vec3(bed.x1, bed.y0, 0), Vec3(bed.x0, bed.y1, 0), Vec3(bed.x1, bed.y1, 0)})
      CHECK(in_frame(shot, 0.5, corner));
    // Then a cut (no blend) to the breaker's view, kOpeningSeconds in, before the strike.
    CHECK(camera_key_text(script[1].key) == "at " + format_number(kOpeningSeconds));
    CHECK(script[1].pre == 0);
    CHECK(script[1].post == 0);
    const double cut = shot.camera->windows().front().event_time;
    CHECK(cut == doctest::Approx(kOpeningSeconds));
    CHECK(cut < shot.timeline.cue_time() - 0.8);
    const int cue_ball = shot.scene.cue().target;
    const Vec3 cue = shot.scene.balls[static_cast<std::size_t>(cue_ball)].position;
    const double heading = shot.scene.cue().heading_deg * kDegToRad;
    CHECK((script[1].location - cue).dot(Vec3(std::cos(heading), std::sin(heading), 0)) < -0.5);
    // A written camera block is kept as written.
    const ShotResult written = load_shot(text + "camera\nevent start 0 0 hover 0 -3 2 0 0 0\nendcamera\n", "written");
    REQUIRE(written.scripted());
    CHECK_FALSE(written.shot->directed);
  }

  TEST_CASE("a game's safety is filmed for where the cue ball goes") {
    if (test::kSanitizedBuild) return;  // a whole game: Release builds only
    const ShotResult loaded = load_shot(test::require_file(test::source_path("scenes/game9.scn")), "game9");
    REQUIRE(loaded.scripted());
    const Shot& shot = *loaded.shot;
    REQUIRE(shot.game);
    REQUIRE(shot.directed);
    int safeties = 0;
    for (const GameTurn& turn : shot.game->turns) {
      if (!turn.planned.safety) continue;
      ++safeties;
      // Every description of that shot after its stroke is about the cue ball.
      const int cue_ball = shot.scene.cues[static_cast<std::size_t>(turn.shot)].target;
      for (std::size_t k = 0; k < shot.directed->shots.size(); ++k)
        if (shot.directed->shots[k].key.shot == turn.shot && shot.directed->shots[k].key.kind != CameraKeyKind::start)
          CHECK(shot.directed->subjects[k] == cue_ball);
    }
    CHECK(safeties > 0);
  }
}
