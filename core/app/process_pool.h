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
  using Clock = std::chrono::steady_clock;

  /// A pool of at most `limit` children at work at once (at least one). A child in its first `settle`
  /// is not counted as at work by a short job: a program that idles as it starts (POV-Ray waits about
  /// 0.65 s on its own threads before it traces) lets a short job start meanwhile, up to twice `limit`
  /// children in all.
  explicit ProcessPool(int limit, Clock::duration settle = Clock::duration::zero())
      : limit_(std::max(limit, 1)), settle_(settle) {}

  /// Whether another child may start now; a `short_job` also while others are still settling.
  bool has_room(bool short_job = false) const {
    const int all = static_cast<int>(running_.size());
    if (!short_job || settle_ == Clock::duration::zero() || all < limit_) return all < limit_;
    const auto now = Clock::now();
    const auto at_work = std::count_if(running_.begin(), running_.end(),
                                       [&](const auto& child) { return now - child.second.started >= settle_; });
    return at_work < limit_ && all < 2 * limit_;
  }
  bool empty() const { return running_.empty(); }

  /// Starts argv (start_process) for `job`. False with `error` set when it cannot be started.
  bool start(const Job& job, const std::vector<std::string>& argv, const std::string& cwd, const std::string& log,
             std::string& error) {
    const pid_t pid = start_process(argv, cwd, log, error);
    if (pid < 0) return false;
    running_.emplace(pid, Child{job, Clock::now()});
    return true;
  }

  /// A child of the pool that ended: its job, whether it exited with status 0, the signal that
  /// killed it (else 0).
  struct Ended {
    Job job;
    bool success = false;
    int signal = 0;
    pid_t pid = 0;
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
      ended = {it->second.job, success, signal, pid};
      running_.erase(it);
      return Wait::ended;
    }
  }

  /// Calls `visit(pid, job)` for every running child.
  template <class Visit>
  void for_each(Visit&& visit) const {
    for (const auto& [pid, child] : running_) visit(pid, child.job);
  }

  /// Stops the running child `pid` (stop_process) and hands back its job.
  Job stop(pid_t pid) {
    stop_process(pid);
    const auto it = running_.find(pid);
    Job job = it->second.job;
    running_.erase(it);
    return job;
  }

  /// Stops every running child (stop_process), then calls `stopped(job)` for its job.
  template <class Stopped>
  void stop_all(Stopped&& stopped) {
    for (const auto& [pid, child] : running_) {
      stop_process(pid);
      stopped(child.job);
    }
    running_.clear();
  }

 private:
  struct Child {
    Job job;
    Clock::time_point started;
  };
  int limit_;
  Clock::duration settle_;
  std::map<pid_t, Child> running_;
};

}  // namespace bsim
