// The preview shows a game's replay too: the window's time runs over the movie (past the game's end
// into the replay, drawn from the replay's camera), the timeline picture has the replay's box after
// the end, and --replay off leaves it out.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

#include "files.h"
#include "frames.h"
#include "scene_renderer.h"
#include "shot.h"
#include "support.h"
#include "timeline_picture.h"
#include "viewer_state.h"

using namespace bsim;
using bsim::test::TempDir;

namespace {

/// A game of 9-ball the players finish in a few shots (as tests/export/test_replay.cpp's).
const std::string kGame = "game 9ball seed 11\nplayer Ann noise 0\nplayer Bo noise 0\n";

}  // namespace

TEST_SUITE("preview replay") {
  TEST_CASE("the window's time runs on into the replay, filmed from the replay's camera, and back out") {
    TempDir dir;
    ViewerState state;
    state.source = scene_source(dir.file("game.scn", kGame), false);
    REQUIRE(load_into(state));
    const Shot& shot = *state.shot;
    const MovieSegment replay = *shot.movie.replay();
    const double game = broadcast_edit(shot.timeline).duration();  // the game as the movie cuts it
    CHECK(game < state.duration());
    CHECK(state.movie_duration() == doctest::Approx(game + replay.length()));

    state.set_movie_time(game + 1.0);  // one second of movie into the replay
    CHECK(state.replay);
    CHECK(state.time == doctest::Approx(replay.start + 0.5));
    CHECK(state.movie_time() == doctest::Approx(game + 1.0));
    const FrameState frame = scripted_frame(shot, state.shown());
    const CameraPose pose = shot.replay_camera->pose(state.time);
    CHECK((frame.camera.eye - pose.location).norm() < 1e-12);
    CHECK((frame.camera.eye - shot.camera->pose(state.time).location).norm() > 0.1);

    // A frame on is a half frame of the simulation on; the end of the movie is the replay's end.
    state.fps = 30;
    const double next_frame = (std::round(state.movie_time() * 30) + 1) / 30;  // on the movie's frames
    state.step_frames(1);
    CHECK(state.movie_time() == doctest::Approx(next_frame));
    CHECK(state.time == doctest::Approx(replay.start + 0.5 * (next_frame - game)));
    state.set_movie_time(1e9);
    CHECK(state.replay);
    CHECK(state.time == replay.end);
    state.set_time(1.0);  // any simulation time: out of the replay
    CHECK_FALSE(state.replay);
    CHECK(state.movie_time() == 1.0);
  }

  TEST_CASE("the animatic ends with the replay: as many frames as the movie, its sound as long") {
    test::require_program("ffmpeg");
    test::require_program("ffprobe");
    TempDir dir;
    const std::string path = dir.file("game.scn", kGame);
    const std::string movie = (dir.path / "a.mp4").string();
    const auto r = test::run_command(test::bin("billiards-preview") + " " + path + " --movie " + movie +
                                     " --fps 4 --size 160x90 --quiet");
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    LoadedShot loaded = load_source(scene_source(path, false));
    REQUIRE(loaded.scripted());
    const int frames = loaded.shot->movie.frame_count(4);
    CHECK(frames > frame_count(loaded.shot->timeline.duration(), 4));
    const auto probe =
        test::run_command("ffprobe -v error -show_entries stream=codec_type,nb_frames,duration -of csv=p=0 " + movie);
    INFO(probe.out);
    // Lines "video,DURATION,FRAMES" and "audio,DURATION,PACKETS": both streams last the movie.
    std::istringstream lines(probe.out);
    int streams = 0;
    for (std::string line; std::getline(lines, line); ++streams) {
      std::istringstream fields(line);
      std::string type, duration, count;
      std::getline(fields, type, ',');
      std::getline(fields, duration, ',');
      std::getline(fields, count, ',');
      CHECK(std::strtod(duration.c_str(), nullptr) == doctest::Approx(loaded.shot->movie.duration()).epsilon(0.01));
      if (type == "video") CHECK(std::atoi(count.c_str()) == frames);
    }
    CHECK(streams == 2);
  }

  TEST_CASE("the timeline picture has the replay after the game's end; --replay off has none") {
    TempDir dir;
    const std::string path = dir.file("game.scn", kGame);
    SceneSource source = scene_source(path, false);
    LoadedShot loaded = load_source(source);
    REQUIRE(loaded.scripted());
    const TimelineData data = timeline_data(*loaded.shot);
    REQUIRE(data.replay);
    CHECK(data.replay->length == loaded.shot->movie.replay()->length());
    CHECK(data.replay->label == "replay");
    CHECK(data.replay->detail.find("half speed") != std::string::npos);
    // What the movie cuts out of the game is marked: here the wait on spinning balls after the
    // winning shot, up to the game's end.
    const Timeline& timeline = loaded.shot->timeline;
    REQUIRE(data.cuts.size() == 1);
    CHECK(data.cuts[0].first == doctest::Approx(timeline.settled(timeline.shot_count() - 1) + 1.5));
    CHECK(data.cuts[0].second == timeline.duration());
    source.replay = false;
    LoadedShot plain = load_source(source);
    REQUIRE(plain.scripted());
    CHECK_FALSE(timeline_data(*plain.shot).replay);
    CHECK(timeline_data(*plain.shot).cuts.empty());
    CHECK_FALSE(plain.shot->movie.replay());

    const auto r = test::run_command(test::bin("billiards-preview") + " " + path + " --timeline -o " +
                                     (dir.path / "t.png").string() + " --size 1600x900");
    INFO(r.err);
    CHECK(r.exit_code == 0);
    CHECK(std::filesystem::file_size(dir.path / "t.png") > 1000);
  }
}
