// pocket_bench: the pockets measured against Dr. Dave Alciatore's effective targets (TP 3.6 corner, TP 3.5
// side), and what the jaws cost the physics.
//  - The effective target (tests/support/pocket_sweep.h): lone balls rolled along parallel lines at each
//    angle of Dr. Dave's tables, at 0.5 m/s (his slow shots), 1.5 and 3 m/s, on the default table and on
//    Dr. Dave's own geometry (sharp jaw points, his 1.125 in corner shelf), beside the bare drop circles
//    the jaws replaced (at 0.5 m/s); the total width of the lines that pot, in mm.
//  - The cost: the same seeded 9-ball breaks (a player's break, tests/support/break_stats.h) on the
//    standard table with its cut pockets and with bare drop circles, timed in one run.
//   pocket_bench [--step MM] [--breaks N] [--no-sweep] [--no-cost]
//   pocket_bench [--step MM] --lines standard|pockets|plane|bare corner|side ANGLE SPEED
//                                   every line of one sweep (EVENTS=1 in the environment: with its events)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "break_stats.h"
#include "pocket_sweep.h"

namespace {

using namespace bsim;
using Clock = std::chrono::steady_clock;

constexpr double kSpeeds[] = {0.5, 1.5, 3.0};

struct Row {
  double target[3] = {0, 0, 0};  ///< mm, per speed
  double centre = 0;             ///< mm, the slow target's centre
  double rail_first = 0;         ///< mm of the slow target from lines that meet a rail first
  int bands = 0;                 ///< of the slow target
  bool truncated = false;        ///< a sweep potted at the end of its range
};

Row measure(pockets::Geometry geometry, PocketKind kind, double angle, double step, int speeds) {
  Row row;
  pockets::SweepSpec spec;
  spec.geometry = geometry;
  spec.kind = kind;
  spec.angle_deg = angle;
  spec.step = step;
  for (int k = 0; k < speeds; ++k) {
    spec.speed = kSpeeds[k];
    const pockets::SweepResult r = pockets::sweep(spec);
    row.target[k] = r.target * 1000;
    row.truncated = row.truncated || r.truncated;
    if (k == 0) {
      row.centre = r.centre * 1000;
      row.rail_first = r.potted_via_rail * step * 1000;
      row.bands = r.bands;
    }
  }
  return row;
}

std::string versus(double mm, double tp) {
  char text[32];
  if (tp > 0)
    std::snprintf(text, sizeof text, "%5.1f %+4.0f%%", mm, 100 * (mm / tp - 1));
  else
    std::snprintf(text, sizeof text, "%5.1f      ", mm);
  return text;
}

template <class Table>
void print_kind(const char* title, PocketKind kind, const Table& table, double step) {
  using pockets::Geometry;
  std::printf("\n%s\n", title);
  std::printf("%-10s | %-55s | %-34s | %-34s | %s\n", "", "standard table", "Dr. Dave's pockets", "his plane model",
              "bare");
  std::printf("%4s %5s | %11s %6s %6s %7s %6s %5s %8s | %11s %8s %6s %6s | %11s %8s %6s %6s | %5s\n", "deg", "TP",
              "0.5 m/s", "1.5", "3", "shrink", "centre", "bands", "rail-1st", "0.5 m/s", "rail-1st", "1.5", "3",
              "0.5 m/s", "rail-1st", "1.5", "3", "0.5");
  for (const pockets::DrDavePoint& point : table) {
    const double tp = point.target_in * pockets::kInch * 1000;
    const Row a = measure(Geometry::standard, kind, point.angle_deg, step, 3);
    const Row b = measure(Geometry::dr_dave_pockets, kind, point.angle_deg, step, 3);
    const Row c = measure(Geometry::dr_dave_plane, kind, point.angle_deg, step, 3);
    const Row bare = measure(Geometry::bare, kind, point.angle_deg, step, 1);
    const double shrink = a.target[0] > 0 ? 100 * (a.target[2] / a.target[0] - 1) : 0;
    std::printf(
        "%4.1f %5.1f | %s %6.1f %6.1f %+6.0f%% %+6.1f %5d %8.1f | %s %8.1f %6.1f %6.1f | %s %8.1f %6.1f %6.1f | "
        "%5.1f\n",
        point.angle_deg, tp, versus(a.target[0], tp).c_str(), a.target[1], a.target[2], shrink, a.centre, a.bands,
        a.rail_first, versus(b.target[0], tp).c_str(), b.rail_first, b.target[1], b.target[2],
        versus(c.target[0], tp).c_str(), c.rail_first, c.target[1], c.target[2], bare.target[0]);
    if (a.truncated || b.truncated || c.truncated || bare.truncated)
      std::printf("     (potting lines at the end of the offsets swept: the target may be wider)\n");
  }
}

void sweeps(double step) {
  std::printf(
      "Effective target, mm: the total width of the parallel lines along which a lone ball, rolling in at the\n"
      "angle, drops into the pocket (lines %.2f mm apart; the speed is the ball's abreast of the mouth). TP: Dr.\n"
      "Dave's TP 3.6 (corner) and TP 3.5 (side), slow shots; %% against it. shrink: 3 m/s against 0.5 m/s.\n"
      "centre: the slow target's middle, mm from the line through the mouth's middle, + toward the jaw passed\n"
      "first. bands: separate runs of potting lines. rail-1st: mm of the slow target from lines that meet the\n"
      "rail first. Standard table: jaw points rounded 5 mm, corner shelf 41.3 mm, noses 36.3 mm high (a ball\n"
      "meets them 27.5 mm from its centre). Dr. Dave's pockets: sharp jaw points, corner shelf 28.6 mm. His\n"
      "plane model: also the noses at the ball's equator (met 28.6 mm from its centre). Bare: the drop circles\n"
      "alone, no jaws.\n",
      step * 1000);
  print_kind("Corner (top-right), angle from the bisector, toward the long rail:", PocketKind::corner,
             pockets::kDrDaveCorner, step);
  print_kind("Side (top), angle from the perpendicular:", PocketKind::side, pockets::kDrDaveSide, step);
}

/// Every line of one sweep: where the ball starts, how fast, and what it meets (EVENTS=1: its events).
void lines(const pockets::SweepSpec& spec) {
  const Scene table = pockets::pocket_table(spec.geometry);
  const auto first = static_cast<int>(std::ceil(spec.min_offset / spec.step - 1e-9));
  const auto last = static_cast<int>(std::floor(spec.max_offset / spec.step + 1e-9));
  std::printf("offset_mm start_x start_y v0 counted jaw_hits rail_hits end_x end_y dropped\n");
  for (int k = first; k <= last; ++k) {
    const double offset = k * spec.step;
    const std::optional<Scene> scene = pockets::line_scene(table, spec, offset);
    if (!scene) continue;
    const SimulationResult r = simulate_events(*scene);
    const pockets::LineOutcome o = pockets::line_outcome(*scene, r, pockets::swept_pocket(spec.kind));
    const BallState end = r.segments[0].back().start;
    std::printf("%8.2f %8.4f %8.4f %6.3f %d %d %d %8.4f %8.4f %d\n", offset * 1000, scene->balls[0].position.x(),
                scene->balls[0].position.y(), scene->balls[0].velocity.norm(), o.potted ? 1 : 0, o.jaw_hits,
                o.rail_hits, end.position.x(), end.position.y(), o.dropped ? 1 : 0);
    if (std::getenv("EVENTS"))
      for (const Event& e : r.events)
        std::printf("    %s t=%.4f rail=%d pocket=%d speed=%.3f at (%.4f, %.4f)\n",
                    std::string(to_string(e.type)).c_str(), e.time, e.rail, e.pocket, e.speed, e.where.x(),
                    e.where.y());
  }
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Cost {
  double us = 0;        ///< median per break
  double events = 0;    ///< mean per break
  double tests = 0;     ///< mean contact tests per break
  double down = 0;      ///< mean object balls down
  double jaw_hits = 0;  ///< mean ball-jaw events
};

Cost time_breaks(const breaks::BreakSetup& setup, int count) {
  std::vector<Scene> scenes;
  for (int k = 1; k <= count; ++k) scenes.push_back(breaks::break_scene(setup, static_cast<std::uint64_t>(k)));
  for (int k = 0; k < std::min(count, 20); ++k) simulate_events(scenes[static_cast<std::size_t>(k)]);  // warm up
  Cost c;
  std::vector<double> us;
  for (const Scene& scene : scenes) {
    const auto t0 = Clock::now();
    const SimulationResult r = simulate_events(scene);
    us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
    c.events += static_cast<double>(r.events.size());
    c.tests += static_cast<double>(r.candidates_tested);
    for (const PocketDrop& d : r.drops) c.down += d.ball != 0 ? 1 : 0;
    for (const Event& e : r.events) c.jaw_hits += e.type == EventType::ball_jaw ? 1 : 0;
  }
  c.us = median(us);
  c.events /= count;
  c.tests /= count;
  c.down /= count;
  c.jaw_hits /= count;
  return c;
}

void cost(int count) {
  std::printf("\nThe jaws' cost: %d seeded 9-ball player's breaks (break_stats), the same breaks on both tables\n",
              count);
  breaks::BreakSetup jaws;
  breaks::BreakSetup bare = jaws;
  bare.bare_pockets = true;
  // Interleaved twice so that a change of the machine's load falls on both alike.
  Cost a = time_breaks(jaws, count), b = time_breaks(bare, count);
  const Cost a2 = time_breaks(jaws, count), b2 = time_breaks(bare, count);
  a.us = std::min(a.us, a2.us);
  b.us = std::min(b.us, b2.us);
  auto line = [](const char* name, const Cost& c) {
    std::printf(
        "  %-34s %7.1f us a break (median)  %5.1f events  %4.0f tests  %4.2f jaw hits  %4.2f down  %5.2f us an "
        "event\n",
        name, c.us, c.events, c.tests, c.jaw_hits, c.down, c.us / c.events);
  };
  line("cut pockets (jaws, shelf, hole)", a);
  line("bare drop circles (no jaws)", b);
  std::printf("  the jaws cost %+.0f%% a break\n", 100 * (a.us / b.us - 1));
}

}  // namespace

int main(int argc, char** argv) {
  double step_mm = 0.25;
  int count = 500;
  bool do_sweep = true, do_cost = true;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--step" && k + 1 < argc) {
      step_mm = std::strtod(argv[++k], nullptr);
    } else if (arg == "--breaks" && k + 1 < argc) {
      count = static_cast<int>(std::strtol(argv[++k], nullptr, 10));
    } else if (arg == "--lines" && k + 4 < argc) {
      pockets::SweepSpec spec;
      const std::string geometry = argv[k + 1];
      spec.geometry = geometry == "pockets" ? pockets::Geometry::dr_dave_pockets
                      : geometry == "plane" ? pockets::Geometry::dr_dave_plane
                      : geometry == "bare"  ? pockets::Geometry::bare
                                            : pockets::Geometry::standard;
      spec.kind = std::string(argv[k + 2]) == "side" ? PocketKind::side : PocketKind::corner;
      spec.angle_deg = std::strtod(argv[k + 3], nullptr);
      spec.speed = std::strtod(argv[k + 4], nullptr);
      spec.step = step_mm / 1000;
      lines(spec);
      return 0;
    } else if (arg == "--no-sweep") {
      do_sweep = false;
    } else if (arg == "--no-cost") {
      do_cost = false;
    } else {
      std::fprintf(stderr,
                   "usage: pocket_bench [--step MM] [--breaks N] [--no-sweep] [--no-cost]\n"
                   "       pocket_bench [--step MM] --lines standard|pockets|plane|bare corner|side ANGLE SPEED\n");
      return 2;
    }
  }
  if (!(step_mm > 0) || count <= 0) {
    std::fprintf(stderr, "pocket_bench: --step and --breaks take positive numbers\n");
    return 2;
  }
  const auto t0 = Clock::now();
  if (do_sweep) sweeps(step_mm / 1000);
  if (do_cost) cost(count);
  std::printf("\n(%.1f s)\n", std::chrono::duration<double>(Clock::now() - t0).count());
  return 0;
}
