#pragma once
// Running POV-Ray and ffmpeg: finding them, starting them with their output in a log file,
// and Ctrl-C handling that lets the exporter stop its children and clean up before it dies.
#include <sys/types.h>

#include <string>
#include <vector>

namespace bsim {

/// Full path of `name` on PATH (or `name` itself when it holds a '/' and is executable); empty if none.
std::string find_program(const std::string& name);

/// Starts argv (argv[0] a full path) in directory `cwd`, stdin from /dev/null, stdout and stderr
/// into `log_path`. Returns the child's pid, or -1 with `error` set.
pid_t start_process(const std::vector<std::string>& argv, const std::string& cwd, const std::string& log_path,
                    std::string& error);

/// Stops a child (SIGTERM, then SIGKILL if it lingers for 5 s) and reaps it.
void stop_process(pid_t pid);

/// Waits for a child to finish. Returns its pid and sets `success` (exit status 0), or returns -1
/// when the wait was cut short by Ctrl-C (InterruptGuard::interrupted()).
pid_t wait_any(bool& success);

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
