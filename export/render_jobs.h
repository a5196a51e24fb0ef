#pragma once
// Rendering frames with POV-Ray: several processes at once, each frame written to a temporary
// name and renamed when whole, the frame record updated as each one lands.
#include <cstdint>
#include <string>
#include <vector>

#include "export_options.h"
#include "frame_cache.h"

namespace bsim {

struct FrameJob {
  int frame = 0;
  std::uint64_t key = 0;  ///< hash of everything the picture depends on
};

struct RenderSettings {
  std::string povray;  ///< full path of the program
  int width = 1280;
  int height = 720;
  Quality quality = Quality::final;
  int processes = 1;   ///< POV-Ray processes at once, one render thread each
  bool quiet = false;  ///< no progress lines
};

enum class RunOutcome { done, failed, interrupted };

/// POV-Ray's command line for one frame, run inside the frames directory.
std::vector<std::string> povray_arguments(const RenderSettings& settings, int frame);

/// Renders `jobs` (frames of `total`; the others are up to date) in `frames_dir`. On failure
/// `error` names the frame and quotes POV-Ray; interrupted means Ctrl-C came and every child was
/// stopped. Either way no partial picture is left behind.
RunOutcome render_frames(const std::string& frames_dir, const std::vector<FrameJob>& jobs, int total,
                         const RenderSettings& settings, FrameCache& cache, std::string& error);

}  // namespace bsim
