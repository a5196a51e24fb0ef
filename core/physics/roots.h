#pragma once
// Real roots of low-degree polynomials on an interval, for exact event times. Roots are isolated by
// splitting the interval at the roots of the derivative (found the same way, recursively), so each
// piece is monotone and a sign change brackets exactly one root; each is then refined by Newton's
// method safeguarded with bisection. No root is lost to complex round-off, as a closed-form quartic
// formula can lose the double root of a grazing contact.
#include <array>
#include <optional>

namespace bsim {

/// c[0] + c[1] t + ... + c[4] t^4.
struct Poly {
  std::array<double, 5> c{};
  double operator()(double t) const { return c[0] + t * (c[1] + t * (c[2] + t * (c[3] + t * c[4]))); }
  Poly derivative() const { return Poly{{c[1], 2 * c[2], 3 * c[3], 4 * c[4], 0}}; }
  int degree() const;
};

/// Up to four real roots, ascending.
struct Roots {
  std::array<double, 4> t{};
  int count = 0;
};

/// The real roots of f in [lo, hi], ascending; a root of even multiplicity counts when f reaches 0 there.
Roots roots_in(const Poly& f, double lo, double hi);

/// Whether f is clearly above zero all over [0, h], h > 0: every Bernstein coefficient of f on [0, h]
/// (whose least is a lower bound of f there) exceeds 1e-12 of the sum of the sizes of f's terms at h.
/// Evaluating f by Horner's rule anywhere in [0, h] errs by far less than that, so then f as evaluated
/// is > 0 at every point of [0, h].
bool clearly_positive(const Poly& f, double h);

/// The first time in [lo, hi] at which f comes down to <= 0, given f(lo) > 0: the last time before it
/// at which f is still > 0 (within 1e-12 max(1, t)), or nullopt when f stays > 0 on [lo, hi].
std::optional<double> first_descent(const Poly& f, double lo, double hi);

}  // namespace bsim
