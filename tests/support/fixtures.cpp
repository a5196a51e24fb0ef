#include "fixtures.h"

namespace bsim::test::fixtures {

std::string camera(std::initializer_list<std::string_view> descriptions) {
  std::string text = "camera\n";
  for (std::string_view d : descriptions) (text += d) += '\n';
  return text + "endcamera\n";
}

std::string cluster_scene() {
  return kClusterBalls + camera({"event 0 0 0 hover -1.5 -1.1 1.0   0 0 0", "event 2 0.3 0.3 follow 0 -0.6 0 0.3"});
}

std::string two_ball_scene(std::initializer_list<std::string_view> more) {
  std::string text = std::string(kTwoBalls) + "camera\n" +
                     "event 0 0 0       hover  -1.9 -1.1 0.9   -0.6 0 0\n"
                     "event 1 0.3 0.5   follow 0   -0.7 0 0.35\n";
  for (std::string_view d : more) (text += d) += '\n';
  return text + "endcamera\n";
}

}  // namespace bsim::test::fixtures
