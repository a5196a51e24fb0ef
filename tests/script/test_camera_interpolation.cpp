// The seed's interpolation pieces: Smooth, the quadratic Bezier, slerp of directions.
#include <doctest/doctest.h>
#include <cmath>

#include "camera_interpolation.h"

using namespace bsim;

namespace {
bool finite(const Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }
}  // namespace

TEST_SUITE("camera_interpolation") {
  TEST_CASE("Smooth runs from 0 to 1 with flat ends and matches the seed's two halves") {
    CHECK(smooth(0.0) == 0.0);
    CHECK(smooth(1.0) == 1.0);
    CHECK(smooth(0.5) == doctest::Approx(0.5));
    CHECK(smooth(0.25) == doctest::Approx(2 * 0.25 * 0.25));
    CHECK(smooth(0.75) == doctest::Approx(1 - 2 * 0.25 * 0.25));
    // Outside [0, 1] it holds its end values, so callers need not clamp.
    CHECK(smooth(-0.5) == 0.0);
    CHECK(smooth(1.5) == 1.0);
    // C1: the slope is 0 at both ends and the same on both sides of one half.
    const double h = 1e-6;
    CHECK(smooth(h) / h == doctest::Approx(0).epsilon(1e-5));
    CHECK((1 - smooth(1 - h)) / h == doctest::Approx(0).epsilon(1e-5));
    const double left = (smooth(0.5) - smooth(0.5 - h)) / h, right = (smooth(0.5 + h) - smooth(0.5)) / h;
    CHECK(left == doctest::Approx(right).epsilon(1e-4));
    double previous = 0;
    for (int i = 1; i <= 100; ++i) {
      const double value = smooth(i / 100.0);
      CHECK(value >= previous);
      previous = value;
    }
  }

  TEST_CASE("the Bezier look point starts and ends on its outer control points") {
    const Vec3 a(0, 0, 0), middle(1, 2, 0), b(2, 0, 1);
    CHECK((bezier(a, middle, b, 0) - a).norm() == 0);
    CHECK((bezier(a, middle, b, 1) - b).norm() == 0);
    // At one half: a/4 + middle/2 + b/4.
    CHECK((bezier(a, middle, b, 0.5) - (0.25 * a + 0.5 * middle + 0.25 * b)).norm() < 1e-15);
  }

  TEST_CASE("slerp stays on the unit sphere and turns at a constant rate") {
    const Vec3 a = Vec3(1, 0, 0), b = Vec3(0, 1, 0);
    for (int i = 0; i <= 10; ++i) {
      const Vec3 v = slerp_unit(a, b, i / 10.0);
      CHECK(v.norm() == doctest::Approx(1.0));
      CHECK(std::acos(std::clamp(v.dot(a), -1.0, 1.0)) == doctest::Approx(i / 10.0 * M_PI / 2));
    }
    CHECK((slerp_unit(a, b, 0) - a).norm() < 1e-15);
    CHECK((slerp_unit(a, b, 1) - b).norm() < 1e-15);
  }

  TEST_CASE("slerp of parallel and opposite directions gives no NaN") {
    const Vec3 down(0, 0, -1), up(0, 0, 1), east(1, 0, 0);
    for (int i = 0; i <= 4; ++i) {
      const double u = i / 4.0;
      CHECK((slerp_unit(down, down, u) - down).norm() < 1e-15);
      const Vec3 flip = slerp_unit(down, up, u);
      CHECK(finite(flip));
      CHECK(flip.norm() == doctest::Approx(1.0));
      const Vec3 turn = slerp_unit(east, -east, u);
      CHECK(finite(turn));
      // Opposite horizontal directions pan about the vertical rather than rolling over.
      CHECK(std::abs(turn.z()) < 1e-12);
    }
    CHECK((slerp_unit(down, up, 1) - up).norm() < 1e-12);
    CHECK(std::abs(slerp_unit(east, -east, 0.5).dot(east)) < 1e-12);
    // Straight down to oblique: halfway is halfway in angle.
    const Vec3 oblique = Vec3(1, 0, -1).normalized();
    CHECK(std::acos(slerp_unit(down, oblique, 0.5).dot(down)) == doctest::Approx(M_PI / 8));
  }

  TEST_CASE("unit_or falls back when the two points coincide") {
    const Vec3 fallback(0, 0, -1);
    CHECK((unit_or(Vec3(1, 1, 1), Vec3(1, 1, 1), fallback) - fallback).norm() == 0);
    CHECK((unit_or(Vec3(0, 0, 0), Vec3(0, 3, 4), fallback) - Vec3(0, 0.6, 0.8)).norm() < 1e-15);
  }
}
