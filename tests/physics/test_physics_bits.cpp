// The physics to the bit over many shots: a hash of every segment, event and drop (physics_fingerprint.h)
// of seeded random breaks (tight racks and racks with gaps, spin, 2-10 m/s) and of seeded 100-ball
// tables, against tests/golden/physics/fingerprints.txt. The scenes' events.json goldens hold a dozen
// shots; this holds hundreds, so work on the simulator's speed that moves any bit of any of them shows
// here. Regenerate it only after an intended change in the physics (BSIM_UPDATE_GOLDENS=1).
//
// And what a simulation keeps on its thread from one shot to the next (the table's geometry, its
// working storage) changes nothing: shots on different tables and of different sizes, one after the
// other on one thread, each give what they give alone on a thread of their own.
#include <doctest/doctest.h>

#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "golden.h"
#include "physics_fingerprint.h"
#include "random_scenes.h"
#include "simulate.h"

using namespace bsim;

namespace {

std::string hex(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(value));
  return text;
}

std::uint64_t fingerprint(const Scene& scene) {
  test::PhysicsFingerprint f;
  f.add(simulate_events(scene));
  return f.hash();
}

/// The fingerprint of each scene simulated alone, on a new thread (nothing kept from another shot).
std::vector<std::uint64_t> each_alone(const std::vector<Scene>& scenes) {
  std::vector<std::uint64_t> hashes;
  for (const Scene& scene : scenes) {
    std::uint64_t hash = 0;
    std::thread([&] { hash = fingerprint(scene); }).join();
    hashes.push_back(hash);
  }
  return hashes;
}

}  // namespace

TEST_SUITE("simulate: bits") {
  TEST_CASE("seeded random breaks and 100-ball tables give the golden fingerprints") {
    std::string text;
    for (int block = 0; block < 8; ++block) {
      test::PhysicsFingerprint f;
      long events = 0;
      for (int seed = 50 * block + 1; seed <= 50 * block + 50; ++seed) {
        const SimulationResult r = simulate_events(scenes::random_break(static_cast<std::uint64_t>(seed)));
        events += static_cast<long>(r.events.size());
        f.add(r);
      }
      text += "random breaks " + std::to_string(50 * block + 1) + "-" + std::to_string(50 * block + 50) + ": " +
              hex(f.hash()) + " (" + std::to_string(events) + " events)\n";
    }
    for (int seed = 1; seed <= 6; ++seed)
      text += "100-ball table " + std::to_string(seed) + ": " +
              hex(fingerprint(scenes::stress_table(100, static_cast<std::uint64_t>(seed)))) + "\n";
    test::check_golden_text(test::golden_path("physics", "fingerprints.txt"), text);
  }

  TEST_CASE("shots one after the other on one thread give what each gives alone") {
    // A break that pockets four balls and meets two jaws, on tables that differ from the standard one
    // in one kind of value each: the rails' nose height, the pockets' radius, their jaws' rounding,
    // pockets no longer cut, the balls' radius; and shots of 16, 2 and 100 balls.
    const Scene standard = scenes::random_break(12);
    std::vector<Scene> shots(6, standard);
    for (Rail& rail : shots[1].rails) rail.a.z() = rail.b.z() = rail.a.z() + 1e-6;
    for (Pocket& pocket : shots[2].pockets) pocket.radius *= 1.05;
    for (Pocket& pocket : shots[3].pockets) pocket.jaw_radius *= 1.5;
    for (Pocket& pocket : shots[4].pockets) pocket.cut = false;
    shots[5].physics.ball_radius *= 0.999;
    shots.push_back(scenes::two_ball_shot());
    shots.push_back(scenes::stress_table(100, 3));
    shots.push_back(standard);
    const std::vector<std::uint64_t> alone = each_alone(shots);
    // Each changed table changes this break, so a table's geometry kept from the shot before would show.
    for (std::size_t k = 1; k <= 5; ++k) CHECK(alone[k] != alone[0]);
    CHECK(alone[8] == alone[0]);
    for (std::size_t k = 0; k < shots.size(); ++k) {
      CAPTURE(k);
      CHECK(fingerprint(shots[k]) == alone[k]);
    }
  }
}
