// A renderer that fails for a reason outside the scene (it times out starting its worker thread
// under load, hangs, dies of a signal, writes no picture) gets the frame again, up to three attempts in
// all; a parse error is never retried and is reported at its file and line. Stand-ins for POV-Ray
// first on PATH fail on cue and hand the other attempts to the real one.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <map>
#include <sstream>

#include "child_process.h"
#include "frames.h"
#include "render_jobs.h"
#include "support.h"

using namespace bsim;
using bsim::test::quoted;
namespace fs = std::filesystem;

namespace {

const char* const kScene =
    "cue 0 0\n"
    "ball 0 -0.3 0 0.028575  0.6 0 0  1 0 0 0\n"
    "ball 9  0.2 0.05 0.028575  0 0 0  1 0 0 0\n"
    "camera\n"
    "event 0 0 0 hover -1.5 -1.2 1.2  0 0 0\n"
    "event 65535 0 0 hover -1.5 -1.2 1.2  0 0 0\n"
    "endcamera\n";
const char* const kOptions = "--size 64x36 --fps 2 --quality draft";
const char* const kTimeout = "Timed out waiting for worker thread startup";

/// The real POV-Ray, found before any stand-in goes first on PATH.
std::string real_povray() {
  const std::string path = find_program("povray");
  REQUIRE_MESSAGE(!path.empty(), "povray is not installed: run bash .ci/test, which installs it");
  return path;
}

/// A stand-in for POV-Ray in `dir`/bin: it notes each render's input file in `dir`/attempts.txt (not a
/// call without one, such as the version query), then
/// runs `body` with $in and $out set from +I and +O and $marks a folder for marker files. Returns
/// the PATH to run the exporter with.
std::string stand_in(const test::TempDir& dir, const std::string& body) {
  fs::create_directories(dir.path / "marks");
  const std::string path =
      dir.file("bin/povray",
               "#!/bin/sh\n"
               "for a in \"$@\"; do case \"$a\" in +I*) in=\"${a#+I}\";; +O*) out=\"${a#+O}\";; esac; done\n"
               "marks=" +
                   quoted((dir.path / "marks").string()) + "\n" + "[ -z \"$in\" ] || echo \"$in\" >> " +
                   quoted((dir.path / "attempts.txt").string()) + "\n" + body + "\n");
  fs::permissions(path, fs::perms::owner_all);
  return "PATH=" + quoted((dir.path / "bin").string()) + ":\"$PATH\"";
}

test::CommandResult run_export(const test::TempDir& dir, const std::string& path_setting, const std::string& extra) {
  const std::string scene = dir.file("tiny.scn", kScene);
  // A frame store of this test's own: every frame is rendered, none comes from an earlier test.
  return test::run_command(path_setting + " BSIM_CACHE_DIR=" + quoted((dir.path / "store").string()) + " " +
                           quoted(test::bin("billiards-export")) + " " + quoted(scene) + " -o " +
                           quoted((dir.path / "out").string()) + " " + kOptions + " " + extra);
}

/// How many times the stand-in was called for each frame file.
std::map<std::string, int> attempts(const test::TempDir& dir) {
  std::map<std::string, int> count;
  std::istringstream in(test::require_file(dir.path / "attempts.txt"));
  for (std::string line; std::getline(in, line);) ++count[line];
  return count;
}

int pictures(const fs::path& frames) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(frames)) n += e.path().extension() == ".png";
  return n;
}

int povs(const fs::path& frames) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(frames)) n += e.path().extension() == ".pov";
  return n;
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

/// What the real POV-Ray prints for `pov` (written with `files` beside it) in a fresh folder.
std::string povray_says(const std::map<std::string, std::string>& files, const std::string& pov) {
  test::TempDir dir;
  for (const auto& [name, text] : files) dir.file(name, text);
  const test::CommandResult r = test::run_command("cd " + quoted(dir.path.string()) + " && " + quoted(real_povray()) +
                                                  " -D +W16 +H9 +I" + pov + " +Oout.png");
  CHECK(r.exit_code != 0);
  return r.out + r.err;
}

}  // namespace

TEST_SUITE("render retry") {
  TEST_CASE("a parse error in POV-Ray's own output is found with its file, line and whole message") {
    const std::string camera = "#version 3.7;\ncamera { location <0, 1, -3> look_at 0 }\n";
    // In an include, with a message long enough that POV-Ray wraps it.
    std::string said =
        povray_says({{"parts.inc", "#declare A = 1;\n#declare B = sphere { 0, 1 pigment { rgb Foo } }\n"},
                     {"scene.pov", camera + "#include \"parts.inc\"\nobject { B }\n"}},
                    "scene.pov");
    std::optional<PovParseError> found = find_parse_error(said);
    REQUIRE(found.has_value());
    CHECK(found->file == "parts.inc");
    CHECK(found->line == 2);
    CHECK(found->message.rfind("Parse Error: ", 0) == 0);
    CHECK(found->message.find("undeclared identifier 'Foo' found instead") != std::string::npos);

    // A missing include: first a "Possible Parse Error" warning, then the error itself.
    said = povray_says({{"scene.pov", camera + "\n#include \"missing.inc\"\n"}}, "scene.pov");
    found = find_parse_error(said);
    REQUIRE(found.has_value());
    CHECK(found->file == "scene.pov");
    CHECK(found->line == 4);
    CHECK(found->message.find("Parse Error: Cannot open include file missing.inc") == 0);

    // No input file at all: an error with no file and line.
    said = povray_says({}, "nothing.pov");
    found = find_parse_error(said);
    REQUIRE(found.has_value());
    CHECK(found->file.empty());
    CHECK(found->line == 0);

    // Not parse errors: the renderer failing to start, a warning alone.
    CHECK_FALSE(find_parse_error(std::string(kTimeout) + "\n").has_value());
    CHECK_FALSE(find_parse_error("File 'a.pov' line 2: Possible Parse Error: Cannot find file 'x.inc',\n"
                                 " even after trying to append file type extension.\n")
                    .has_value());
  }

  TEST_CASE("a frame that fails for a reason outside the scene is rendered again, with a warning") {
    for (const char* tool : {"povray", "ffmpeg"}) test::require_program(tool);
    test::TempDir dir;
    // The first attempt at each of frames 0 to 4 fails, each in its own way; every other attempt
    // is the real POV-Ray's.
    const std::string path = stand_in(dir,
                                      "if [ ! -e \"$marks/$in\" ]; then\n"
                                      "  : > \"$marks/$in\"\n"
                                      "  case \"$in\" in\n"
                                      "    frame_00000.pov) echo '" +
                                          std::string(kTimeout) +
                                          "' >&2; exit 1;;\n"
                                          "    frame_00001.pov) kill -KILL $$;;\n"
                                          "    frame_00002.pov) exit 0;;\n"
                                          "    frame_00003.pov) : > \"$out\"; exit 0;;\n"
                                          "    frame_00004.pov) echo garbage > \"$out\"; exit 0;;\n"
                                          "  esac\n"
                                          "fi\n"
                                          "exec " +
                                          quoted(real_povray()) + " \"$@\"");
    const test::CommandResult r = run_export(dir, path, "--jobs 2");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    const fs::path out = dir.path / "out";
    const int frames = povs(out / "frames");
    REQUIRE(frames >= 6);
    CHECK(pictures(out / "frames") == frames);
    CHECK(fs::file_size(out / "movie.mp4") > 0);
    CHECK(test::leftovers(out).empty());

    const std::string retry = "; retrying (attempt 2 of 3)\n";
    CHECK(r.err.find("billiards-export: warning: frame 0 (frames/frame_00000.pov): povray failed (" +
                     std::string(kTimeout) + ")" + retry) != std::string::npos);
    CHECK(
        r.err.find("billiards-export: warning: frame 1 (frames/frame_00001.pov): povray failed (killed by signal 9: " +
                   std::string(strsignal(9)) + ")" + retry) != std::string::npos);
    CHECK(r.err.find("billiards-export: warning: frame 2 (frames/frame_00002.pov): povray failed (wrote no picture)" +
                     retry) != std::string::npos);
    CHECK(r.err.find("billiards-export: warning: frame 3 (frames/frame_00003.pov): povray failed (wrote an empty "
                     "picture)" +
                     retry) != std::string::npos);
    CHECK(r.err.find("billiards-export: warning: frame 4 (frames/frame_00004.pov): povray failed (wrote a picture "
                     "that cannot be read: not a Radiance .hdr picture)" +
                     retry) != std::string::npos);
    CHECK(occurrences(r.err, "warning:") == 5);
    CHECK(r.err.find("error") == std::string::npos);

    const std::map<std::string, int> count = attempts(dir);
    CHECK(static_cast<int>(count.size()) <= frames);  // frames alike are rendered once
    for (const auto& entry : count) {
      const std::string& pov = entry.first;  // a plain name: CAPTURE cannot take a binding
      const int n = entry.second;
      CAPTURE(pov);
      const int expected = pov < std::string("frame_00005.pov") ? 2 : 1;
      CHECK(n == expected);
    }
  }

  TEST_CASE("a POV-Ray that hangs printing nothing is stopped and the frame rendered again") {
    for (const char* tool : {"povray", "ffmpeg"}) test::require_program(tool);
    test::TempDir dir;
    // The first attempt at frame 0 prints its banner, then spins for good, deaf to SIGTERM, as POV-Ray
    // 3.7 does when its render thread fails to start; every other attempt is the real POV-Ray's.
    const std::string path = stand_in(dir,
                                      "if [ \"$in\" = frame_00000.pov ] && [ ! -e \"$marks/hung\" ]; then\n"
                                      "  : > \"$marks/hung\"\n"
                                      "  echo 'Persistence of Vision(tm) Ray Tracer Version 3.7' >&2\n"
                                      "  trap '' TERM\n"
                                      "  while :; do :; done\n"
                                      "fi\n"
                                      "exec " +
                                          quoted(real_povray()) + " \"$@\"");
    const test::CommandResult r = run_export(dir, "BSIM_POVRAY_STALL_SECONDS=4 " + path, "--jobs 2");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK(r.err.find("billiards-export: warning: frame 0 (frames/frame_00000.pov): povray failed (printed nothing "
                     "for 4 s: it hangs); retrying (attempt 2 of 3)") != std::string::npos);
    const fs::path out = dir.path / "out";
    CHECK(pictures(out / "frames") == povs(out / "frames"));
    CHECK(test::leftovers(out).empty());
    CHECK(attempts(dir).at("frame_00000.pov") == 2);
  }

  TEST_CASE("a frame that fails three times ends the run after exactly three attempts") {
    test::TempDir dir;
    const std::string path = stand_in(dir, "echo 'Persistence of Vision(tm) Ray Tracer Version 3.7' >&2\necho '" +
                                               std::string(kTimeout) + "' >&2\nexit 1");
    test::CommandResult r = run_export(dir, path, "--jobs 1");
    CHECK(r.exit_code == 1);
    const std::map<std::string, int> one = attempts(dir);
    CHECK(one == std::map<std::string, int>{{"frame_00000.pov", 3}});
    const std::string warning = "billiards-export: warning: frame 0 (frames/frame_00000.pov): povray failed (" +
                                std::string(kTimeout) + "); retrying (attempt ";
    CHECK(r.err.find(warning + "2 of 3)") != std::string::npos);
    CHECK(r.err.find(warning + "3 of 3)") != std::string::npos);
    CHECK(occurrences(r.err, "warning:") == 2);
    CHECK(r.err.find("billiards-export: error: frame 0 (frames/frame_00000.pov) failed to render (3 attempts): " +
                     std::string(kTimeout) + "\n") != std::string::npos);
    CHECK_FALSE(fs::exists(dir.path / "out"));  // a failed run leaves no output

    // Several at once: no frame gets a fourth attempt, and one that got its third ends the run.
    fs::remove(dir.path / "attempts.txt");
    r = run_export(dir, path, "--jobs 3");
    CHECK(r.exit_code == 1);
    CHECK(r.err.find("failed to render (3 attempts): " + std::string(kTimeout)) != std::string::npos);
    CHECK(r.err.find("attempt 4") == std::string::npos);
    const std::map<std::string, int> several = attempts(dir);
    int most = 0;
    for (const auto& entry : several) most = std::max(most, entry.second);
    CHECK(most == 3);
    CHECK_FALSE(fs::exists(dir.path / "out"));
  }

  TEST_CASE("a parse error is not retried and is reported at the frame's file and line") {
    test::TempDir dir;
    // Frame 1 gets a line POV-Ray cannot parse, then the real POV-Ray reads it.
    const std::string path = stand_in(dir,
                                      "if [ \"$in\" = frame_00001.pov ]; then\n"
                                      "  printf '\\nsphere { 0, 1 pigment { rgb Undeclared_Colour } }\\n' >> \"$in\"\n"
                                      "  cp \"$in\" ../../broken.pov\n"
                                      "fi\n"
                                      "exec " +
                                          quoted(real_povray()) + " \"$@\"");
    const test::CommandResult r = run_export(dir, path, "--jobs 1");
    CHECK(r.exit_code == 1);
    CHECK(attempts(dir)["frame_00001.pov"] == 1);
    // Named where the frame goes in the output directory (the run failed, so it is not there).
    const fs::path pov = dir.path / "out" / "frames" / "frame_00001.pov";
    const std::string text = test::require_file(dir.path / "broken.pov");
    const auto line = std::count(text.begin(), text.end(), '\n');  // the broken line is the last
    const std::string where = pov.string() + ":" + std::to_string(line) + ": error: povray: Parse Error: ";
    const auto at = r.err.find(where);
    REQUIRE_MESSAGE(at != std::string::npos, r.err);
    CHECK(r.err.find("'Undeclared_Colour'", at) < r.err.find('\n', at));
    CHECK(r.err.find("billiards-export: error: frame 1 (frames/frame_00001.pov) failed to render") !=
          std::string::npos);
    CHECK(r.err.find("warning") == std::string::npos);
    CHECK_FALSE(fs::exists(dir.path / "out"));
  }

  TEST_CASE("Ctrl-C that kills POV-Ray too stops the run without retrying") {
    test::TempDir dir;
    // Each stand-in starts its picture, then hangs until the interrupt kills it.
    const std::string path = stand_in(dir, "touch \"$out\"\nexec sleep 60");
    const fs::path out = dir.path / "out";
    const std::string scene = dir.file("tiny.scn", kScene);
    // setsid: the exporter leads its own process group, so the interrupt reaches it and its
    // renderers at once, as Ctrl-C on a terminal does.
    const std::string command = path + " BSIM_CACHE_DIR=" + quoted((dir.path / "store").string()) + " setsid " +
                                quoted(test::bin("billiards-export")) + " " + quoted(scene) + " -o " +
                                quoted(out.string()) + " " + kOptions +
                                " --jobs 2 & pid=$!; i=0; "
                                "while [ -z \"$(find " +
                                quoted(dir.path.string()) +
                                " -name '*.tmp.hdr' 2>/dev/null)\" ] && [ $i -lt 600 ]; do "
                                "sleep 0.05; i=$((i+1)); done; kill -INT -$pid; wait $pid; echo \"status $?\"";
    const test::CommandResult r = test::run_command(command);
    CHECK(r.out.find("status 0") == std::string::npos);
    CHECK(r.err.find("retrying") == std::string::npos);
    for (const auto& entry : attempts(dir)) CHECK(entry.second == 1);
    CHECK_FALSE(fs::exists(out));  // an interrupted run leaves no output
  }
}
