// The replay: after the shot that wins a game, that shot again at half speed from a second camera.
// The movie's timeline (frames.h) is then longer than the simulation: camera.csv has a row per movie
// frame with the simulation time it shows and a `replay` column, the .pov frames and the sound track
// follow the movie, and --replay off gives the plain movie.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "builtin_scene.h"
#include "camera_clearance.h"
#include "files.h"
#include "frames.h"
#include "mastering.h"
#include "number_format.h"
#include "replay_camera.h"
#include "shot.h"
#include "soundtrack.h"
#include "support.h"

using namespace bsim;
namespace fs = std::filesystem;

namespace {

/// A game of 9-ball the players finish in a few shots (so it loads in a moment).
const std::string kGame = "game 9ball seed 11\nplayer Ann noise 0\nplayer Bo noise 0\n";

struct Row {
  int frame = 0;
  double time = 0;
  Vec3 location{0, 0, 0};
  bool replay = false;
};

std::vector<Row> read_rows(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  REQUIRE(line == "frame,time,cam_x,cam_y,cam_z,look_x,look_y,look_z,interpolating,replay");
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) f.push_back(field);
    REQUIRE(f.size() == 10);
    rows.push_back(
        {std::atoi(f[0].c_str()),
         std::strtod(f[1].c_str(), nullptr),
         {std::strtod(f[2].c_str(), nullptr), std::strtod(f[3].c_str(), nullptr), std::strtod(f[4].c_str(), nullptr)},
         f[9] == "1"});
    REQUIRE((f[9] == "0" || f[9] == "1"));
  }
  return rows;
}

test::CommandResult run_export(const std::string& scene, const fs::path& out, const std::string& extra) {
  return test::run_command(test::bin("billiards-export") + " " + test::quoted(scene) + " -o " +
                           test::quoted(out.string()) + " --quiet " + extra);
}

/// Samples per channel of a 16-bit stereo WAV (its data chunk's size over 4).
std::size_t wav_samples(const std::string& bytes) {
  const std::size_t at = bytes.find("data");
  REQUIRE(at != std::string::npos);
  std::uint32_t size = 0;
  for (int i = 3; i >= 0; --i)
    size = size * 256 + static_cast<unsigned char>(bytes[at + 4 + static_cast<std::size_t>(i)]);
  return size / 4;
}

std::unique_ptr<Shot> load(const std::string& text, ReplayChoice replay = ReplayChoice::on) {
  ShotResult r = load_shot(text, "game", {}, CameraChoice::scene, replay);
  REQUIRE(r.scripted());
  return std::move(r.shot);
}

}  // namespace

TEST_SUITE("replay") {
  TEST_CASE("a plain movie is the simulation: movie frame k shows t = k / fps, as many frames") {
    const MovieTimeline movie(7.0);
    CHECK(movie.duration() == 7.0);
    CHECK(movie.frame_count(30) == frame_count(7.0, 30));
    for (int k = 0; k < movie.frame_count(30); ++k) {
      const MovieFrame f = movie.frame(k, 30);
      CHECK(f.time == frame_time(k, 30));
      CHECK_FALSE(f.replay);
      CHECK(f.rate == 1);
    }
    CHECK_FALSE(movie.replay());
  }

  TEST_CASE("a movie with a replay goes back to the replayed span and runs through it at half rate") {
    MovieTimeline movie(10.0);
    movie.add({4.0, 6.5, 0.5, true});
    CHECK(movie.duration() == 15.0);
    CHECK(movie.frame_count(10) == 150);
    CHECK(movie.frame(99, 10).time == doctest::Approx(9.9));
    CHECK_FALSE(movie.frame(99, 10).replay);
    for (int k = 100; k < 150; ++k) {
      const MovieFrame f = movie.frame(k, 10);
      CHECK(f.replay);
      CHECK(f.rate == 0.5);
      CHECK(f.time == doctest::Approx(4.0 + 0.05 * (k - 100)));
    }
    CHECK(movie.movie_time(5.0, true) == doctest::Approx(12.0));
    CHECK(movie.movie_time(5.0, false) == doctest::Approx(5.0));
    CHECK(movie.at(12.0).time == doctest::Approx(5.0));
    CHECK(movie.at(99.0).time == 6.5);  // past the end: the movie's last instant
  }

  TEST_CASE("a time the movie cuts out is shown where the movie leaves or rejoins the simulation, the nearer") {
    MovieTimeline movie;
    movie.add({0.0, 4.0, 1.0, false});
    movie.add({6.0, 9.0, 1.0, false});
    CHECK(movie.duration() == 7.0);
    CHECK(movie.at(4.5).time == doctest::Approx(6.5));  // after the cut: the simulation from 6 s
    CHECK(movie.movie_time(7.0, false) == doctest::Approx(5.0));
    CHECK(movie.movie_time(4.5, false) == doctest::Approx(4.0));  // nearer the cut's start
    CHECK(movie.movie_time(5.8, false) == doctest::Approx(4.0));  // nearer its end: where 6 s is shown
  }

  TEST_CASE("a game's broadcast edit cuts only the waits on balls that only spin in place, after a moment's hold") {
    const auto shot = load(kGame);
    const Timeline& timeline = shot->timeline;
    const MovieTimeline edit = broadcast_edit(timeline);
    const auto& segments = edit.segments();
    CHECK(segments.front().start == 0.0);
    // The cuts: between the segments, and after the last one up to the simulation's end.
    std::vector<std::pair<double, double>> cuts;
    for (std::size_t j = 0; j < segments.size(); ++j)
      if (const double to = j + 1 < segments.size() ? segments[j + 1].start : timeline.duration(); to > segments[j].end)
        cuts.emplace_back(segments[j].end, to);
    REQUIRE_FALSE(cuts.empty());
    const auto translating = [&](double t) {
      for (int b = 0; b < timeline.ball_count(); ++b) {
        const Motion m = timeline.motion_state(b, t).motion;
        if (m == Motion::sliding || m == Motion::rolling || m == Motion::falling) return true;
      }
      return false;
    };
    int spinning = 0;
    for (const auto& cut : cuts) {
      const double from = cut.first, to = cut.second;
      CAPTURE(from);
      const int k = timeline.shot_at(from);
      // From its shot's settling plus the hold (longer on the winning shot: its call is read) to the
      // next shot's start, where the director cuts, or to the end, where the replay follows.
      const bool last = k + 1 == timeline.shot_count();
      CHECK(from == doctest::Approx(timeline.settled(k) + (last ? 1.5 : 0.8)));
      CHECK(to == (last ? timeline.duration() : timeline.shots()[static_cast<std::size_t>(k) + 1].start));
      CHECK(translating(timeline.settled(k) - 0.01));
      for (double t = timeline.settled(k) + 1e-6; t < to; t += 0.01) {
        CHECK_FALSE(translating(t));
        for (int b = 0; b < timeline.ball_count(); ++b)
          if (timeline.motion_state(b, t).motion == Motion::spinning) ++spinning;
      }
    }
    CHECK(spinning > 0);  // what is cut is a wait on a spinning ball
    // A scene's own camera script is shown whole: the edit is the director's.
    const auto scripted = load(kGame + "camera\nevent 0 0 0 hover 0 -2 2 0 0 0\nendcamera\n");
    REQUIRE(scripted->movie.replay());
    CHECK(scripted->movie.segments().size() == 2);
    CHECK(scripted->movie.segments().front().end == scripted->timeline.duration());
  }

  TEST_CASE("a cut in the sound is a splice: the cut-out sound fades into the sound that follows, no click") {
    // The built-in break cut just after its loudest moment, so the sound on the two sides differs.
    ShotResult r = load_shot(builtin_scene_text(), "break");
    REQUIRE(r.scripted());
    const Shot& shot = *r.shot;
    const double cut_from = 2.70, cut_to = 3.20;
    MovieTimeline cut;
    cut.add({0.0, cut_from, 1.0, false});
    cut.add({cut_to, shot.timeline.duration(), 1.0, false});
    MovieTimeline whole;  // the sound uncut, in two segments that join, as long as the cut one
    whole.add({0.0, cut_from, 1.0, false});
    whole.add({cut_from, shot.timeline.duration() - (cut_to - cut_from), 1.0, false});
    SoundOptions options;
    options.level.mode = LevelMode::off;  // no level stage: the tracks differ only where the sound does
    const auto track = [&](const MovieTimeline& movie) {
      AudioBuffer out;
      std::string error;
      const auto n = static_cast<std::size_t>(std::llround(movie.duration() * kSampleRate));
      REQUIRE(
          mix_movie_soundtrack({shot.scene, shot.timeline, *shot.camera}, {&movie, nullptr}, options, n, out, error));
      return out;
    };
    const AudioBuffer a = track(whole), b = track(cut);
    // Both tracks hold the same room tone sample by sample (they are as long), and the same sound up
    // to the cut, so from
    // the cut on their difference is the incoming sound less what the cut-out stretch would have been.
    const auto at = static_cast<std::size_t>(std::llround(cut_from * kSampleRate));
    for (std::size_t i = 0; i < at; i += 97) REQUIRE(a.left[i] == b.left[i]);
    double later = 0;  // after the 10 ms fade: the whole difference
    for (std::size_t i = 480; i < 960; ++i) later = std::max(later, double(std::abs(b.left[at + i] - a.left[at + i])));
    REQUIRE(later > 1e-3);
    // At the splice, the outgoing sound still holds: the difference starts near zero and grows.
    CHECK(std::abs(b.left[at] - a.left[at]) < 0.02 * later);
    CHECK(std::abs(b.left[at + 1] - a.left[at + 1]) < 0.05 * later);
  }

  TEST_CASE("a game with a winner gets a replay of its winning shot from another camera, clear of everything") {
    const auto shot = load(kGame);
    REQUIRE(shot->game);
    REQUIRE(shot->game->winner);
    const std::optional<MovieSegment> replay = shot->movie.replay();
    REQUIRE(replay);
    REQUIRE(shot->replay_camera);
    CHECK(replay->rate == kReplayRate);
    // The game as the broadcast edit cuts it, then the replay.
    const MovieTimeline edit = broadcast_edit(shot->timeline);
    CHECK(shot->movie.segments().size() == edit.segments().size() + 1);
    CHECK(shot->movie.segments().back().replay);
    CHECK(shot->movie.duration() == doctest::Approx(edit.duration() + replay->length()));
    // A whole number of seconds of movie, from before the strike of the winning shot to after its rest
    // or a second after the winning ball drops.
    CHECK(replay->length() == std::round(replay->length()));
    const ShotSpan& won = shot->timeline.shots()[static_cast<std::size_t>(shot->game->turns.back().shot)];
    CHECK(replay->start < won.cue);
    CHECK(replay->start >= won.cue - kReplayLead - 1e-9);
    bool dropped = false;
    for (const PocketDrop& d : shot->timeline.pocket_drops())
      if (d.time > won.cue && d.time <= won.rest && shot->scene.ball(d.ball).number == 9) {
        dropped = true;
        CHECK(replay->end > d.time);
      }
    CHECK(dropped);
    std::vector<Diagnostic> warnings;
    check_camera_clearance(shot->scene, shot->timeline, *shot->replay_camera, warnings);
    CHECK(warnings.empty());
    CHECK(shot->replay_what.find("behind") != std::string::npos);  // the pocket camera
    // Another place than the movie's camera at the strike.
    const double strike = won.cue;
    CHECK((shot->replay_camera->pose(strike).location - shot->camera->pose(strike).location).norm() > 0.5);
  }

  TEST_CASE("no replay for a scene that is not a game, nor for a game with no winner, nor with --replay off") {
    CHECK(load("cue 0 0\nball 0 -0.5 0 0.028575 1 0 0 1 0 0 0\nball 1 0.3 0 0.028575 0 0 0 1 0 0 0\n")
              ->movie.segments()
              .size() == 1);
    CHECK_FALSE(load("game 9ball seed 3 shots 2\n")->movie.replay());
    const auto off = load(kGame, ReplayChoice::off);
    CHECK_FALSE(off->movie.replay());
    CHECK_FALSE(off->replay_camera);
    CHECK(off->movie.duration() == off->timeline.duration());
  }

  TEST_CASE("camera.csv: a row per movie frame; the replay's rows show the winning shot's times again, slowed") {
    test::TempDir dir;
    const std::string scene = dir.file("game.scn", kGame);
    const int fps = 10;
    const auto on = run_export(scene, dir.path / "on", "--events-only --fps " + std::to_string(fps));
    REQUIRE_MESSAGE(on.exit_code == 0, on.err);
    const auto said = test::run_command(test::bin("billiards-export") + " " + test::quoted(scene) + " -o " +
                                        test::quoted((dir.path / "said").string()) + " --events-only");
    CHECK(said.err.find(" s with the replay, ") != std::string::npos);
    CHECK(said.err.find(" s of balls only spinning cut)") != std::string::npos);
    const std::string csv = test::require_file(dir.path / "on" / "camera.csv");
    const std::vector<Row> rows = read_rows(csv);
    const auto shot = load(kGame);
    const MovieSegment replay = *shot->movie.replay();
    REQUIRE(static_cast<int>(rows.size()) == shot->movie.frame_count(fps));
    // The game's frames show the broadcast edit's times: the simulation less its cuts.
    const MovieTimeline edit = broadcast_edit(shot->timeline);
    REQUIRE(edit.duration() < shot->timeline.duration());  // this game has a wait on spinning balls to cut
    const int game_frames = frame_count(edit.duration(), fps);
    int replayed = 0;
    for (const Row& row : rows) {
      CHECK(row.frame == &row - rows.data());
      if (row.frame < game_frames) {
        CHECK_FALSE(row.replay);
        CHECK(row.time == edit.frame(row.frame, fps).time);
        continue;
      }
      CHECK(row.replay);
      ++replayed;
      // Back to the replay's start, then half a frame's time of the simulation per frame.
      CHECK(row.time == doctest::Approx(replay.start + 0.5 * (frame_time(row.frame, fps) - edit.duration())));
      CHECK(row.time <= replay.end);
      CHECK(row.location == shot->replay_camera->pose(row.time).location);
    }
    CHECK(std::abs(replayed - replay.length() * fps) <= 1);
    // It goes back where the replay starts.
    CHECK(rows[static_cast<std::size_t>(game_frames)].time < rows[static_cast<std::size_t>(game_frames) - 1].time);

    // The same bytes every run; --replay off: the plain movie, every frame of the game as it plays, the
    // same rows up to the first cut.
    REQUIRE(run_export(scene, dir.path / "again", "--events-only --fps " + std::to_string(fps)).exit_code == 0);
    CHECK(test::require_file(dir.path / "again" / "camera.csv") == csv);
    const auto off = run_export(scene, dir.path / "off", "--events-only --replay off --fps " + std::to_string(fps));
    REQUIRE_MESSAGE(off.exit_code == 0, off.err);
    const std::vector<Row> plain = read_rows(test::require_file(dir.path / "off" / "camera.csv"));
    CHECK(static_cast<int>(plain.size()) == frame_count(shot->timeline.duration(), fps));
    for (const Row& row : plain) {
      CHECK_FALSE(row.replay);
      CHECK(row.time == frame_time(row.frame, fps));
      if (frame_time(row.frame, fps) < edit.segments().front().end) {
        CHECK(row.time == rows[static_cast<std::size_t>(row.frame)].time);
        CHECK(row.location == rows[static_cast<std::size_t>(row.frame)].location);
      }
    }
    CHECK(test::require_file(dir.path / "off" / "events.json") == test::require_file(dir.path / "on" / "events.json"));
    const auto bad = run_export(scene, dir.path / "bad", "--events-only --replay maybe");
    CHECK(bad.exit_code == 2);
    CHECK(bad.err.find("bad value 'maybe' for --replay: expected on or off") != std::string::npos);
  }

  TEST_CASE(
      "--no-render: a .pov per movie frame, the replay's from its camera, and a sound track as long as the movie") {
    test::TempDir dir;
    const std::string scene = dir.file("game.scn", kGame);
    const int fps = 4;
    const auto r = run_export(scene, dir.path / "out", "--no-render --fps " + std::to_string(fps));
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    const auto shot = load(kGame);
    const int frames = shot->movie.frame_count(fps);
    CHECK(fs::exists(
        dir.path / "out" / "frames" /
        ("frame_" + std::string(5 - std::to_string(frames - 1).size(), '0') + std::to_string(frames - 1) + ".pov")));
    CHECK_FALSE(
        fs::exists(dir.path / "out" / "frames" /
                   ("frame_" + std::string(5 - std::to_string(frames).size(), '0') + std::to_string(frames) + ".pov")));
    // The last frame is the replay's: its header says so, and its camera is the replay's.
    const std::string last_name =
        "frame_" + std::string(5 - std::to_string(frames - 1).size(), '0') + std::to_string(frames - 1) + ".pov";
    const std::string last = test::require_file(dir.path / "out" / "frames" / last_name);
    CHECK(last.find("(replay)") != std::string::npos);
    const std::vector<Row> rows = read_rows(test::require_file(dir.path / "out" / "camera.csv"));
    REQUIRE(static_cast<int>(rows.size()) == frames);
    const std::string first = test::require_file(dir.path / "out" / "frames" / "frame_00000.pov");
    CHECK(first.find("(replay)") == std::string::npos);
    // The sound track lasts as long as the movie, to the sample: longer than the game by the replay.
    const std::size_t samples = wav_samples(test::require_file(dir.path / "out" / "soundtrack.wav"));
    CHECK(samples == static_cast<std::size_t>(std::llround(shot->movie.duration() * 48000)));
    CHECK(samples > static_cast<std::size_t>(std::llround(shot->timeline.duration() * 48000)));
    CHECK(test::require_file(dir.path / "out" / "run.json").find("\"total\": " + std::to_string(frames)) !=
          std::string::npos);
    // Each movie frame's caption (frames/captions.txt, a line per frame after its header): the replay's
    // frames, exactly those camera.csv marks, are captioned as the replay, with the winner.
    std::istringstream captions(test::require_file(dir.path / "out" / "frames" / "captions.txt"));
    std::string line;
    std::getline(captions, line);  // the header
    int k = 0;
    for (; std::getline(captions, line); ++k) {
      REQUIRE(k < frames);
      CAPTURE(line);
      CHECK(line.starts_with(std::to_string(k) + "\t"));
      CHECK((line.find("\treplay\t") != std::string::npos) == rows[static_cast<std::size_t>(k)].replay);
      if (rows[static_cast<std::size_t>(k)].replay) CHECK(line.find("WINNER") != std::string::npos);
    }
    CHECK(k == frames);

    // The same bytes every run: the sound track and the replay's frames.
    const auto again = run_export(scene, dir.path / "again", "--no-render --fps " + std::to_string(fps));
    REQUIRE_MESSAGE(again.exit_code == 0, again.err);
    CHECK(test::require_file(dir.path / "again" / "soundtrack.wav") ==
          test::require_file(dir.path / "out" / "soundtrack.wav"));
    CHECK(test::require_file(dir.path / "again" / "frames" / last_name) == last);
  }
}
