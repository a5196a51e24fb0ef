// The cue stick's four phases on simulated shots: the strike lands exactly at the cue event, two
// practice strokes, removal out of view, and no contact with the bed, the cushions or other balls;
// in a scene of several shots, every shot's stick comes in, strikes and leaves.
#include <doctest/doctest.h>
#include <cmath>
#include <string>

#include "cue_geometry.h"
#include "files.h"
#include "shot.h"
#include "shots.h"
#include "timeline.h"
#include "tolerance.h"

using namespace bsim;

namespace {

std::unique_ptr<Shot> load(const std::string& text) {
  std::unique_ptr<Shot> shot = test::load_scene(text);
  REQUIRE(shot->cue);
  return shot;
}

constexpr double kR = 0.028575;
const std::string kCamera = "camera\nevent 0 0 0 hover -1.6 -1.5 1.2 0 0 0\nendcamera\n";
const std::string kPlain = "cue 0 0\nball 0 -0.6 0 0.028575 1.5 0 0 1 0 0 0\nball 1 0.3 0.2 0.028575 0 0 0 1 0 0 0\n";

/// m the tip is behind the contact point along the stick (negative past it).
double behind(const CueScript& cue, double t) {
  const CuePose pose = cue.pose(t);
  return (pose.tip - cue.contact_point()).dot(pose.axis);
}

/// The least clearance to the bed, cushions and every ball (the struck one included) while visible.
double worst_clearance(const Shot& shot) {
  double worst = 1e9;
  for (double t = 0; t <= shot.timeline.duration(); t += 1.0 / 120) {
    const CuePose pose = shot.cue->pose(t);
    if (!pose.visible) continue;
    worst = std::min(worst, stick_clearance(pose, shot.scene, shot.timeline.states(t), kR));
  }
  const double strike = shot.timeline.cue_time();
  return std::min(worst, stick_clearance(shot.cue->pose(strike), shot.scene, shot.timeline.states(strike), kR));
}

}  // namespace

TEST_SUITE("cue_script") {
  TEST_CASE("four phases in order, approach and strokes within the lead time") {
    auto shot = load(kPlain + kCamera);
    const auto& phases = shot->cue->phases();
    REQUIRE(phases.size() == 4);
    CHECK(phases[0].phase == CuePhase::approach);
    CHECK(phases[1].phase == CuePhase::preflight);
    CHECK(phases[2].phase == CuePhase::impact);
    CHECK(phases[3].phase == CuePhase::retraction);
    CHECK(phases[0].begin == 0.0);
    for (std::size_t i = 0; i < phases.size(); ++i) {
      CHECK(phases[i].end >= phases[i].begin);
      if (i > 0) CHECK(phases[i].begin == phases[i - 1].end);
    }
    const double strike = shot->timeline.cue_time();
    CHECK(strike <= kCueLeadTime);
    CHECK(phases[1].end < strike);
    CHECK(phases[2].end > strike);
  }

  TEST_CASE("the tip meets the ball's surface exactly at the cue event, on the line through its centre") {
    auto shot = load(kPlain + kCamera);
    const CueScript& cue = *shot->cue;
    const double strike = shot->timeline.cue_time();
    const Vec3 centre = shot->scene.balls[0].position;
    const CuePose at = cue.pose(strike);
    CHECK(at.visible);
    CHECK((at.tip - cue.contact_point()).norm() < 1e-12);
    CHECK((at.tip - centre).norm() == doctest::Approx(kR).epsilon(1e-12));
    CHECK((centre - at.tip).cross(at.axis).norm() < 1e-12);
    // The stick points along the heading (+x), butt raised.
    CHECK(at.axis.x() < 0);
    CHECK(std::abs(at.axis.y()) < 1e-12);
    CHECK(at.axis.z() > 0);
    // Never on the ball before: the gap closes only at the strike.
    for (double t = 0; t < strike - 1e-6; t += 1.0 / 240) CHECK(stick_ball_gap(cue.pose(t), centre, kR) > 0);
  }

  TEST_CASE("the strike: accelerates into the ball at a speed tied to the ball's, then slows to rest") {
    auto shot = load(kPlain + kCamera);
    const CueScript& cue = *shot->cue;
    const double strike = shot->timeline.cue_time();
    const double h = 1e-6;
    const double speed = (behind(cue, strike - h) - behind(cue, strike)) / h;
    CHECK(speed == doctest::Approx(cue.tip_speed()).epsilon(1e-4));
    CHECK(cue.tip_speed() == doctest::Approx(1.5 / 1.4));
    CHECK(cue.tip_speed() < 1.5);  // the ball leaves faster than the tip follows
    // Speeding up all the way in: the forward speed grows through the impact phase's first part.
    const double begin = cue.phases()[2].begin;
    double previous = 0;
    for (int i = 1; i <= 10; ++i) {
      const double t = begin + (strike - begin) * i / 10.0;
      const double v = (behind(cue, t - h) - behind(cue, t)) / h;
      CHECK(v > previous);
      previous = v;
    }
    // From rest at the back-swing, evenly, in the quarter second an ordinary stroke takes: the tip
    // covers tip_speed x 0.25 / 2 to the ball.
    CHECK(strike - begin == test::near(0.25, 1e-12));
    CHECK(behind(cue, begin) == test::near(cue.tip_speed() * (strike - begin) / 2, 1e-12));
    // After it, slowing evenly to rest: the follow-through is tip_speed x its duration / 2 past the
    // contact point, and at most 15 cm.
    const double end = cue.phases()[2].end;
    CHECK(std::abs(behind(cue, end - h) - behind(cue, end)) / h < 1e-3);
    CHECK(behind(cue, end) == test::near(-cue.tip_speed() * (end - strike) / 2, 1e-12));
    CHECK(behind(cue, end) >= -0.15);
  }

  TEST_CASE("preflight: two practice strokes, then the back-swing") {
    auto shot = load(kPlain + kCamera);
    const CueScript& cue = *shot->cue;
    const CuePhaseSpan preflight = cue.phases()[1];
    int peaks = 0, troughs = 0;
    const double step = (preflight.end - preflight.begin) / 600;
    double a = behind(cue, preflight.begin), b = behind(cue, preflight.begin + step);
    for (double t = preflight.begin + 2 * step; t < preflight.end - step / 2; t += step) {
      const double c = behind(cue, t);
      peaks += b > a && b > c;
      troughs += b < a && b < c;
      a = b;
      b = c;
    }
    CHECK(peaks == 2);
    CHECK(troughs == 2);  // back at the address between the strokes and before the back-swing
    // The back-swing ends at rest, farther back than the address.
    CHECK(behind(cue, preflight.end) > behind(cue, preflight.begin));
  }

  TEST_CASE("the stick comes from out of view and is removed only once out of view") {
    auto shot = load(kPlain + kCamera);
    const CueScript& cue = *shot->cue;
    const CameraScript& camera = *shot->camera;
    CHECK_FALSE(stick_in_view(cue.pose(0), camera.pose(0)));
    CHECK(cue.pose(0).visible);
    const CuePhaseSpan retraction = cue.phases()[3];
    CHECK(cue.pose(retraction.end - 1e-6).visible);
    CHECK_FALSE(stick_in_view(cue.pose(retraction.end), camera.pose(retraction.end)));
    for (double t = retraction.end; t <= shot->timeline.duration(); t += 0.1) CHECK_FALSE(cue.pose(t).visible);
    // Seen during the strike.
    CHECK(stick_in_view(cue.pose(shot->timeline.cue_time()), camera.pose(shot->timeline.cue_time())));
  }

  TEST_CASE("the stick moves continuously through every phase boundary") {
    auto shot = load(kPlain + kCamera);
    const CueScript& cue = *shot->cue;
    for (const CuePhaseSpan& span : cue.phases()) {
      for (double edge : {span.begin, span.end}) {
        if (edge <= 0) continue;
        CHECK((cue.pose(edge - 1e-9).tip - cue.pose(edge + 1e-9).tip).norm() < 1e-6);
        CHECK((cue.pose(edge - 1e-9).axis - cue.pose(edge + 1e-9).axis).norm() < 1e-6);
      }
    }
  }

  TEST_CASE("an open shot keeps the stick low and clear") {
    auto shot = load(kPlain + kCamera);
    CHECK(shot->cue->elevation_deg() == doctest::Approx(5.0));
    CHECK(worst_clearance(*shot) >= -1e-9);
  }

  TEST_CASE("a ball just behind the cue ball: the butt is raised over it") {
    // Ball 1 sits 2.2 radii behind the cue ball on the cue line.
    auto shot =
        load("cue 0 0\nball 0 0 0 0.028575 1 0 0 1 0 0 0\nball 1 -0.062865 0 0.028575 0 0 0 1 0 0 0\n" + kCamera);
    // The lowest whole degree that keeps the stick the script's 2 mm from ball 1 wherever it slides
    // along its line (the strokes reach 11 cm back): 37, as README says.
    const Vec3 centre = shot->scene.balls[0].position, other = shot->scene.balls[1].position;
    auto least_gap = [&](double degrees) {
      const double a = degrees * M_PI / 180;
      CuePose pose;
      pose.axis = Vec3(-std::cos(a), 0, std::sin(a));
      double least = 1e9;
      for (int k = 0; k <= 1100; ++k) {
        pose.tip = centre + (kR + k * 1e-4) * pose.axis;
        least = std::min(least, stick_ball_gap(pose, other, kR));
      }
      return least;
    };
    const double elevation = shot->cue->elevation_deg();
    CHECK(elevation == test::near(37, 1e-9));
    CHECK(least_gap(elevation) >= 0.002);
    CHECK(least_gap(elevation - 1) < 0.002);
    CHECK(worst_clearance(*shot) >= -1e-9);
  }

  TEST_CASE("a cue ball near a cushion: the stick passes over the cushion") {
    auto shot = load("cue 0 180\nball 0 1.17 0.1 0.028575 -1 0 0 1 0 0 0\n" + kCamera);
    CHECK(shot->cue->elevation_deg() > 10);
    CHECK(worst_clearance(*shot) >= -1e-9);
  }

  TEST_CASE("a ball almost against the cushion, shot straight away: a steep stroke that does not chase the ball") {
    auto shot = load("cue 0 180\nball 0 1.2404 0.1 0.028575 -1 0 0 1 0 0 0\n" + kCamera);
    const double elevation = shot->cue->elevation_deg() * M_PI / 180;
    CHECK(elevation > 40 * M_PI / 180);
    // Slower than the ball's speed along the stick, so the tip falls behind as the ball leaves.
    CHECK(shot->cue->tip_speed() < 1.0 * std::cos(elevation));
    CHECK(worst_clearance(*shot) >= -1e-9);
  }

  TEST_CASE("a shot with the cue heading across the table and balls about") {
    auto shot = load(
        "cue 0 120\nball 0 0.2 -0.3 0.028575 -1 1.7320508 0 1 0 0 0\n"
        "ball 1 0.5 -0.5 0.028575 0 0 0 1 0 0 0\nball 2 0.3 -0.55 0.028575 0 0 0 1 0 0 0\n" +
        kCamera);
    CHECK(worst_clearance(*shot) >= -1e-9);
    const CuePose at = shot->cue->pose(shot->timeline.cue_time());
    CHECK(std::atan2(-at.axis.y(), -at.axis.x()) == doctest::Approx(120 * M_PI / 180));
  }
}

TEST_SUITE("cue_script: the stick tells the stroke") {
  /// The cue ball at (-0.6, 0) struck along +x with `stroke`; the 1 out of the way.
  std::string stroked(const std::string& stroke) {
    return "cue 0 0\nstroke " + stroke +
           "\nball 0 -0.6 0 0.028575 0 0 0 1 0 0 0\nball 1 0.3 0.2 0.028575 0 0 0 1 0 0 0\n" + kCamera;
  }

  /// m, the farthest the tip goes back on the practice strokes (before the back-swing).
  double practice_reach(const CueScript& cue) {
    const CuePhaseSpan& preflight = cue.phases()[1];
    double reach = 0;
    for (double t = preflight.begin; t < preflight.begin + 0.5 * (preflight.end - preflight.begin); t += 1e-3)
      reach = std::max(reach, behind(cue, t));
    return reach;
  }

  TEST_CASE(
      "at impact the tip is on the ball at the offset, the stick raised by the elevation, at the stroke's speed") {
    const auto shot = load(stroked("2 0.2 -0.3 20"));
    const CueScript& cue = *shot->cue;
    const double strike = shot->timeline.cue_time();
    const CuePose at = cue.pose(strike);
    const Vec3 centre = shot->scene.balls[0].position;
    // On the ball's surface, the stick raised exactly 20 degrees (it clears at that elevation).
    CHECK(cue.clears());
    CHECK(cue.elevation_deg() == test::near(20, 1e-12));
    CHECK(std::asin(at.axis.z()) / kDegToRad == test::near(20, 1e-12));
    CHECK((at.tip - centre).norm() == test::near(kR, 1e-12));
    // The axis passes the centre at the offset: 0.2 R to the shooter's right (-y for a +x heading),
    // 0.3 R below across the stick; its distance from the centre is R sqrt(a^2 + b^2).
    const Vec3 w = centre - at.tip;
    const Vec3 off_axis = w - w.dot(at.axis) * at.axis;
    CHECK(off_axis.norm() == test::near(kR * std::hypot(0.2, 0.3), 1e-12));
    CHECK((at.tip - centre).y() == test::near(-0.2 * kR, 1e-12));
    const double h = 1e-6;
    CHECK((behind(cue, strike - h) - behind(cue, strike)) / h == doctest::Approx(2).epsilon(1e-4));
    CHECK(cue.tip_speed() == 2);
  }

  TEST_CASE("practice strokes and follow-through grow with the stroke's speed") {
    const auto touch = load(stroked("0.5 0 0 0"));
    const auto medium = load(stroked("1.5 0 0 0"));
    const auto power = load(stroked("4 0 0 0"));
    const double reach[] = {practice_reach(*touch->cue), practice_reach(*medium->cue), practice_reach(*power->cue)};
    CHECK(reach[0] < reach[1]);
    CHECK(reach[1] < reach[2]);
    auto follow = [](const Shot& shot) { return -behind(*shot.cue, shot.cue->phases()[2].end); };
    CHECK(follow(*touch) < follow(*medium));
    CHECK(follow(*medium) <= follow(*power));
    // A level stroke is drawn just high enough to clear the cushion, and nothing is hit.
    for (const Shot* shot : {touch.get(), medium.get(), power.get()}) CHECK(worst_clearance(*shot) > 0);
  }

  TEST_CASE("a stick that no elevation clears: a warning at the stroke") {
    // A wall half a metre high just behind the cue ball: even at 75 degrees the stick runs into it.
    const ShotResult loaded = load_shot(
        "cue 0 0\nstroke 1 0 0 0\nball 0 -0.6 0 0.028575 0 0 0 1 0 0 0\n"
        // The wall stands on the standard table, whose cushions (written out, on the same line) close round it.
        "rail -0.7 -0.5 0.5  -0.7 0.5 0.5  "
        "rail -1.19 0.635 0.0363 -0.065 0.635 0.0363  rail 0.065 0.635 0.0363 1.19 0.635 0.0363  "
        "rail 1.27 0.555 0.0363 1.27 -0.555 0.0363  rail 1.19 -0.635 0.0363 0.065 -0.635 0.0363  "
        "rail -0.065 -0.635 0.0363 -1.19 -0.635 0.0363  rail -1.27 -0.555 0.0363 -1.27 0.555 0.0363\n" +
            kCamera,
        "t", {}, CameraChoice::scene);
    REQUIRE(loaded.shot);
    bool warned = false;
    for (const Diagnostic& d : loaded.diagnostics)
      warned = warned || (d.severity == Severity::warning && d.loc.line == 2 && d.loc.column == 1 &&
                          d.message.find("no pose clears") != std::string::npos);
    CHECK(warned);
  }
}

TEST_SUITE("cue_script: several shots") {
  /// tests/scene/three_shots.scn: the cue ball struck three times, each aimed from where it stopped.
  std::unique_ptr<Shot> three_shots() {
    const std::optional<std::string> text = test::read_file(test::source_path("tests/scene/three_shots.scn"));
    REQUIRE(text);
    return load(*text);
  }

  TEST_CASE("every shot's tip meets its struck ball where it stands at that shot's strike, along that cue's heading") {
    const auto shot = three_shots();
    const CueScript& cue = *shot->cue;
    const auto& shots = shot->timeline.shots();
    REQUIRE(shots.size() == 3);
    REQUIRE(cue.strokes().size() == 3);
    for (std::size_t k = 0; k < shots.size(); ++k) {
      CAPTURE(k);
      const Cue& written = shot->scene.cues[k];
      const double strike = shots[k].cue;
      const Vec3 centre = shot->timeline.state(written.target, strike).position;
      if (k > 0) CHECK((centre - shot->scene.balls[0].position).norm() > 0.1);  // the ball has moved since
      const CuePose at = cue.pose(strike);
      CHECK(at.visible);
      // On the ball's surface (within a millimetre; the script puts it there exactly).
      CHECK(std::abs((at.tip - centre).norm() - kR) < 1e-3);
      CHECK((at.tip - cue.strokes()[k].contact).norm() < 1e-3);
      // A level stroke (`stroke V A B 0`) at A = 0 or B = 0: the axis passes the centre at the offset.
      CHECK(at.axis.z() > 0);
      const double heading = std::atan2(-at.axis.y(), -at.axis.x()) / kDegToRad;
      CHECK(std::abs(std::remainder(heading - written.heading_deg, 360.0)) < 1e-9);
      // The tip arrives at the shot's stroke speed (2, 2.2 and 2.2 m/s in the file).
      const double h = 1e-6;
      const Vec3 moved = cue.pose(strike).tip - cue.pose(strike - h).tip;
      CHECK(moved.norm() / h == doctest::Approx(written.stroke->speed).epsilon(1e-4));
      // Never on the ball before its strike, from the shot's start.
      for (double t = shots[k].start; t < strike - 1e-6; t += 1.0 / 120)
        CHECK(stick_ball_gap(cue.pose(t), centre, kR) > 0);
    }
  }

  TEST_CASE("the stick leaves after each stroke and comes back out of view for the next") {
    const auto shot = three_shots();
    const CueScript& cue = *shot->cue;
    const auto& shots = shot->timeline.shots();
    const auto& phases = cue.phases();
    REQUIRE(phases.size() == 12);
    for (std::size_t i = 0; i < phases.size(); ++i) {
      CAPTURE(i);
      CHECK(phases[i].shot == static_cast<int>(i / 4));
      CHECK(static_cast<int>(phases[i].phase) == static_cast<int>(i % 4));
      CHECK(phases[i].end >= phases[i].begin);
      if (i > 0) CHECK(phases[i].begin >= phases[i - 1].end);
    }
    for (std::size_t k = 0; k < shots.size(); ++k) {
      CAPTURE(k);
      const double start = shots[k].start;
      CHECK(phases[4 * k].begin == start);
      // The approach and strokes take the same share of the 2.5 s lead as the first shot's.
      CHECK(phases[4 * k].end - start == test::near(phases[0].end, 1e-9));
      CHECK(phases[4 * k + 1].end < shots[k].cue);
      CHECK(phases[4 * k + 2].end > shots[k].cue);
      // It comes in from where the camera cannot see it.
      CHECK_FALSE(stick_in_view(cue.pose(start), shot->camera->pose(start)));
      if (k == 0) continue;
      // The stroke before was removed before this shot's start, and nothing shows in between.
      CHECK(phases[4 * k - 1].end < start);
      for (double t = phases[4 * k - 1].end; t < start; t += 0.05) CHECK_FALSE(cue.pose(t).visible);
      CHECK_FALSE(cue.pose(start - 1e-3).visible);
    }
  }

  TEST_CASE("across the whole scene the stick never passes through a ball, a cushion or the bed") {
    const auto shot = three_shots();
    const auto& shots = shot->timeline.shots();
    // Sampled over the whole scene while the stick is seen, each strike's instant included.
    std::vector<double> times;
    for (double t = 0; t <= shot->timeline.duration(); t += 1.0 / 120) times.push_back(t);
    for (const ShotSpan& span : shots) times.push_back(span.cue);
    double worst = 1e9;
    for (double t : times) {
      const CuePose pose = shot->cue->pose(t);
      if (!pose.visible) continue;
      const int k = shot->timeline.shot_at(t);
      const Cue& written = shot->scene.cues[static_cast<std::size_t>(k)];
      const bool strike = std::abs(t - shots[static_cast<std::size_t>(k)].cue) < 1e-6;
      // At the strike the tip's flat face touches the struck ball at the stroke's offset, its centre
      // on the surface: the face's rim then reaches in at most the tip's radius times the offset's
      // sine, sqrt(A^2 + B^2) (0.2 here: 1.3 mm), which the leather's give takes up. The rest clears.
      worst = std::min(worst,
                       stick_clearance(pose, shot->scene, shot->timeline.states(t), kR, strike ? written.target : -1));
      if (strike) {
        const double offset = std::hypot(written.stroke->side, written.stroke->height);
        const Vec3 centre = shot->timeline.state(written.target, t).position;
        CHECK(stick_ball_gap(pose, centre, kR) >= -kCueTipRadius * offset - 1e-9);
      }
    }
    CHECK(worst >= -1e-9);
    // Continuous within each stroke.
    for (const CuePhaseSpan& span : shot->cue->phases()) {
      const double edge = span.end;
      CHECK((shot->cue->pose(edge - 1e-9).tip - shot->cue->pose(edge + 1e-9).tip).norm() < 1e-6);
    }
  }

  TEST_CASE("a later shot's stroke that no elevation clears: a warning at that shot's stroke") {
    // The first shot sends ball 0 away up the table; the second strikes ball 1, a wall half a metre
    // high just behind it.
    const ShotResult loaded = load_shot(
        "ball 0 0.5 0.3 0.028575 0 0 0 1 0 0 0\n"
        "ball 1 -0.6 0 0.028575 0 0 0 1 0 0 0\n"
        "rail -0.7 -0.5 0.5  -0.7 0.5 0.5  "
        "rail -1.19 0.635 0.0363 -0.065 0.635 0.0363  rail 0.065 0.635 0.0363 1.19 0.635 0.0363  "
        "rail 1.27 0.555 0.0363 1.27 -0.555 0.0363  rail 1.19 -0.635 0.0363 0.065 -0.635 0.0363  "
        "rail -0.065 -0.635 0.0363 -1.19 -0.635 0.0363  rail -1.27 -0.555 0.0363 -1.27 0.555 0.0363\n"
        "cue 0 90\nstroke 0.5 0 0 30\n"
        "cue 1 0\nstroke 1 0 0 0\n" +
            kCamera,
        "t", {}, CameraChoice::scene);
    REQUIRE(loaded.shot);
    int warnings = 0;
    bool at_second = false;
    for (const Diagnostic& d : loaded.diagnostics) {
      if (d.severity != Severity::warning || d.message.find("no pose clears") == std::string::npos) continue;
      ++warnings;
      at_second = at_second || (d.loc.line == 7 && d.loc.column == 1);
    }
    CHECK(warnings == 1);
    CHECK(at_second);
  }
}
