#include "atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace bsim {

namespace {

std::string cannot_write(const std::string& path, int code) {
  return "cannot write " + path + ": " + std::strerror(code);
}

/// The directory that holds `path` ("." for a bare name).
std::string directory_of(const std::string& path) {
  const std::string parent = std::filesystem::path(path).parent_path().string();
  return parent.empty() ? "." : parent;
}

/// The permission bits of the file at `path`, or nothing when there is none.
std::optional<unsigned> existing_mode(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) return std::nullopt;
  return static_cast<unsigned>(info.st_mode & 07777);
}

/// Flushes the directory entry of a rename to the disk. Some file systems cannot fsync a directory
/// (EINVAL): the rename stands there all the same.
int sync_directory(const std::string& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return errno;
  const int code = ::fsync(fd) == 0 || errno == EINVAL ? 0 : errno;
  ::close(fd);
  return code;
}

/// Creates a new file beside `path` (hidden, named after it and this process) for writing; its
/// descriptor, or -1 with errno set.
int create_beside(const std::string& path, std::string& temp) {
  const std::filesystem::path target(path);
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string name =
        "." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(attempt);
    temp = (target.parent_path() / name).string();
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  return -1;
}

int write_all(int fd, std::string_view content) {
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errno;
    if (n == 0) return EIO;
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

/// Gives the open file `fd` the mode `mode` (when set), flushes it and closes it; 0 or the errno.
int finish_file(int fd, std::optional<unsigned> mode) {
  int code = 0;
  if (mode && ::fchmod(fd, static_cast<mode_t>(*mode)) != 0) code = errno;
  if (code == 0 && ::fsync(fd) != 0) code = errno;
  if (::close(fd) != 0 && code == 0) code = errno;
  return code;
}

/// Renames the finished `temp` over `path` and flushes the directory; 0 or the errno.
int rename_over(const std::string& temp, const std::string& path) {
  if (std::rename(temp.c_str(), path.c_str()) != 0) return errno;
  return sync_directory(directory_of(path));
}

}  // namespace

bool write_file_atomically(const std::string& path, std::string_view content, std::string& error,
                           std::optional<unsigned> mode) {
  if (!mode) mode = existing_mode(path);
  std::string temp;
  const int fd = create_beside(path, temp);
  if (fd < 0) {
    error = cannot_write(path, errno);
    return false;
  }
  int code = write_all(fd, content);
  if (code != 0) {
    ::close(fd);
  } else {
    code = finish_file(fd, mode);
  }
  if (code == 0) code = rename_over(temp, path);
  if (code == 0) return true;
  ::unlink(temp.c_str());  // gone already when only the directory's flush failed
  error = cannot_write(path, code);
  return false;
}

bool move_into_place(const std::string& written, const std::string& path, std::string& error) {
  int code = 0;
  const int fd = ::open(written.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    code = errno;
  } else {
    code = finish_file(fd, existing_mode(path));
  }
  if (code == 0) code = rename_over(written, path);
  if (code == 0) return true;
  ::unlink(written.c_str());
  error = cannot_write(path, code);
  return false;
}

}  // namespace bsim
