// --farm slurm without a cluster: the chunking, the command line, what is staged and handed to
// sbatch (a stand-in that records its arguments), and the task and movie commands run by hand, whose
// movie must equal a local render's byte for byte. The real one-node Slurm test is
// tests/farm/one_node_slurm.sh.
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "export_options.h"
#include "farm_files.h"
#include "farm_slurm.h"
#include "files.h"
#include "movie_export.h"
#include "output_stage.h"
#include "pov_frame.h"
#include "run_summary.h"
#include "shot.h"
#include "shots.h"
#include "support.h"

namespace fs = std::filesystem;

namespace {

std::string sh(const std::string& s) { return bsim::test::quoted(s); }

/// A 5-second shot: 10 frames at 2 fps, 32x18, draft; the ball rests from frame 8 on, under a still
/// camera, so frame 9's .pov is frame 8's (each has its own grain: frame 9 is no copy of frame 8).
const char* const kScene =
    "cue 0 0\n"
    "ball 0 -0.3 0 0.028575  0.15 0 0  1 0 0 0\n"
    "camera\nevent 0 0 0 hover -1.5 -1.2 1.2  0 0 0\nendcamera\n";
const char* const kOptions = " --size 32x18 --fps 2 --quality draft --quiet";

/// A directory with the scene and a stand-in sbatch that records its arguments in sbatch.args and
/// hands out job ids 41, 42, ...; `refuse` makes it turn every job down.
struct Farm {
  bsim::test::TempDir dir;
  std::string scene = dir.file("shot.scn", kScene);
  fs::path out = dir.path / "out";

  explicit Farm(bool refuse = false) {
    const std::string sbatch = dir.file(
        "bin/sbatch", "#!/bin/sh\necho \"$*\" >> " + sh((dir.path / "sbatch.args").string()) + "\n" +
                          (refuse ? "echo 'sbatch: error: Invalid partition name specified' >&2; exit 1\n"
                                  : "case \"$*\" in *--test-only*) echo 'sbatch: Job 7 to start'; exit 0;; esac\n"
                                    "n=$(grep -vc test-only " +
                                        sh((dir.path / "sbatch.args").string()) + ")\necho $((40 + n))\n"));
    fs::permissions(sbatch, fs::perms::owner_all);
  }
  std::string store = "off";        ///< BSIM_CACHE_DIR
  fs::path tmp = dir.path / "tmp";  ///< TMPDIR, where the captured output of sbatch goes
  bsim::test::CommandResult run(const std::string& arguments, bool with_sbatch = true) const {
    std::error_code ignored;
    fs::create_directories(tmp, ignored);
    const std::string path = with_sbatch ? "PATH=" + sh((dir.path / "bin").string()) + ":\"$PATH\" " : "";
    return bsim::test::run_command(path + "BSIM_CACHE_DIR=" + sh(store) + " TMPDIR=" + sh(tmp.string()) + " " +
                                   sh(bsim::test::bin("billiards-export")) + " " + arguments);
  }
  bsim::test::CommandResult submit(const std::string& extra = "") const {
    return run(sh(scene) + " --farm slurm -o " + sh(out.string()) + kOptions + extra);
  }
  std::string sbatch_args() const { return bsim::test::read_file(dir.path / "sbatch.args").value_or(""); }
};

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// Sets an environment variable of this process for a scope.
class EnvGuard {
 public:
  EnvGuard(const char* name, const std::string& value) : name_(name) {
    if (const char* was = std::getenv(name)) was_ = was;
    ::setenv(name, value.c_str(), 1);
  }
  ~EnvGuard() {
    if (was_)
      ::setenv(name_, was_->c_str(), 1);
    else
      ::unsetenv(name_);
  }
  EnvGuard(const EnvGuard&) = delete;
  EnvGuard& operator=(const EnvGuard&) = delete;

 private:
  const char* name_;
  std::optional<std::string> was_;
};

}  // namespace

TEST_SUITE("rendering on a Slurm cluster") {
  TEST_CASE("a task gets about three minutes of frames, and chunks never span a frame already done") {
    CHECK(bsim::default_farm_chunk(1280, 720, bsim::Quality::final) == 20);  // 9 s a frame (README's table)
    CHECK(bsim::default_farm_chunk(640, 360, bsim::Quality::draft) == 96);
    CHECK(bsim::default_farm_chunk(16384, 16384, bsim::Quality::final) == 1);
    using Chunks = std::vector<std::pair<int, int>>;
    CHECK(bsim::farm_chunks({0, 1, 2, 3, 4, 7, 8, 10}, 3) == Chunks{{0, 2}, {3, 4}, {7, 8}, {10, 10}});
    CHECK(bsim::farm_chunks({}, 3).empty());
    CHECK(bsim::farm_chunks({5, 6, 7}, 100) == Chunks{{5, 7}});
    std::vector<int> all(300);
    for (int k = 0; k < 300; ++k) all[k] = k;
    CHECK(bsim::farm_chunks(all, 196) == Chunks{{0, 149}, {150, 299}});  // two halves, not 196 and 104
  }

  TEST_CASE("the command line: --farm's modes, --chunk and --sbatch-option go with --farm slurm") {
    bsim::ExportOptions o;
    std::string message;
    REQUIRE(bsim::parse_export_options({"s.scn", "--farm", "slurm", "--chunk", "5", "--sbatch-option=--time=10",
                                        "--sbatch-option", "--partition=short"},
                                       o, message) == bsim::CommandLineOutcome::run);
    CHECK(o.farm == bsim::FarmMode::slurm);
    CHECK(o.chunk == 5);
    CHECK(o.sbatch_options == std::vector<std::string>{"--time=10", "--partition=short"});
    REQUIRE(bsim::parse_export_options({"out/x", "--farm", "render", "--frames", "3-9"}, o, message) ==
            bsim::CommandLineOutcome::run);
    CHECK(o.first_frame == 3);
    CHECK(o.last_frame == 9);
    std::string help;
    REQUIRE(bsim::parse_export_options({"--help"}, o, help) == bsim::CommandLineOutcome::exit_success);
    for (const char* line : {"--farm slurm", "--chunk N", "--sbatch-option ARG", "DIR --farm status",
                             "DIR --farm assemble", "DIR --farm render --frames A-B"})
      CHECK_MESSAGE(has(help, line), line);
    for (const std::vector<std::string>& bad : {std::vector<std::string>{"--chunk", "5"},
                                                {"--farm", "cloud"},
                                                {"--farm", "status"},
                                                {"s.scn", "--farm", "slurm", "--no-render"},
                                                {"s.scn", "--farm", "slurm", "--chunk", "0"},
                                                {"d", "--farm", "render", "--frames", "9-3"},
                                                {"s.scn", "--frames", "1-2"}}) {
      CHECK_MESSAGE(bsim::parse_export_options(bad, o, message) == bsim::CommandLineOutcome::exit_usage, bad[1]);
      CHECK(!message.empty());
    }
  }

  TEST_CASE("no sbatch, or sbatch refusing the jobs: a clear error and no output directory") {
    Farm farm;
    const bsim::test::CommandResult missing =
        bsim::test::run_command("PATH=/nonexistent " + sh(bsim::test::bin("billiards-export")) + " " + sh(farm.scene) +
                                " --farm slurm -o " + sh(farm.out.string()));
    CHECK(missing.exit_code == 1);
    CHECK(has(missing.err, "sbatch is not on PATH"));
    CHECK_FALSE(fs::exists(farm.out));

    Farm refusing(true);
    const bsim::test::CommandResult refused = refusing.submit(" --sbatch-option=--partition=nowhere");
    CHECK(refused.exit_code == 1);
    CHECK(has(refused.err, "sbatch would not take the jobs: sbatch: error: Invalid partition name specified"));
    CHECK(has(refusing.sbatch_args(), "--test-only"));
    CHECK(has(refusing.sbatch_args(), "--partition=nowhere"));
    CHECK_FALSE(fs::exists(refusing.out));
    CHECK(bsim::test::leftovers(refusing.dir.path).empty());

    // sbatch's output is captured in $TMPDIR: one that cannot be written is named.
    Farm no_tmp;
    no_tmp.tmp = no_tmp.dir.path / "tmp-file";
    REQUIRE(bsim::test::write_file(no_tmp.tmp, "not a directory"));
    const bsim::test::CommandResult unwritable =
        no_tmp.run("--farm slurm -o " + sh(no_tmp.out.string()) + " " + sh(no_tmp.scene) + kOptions);
    CHECK(unwritable.exit_code == 1);
    CHECK(has(unwritable.err, "cannot create a temporary file in " + no_tmp.tmp.string()));
    CHECK_FALSE(fs::exists(no_tmp.out));
  }

  TEST_CASE("submitted, the tasks and the movie job run by hand make the local render's movie") {
    for (const char* tool : {"povray", "ffmpeg"}) bsim::test::require_program(tool);
    Farm farm;
    const bsim::test::CommandResult submitted = farm.submit(" --chunk 3 --sbatch-option=--time=5");
    REQUIRE_MESSAGE(submitted.exit_code == 0, submitted.err);
    // Frame 9 traces frame 8's .pov, but it gets its own grain: no frame is a copy of another.
    CHECK(has(submitted.out, "submitted job 41: 4 tasks render 10 of 10 frames, up to 3 a task\n"));
    CHECK(has(submitted.out, "submitted job 42: checks every frame"));
    const std::string args = farm.sbatch_args();
    CHECK(has(args, "--array=0-3"));
    CHECK(has(args, "--dependency=afterany:41"));
    CHECK(has(args, "--time=5"));
    for (const char* file : {"farm/farm.conf", "farm/chunks.txt", "farm/copies.txt", "farm/task.sh", "farm/movie.sh",
                             "farm/billiards-export", "frames/frame_00002.pov", "soundtrack.wav"})
      CHECK_MESSAGE(fs::exists(farm.out / file), file);
    CHECK(bsim::test::read_file(farm.out / "farm/chunks.txt") == "0-2\n3-5\n6-7\n8-9\n");
    CHECK(bsim::test::read_file(farm.out / "farm/copies.txt") == "");
    CHECK(has(bsim::test::read_file(farm.out / "farm/farm.conf").value_or(""), "frames_job=41\nmovie_job=42\n"));

    const std::string dir = sh(farm.out.string());
    const bsim::test::CommandResult task = farm.run(dir + " --farm render --frames 0-5", false);
    CHECK_MESSAGE(task.exit_code == 0, task.err);
    const bsim::test::CommandResult early = farm.run(dir + " --farm assemble", false);
    CHECK(early.exit_code == 1);
    CHECK(has(early.err,
              "frame 6 (frames/frame_00006.png) was not rendered; see its task's log, "
              "farm/logs/frames-41_2.log"));
    CHECK(has(early.err,
              "frame 9 (frames/frame_00009.png) was not rendered; see its task's log, farm/logs/frames-41_3.log"));
    CHECK(has(early.err, "no movie: 4 of 10 frames are missing"));
    CHECK_FALSE(fs::exists(farm.out / "movie.mp4"));
    const bsim::test::CommandResult status = farm.run(dir + " --farm status", false);
    CHECK(has(status.out, "6 of 10 frames rendered"));

    // Submitted again, only the missing frames are rendered; frame 9 from frame 8's trace, with its own
    // grain.
    const bsim::test::CommandResult again = farm.submit();
    REQUIRE_MESSAGE(again.exit_code == 0, again.err);
    CHECK(has(again.out, "1 task render 4 of 10 frames"));
    CHECK(bsim::test::read_file(farm.out / "farm/chunks.txt") == "6-9\n");
    CHECK(farm.run(dir + " --farm render --frames 6-9", false).exit_code == 0);
    const std::string nine = bsim::test::require_file(farm.out / "frames/frame_00009.png");
    CHECK(nine != bsim::test::require_file(farm.out / "frames/frame_00008.png"));
    CHECK(has(farm.run(dir + " --farm status", false).out, "10 of 10 frames rendered"));
    const bsim::test::CommandResult movie = farm.run(dir + " --farm assemble", false);
    REQUIRE_MESSAGE(movie.exit_code == 0, movie.err);

    const bsim::test::CommandResult local =
        farm.run(sh(farm.scene) + " -o " + sh((farm.dir.path / "local").string()) + kOptions, false);
    REQUIRE_MESSAGE(local.exit_code == 0, local.err);
    CHECK(bsim::test::require_file(farm.out / "movie.mp4") ==
          bsim::test::require_file(farm.dir.path / "local/movie.mp4"));
    CHECK(bsim::test::leftovers(farm.out).empty());
    CHECK(fs::is_empty(farm.tmp));

    // A frame gone: it alone is rendered again, now traced whole, and comes out the same.
    fs::remove(farm.out / "frames/frame_00009.png");
    const bsim::test::CommandResult lost = farm.submit();
    REQUIRE_MESSAGE(lost.exit_code == 0, lost.err);
    CHECK(has(lost.out, "1 task render 1 of 10 frames"));
    CHECK(farm.run(dir + " --farm render --frames 9-9", false).exit_code == 0);
    CHECK(bsim::test::require_file(farm.out / "frames/frame_00009.png") == nine);

    // The movie job keeps the frames in the frame store, and a submission takes what the store has.
    farm.store = (farm.dir.path / "store").string();
    REQUIRE(farm.run(dir + " --farm assemble", false).exit_code == 0);
    farm.out = farm.dir.path / "elsewhere";
    const bsim::test::CommandResult stored = farm.submit();
    REQUIRE_MESSAGE(stored.exit_code == 0, stored.err);
    CHECK(has(stored.out, "all 10 frames are rendered already"));
    CHECK(fs::exists(farm.out / "frames/frame_00009.png"));
  }

  TEST_CASE("the jobs run the billiards-export installed on the node when it is this version, else the copy") {
    Farm farm;
    REQUIRE(farm.submit(" --chunk 3").exit_code == 0);  // chunks 0-2, 3-5, 6-7, 8-9; task 1 renders 3-5
    const std::string dir = farm.out.string();
    // A stand-in for the installed program: answers --version with `version`, records any other run.
    const fs::path record = farm.dir.path / "installed.args";
    const auto install = [&](const std::string& version) {
      const std::string program =
          farm.dir.file("node/billiards-export", "#!/bin/sh\n[ \"$1\" = --version ] && { echo '" + version +
                                                     "'; exit 0; }\necho \"$*\" >> " + sh(record.string()) + "\n");
      fs::permissions(program, fs::perms::owner_all);
    };
    const auto job = [&](const std::string& script) {
      return bsim::test::run_command("PATH=" + sh((farm.dir.path / "node").string()) +
                                     ":\"$PATH\" SLURM_ARRAY_TASK_ID=1 BSIM_CACHE_DIR=off sh " +
                                     sh(dir + "/farm/" + script));
    };
    // The installed program of this version (the Debian package): the tasks and the movie job run it.
    install(std::string("billiards-export ") + BSIM_VERSION);
    const bsim::test::CommandResult task = job("task.sh");
    CHECK_MESSAGE(task.exit_code == 0, task.err);
    CHECK(has(task.err, "running " + (farm.dir.path / "node/billiards-export").string()));
    CHECK(job("movie.sh").exit_code == 0);
    CHECK(bsim::test::read_file(record) == dir + " --farm render --frames 3-5\n" + dir + " --farm assemble\n");
    // Another version installed: the copy submitted with the run, which finds the frames missing.
    fs::remove(record);
    install("billiards-export 0.0.1");
    const bsim::test::CommandResult movie = job("movie.sh");
    CHECK(movie.exit_code == 1);
    CHECK(has(movie.err, "running " + dir + "/farm/billiards-export"));
    CHECK(has(movie.err, "no movie: 10 of 10 frames are missing"));
    CHECK_FALSE(fs::exists(record));
  }

  TEST_CASE("a submission keys and plans the frames as written, computing none of them again") {
    Farm farm;
    // This process finds the stand-in sbatch, and no store serves a frame.
    const char* path_now = std::getenv("PATH");
    const EnvGuard path("PATH", (farm.dir.path / "bin").string() + ":" + (path_now ? path_now : "/usr/bin:/bin"));
    const EnvGuard store("BSIM_CACHE_DIR", "off");
    const std::unique_ptr<bsim::Shot> shot = bsim::test::load_scene(kScene, "shot");
    bsim::ExportOptions options;
    options.width = 32;
    options.height = 18;
    options.fps = 2;
    options.quality = bsim::Quality::draft;
    options.chunk = 3;
    options.farm = bsim::FarmMode::slurm;
    std::string error;
    bsim::SlurmSubmission submission;
    REQUIRE_MESSAGE(submission.prepare(options, farm.out.string(), error), error);
    bsim::OutputStage stage;
    REQUIRE_MESSAGE(stage.open(farm.out.string(), error), error);
    bsim::ExportOptions staged = options;
    staged.no_render = true;  // as billiards-export stages a submission
    bsim::StagedFrames frames;
    bsim::RunSummary summary;
    REQUIRE_MESSAGE(bsim::write_frames_and_sound(*shot, staged, stage, frames, summary, error), error);
    const long before = bsim::frame_contents_computed();
    REQUIRE_MESSAGE(submission.stage(*shot, options, stage, frames, error), error);
    CHECK(bsim::frame_contents_computed() == before);
    // Each chunk's partial frames as planned from each frame computed anew.
    CHECK(bsim::test::read_file(stage.path(bsim::farm::kChunks)) == "0-2\n3-5\n6-7\n8-9\n");
    std::map<int, bsim::farm::PartialPlan> expected;
    for (const auto& [first, last] : std::vector<std::pair<int, int>>{{0, 2}, {3, 5}, {6, 7}, {8, 9}}) {
      std::vector<bsim::FrameJob> jobs;
      for (int k = first; k <= last; ++k) jobs.push_back({k, 0});
      bsim::plan_partial_frames(*shot, options, jobs);
      for (const bsim::FrameJob& job : jobs)
        if (job.reference >= 0) expected[job.frame] = {job.reference, job.rects};
    }
    CHECK_FALSE(expected.empty());
    CHECK(bsim::test::read_file(stage.path(bsim::farm::kPartial)) == bsim::farm::partial_text(expected));
  }

  TEST_CASE("farm/partial.txt keeps each partial frame's reference and rectangles") {
    // A frame laid over an earlier one of its chunk reads back as it was written.
    const std::map<int, bsim::farm::PartialPlan> plans = {{5, {4, {{0, 32, 64, 96}, {128, 0, 160, 32}}}}, {6, {5, {}}}};
    bsim::test::TempDir dir;
    std::filesystem::create_directories(dir.path / "farm");
    REQUIRE(bsim::test::write_file(dir.path / bsim::farm::kPartial, bsim::farm::partial_text(plans)));
    const std::map<int, bsim::farm::PartialPlan> read = bsim::farm::read_partial(dir.path.string());
    REQUIRE(read.size() == 2);
    CHECK(read.at(5).reference == 4);
    CHECK(read.at(5).rects == plans.at(5).rects);
    CHECK(read.at(6).rects.empty());
    CHECK(bsim::farm::read_partial((dir.path / "none").string()).empty());  // none: every frame whole
  }
}
