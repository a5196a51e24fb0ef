#pragma once
// Golden files: tests/golden/<kind>/<name>, compared with what the code makes now. One environment
// variable, BSIM_UPDATE_GOLDENS, makes every golden test write its files instead; regenerate all of
// them with
//   BSIM_UPDATE_GOLDENS=1 build/bin/bsim_tests
// A golden file that is missing is a failure, never a skipped comparison.
#include <filesystem>
#include <string>

namespace bsim::test {

/// The one variable that asks for the golden files to be rewritten.
inline constexpr const char* kUpdateGoldens = "BSIM_UPDATE_GOLDENS";

/// Whether this run rewrites the golden files: BSIM_UPDATE_GOLDENS is set, not empty and not "0".
bool updating_goldens();

/// tests/golden/<kind>/<name> in the source tree.
std::filesystem::path golden_path(const std::string& kind, const std::string& name);

/// Writes the golden file (creating its folder) unless it already holds exactly `bytes`.
void write_golden(const std::filesystem::path& golden, const std::string& bytes);

/// The text must equal the golden file byte for byte. When updating, the file is written first.
void check_golden_text(const std::filesystem::path& golden, const std::string& text);

/// The failure message for a golden file that does not exist yet.
std::string missing_golden_message(const std::filesystem::path& golden);

}  // namespace bsim::test
