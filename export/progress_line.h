#pragma once
// The one-line progress report on standard error while frames render: frames done of the total,
// frames per second and the time left. Drawn only on a terminal, and not under CI.
#include <chrono>
#include <string>

namespace bsim {

class ProgressLine {
 public:
  /// `label` starts the line ("rendering"); draws nothing unless wanted().
  ProgressLine(std::string label, int total, int already_done);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// One more frame finished.
  void advance();
  /// Ends the line (a newline) if one was drawn.
  void finish();

  /// Standard error is a terminal and the CI variable is unset.
  static bool wanted();

 private:
  void draw();

  std::string label_;
  int total_ = 0;
  int done_ = 0;
  int done_here_ = 0;  ///< frames finished in this run, for the rate
  bool enabled_ = false;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace bsim
