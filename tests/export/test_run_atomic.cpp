// A run of billiards-export is all or nothing: whatever goes wrong (a program missing, a frame that
// fails, Ctrl-C while rendering or encoding, a full disk) the output directory is left exactly as the
// previous run left it, and no staging directory stays behind. Frames finished before the trouble
// are kept in the frame store for the next run. run.json sums up a run that succeeded.
#include <doctest/doctest.h>

#include <filesystem>
#include <map>
#include <regex>
#include <string>

#include "files.h"
#include "frames.h"
#include "support.h"

using bsim::test::quoted;
namespace fs = std::filesystem;

namespace {

/// A short shot (about 5 s), so a run at 2 fps and 32x18 has about ten tiny frames.
const char* const kScene =
    "cue 0 0\n"
    "ball 0 -0.3 0 0.028575  0.4 0 0  1 0 0 0\n"
    "ball 9  0.2 0.05 0.028575  0 0 0  1 0 0 0\n"
    "camera\nevent 0 0 0 hover -1.5 -1.2 1.2  0 0 0\nendcamera\n";
const char* const kOptions = " --size 32x18 --fps 2 --quality draft";

/// Every file below `dir` with its bytes: what "exactly as it was" compares.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = bsim::test::require_file(e.path());
  return files;
}

/// Names in `dir` (not below) that a run may leave only by mistake: staging directories.
std::vector<std::string> staging_left(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (name.find(".partial-") != std::string::npos || name.find(".old-") != std::string::npos) found.push_back(name);
  }
  return found;
}

int count_files(const fs::path& dir) {
  int n = 0;
  if (fs::exists(dir))
    for (const auto& e : fs::directory_iterator(dir)) n += e.is_regular_file();
  return n;
}

/// A stand-in program in dir/bin: a shell script.
void stand_in(const bsim::test::TempDir& dir, const std::string& name, const std::string& body) {
  const std::string path = dir.file("bin/" + name, "#!/bin/sh\n" + body + "\n");
  fs::permissions(path, fs::perms::owner_all);
}

/// A working directory with a scene, its own frame store and a finished run in `out`.
struct Workspace {
  bsim::test::TempDir dir;
  std::string scene = dir.file("shot.scn", kScene);
  fs::path out = dir.path / "out";
  fs::path store = dir.path / "store";

  /// The export's command line with `env` before it (PATH=..., ulimit -f ...; ).
  std::string command(const std::string& env = "") const {
    return env + " BSIM_CACHE_DIR=" + quoted(store.string()) + " " + quoted(bsim::test::bin("billiards-export")) + " " +
           quoted(scene) + " -o " + quoted(out.string()) + kOptions;
  }
  void finish_a_run() const {
    const bsim::test::CommandResult r = bsim::test::run_command(command());
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    REQUIRE(fs::exists(out / "movie.mp4"));
  }
  /// Starts the export in the background, waits (up to a minute) until `ready` (a shell test) holds,
  /// sends SIGINT and reports the exit status as "status N".
  bsim::test::CommandResult interrupt_when(const std::string& env, const std::string& ready) const {
    return bsim::test::run_command(command(env) + " & pid=$!; i=0; while ! " + ready +
                                   " && [ $i -lt 1200 ]; do sleep 0.05; i=$((i+1)); done; "
                                   "kill -INT $pid; wait $pid; echo \"status $?\"");
  }
};

}  // namespace

TEST_SUITE("a run is all or nothing") {
  TEST_CASE("a missing program is found before any work: no stage, no frame rendered") {
    for (const char* tool : {"povray", "ffmpeg"}) bsim::test::require_program(tool);
    Workspace w;
    w.finish_a_run();
    const auto before = snapshot(w.dir.path);

    SUBCASE("no POV-Ray") {
      fs::create_directories(w.dir.path / "bin");
      const bsim::test::CommandResult r =
          bsim::test::run_command(w.command("PATH=" + quoted((w.dir.path / "bin").string())));
      CHECK(r.exit_code == 1);
      CHECK(r.err.find("povray is not installed") != std::string::npos);
    }
    SUBCASE("POV-Ray but no ffmpeg") {
      // A different shot, whose frames the store does not have: any frame rendered would show there.
      w.dir.file("shot.scn", std::string(kScene) + "ball 10 0.5 0.3 0.028575  0 0 0  1 0 0 0\n");
      const int stored = count_files(w.store);
      fs::create_directories(w.dir.path / "bin");
      fs::create_symlink("/usr/bin/povray", w.dir.path / "bin" / "povray");
      const bsim::test::CommandResult r =
          bsim::test::run_command(w.command("PATH=" + quoted((w.dir.path / "bin").string())));
      CHECK(r.exit_code == 1);
      CHECK(r.err.find("ffmpeg is not installed") != std::string::npos);
      CHECK(count_files(w.store) == stored);
      w.dir.file("shot.scn", kScene);
    }
    fs::remove_all(w.dir.path / "bin");
    CHECK(snapshot(w.dir.path) == before);
    CHECK(staging_left(w.dir.path).empty());
  }

  TEST_CASE("a frame that fails leaves the previous run's outputs as they were") {
    bsim::test::require_program("povray");
    Workspace w;
    w.finish_a_run();
    const auto before = snapshot(w.out);
    // A different shot, so the new run has frames to render; its POV-Ray fails on one of them.
    w.dir.file("shot.scn", std::string(kScene) + "ball 10 0.5 0.3 0.028575  0 0 0  1 0 0 0\n");
    stand_in(w.dir, "povray",
             "for a in \"$@\"; do case \"$a\" in +I*) in=\"${a#+I}\";; esac; done\n"
             "case \"$in\" in frame_00004.pov) echo \"File '$in' line 3: Parse Error: broken\" >&2; exit 1;; esac\n"
             "exec povray_real \"$@\"");
    fs::create_symlink("/usr/bin/povray", w.dir.path / "bin" / "povray_real");
    const bsim::test::CommandResult r =
        bsim::test::run_command(w.command("PATH=" + quoted((w.dir.path / "bin").string()) + ":\"$PATH\""));
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("frame 4") != std::string::npos);
    CHECK(snapshot(w.out) == before);
    CHECK(staging_left(w.dir.path).empty());
    CHECK(count_files(w.store) > 0);  // the frames that did render wait for the next run
  }

  TEST_CASE("Ctrl-C while rendering: the directory as it was, the process dies of the signal") {
    Workspace w;
    w.finish_a_run();
    const auto before = snapshot(w.out);
    w.dir.file("shot.scn", std::string(kScene) + "ball 10 0.5 0.3 0.028575  0 0 0  1 0 0 0\n");
    // Each stand-in starts its picture, then hangs: only the interrupt can end the run.
    stand_in(w.dir, "povray",
             "for a in \"$@\"; do case \"$a\" in +O*) out=\"${a#+O}\";; esac; done\n"
             "touch \"$out\"; exec sleep 60");
    const bsim::test::CommandResult r =
        w.interrupt_when("PATH=" + quoted((w.dir.path / "bin").string()) + ":\"$PATH\"",
                         "[ -n \"$(find " + quoted(w.out.string()) + " -name '*.tmp.hdr' 2>/dev/null)\" ]");
    CHECK(r.out.find("status 130") != std::string::npos);  // 128 + SIGINT
    CHECK(r.err.find("billiards-export: interrupted; " + w.out.string() + " is left as it was") != std::string::npos);
    CHECK(snapshot(w.out) == before);
    CHECK(staging_left(w.dir.path).empty());
  }

  TEST_CASE("Ctrl-C while encoding: the directory as it was, the rendered frames kept in the store") {
    bsim::test::require_program("povray");
    Workspace w;
    w.finish_a_run();
    const auto before = snapshot(w.out);
    const int stored = count_files(w.store);
    w.dir.file("shot.scn", std::string(kScene) + "ball 10 0.5 0.3 0.028575  0 0 0  1 0 0 0\n");
    const fs::path encoding = w.dir.path / "encoding";
    stand_in(w.dir, "ffmpeg",
             "case \"$1\" in -version) echo 'ffmpeg version stand-in'; exit 0;; esac\n"
             "touch " +
                 quoted(encoding.string()) + "; exec sleep 60");
    const bsim::test::CommandResult r = w.interrupt_when("PATH=" + quoted((w.dir.path / "bin").string()) + ":\"$PATH\"",
                                                         "[ -e " + quoted(encoding.string()) + " ]");
    REQUIRE(fs::exists(encoding));
    CHECK(r.out.find("status 130") != std::string::npos);
    // Ctrl-C says what the next run keeps: every frame, in the store.
    CHECK(std::regex_search(r.err, std::regex("billiards-export: interrupted; .* is left as it was; the [0-9]+ frames "
                                              "finished are kept in the frame store \\(" +
                                              w.store.string() + "\\) and the next run reuses them\n")));
    CHECK(snapshot(w.out) == before);
    CHECK(staging_left(w.dir.path).empty());
    CHECK(count_files(w.store) > stored);

    // The next run renders none of the frames it already has.
    const bsim::test::CommandResult again = bsim::test::run_command(w.command());
    REQUIRE_MESSAGE(again.exit_code == 0, again.err);
    const std::string summary = bsim::test::require_file(w.out / "run.json");
    CHECK(summary.find("\"rendered\": 0,") != std::string::npos);
  }

  TEST_CASE("a full disk: the write that fails is named, the directory as it was") {
    Workspace w;
    w.finish_a_run();
    const auto before = snapshot(w.out);
    w.dir.file("shot.scn", std::string(kScene) + "ball 10 0.5 0.3 0.028575  0 0 0  1 0 0 0\n");
    // No file may grow past 64 KiB: the sound track (half a megabyte a second) cannot be written.
    const bsim::test::CommandResult r = bsim::test::run_command("ulimit -f 128; " + w.command());
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("cannot write") != std::string::npos);
    CHECK(r.err.find("soundtrack.wav") != std::string::npos);
    CHECK(snapshot(w.out) == before);
    CHECK(staging_left(w.dir.path).empty());
  }

  TEST_CASE("a data check after a render keeps the movie, its frames and its sound track, and says so") {
    bsim::test::require_program("povray");
    Workspace w;
    w.finish_a_run();
    const auto before = snapshot(w.out);
    const std::string events_only = bsim::test::quoted(bsim::test::bin("billiards-export")) + " " +
                                    bsim::test::quoted(w.scene) + " -o " + bsim::test::quoted(w.out.string()) +
                                    " --events-only --fps 2";
    const bsim::test::CommandResult r = bsim::test::run_command(events_only);
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    // Every file of the render is still there, byte for byte; the data files are this run's (the same).
    CHECK(snapshot(w.out) == before);
    CHECK(r.err.find("; kept from an earlier run: frames/, movie.mp4, soundtrack.wav, run.json\n") !=
          std::string::npos);
    CHECK(r.err.find("made before the shot changed") == std::string::npos);

    // The shot changes: the data files are new, the movie stays, and the line says it is out of date.
    w.dir.file("shot.scn", std::string(kScene) + "ball 10 0.5 0.3 0.028575  0 0 0  1 0 0 0\n");
    const bsim::test::CommandResult changed = bsim::test::run_command(events_only);
    REQUIRE_MESSAGE(changed.exit_code == 0, changed.err);
    CHECK(bsim::test::require_file(w.out / "movie.mp4") == before.at("movie.mp4"));
    CHECK(bsim::test::require_file(w.out / "events.json") != before.at("events.json"));
    CHECK(changed.err.find("kept from an earlier run: frames/, movie.mp4, soundtrack.wav, run.json (made before the "
                           "shot changed; render again to bring them up to date)") != std::string::npos);
  }

  TEST_CASE("a run replaces what it makes, keeps the rest, and run.json sums it up") {
    bsim::test::require_program("povray");
    Workspace w;
    w.finish_a_run();
    bsim::test::write_file(w.out / "notes.txt", "mine");
    const std::string movie = bsim::test::require_file(w.out / "movie.mp4");
    const bsim::test::CommandResult r = bsim::test::run_command(w.command() + " --no-render");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    // The frames folder is replaced whole (no older pictures beside the new .pov files); the movie
    // this run did not make stays, and the closing line names it.
    CHECK(bsim::test::require_file(w.out / "movie.mp4") == movie);
    for (const auto& e : fs::directory_iterator(w.out / "frames")) CHECK(e.path().extension() != ".png");
    CHECK(bsim::test::require_file(w.out / "notes.txt") == "mine");
    CHECK(r.err.find("; kept from an earlier run: movie.mp4\n") != std::string::npos);

    const bsim::test::CommandResult full = bsim::test::run_command(w.command());
    REQUIRE_MESSAGE(full.exit_code == 0, full.err);
    const std::string summary = bsim::test::require_file(w.out / "run.json");
    const double duration = std::stod(std::regex_replace(bsim::test::require_file(w.out / "events.json"),
                                                         std::regex(R"([\s\S]*"duration": ([0-9.]+)[\s\S]*)"), "$1"));
    const int frames = bsim::frame_count(duration, 2);
    CHECK(summary.find("\"scene\": \"" + w.scene + "\"") != std::string::npos);
    CHECK(summary.find("\"size\": \"32x18\", \"quality\": \"draft\"") != std::string::npos);
    CHECK(summary.find("\"total\": " + std::to_string(frames) +
                       ", \"rendered\": 0, \"reused\": " + std::to_string(frames)) != std::string::npos);
    for (const char* key : {"\"simulating\": ", "\"writing\": ", "\"rendering\": ", "\"encoding\": "})
      CHECK(summary.find(key) != std::string::npos);
    CHECK(std::regex_search(summary, std::regex("\"povray\": \"POV-Ray 3\\.[0-9]")));
    CHECK(std::regex_search(summary, std::regex("\"ffmpeg\": \"ffmpeg version [0-9]")));
    const std::string movie_entry =
        "{\"path\": \"movie.mp4\", \"bytes\": " + std::to_string(fs::file_size(w.out / "movie.mp4")) + "}";
    CHECK(summary.find(movie_entry) != std::string::npos);
    CHECK(summary.find("{\"path\": \"frames/\", \"bytes\": ") != std::string::npos);
    CHECK(summary.find("notes.txt") == std::string::npos);  // not an output of the run
  }
}

TEST_SUITE("one length everywhere") {
  TEST_CASE("frames, movie, trajectory.csv and camera.csv all hold the frames at t = k/fps below the duration") {
    for (const char* tool : {"povray", "ffmpeg", "ffprobe"}) bsim::test::require_program(tool);
    Workspace w;
    w.finish_a_run();
    const double duration = std::stod(std::regex_replace(bsim::test::require_file(w.out / "events.json"),
                                                         std::regex(R"([\s\S]*"duration": ([0-9.]+)[\s\S]*)"), "$1"));
    const int frames = static_cast<int>(duration) * 2;  // a whole number of seconds at 2 fps
    CHECK(bsim::frame_count(duration, 2) == frames);
    int pngs = 0, povs = 0;
    for (const auto& e : fs::directory_iterator(w.out / "frames")) {
      pngs += e.path().extension() == ".png";
      povs += e.path().extension() == ".pov";
    }
    CHECK(pngs == frames);
    CHECK(povs == frames);
    const bsim::test::CommandResult probe = bsim::test::run_command(
        "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames -of csv=p=0 " +
        quoted((w.out / "movie.mp4").string()));
    REQUIRE_MESSAGE(probe.exit_code == 0, probe.err);
    CHECK(std::stoi(probe.out) == frames);
    auto lines = [](const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); };
    CHECK(lines(bsim::test::require_file(w.out / "camera.csv")) == 1 + frames);
    CHECK(lines(bsim::test::require_file(w.out / "trajectory.csv")) == 1 + 2 * frames);  // two balls
  }
}
