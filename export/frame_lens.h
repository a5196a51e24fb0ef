#pragma once
// Each frame's lens and what it sees, written into the frames folder beside the .pov frames
// (frames/lens.txt) and read by the develop stage wherever the frame is developed: here, or on a
// render farm's node that has only the frames folder, so a frame is the same picture either way. A
// frame's line (and the fixed scene) is part of its key in the frame store, so a changed lens or focus
// develops a traced picture again, and every frame, its number on its line, gets its own grain.
//
// lens.txt: `#` comment lines; the fixed scene the depth is cast from (depth_scene.h: `ball`, `room`,
// `column`, `solid` and `cup` lines); then one line per movie frame:
//   frame K camera EX EY EZ LX LY LZ lens FOCAL_MM APERTURE FOCUS_M balls N X Y Z ... stick TX TY TZ AX AY AZ
// the camera as POV-Ray gets it (its location and the point it looks at), the lens (lens.h), the balls'
// centres and the stick's tip and axis (`stick -` when it is not in the scene). A frame with no line
// is developed without the lens (no depth of field, no grain, the stopped-down vignetting).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "camera_view.h"
#include "depth_scene.h"
#include "lens.h"

namespace bsim {

struct Shot;

/// The file in the frames folder.
inline constexpr const char* kLensName = "lens.txt";

/// What the develop stage needs of one frame beyond its picture.
struct FrameLens {
  int frame = 0;    ///< the movie frame: it seeds the frame's grain
  CameraPose pose;  ///< the camera POV-Ray renders from
  Lens lens;
  DepthMoving moving;  ///< the balls and the stick where the frame shows them
};

/// Each movie frame's lens and moving things (Shot::movie: a replay's frame from the replay's camera).
std::vector<FrameLens> frame_lenses(const Shot& shot, int fps);
/// The same with the camera poses POV-Ray renders each frame from (FrameContent::camera_pose), as
/// the frames' contents already hold them.
std::vector<FrameLens> frame_lenses(const Shot& shot, int fps, const std::vector<CameraPose>& poses);

/// lens.txt's text for the shot's scene and `frames`.
std::string lens_text(const DepthScene& scene, const std::vector<FrameLens>& frames);

/// lens.txt as read: the fixed scene's lines, and each frame's line (from `frame` on) by its number.
/// Both empty when the file is missing.
struct LensFile {
  std::string scene;
  std::map<int, std::string> frames;
};
LensFile read_lens_file(const std::string& frames_dir);
/// The same from lens.txt's text.
LensFile lens_file(const std::string& text);

/// A frame's line read back; false when it is not one.
bool parse_frame_lens(const std::string& line, FrameLens& frame);

/// Folds each frame's line and the fixed scene into its frame store key.
void add_lens_keys(const std::string& frames_dir, std::vector<std::uint64_t>& keys);
/// The same from lens.txt as read (lens_file of the text written).
void add_lens_keys(const LensFile& file, std::vector<std::uint64_t>& keys);

}  // namespace bsim
