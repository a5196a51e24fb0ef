#pragma once
// Rendering frames with POV-Ray: several processes at once, each frame written to a temporary
// name and renamed when whole, the frame record updated as each one lands.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "changed_region.h"
#include "export_options.h"
#include "frame_cache.h"

namespace bsim {

struct FrameJob {
  int frame = 0;
  std::uint64_t key = 0;  ///< hash of everything the picture depends on
  /// -1: the frame is traced whole. Else an earlier job's frame of the same camera: only `rects`
  /// (changed_region.h) are traced, and every other pixel is that frame's (its picture before it is
  /// developed, which is the whole-frame render's, however it was made).
  int reference = -1;
  std::vector<PixelRect> rects{};
};

struct RenderSettings {
  std::string povray;  ///< full path of the program
  int width = 1280;
  int height = 720;
  Quality quality = Quality::final;
  int processes = 1;  ///< POV-Ray processes at once, one render thread each
  /// Where messages say the frames are (the output directory's frames/, while they render in a
  /// staging directory); empty: where they render.
  std::string shown_frames_dir;
  bool quiet = false;  ///< no progress lines
};

enum class RunOutcome { done, failed, interrupted };

/// Attempts a frame gets when POV-Ray fails for a reason that is not in the scene: it times out
/// starting its worker thread under load, hangs, dies of a signal, or exits 0 without a picture.
constexpr int kRenderAttempts = 3;

/// Seconds a POV-Ray run may print nothing before it is taken to hang: POV-Ray 3.7 can spin for good
/// when its render thread fails to start under load, while a running render prints a line for every
/// block of 32 x 32 pixels it finishes (a few hundredths of a second each at final quality). The
/// environment variable BSIM_POVRAY_STALL_SECONDS sets another limit.
constexpr int kStallSeconds = 60;

/// A parse error POV-Ray reported: the file and line it names (empty and 0 when it names none) and
/// its message from "Parse Error:" on, with the lines POV-Ray wrapped joined again.
struct PovParseError {
  std::string file;
  int line = 0;
  std::string message;
};

/// The parse error in POV-Ray's output, if there is one. "Possible Parse Error" lines are warnings,
/// not errors.
std::optional<PovParseError> find_parse_error(const std::string& log_text);

/// POV-Ray's options for a quality preset (what the frame store's key records too).
std::vector<std::string> povray_quality_arguments(Quality quality);

/// POV-Ray's command line for one frame, run inside the frames directory: the whole frame, or only
/// rectangle `part` of `job`'s rects (+SC/+EC/+SR/+ER, 1-based and inclusive).
std::vector<std::string> povray_arguments(const RenderSettings& settings, int frame);
std::vector<std::string> povray_arguments(const RenderSettings& settings, const FrameJob& job, int part);

/// Renders `jobs` (frames of `total`; the others are up to date) in `frames_dir`. A job with a
/// reference is traced in its rectangles only (each a POV-Ray run of its own) and laid over its
/// reference's picture; a reference must come earlier in `jobs`. A frame that fails (or hangs,
/// kStallSeconds) for a reason not in the scene is tried again, up to kRenderAttempts in all, with a warning on
/// standard error; a parse error is never retried and is printed as `FILE:LINE: error: povray: ...`.
/// On failure `error` names the frame and quotes POV-Ray; interrupted means Ctrl-C came and every
/// child was stopped. Either way no partial picture is left behind.
/// `failed_frame`, when given, is set to the frame that failed.
RunOutcome render_frames(const std::string& frames_dir, const std::vector<FrameJob>& jobs, int total,
                         const RenderSettings& settings, FrameCache& cache, std::string& error,
                         int* failed_frame = nullptr);

}  // namespace bsim
