// The scenes that ship film what matters: in every example scene, at each shot's start and at its
// strike, the scene's own camera has the struck ball and the ball it is played at inside the picture,
// and at the strike the pocket that ball is played into too.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "camera_view.h"
#include "files.h"
#include "shots.h"
#include "support.h"

using namespace bsim;

namespace {

/// Every scene file in scenes/, by name.
std::vector<std::filesystem::path> example_scenes() {
  std::vector<std::filesystem::path> out;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("scenes")))
    if (entry.path().extension() == ".scn") out.push_back(entry.path());
  std::sort(out.begin(), out.end());
  return out;
}

/// The struck ball's first contact with another ball in shot `k`, or none.
const Event* first_contact(const Timeline& timeline, int k, int struck) {
  for (const Event& e : timeline.events())
    if (e.shot == k && e.type == EventType::ball_ball && std::count(e.balls.begin(), e.balls.end(), struck))
      return &e;
  return nullptr;
}

/// The ball the struck ball meets first in `contact` (file-order index).
int ball_met(const Event& contact, int struck) {
  for (const Contact& c : contact.contacts)
    if (c.a == struck || c.b == struck) return c.a == struck ? c.b : c.a;
  return -1;
}

/// The pocket `ball` drops into in shot `k`, or -1.
int pocket_taken(const Timeline& timeline, int k, int ball) {
  const ShotSpan& span = timeline.shots()[static_cast<std::size_t>(k)];
  for (const PocketDrop& d : timeline.pocket_drops())
    if (d.ball == ball && d.time >= span.cue && d.time <= span.rest) return d.pocket;
  return -1;
}

/// What matters in shot `k`: the struck ball, the ball played at (`pot`'s, else the first one met), the
/// pocket it is played into (`pot`'s, else the one it drops into; -1 for none, and for a break: a first
/// contact that is a group collision sends balls where the rack sends them, not where they are played).
struct Subject {
  int struck = -1, object = -1, pocket = -1;
};

Subject subject_of(const Shot& shot, int k) {
  const Cue& cue = shot.scene.cues[static_cast<std::size_t>(k)];
  Subject s;
  s.struck = cue.target;
  if (cue.aims()) {
    s.object = cue.pot_ball;
    s.pocket = cue.pot_pocket;
  } else if (const Event* contact = first_contact(shot.timeline, k, s.struck)) {
    s.object = ball_met(*contact, s.struck);
    if (!contact->grouped) s.pocket = pocket_taken(shot.timeline, k, s.object);
  }
  return s;
}

/// Where `p` lands in the camera's picture at `t`, as text for a failure.
std::string where(const CameraView& view, const Vec3& p) {
  std::ostringstream out;
  if (const auto at = view.project(p))
    out << "(" << at->x << ", " << at->y << ")";
  else
    out << "behind the camera";
  return out.str();
}

// A ball's centre this far inside the edges (a fraction of the picture's width and height) shows the
// whole ball for every camera of the example scenes, none of them nearer than about 0.4 m.
constexpr double kBallMargin = 0.02;

void check_framed(const Shot& shot, int k, double t, const std::string& moment) {
  const Subject s = subject_of(shot, k);
  const CameraView view(shot.camera->pose(t));
  const auto ball = [&](int i) { return shot.timeline.state(i, t).position; };
  INFO("shot " << k + 1 << ", " << moment << " (t = " << t << " s)");
  INFO("the struck ball (index " << s.struck << ") lands at " << where(view, ball(s.struck)));
  CHECK(view.contains(ball(s.struck), kBallMargin));
  if (s.object < 0) return;
  INFO("the ball played at (index " << s.object << ") lands at " << where(view, ball(s.object)));
  CHECK(view.contains(ball(s.object), kBallMargin));
  if (s.pocket < 0 || moment != "the strike") return;
  const Vec3 pocket = shot.scene.pockets[static_cast<std::size_t>(s.pocket)].center;
  INFO("its pocket (" << s.pocket << ") lands at " << where(view, pocket));
  CHECK(view.contains(pocket));
}

}  // namespace

TEST_SUITE("movie scenes") {
  TEST_CASE("each example scene's camera frames the struck ball, the ball it is played at and its pocket") {
    const std::vector<std::filesystem::path> scenes = example_scenes();
    REQUIRE(scenes.size() >= 10);
    for (const std::filesystem::path& path : scenes) {
      CAPTURE(path.filename().string());
      const auto shot = test::load_clean(test::require_file(path), path.stem().string());
      REQUIRE(shot->camera);
      const Timeline& timeline = shot->timeline;
      REQUIRE(timeline.shot_count() == shot->scene.shot_count());
      for (int k = 0; k < timeline.shot_count(); ++k) {
        const ShotSpan& span = timeline.shots()[static_cast<std::size_t>(k)];
        check_framed(*shot, k, span.start, "the shot's start");
        check_framed(*shot, k, span.cue, "the strike");
      }
    }
  }
}
