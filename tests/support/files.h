#pragma once
// Reading and writing whole files, and paths in the source tree. No test framework here: the
// benchmarks use these too.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace bsim::test {

/// The bytes of the file at `path`, or nothing if it cannot be read.
std::optional<std::string> read_file(const std::filesystem::path& path);

/// Writes `contents` to `path`, replacing it; false if that fails (its folder must exist).
bool write_file(const std::filesystem::path& path, std::string_view contents);

/// A path in the source tree, e.g. source_path("scenes/break.scn").
std::filesystem::path source_path(const std::string& relative);

}  // namespace bsim::test
