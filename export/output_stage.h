#pragma once
// Writes a run's outputs under a temporary directory beside the destination and moves them into
// place only when the whole run succeeded, so a failing run leaves nothing half-written.
#include <string>

namespace bsim {

class OutputStage {
 public:
  /// Fails (returns false, `error` set) when `dir` exists as something other than a directory.
  bool open(const std::string& dir, std::string& error);
  /// Path inside the staging directory for a relative name ("events.json", "frames/frame_00000.pov").
  std::string path(const std::string& relative) const;
  /// Moves every staged file into the destination (creating it), replacing older copies.
  bool commit(std::string& error);
  /// Removes the staging directory; the destination is untouched. Also done by the destructor.
  void discard();
  ~OutputStage();

  const std::string& destination() const { return destination_; }
  const std::string& staging() const { return staging_; }

 private:
  std::string destination_;
  std::string staging_;
  bool open_ = false;
};

}  // namespace bsim
