#include "slurm_client.h"

#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "child_process.h"
#include "scene_file.h"

namespace fs = std::filesystem;

namespace bsim::farm {

bool run_captured(const std::vector<std::string>& argv, std::string& output, std::string& error) {
  const char* tmpdir = std::getenv("TMPDIR");
  const std::string folder = tmpdir && *tmpdir ? tmpdir : "/tmp";
  std::string log = folder + "/billiards-export-XXXXXX";
  const int fd = ::mkstemp(log.data());
  if (fd < 0) {
    error = "cannot create a temporary file in " + folder + ": " + std::strerror(errno);
    return false;
  }
  ::close(fd);
  const pid_t pid = start_process(argv, ".", log, error);
  const bool ok = pid > 0 && wait_for(pid);
  output = read_text_file(log);
  std::error_code ignored;
  fs::remove(log, ignored);
  while (!output.empty() && (output.back() == '\n' || output.back() == ' ')) output.pop_back();
  return ok;
}

std::string jobs_in_queue(const std::string& squeue, const FarmConf& conf) {
  if (squeue.empty() || (conf.frames_job.empty() && conf.movie_job.empty())) return "";
  std::string ids = conf.frames_job;
  if (!conf.movie_job.empty()) ids += (ids.empty() ? "" : ",") + conf.movie_job;
  std::string output, error;
  // Unknown ids (jobs long finished) make squeue fail: none of them is queued.
  if (!run_captured({squeue, "--noheader", "--jobs=" + ids, "--format=%i"}, output, error)) return "";
  std::string found;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    line.erase(0, line.find_first_not_of(' '));
    if (!line.empty() && std::isdigit(static_cast<unsigned char>(line[0]))) found += (found.empty() ? "" : " ") + line;
  }
  return found;
}

std::string job_id(const std::string& output) {
  const std::size_t line_start = output.rfind('\n');
  std::string line = output.substr(line_start == std::string::npos ? 0 : line_start + 1);
  line = line.substr(0, line.find(';'));
  if (line.empty() || line.find_first_not_of("0123456789") != std::string::npos) return "";
  return line;
}

}  // namespace bsim::farm
