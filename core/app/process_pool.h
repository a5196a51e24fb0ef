#pragma once
// A small pool of child processes (child_process.h), each started for a job of the caller's: at most
// a given number run at once, a finished one is handed back with its job, and all of them can be
// stopped at once (a failure or Ctrl-C). POV-Ray's frames are rendered this way, several at a time.
#include <sys/types.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "child_process.h"

namespace bsim {

template <class Job>
class ProcessPool {
 public:
  /// A pool of at most `limit` children at once (at least one).
  explicit ProcessPool(int limit) : limit_(std::max(limit, 1)) {}

  /// Whether another child may start now.
  bool has_room() const { return static_cast<int>(running_.size()) < limit_; }
  bool empty() const { return running_.empty(); }

  /// Starts argv (start_process) for `job`. False with `error` set when it cannot be started.
  bool start(const Job& job, const std::vector<std::string>& argv, const std::string& cwd, const std::string& log,
             std::string& error) {
    const pid_t pid = start_process(argv, cwd, log, error);
    if (pid < 0) return false;
    running_.emplace(pid, job);
    return true;
  }

  /// A child of the pool that ended: its job, whether it exited with status 0, the signal that
  /// killed it (else 0).
  struct Ended {
    Job job;
    bool success = false;
    int signal = 0;
  };
  enum class Wait { ended, still_running, interrupted };

  /// Waits up to `timeout` for a child of the pool to end (wait_any): `ended` with `ended` set,
  /// `still_running` when none did in time, `interrupted` on Ctrl-C (the children still run).
  Wait wait(std::chrono::milliseconds timeout, Ended& ended) {
    for (;;) {
      bool success = false;
      int signal = 0;
      const pid_t pid = wait_any(success, timeout, &signal);
      if (pid == 0) return Wait::still_running;
      if (pid < 0) return Wait::interrupted;
      const auto it = running_.find(pid);
      if (it == running_.end()) continue;  // a child the pool did not start
      ended = {it->second, success, signal};
      running_.erase(it);
      return Wait::ended;
    }
  }

  /// Stops every running child (stop_process), then calls `stopped(job)` for its job.
  template <class Stopped>
  void stop_all(Stopped&& stopped) {
    for (const auto& [pid, job] : running_) {
      stop_process(pid);
      stopped(job);
    }
    running_.clear();
  }

 private:
  int limit_;
  std::map<pid_t, Job> running_;
};

}  // namespace bsim
