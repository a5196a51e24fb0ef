// bench_preview: how long billiards-preview takes as a user runs it, whole processes timed on the wall
// clock (starting the program, loading Mesa, parsing, simulating, drawing, writing the file).
//   bench_preview              10 snapshot processes at 1280x720 and one animatic, on the built-in break
//   bench_preview --runs N     N snapshot processes
//   bench_preview --no-movie   snapshots only
// The binary is the billiards-preview beside this one. Figures depend on the machine and its load,
// so the load average is printed with them.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "builtin_scene.h"
#include "files.h"
#include "frames.h"
#include "shot.h"

namespace {

using Clock = std::chrono::steady_clock;

struct Run {
  int status = -1;  ///< exit status, -1 when it did not exit normally
  double wall = 0;  ///< s
  double cpu = 0;   ///< s, user + system of the process and the children it waited for (ffmpeg)
};

// fork/exec rather than system(): no shell in the timing, and wait4 gives the process's CPU time.
// The program's messages go to `log`, shown only when it fails.
Run run(const std::vector<std::string>& args, const std::string& log) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  Run result;
  const auto t0 = Clock::now();
  const pid_t pid = fork();
  if (pid < 0) return result;
  if (pid == 0) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd >= 0) {
      dup2(fd, STDOUT_FILENO);
      dup2(fd, STDERR_FILENO);
      close(fd);
    }
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid) return result;
  result.wall = std::chrono::duration<double>(Clock::now() - t0).count();
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
  };
  result.cpu = seconds(usage.ru_utime) + seconds(usage.ru_stime);
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  double one = 0, five = 0;
  if (!(in >> one >> five)) return "unknown";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.2f (1 min), %.2f (5 min)", one, five);
  return buffer;
}

/// The snapshot process at `at` seconds, `runs` times after one untimed run (files into the page
/// cache): prints the timings; false when a run fails.
bool time_snapshots(const std::string& preview, const char* at, int runs, const std::filesystem::path& dir,
                    const std::string& log) {
  std::vector<double> wall, cpu;
  bool ok = true;
  const std::string png = (dir / "snapshot.png").string();
  run({preview, "--at", at, "--size", "1280x720", "-o", png}, log);
  for (int k = 0; k < runs; ++k) {
    const Run r = run({preview, "--at", at, "--size", "1280x720", "-o", png}, log);
    if (r.status != 0) {
      std::fprintf(stderr, "bench_preview: billiards-preview --at %s failed (status %d):\n%s", at, r.status,
                   bsim::test::read_file(log).value_or("").c_str());
      ok = false;
      break;
    }
    wall.push_back(r.wall);
    cpu.push_back(r.cpu);
  }
  if (!wall.empty())
    std::printf(
        "snapshot process (--at %s -o FILE.png, %zu runs): wall median %.3f s, min %.3f s, max %.3f s; "
        "CPU median %.3f s\n",
        at, wall.size(), median(wall), *std::min_element(wall.begin(), wall.end()),
        *std::max_element(wall.begin(), wall.end()), median(cpu));
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 10;
  bool movie = true;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--runs" && k + 1 < argc && std::atoi(argv[k + 1]) > 0) {
      runs = std::atoi(argv[++k]);
    } else if (arg == "--no-movie") {
      movie = false;
    } else {
      std::fprintf(stderr, "usage: bench_preview [--runs N] [--no-movie]\n");
      return 2;
    }
  }
  const std::filesystem::path self = std::filesystem::canonical("/proc/self/exe");
  const std::string preview = (self.parent_path() / "billiards-preview").string();
  if (access(preview.c_str(), X_OK) != 0) {
    std::fprintf(stderr, "bench_preview: no billiards-preview beside this program (%s)\n", preview.c_str());
    return 1;
  }

  // The middle of the built-in break: the balls spread over the table, the stick gone.
  const bsim::ShotResult shot = bsim::load_shot(bsim::builtin_scene_text(), bsim::kBuiltinSceneName);
  if (!shot.scripted()) {
    std::fprintf(stderr, "bench_preview: the built-in break does not load\n");
    return 1;
  }
  const double duration = shot.shot->timeline.duration();
  const int frames = bsim::frame_count(duration, 30);
  char at[32];
  std::snprintf(at, sizeof at, "%.3f", duration / 2);

  std::string pattern = (std::filesystem::temp_directory_path() / "bench_preview.XXXXXX").string();
  if (!mkdtemp(pattern.data())) {
    std::fprintf(stderr, "bench_preview: cannot make a temporary directory\n");
    return 1;
  }
  const std::filesystem::path dir = pattern;
  const std::string log = (dir / "messages.txt").string();
  std::printf("billiards-preview on the built-in break (%.2f s, %zu events), 1280x720; load average %s\n", duration,
              shot.shot->timeline.events().size(), load_average().c_str());

  int status = time_snapshots(preview, at, runs, dir, log) ? 0 : 1;

  if (movie) {
    const Run r = run({preview, "--movie", (dir / "break.mp4").string()}, log);
    if (r.status != 0) {
      std::fprintf(stderr, "bench_preview: billiards-preview --movie failed (status %d):\n%s", r.status,
                   bsim::test::read_file(log).value_or("").c_str());
      status = 1;
    } else {
      std::printf(
          "animatic (--movie FILE.mp4, %d frames at 30 fps with sound): wall %.2f s, CPU %.2f s with ffmpeg "
          "(%.1f ms of wall time a frame)\n",
          frames, r.wall, r.cpu, 1e3 * r.wall / frames);
    }
  }
  std::error_code ignored;
  std::filesystem::remove_all(dir, ignored);
  return status;
}
