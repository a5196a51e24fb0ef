#pragma once
// Writes a run's outputs under a temporary directory beside the destination and moves them into
// place only when the whole run succeeded, so a failing run leaves nothing half-written.
#include <string>
#include <vector>

namespace bsim {

class OutputStage {
 public:
  /// Fails (returns false, `error` set) when `dir` exists as something other than a directory.
  bool open(const std::string& dir, std::string& error);
  /// Path inside the staging directory for a relative name ("events.json", "frames/frame_00000.pov").
  std::string path(const std::string& relative) const;
  /// Moves what is staged into the destination: a destination that does not exist yet is the staging
  /// directory renamed; otherwise each top-level file replaces an older copy (one rename each,
  /// events.json last) and each top-level folder replaces the older folder whole. Nothing this run
  /// did not stage is removed: each name in `owned` (what a run may write) that an earlier run left
  /// and this one did not make stays, and is listed by kept() (in `owned`'s order, folders with a
  /// trailing '/'); anything else in the destination is left alone too.
  /// `later` names outputs this run makes after the commit (a farm submission's movie, made by its
  /// movie job): an earlier run's copy of one of them goes at the commit, so it is never taken for this
  /// run's.
  bool commit(std::string& error, const std::vector<std::string>& owned = {},
              const std::vector<std::string>& later = {});
  /// After commit: the outputs of an earlier run that this run did not replace ("movie.mp4", "frames/").
  const std::vector<std::string>& kept() const { return kept_; }
  /// Removes the staging directory; the destination is untouched. Also done by the destructor.
  void discard();
  ~OutputStage();

  const std::string& destination() const { return destination_; }
  const std::string& staging() const { return staging_; }

 private:
  std::string destination_;
  std::string staging_;
  bool open_ = false;
  std::vector<std::string> kept_;
};

}  // namespace bsim
