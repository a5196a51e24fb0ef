#pragma once
// The one way both programs run POV-Ray and ffmpeg: finding them, starting them with their output in
// a log file (and, for a stream of frames, a pipe to their standard input), waiting for them, and
// Ctrl-C handling that lets a run stop its children and clean up before it dies.
#include <sys/types.h>

#include <chrono>
#include <string>
#include <vector>

namespace bsim {

/// Full path of `name` on PATH (or `name` itself when it holds a '/' and is executable); empty if none.
std::string find_program(const std::string& name);

/// Starts argv (argv[0] a full path) in directory `cwd`, stdout and stderr into `log_path`, stdin from
/// /dev/null or, when `stdin_pipe` is given, from a pipe whose writing end (close-on-exec) is stored
/// there. Returns the child's pid, or -1 with `error` set.
pid_t start_process(const std::vector<std::string>& argv, const std::string& cwd, const std::string& log_path,
                    std::string& error, int* stdin_pipe = nullptr);

/// Stops a child (SIGTERM, then SIGKILL if it lingers for 5 s) and reaps it.
void stop_process(pid_t pid);

/// Waits for a child to finish. Returns its pid and sets `success` (exit status 0) and, when given,
/// `signal` (the signal that killed it, else 0), or returns -1 when the wait was cut short by Ctrl-C
/// (InterruptGuard::interrupted()).
pid_t wait_any(bool& success, int* signal = nullptr);
/// The same, giving up after `timeout`: then it returns 0, so the caller can report progress.
pid_t wait_any(bool& success, std::chrono::milliseconds timeout, int* signal = nullptr);

/// Waits for one child; true when it exited with status 0.
bool wait_for(pid_t pid);

/// The last error POV-Ray or ffmpeg wrote: its line naming an error with the lines continuing it,
/// else the last non-empty line of the log.
std::string error_from_log(const std::string& log_text);

/// While one lives, SIGINT and SIGTERM only set a flag, so a long render can stop its children
/// and delete half-written files; then finish() re-raises the signal with its default action.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
  static bool interrupted();
  /// Restores the old handlers and, if a signal came, dies of it as the user asked.
  void finish();

 private:
  bool active_ = false;
};

}  // namespace bsim
