// The whole export at a tiny size: frames rendered by POV-Ray, movie.mp4 with both streams as long
// as the shot; a re-run renders only what changed; a missing program, a failing frame and Ctrl-C
// end cleanly with nothing half-written left behind.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <regex>

#include "frames.h"
#include "picture.h"
#include "support.h"

using namespace bsim;
using bsim::test::quoted;
namespace fs = std::filesystem;

namespace {

std::string scene(const char* last_camera, double speed = 0.6, const char* cue_camera = "") {
  return "cue 0 0\nball 0 -0.3 0 0.028575  " + std::to_string(speed) +
         " 0 0  1 0 0 0\n"
         "ball 9  0.2 0.05 0.028575  0 0 0  1 0 0 0\n"
         "camera\nevent 0 0 0 hover -1.5 -1.2 1.2  0 0 0\n" +
         cue_camera + last_camera + "endcamera\n";
}
const char* const kEndA = "event 65535 0 0 hover -1.5 -1.2 1.2  0 0 0\n";
const char* const kCueB = "event 1 0 0 hover 1.5 -1.2 1.2  0 0 0\n";

test::CommandResult run_export(const std::string& scene_path, const fs::path& out, const std::string& extra,
                               const std::string& env = "") {
  return test::run_command(env + " " + quoted(test::bin("billiards-export")) + " " + quoted(scene_path) + " -o " +
                           quoted(out.string()) + " " + extra);
}

double json_number(const std::string& json, const std::string& key) {
  std::smatch m;
  REQUIRE(std::regex_search(json, m, std::regex("\"" + key + "\": ?\"?([0-9.]+)")));
  return std::stod(m[1]);
}

std::map<std::string, fs::file_time_type> picture_times(const fs::path& frames) {
  std::map<std::string, fs::file_time_type> times;
  for (const auto& e : fs::directory_iterator(frames))
    if (e.path().extension() == ".png") times[e.path().filename().string()] = e.last_write_time();
  return times;
}

/// A stand-in for POV-Ray: `body` runs with $in and $out set from +I and +O.
std::string fake_povray(const test::TempDir& dir, const std::string& body) {
  const std::string path =
      dir.file("bin/povray",
               "#!/bin/sh\n"
               "for a in \"$@\"; do case \"$a\" in +I*) in=\"${a#+I}\";; +O*) out=\"${a#+O}\";; esac; done\n" +
                   body + "\n");
  fs::permissions(path, fs::perms::owner_all);
  return (dir.path / "bin").string();
}

}  // namespace

TEST_SUITE("movie") {
  TEST_CASE(
      "a tiny movie: every frame rendered, H.264 and AAC as long as the shot, and re-runs render only what changed") {
    for (const char* tool : {"povray", "ffmpeg", "ffprobe"}) test::require_program(tool);
    test::TempDir dir;
    const std::string path = dir.file("tiny.scn", scene(kEndA));
    const fs::path out = dir.path / "out";
    const std::string options = "--size 32x18 --fps 4 --quality draft";
    test::CommandResult r = run_export(path, out, options);
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK(r.err.find('\r') == std::string::npos);  // no progress line off a terminal

    const double duration = json_number(test::require_file(out / "events.json"), "duration");
    const int frames = frame_count(duration, 4);
    auto times = picture_times(out / "frames");
    CHECK(static_cast<int>(times.size()) == frames);
    CHECK(test::leftovers(out).empty());

    const test::CommandResult probe = test::run_command(
        "ffprobe -v error -show_entries stream=codec_name,codec_type,pix_fmt,width,height,sample_rate,channels:"
        "format=duration -of json " +
        quoted((out / "movie.mp4").string()));
    REQUIRE_MESSAGE(probe.exit_code == 0, probe.err);
    CHECK(probe.out.find("\"codec_name\": \"h264\"") != std::string::npos);
    CHECK(probe.out.find("\"pix_fmt\": \"yuv420p\"") != std::string::npos);
    CHECK(probe.out.find("\"width\": 32") != std::string::npos);
    CHECK(probe.out.find("\"codec_name\": \"aac\"") != std::string::npos);
    CHECK(probe.out.find("\"sample_rate\": \"48000\"") != std::string::npos);
    CHECK(probe.out.find("\"channels\": 2") != std::string::npos);
    CHECK(json_number(probe.out, "duration") == doctest::Approx(duration).epsilon(0.25 / duration));
    const std::string faststart = test::require_file(out / "movie.mp4");
    CHECK(faststart.find("moov") < faststart.find("mdat"));

    // run.json: every frame accounted for, rendered here or reused; frames alike (the balls at rest
    // under the still camera) traced once, the later ones developed from that trace (each with its own
    // grain) and tracing nothing themselves.
    std::string summary = test::require_file(out / "run.json");
    const int rendered = static_cast<int>(json_number(summary, "rendered"));
    CHECK(json_number(summary, "total") == frames);
    CHECK(rendered + json_number(summary, "reused") == frames);
    CHECK(json_number(summary, "partial") >= 1);
    CHECK(json_number(summary, "traced") < 1);
    // The sound track as measured: at the calibrated level (this small shot quieter than the break's
    // -16 LUFS), under the ceiling.
    std::smatch sound;
    REQUIRE(std::regex_search(summary, sound,
                              std::regex(R"("sound": \{"level": "calibrated", "target_lufs": null, )"
                                         R"("loudness_lufs": (-?[0-9.]+), "true_peak_dbtp": (-?[0-9.]+)\})")));
    CHECK(std::stod(sound[1]) < -16.0);
    CHECK(std::stod(sound[2]) <= -1.0);

    // The same again: nothing to render, every picture from the store, the same bytes.
    const std::string first_picture = test::require_file(out / "frames" / "frame_00000.png");
    r = run_export(path, out, options);
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    summary = test::require_file(out / "run.json");
    CHECK(json_number(summary, "rendered") == 0);
    CHECK(json_number(summary, "reused") == frames);
    CHECK(test::require_file(out / "frames" / "frame_00000.png") == first_picture);
    CHECK(static_cast<int>(picture_times(out / "frames").size()) == frames);
    CHECK(fs::exists(out / "movie.mp4"));

    // The camera moved from the cue on: the frames before the cue (t < 2.5 s) come from the store.
    r = run_export(dir.file("tiny.scn", scene(kEndA, 0.6, kCueB)), out, options);
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    summary = test::require_file(out / "run.json");
    CHECK(json_number(summary, "rendered") >= 1);
    CHECK(json_number(summary, "reused") >= 10);
    CHECK(test::require_file(out / "frames" / "frame_00000.png") == first_picture);
    CHECK(test::leftovers(out).empty());

    // A shorter shot into the same directory: the frames past its end go, files and pictures.
    r = run_export(dir.file("tiny.scn", scene(kEndA, 0.15)), out, options);
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    const int fewer = frame_count(json_number(test::require_file(out / "events.json"), "duration"), 4);
    REQUIRE(fewer < frames);
    CHECK(static_cast<int>(picture_times(out / "frames").size()) == fewer);
    int povs = 0;
    for (const auto& e : fs::directory_iterator(out / "frames")) povs += e.path().extension() == ".pov";
    CHECK(povs == fewer);
  }

  TEST_CASE("a scene with no camera block is filmed from under the ceiling: the table, not a black picture") {
    for (const char* tool : {"povray", "ffmpeg"}) test::require_program(tool);
    test::TempDir dir;
    const std::string path = dir.file("plain.scn",
                                      "cue 0 0\nball 0 -0.3 0 0.028575  0.3 0 0  1 0 0 0\n"
                                      "ball 9  0.2 0.05 0.028575  0 0 0  1 0 0 0\n");
    const fs::path out = dir.path / "out";
    const test::CommandResult r = run_export(path, out, "--size 64x36 --fps 1 --quality draft");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    const test::Picture picture = test::load_png(out / "frames" / "frame_00000.png");
    const int width = picture.width, height = picture.height;
    double green = 0;  // the lit cloth fills the middle of the picture
    for (int y = height / 3; y < 2 * height / 3; ++y)
      for (int x = width / 3; x < 2 * width / 3; ++x)
        green += picture.rgb[static_cast<std::size_t>(y * width + x) * 3 + 1];
    CHECK(green / ((height / 3) * (width / 3)) > 60);
  }

  TEST_CASE("the progress line shows on a terminal; under CI, plain lines") {
    test::TempDir dir;
    const std::string path = dir.file("tiny.scn", scene(kEndA));
    // A store of its own, empty: every frame is rendered, so there is progress to show.
    const std::string command = "BSIM_CACHE_DIR=" + quoted((dir.path / "store").string()) + " " +
                                quoted(test::bin("billiards-export")) + " " + quoted(path) + " -o " +
                                quoted((dir.path / "out").string()) + " --size 32x18 --fps 2 --quality draft";
    // `script` runs the command on a pseudo-terminal.
    test::CommandResult r = test::run_command("unset CI; script -qec " + quoted(command) + " /dev/null");
    REQUIRE_MESSAGE(r.exit_code == 0, r.out);
    CHECK(r.out.find("rendering frame") != std::string::npos);
    CHECK(r.out.find("frames/s") != std::string::npos);
    fs::remove_all(dir.path / "out");
    r = test::run_command("CI=1 script -qec " + quoted(command) + " /dev/null");
    REQUIRE_MESSAGE(r.exit_code == 0, r.out);
    CHECK(r.out.find("rendering frame") == std::string::npos);
    CHECK(r.out.find("billiards-export: rendering: ") != std::string::npos);
  }

  TEST_CASE("without POV-Ray the export says in one line how to set it up") {
    test::TempDir dir;
    const std::string path = dir.file("tiny.scn", scene(kEndA));
    fs::create_directories(dir.path / "empty");
    const test::CommandResult r =
        run_export(path, dir.path / "out", "--size 32x18 --fps 2", "PATH=" + quoted((dir.path / "empty").string()));
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("povray") != std::string::npos);
    CHECK(r.err.find("bash .ci/make-movie") != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(fs::exists(dir.path / "out" / "movie.mp4"));
  }

  TEST_CASE("a frame POV-Ray cannot render is named with POV-Ray's own message") {
    test::TempDir dir;
    const std::string path = dir.file("tiny.scn", scene(kEndA));
    const std::string fake =
        fake_povray(dir,
                    "if [ \"$in\" = frame_00003.pov ]; then\n"
                    "  echo \"File 'frame_00003.pov' line 7: Parse Error: No matrix here\" >&2; exit 1\n"
                    "fi\n"
                    // The other frames get a one-pixel Radiance picture.
                    "printf '#?RADIANCE\\nFORMAT=32-bit_rle_rgbe\\n\\n-Y 1 +X 1\\n\\200\\200\\200\\200' > \"$out\"");
    const test::CommandResult r =
        run_export(path, dir.path / "out", "--size 32x18 --fps 2 --jobs 1", "PATH=" + quoted(fake) + ":\"$PATH\"");
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("frame 3") != std::string::npos);
    // Named where a --no-render run into the same directory puts it, to look at.
    const std::string pov = (dir.path / "out" / "frames" / "frame_00003.pov").string();
    CHECK(r.err.find(pov + ":7: error: povray: Parse Error: No matrix here\n") != std::string::npos);
    CHECK_FALSE(fs::exists(dir.path / "out"));  // nothing of a failed run reaches its output directory
  }
}
