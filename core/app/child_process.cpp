#include "child_process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace bsim {

namespace {

volatile sig_atomic_t g_signal = 0;
struct sigaction g_old_int {
}, g_old_term{};

void on_signal(int signal) { g_signal = signal; }

bool executable(const std::string& path) {
  struct stat info {};
  return stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode) && access(path.c_str(), X_OK) == 0;
}

bool is_blank(const std::string& line) { return line.find_first_not_of(" \t\r") == std::string::npos; }

}  // namespace

std::string find_program(const std::string& name) {
  if (name.find('/') != std::string::npos) return executable(name) ? name : "";
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
    if (executable(candidate)) return candidate;
  }
  return "";
}

pid_t start_process(const std::vector<std::string>& argv, const std::string& cwd, const std::string& log_path,
                    std::string& error, int* stdin_pipe) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  int fds[2] = {-1, -1};
  if (stdin_pipe && pipe2(fds, O_CLOEXEC) != 0) {
    error = std::string("cannot start ") + argv.front() + ": no pipe: " + std::strerror(errno);
    return -1;
  }
  // SIGINT and SIGTERM wait until the child has dropped the handlers it inherits: a signal sent to it
  // between fork and exec (a run stopped at once) must end it, never run this program's handler in it.
  sigset_t stops, before;
  sigemptyset(&stops);
  sigaddset(&stops, SIGINT);
  sigaddset(&stops, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stops, &before);
  const pid_t pid = fork();
  if (pid != 0) pthread_sigmask(SIG_SETMASK, &before, nullptr);
  if (pid < 0) {
    error = std::string("cannot start ") + argv.front() + ": " + std::strerror(errno);
    if (stdin_pipe) {
      close(fds[0]);
      close(fds[1]);
    }
    return -1;
  }
  if (pid == 0) {
    // In the child: only async-signal-safe calls until exec.
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    sigprocmask(SIG_SETMASK, &before, nullptr);
    const int in = stdin_pipe ? fds[0] : open("/dev/null", O_RDONLY);
    const int log = open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0 || log < 0 || chdir(cwd.c_str()) != 0) _exit(127);
    dup2(in, 0);
    dup2(log, 1);
    dup2(log, 2);
    close(in);
    close(log);
    execv(args[0], args.data());
    _exit(127);
  }
  if (stdin_pipe) {
    close(fds[0]);
    *stdin_pipe = fds[1];
  }
  return pid;
}

void stop_process(pid_t pid) {
  // POV-Ray and ffmpeg stop within a second of SIGTERM; one that does not is killed outright.
  kill(pid, SIGTERM);
  int status = 0;
  for (int tries = 0; tries < 100; ++tries) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid || (done < 0 && errno != EINTR)) return;
    usleep(50000);
  }
  kill(pid, SIGKILL);
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
}

pid_t wait_any(bool& success, int* signal) {
  for (;;) {
    if (InterruptGuard::interrupted()) return -1;
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid > 0) {
      success = WIFEXITED(status) && WEXITSTATUS(status) == 0;
      if (signal) *signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
      return pid;
    }
    if (errno != EINTR) return -1;
  }
}

pid_t wait_any(bool& success, std::chrono::milliseconds timeout, int* signal) {
  // Polled: a blocking wait cannot time out, and an alarm signal would disturb the children.
  constexpr auto kPoll = std::chrono::milliseconds(10);
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    if (InterruptGuard::interrupted()) return -1;
    int status = 0;
    const pid_t pid = waitpid(-1, &status, WNOHANG);
    if (pid > 0) {
      success = WIFEXITED(status) && WEXITSTATUS(status) == 0;
      if (signal) *signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
      return pid;
    }
    if (pid < 0 && errno != EINTR) return -1;
    const auto now = std::chrono::steady_clock::now();
    if (now >= deadline) return 0;
    const auto pause = std::min<std::chrono::steady_clock::duration>(kPoll, deadline - now);
    const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(pause).count();
    timespec request{static_cast<time_t>(ns / 1000000000), static_cast<long>(ns % 1000000000)};
    nanosleep(&request, nullptr);  // a signal ends it early; the loop looks again
  }
}

bool wait_for(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return false;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

std::string error_from_log(const std::string& log_text) {
  std::vector<std::string> lines;
  std::stringstream in(log_text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  auto joined_from = [&](std::size_t i) {
    std::string text = lines[i];
    // POV-Ray wraps long messages at 80 columns, continuing with a leading space.
    for (std::size_t k = i + 1; k < lines.size() && !lines[k].empty() && lines[k][0] == ' '; ++k) text += lines[k];
    return text;
  };
  for (const char* marker : {"Error:", "error:"}) {
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (lines[i].find(marker) != std::string::npos) return joined_from(i);
  }
  for (std::size_t i = lines.size(); i-- > 0;)
    if (!is_blank(lines[i])) return lines[i];
  return "no message";
}

InterruptGuard::InterruptGuard() {
  g_signal = 0;
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: a signal wakes the wait for children
  sigaction(SIGINT, &action, &g_old_int);
  sigaction(SIGTERM, &action, &g_old_term);
  active_ = true;
}

InterruptGuard::~InterruptGuard() {
  if (active_) {
    sigaction(SIGINT, &g_old_int, nullptr);
    sigaction(SIGTERM, &g_old_term, nullptr);
  }
}

bool InterruptGuard::interrupted() { return g_signal != 0; }

void InterruptGuard::finish() {
  if (!active_) return;
  sigaction(SIGINT, &g_old_int, nullptr);
  sigaction(SIGTERM, &g_old_term, nullptr);
  active_ = false;
  const int received = g_signal;
  if (received != 0) {
    signal(received, SIG_DFL);
    raise(received);
  }
}

}  // namespace bsim
