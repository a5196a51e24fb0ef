// Progress as a CI log shows it: both programs run with standard error captured (not a terminal)
// print whole progress lines with frames done of the total, up to the whole, and none with --quiet,
// which still lets warnings through.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "fixtures.h"
#include "frames.h"
#include "support.h"

using namespace bsim;
using bsim::test::quoted;
namespace fs = std::filesystem;

namespace {

/// The cue ball rolling slowly for a couple of seconds: a handful of frames at 4 fps.
std::string slow_shot(int cue_heading = 0) {
  return "cue 0 " + std::to_string(cue_heading) + "\nball 0 -0.3 0 0.028575  0.3 0 0  1 0 0 0\n" +
         test::fixtures::kHoverCamera;
}

struct ProgressLine {
  int done = 0;
  int total = 0;
};

/// The plain progress lines of `program` for `stage` ("rendering") in `err`, in order; fails the test
/// case on a line that starts like one but does not read like one.
std::vector<ProgressLine> progress_lines(const std::string& err, const std::string& program, const std::string& stage) {
  const std::string start = program + ": " + stage + ": ";
  const std::regex line_form(start +
                             R"(([0-9]+)/([0-9]+) frames \(([0-9]+)%\), ([0-9hms]+) elapsed, ETA ([0-9hms]+|unknown))");
  std::vector<ProgressLine> lines;
  std::istringstream in(err);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(start, 0) != 0) continue;
    std::smatch m;
    CHECK_MESSAGE(std::regex_match(line, m, line_form), line);
    if (m.empty()) continue;
    lines.push_back({std::stoi(m[1]), std::stoi(m[2])});
    CHECK(std::stoi(m[3]) == lines.back().done * 100 / lines.back().total);
  }
  return lines;
}

/// Each line reports more frames than the one before, all of the same total, the last all of them.
void check_counts_up_to(const std::vector<ProgressLine>& lines, int total) {
  REQUIRE_FALSE(lines.empty());
  for (std::size_t i = 0; i < lines.size(); ++i) {
    CHECK(lines[i].total == total);
    if (i > 0) CHECK(lines[i].done > lines[i - 1].done);
  }
  CHECK(lines.back().done == total);
}

double json_duration(const fs::path& events) {
  std::smatch m;
  const std::string json = test::require_file(events);
  REQUIRE(std::regex_search(json, m, std::regex("\"duration\": ?([0-9.]+)")));
  return std::stod(m[1]);
}

bool mentions_progress(const std::string& err) { return err.find(" frames (") != std::string::npos; }

}  // namespace

TEST_SUITE("progress runs") {
  TEST_CASE("the export prints plain progress lines for rendering and encoding off a terminal, none with --quiet") {
    for (const char* tool : {"povray", "ffmpeg"}) test::require_program(tool);
    test::TempDir dir;
    const std::string scene = dir.file("slow.scn", slow_shot());
    const std::string options = " --size 64x36 --quality draft --fps 4";
    const fs::path out = dir.path / "out";
    test::CommandResult r = test::run_command(quoted(test::bin("billiards-export")) + " " + quoted(scene) + " -o " +
                                              quoted(out.string()) + options);
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    INFO(r.err);
    CHECK(r.err.find('\r') == std::string::npos);
    CHECK(r.err.find("\033[") == std::string::npos);
    const double duration = json_duration(out / "events.json");
    const int frames = frame_count(duration, 4);
    REQUIRE(frames >= 4);
    const auto rendering = progress_lines(r.err, "billiards-export", "rendering");
    check_counts_up_to(rendering, frames);
    CHECK(rendering.size() >= 2);  // a line for every tenth of the frames, not only the last
    const auto encoding = progress_lines(r.err, "billiards-export", "encoding");
    check_counts_up_to(encoding, static_cast<int>(std::ceil(duration * 4 - 1e-9)));
    CHECK(r.err.find("billiards-export: rendering:") < r.err.find("billiards-export: encoding:"));

    // --quiet: the same run (a warning in the scene) with no progress, the warning still there.
    const std::string warned = dir.file("warned.scn", slow_shot(10));
    r = test::run_command(quoted(test::bin("billiards-export")) + " " + quoted(warned) + " -o " +
                          quoted((dir.path / "quiet").string()) + options + " --quiet");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK_MESSAGE(std::regex_search(r.err, std::regex("warned\\.scn:[0-9]+:[0-9]+: warning: ")), r.err);
    CHECK_MESSAGE(!mentions_progress(r.err), r.err);
    CHECK(r.err.find("rendering") == std::string::npos);
    CHECK(r.err.find("encoding") == std::string::npos);
    CHECK_MESSAGE(r.err.find("wrote") == std::string::npos, r.err);  // success is the exit status alone
    CHECK(fs::exists(dir.path / "quiet" / "movie.mp4"));
  }

  TEST_CASE("the animatic prints plain progress lines off a terminal, none with --quiet") {
    test::require_program("ffmpeg");
    test::TempDir dir;
    const std::string scene = dir.file("slow.scn", slow_shot());
    const std::string movie = (dir.path / "a.mp4").string();
    const std::string preview = quoted(test::bin("billiards-preview")) + " ";
    test::CommandResult r =
        test::run_command(preview + quoted(scene) + " --movie " + quoted(movie) + " --size 64x36 --fps 8");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    INFO(r.err);
    CHECK(r.err.find('\r') == std::string::npos);
    // As many frames as the export would render at this rate: frame k shows t = k / fps.
    const std::string events = (dir.path / "events").string();
    const test::CommandResult e = test::run_command(quoted(test::bin("billiards-export")) + " " + quoted(scene) +
                                                    " --events-only -o " + quoted(events));
    REQUIRE_MESSAGE(e.exit_code == 0, e.err);
    const int frames = frame_count(json_duration(fs::path(events) / "events.json"), 8);
    const auto lines = progress_lines(r.err, "billiards-preview", "animatic");
    check_counts_up_to(lines, frames);
    CHECK(lines.size() >= 2);

    const std::string warned = dir.file("warned.scn", slow_shot(10));
    r = test::run_command(preview + quoted(warned) + " --movie " + quoted(movie) + " --size 64x36 --fps 8 --quiet");
    REQUIRE_MESSAGE(r.exit_code == 0, r.err);
    CHECK_MESSAGE(std::regex_search(r.err, std::regex("warned\\.scn:[0-9]+:[0-9]+: warning: ")), r.err);
    CHECK_MESSAGE(!mentions_progress(r.err), r.err);
    CHECK(r.err.find("animatic:") == std::string::npos);
    CHECK_MESSAGE(r.err.find("wrote") == std::string::npos, r.err);
    CHECK(fs::exists(movie));
  }
}
