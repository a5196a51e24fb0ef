// Root isolation for the event times: roots are found by splitting at the derivative's roots, so
// double roots (grazing contacts) and degenerate polynomials are handled without complex round-off.
#include <doctest/doctest.h>

#include <cmath>

#include "random_scenes.h"
#include "roots.h"

using namespace bsim;

namespace {

/// (t - a)(t - b)(t - c)(t - d) as coefficients, scaled by k.
Poly from_roots(double a, double b, double c, double d, double k = 1) {
  const double s1 = a + b + c + d;
  const double s2 = a * b + a * c + a * d + b * c + b * d + c * d;
  const double s3 = a * b * c + a * b * d + a * c * d + b * c * d;
  const double s4 = a * b * c * d;
  return Poly{{k * s4, -k * s3, k * s2, -k * s1, k}};
}

}  // namespace

TEST_SUITE("detect: roots") {
  TEST_CASE("four distinct roots are all found, in order") {
    const Roots r = roots_in(from_roots(0.3, 1.1, 2.5, 4.0), 0, 10);
    REQUIRE(r.count == 4);
    CHECK(r.t[0] == doctest::Approx(0.3).epsilon(1e-12));
    CHECK(r.t[1] == doctest::Approx(1.1).epsilon(1e-12));
    CHECK(r.t[2] == doctest::Approx(2.5).epsilon(1e-12));
    CHECK(r.t[3] == doctest::Approx(4.0).epsilon(1e-12));
  }

  TEST_CASE("only roots inside the interval count") {
    CHECK(roots_in(from_roots(-1, 0.5, 3, 7), 0, 2).count == 1);
    CHECK(roots_in(from_roots(-1, -0.5, 3, 7), 0, 2).count == 0);
  }

  TEST_CASE("a double root (a grazing contact) is found where the polynomial touches zero") {
    // (t - 1)^2 (t - 3)(t - 5): positive on [0, 2] except that it touches zero at t = 1.
    const Poly f = from_roots(1, 1, 3, 5);
    const auto touch = first_descent(f, 0, 2);
    REQUIRE(touch.has_value());
    CHECK(*touch == doctest::Approx(1).epsilon(1e-6));
    // Lifted by a hair it never reaches zero; lowered by a hair it crosses twice near 1.
    Poly above = f, below = f;
    above.c[0] += 1e-9;
    below.c[0] -= 1e-9;
    CHECK_FALSE(first_descent(above, 0, 2).has_value());
    const auto t = first_descent(below, 0, 2);
    REQUIRE(t.has_value());
    CHECK(*t == doctest::Approx(1).epsilon(1e-4));
    CHECK(*t < 1);
  }

  TEST_CASE("first_descent returns the last time the polynomial is still positive") {
    const Poly f = from_roots(0.75, 2, 3, 4, 2.5);
    const auto t = first_descent(f, 0, 10);
    REQUIRE(t.has_value());
    CHECK(f(*t) > 0);
    CHECK(*t == doctest::Approx(0.75).epsilon(1e-12));
    CHECK(f(*t + 2e-12) <= 0);
  }

  TEST_CASE("degenerate polynomials: leading coefficients zero or vanishingly small") {
    // Quadratic written as a quartic.
    const Poly quadratic{{2, -3, 1, 0, 0}};  // roots 1 and 2
    const Roots r = roots_in(quadratic, 0, 5);
    REQUIRE(r.count == 2);
    CHECK(r.t[0] == doctest::Approx(1));
    CHECK(r.t[1] == doctest::Approx(2));
    // A tiny quartic term (two balls with nearly equal accelerations) must not disturb the near root.
    Poly nearly{{2, -3, 1, 1e-20, 1e-30}};
    const auto t = first_descent(nearly, 0, 1.5);
    REQUIRE(t.has_value());
    CHECK(*t == doctest::Approx(1).epsilon(1e-12));
    // Linear and constant.
    CHECK(roots_in(Poly{{-1, 2, 0, 0, 0}}, 0, 1).count == 1);
    CHECK(roots_in(Poly{{3, 0, 0, 0, 0}}, 0, 1).count == 0);
    CHECK_FALSE(first_descent(Poly{{3, 0, 0, 0, 0}}, 0, 1).has_value());
  }

  TEST_CASE("roots of very different scales are each found to relative precision") {
    const Roots r = roots_in(from_roots(1e-6, 1e-3, 1, 1e3), 0, 2000);
    REQUIRE(r.count == 4);
    CHECK(r.t[0] == doctest::Approx(1e-6).epsilon(1e-5));
    CHECK(r.t[3] == doctest::Approx(1e3).epsilon(1e-12));
  }

  TEST_CASE("clearly_positive: never where the polynomial comes to zero, and it does answer for one far above it") {
    // Random quartics of every scale, and each lowered until it grazes zero inside [0, h]: whenever
    // clearly_positive says so, f as evaluated is > 0 all over [0, h] and no root is found there, so
    // first_descent's shortcut changes no answer.
    scenes::Rng rng(7);
    int clear = 0, grazing = 0;
    for (int k = 0; k < 4000; ++k) {
      Poly f;
      for (double& c : f.c) c = rng.uniform(-1, 1) * std::pow(10.0, rng.uniform(-6, 3));
      f.c[4] = std::abs(f.c[4]);
      const double h = std::pow(10.0, rng.uniform(-4, 1));
      double least = INFINITY;
      for (int i = 0; i <= 1000; ++i) least = std::min(least, f(h * i / 1000));
      // Half of them lowered to touch zero at the least of the samples: a grazing contact.
      if (k % 2 == 1 && least > 0) {
        f.c[0] -= least;
        ++grazing;
      }
      if (!clearly_positive(f, h)) continue;
      ++clear;
      CAPTURE(k);
      bool above = true;
      for (int i = 0; i <= 10000; ++i) above = above && f(h * i / 10000) > 0;
      REQUIRE(above);
      REQUIRE(roots_in(f, 0, h).count == 0);
      REQUIRE_FALSE(first_descent(f, 0, h).has_value());
    }
    CHECK(clear > 500);
    CHECK(grazing > 500);
    // A gap of a millimetre closing at 1 m/s over 0.5 ms is clear; over 2 ms it is not (it closes at 1 ms).
    const Poly gap{{1e-3, -1, 0, 0, 0}};
    CHECK(clearly_positive(gap, 0.5e-3));
    CHECK_FALSE(clearly_positive(gap, 2e-3));
    // A polynomial that touches zero inside (a double root) is never clear.
    CHECK_FALSE(clearly_positive(from_roots(0.5, 0.5, 3, 4), 1));
  }
}
