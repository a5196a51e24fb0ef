#pragma once
// Replacing a file whole or not at all, the one way both programs write a file that someone may be
// reading or that must survive a crash: the new content goes to a temporary file in the target's
// directory, is flushed to the disk (fsync), takes the permissions of the file it replaces, and is
// renamed over the target; the directory is then flushed too, so that the rename itself survives a
// crash. A reader sees the old file or the new one, never half of one. When anything fails the
// target is left as it was and no temporary file is left behind.
#include <optional>
#include <string>
#include <string_view>

namespace bsim {

/// Writes `content` to `path` as above. The file keeps the permissions of the file it replaces, or
/// `mode` when given; a new file gets the usual 0666 less the umask. A symbolic link at `path` is
/// replaced, not followed (resolve it first to replace its target). False with `error` set
/// ("cannot write PATH: REASON") when it fails.
bool write_file_atomically(const std::string& path, std::string_view content, std::string& error,
                           std::optional<unsigned> mode = std::nullopt);

/// Moves `written`, a complete file in the same directory as `path` (one a child program such as
/// ffmpeg wrote), over `path` with the same guarantees: flushed, the replaced file's permissions
/// kept, renamed, the directory flushed. False with `error` set ("cannot write PATH: REASON") when
/// it fails; `written` is removed either way.
bool move_into_place(const std::string& written, const std::string& path, std::string& error);

}  // namespace bsim
