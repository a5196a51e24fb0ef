// libFuzzer entry point: any bytes must give either a Scene or located errors, never a crash, a
// sanitizer report, or a broken promise of the parser's interface.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "scene_parse.h"

namespace {

void require(bool condition, const char* what) {
  if (condition) return;
  std::fprintf(stderr, "parser invariant broken: %s\n", what);
  std::abort();
}

void check(std::string_view text, const bsim::ParseOptions& options) {
  const bsim::ParseResult r = bsim::parse_scene(text, "fuzz", options);
  require(r.scene.has_value() != bsim::has_errors(r.diagnostics), "a scene comes exactly when there is no error");
  int lines = 1;
  for (char c : text) lines += c == '\n';
  for (const bsim::Diagnostic& d : r.diagnostics) {
    require(d.loc.line >= 1 && d.loc.column >= 1, "every diagnostic is located");
    require(d.loc.line <= lines, "a location lies inside the text");
    require(!d.message.empty() && d.message.find('\n') == std::string::npos, "a message is one line");
  }
  if (!r.scene) return;
  const bsim::Scene& s = *r.scene;
  require(!s.balls.empty() && s.balls.size() <= 16, "1 to 16 balls");
  require(!s.cues.empty() || s.game.has_value(), "a scene has a cue, but a game its players may play from the break");
  for (const bsim::Cue& cue : s.cues)
    require(cue.target >= 0 && static_cast<std::size_t>(cue.target) < s.balls.size(), "each cue's target exists");
  require(!s.rails.empty() && !s.pockets.empty(), "the table is complete");
  for (const bsim::Ball& b : s.balls) {
    require(std::abs(b.orientation.norm() - 1.0) < 1e-9, "orientations are unit quaternions");
    require(b.position.allFinite() && b.velocity.allFinite() && b.spin.allFinite(), "ball values are finite");
  }
  for (const bsim::CameraShot& shot : s.camera) {
    require(shot.pre >= 0 && shot.pre <= 1 && shot.post >= 0 && shot.post <= 1, "windows are fractions");
    require(shot.mode == bsim::CameraMode::hover ||
                (shot.ball >= 0 && static_cast<std::size_t>(shot.ball) < s.balls.size()),
            "camera balls exist");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  check(text, {});
  check(text, {.strict = true});
  return 0;
}
