#include "roots.h"

#include <algorithm>
#include <cmath>

namespace bsim {

namespace {

/// Width to which a root is narrowed, relative to max(1, |t|): far below any physical time scale
/// (a ball at 10 m/s moves 1e-11 m), yet above the round-off band of a polynomial near its root, so
/// Newton's answer can be bracketed instead of wandering in the noise.
double tolerance(double x) { return 1e-12 * std::max(1.0, std::abs(x)); }

struct Bracket {
  double lo, hi;
};

/// Narrows [lo, hi] around the one root of f inside, keeping which side is positive:
/// (f(lo) > 0) == lo_positive and (f(hi) > 0) != lo_positive throughout.
Bracket refine(const Poly& f, const Poly& df, double lo, double hi, bool lo_positive) {
  double x = 0.5 * (lo + hi);
  for (int i = 0; i < 200 && hi - lo > tolerance(hi); ++i) {
    const double fx = f(x);
    if ((fx > 0) == lo_positive)
      lo = x;
    else
      hi = x;
    const double d = df(x);
    double next = d != 0 ? x - fx / d : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) {
      next = 0.5 * (lo + hi);
    } else if (std::abs(next - x) <= tolerance(next)) {
      // Newton has converged from one side: probe just either side of its answer to close the bracket.
      const double tol = tolerance(next);
      const double l = std::max(lo, next - tol), h = std::min(hi, next + tol);
      if (l > lo && (f(l) > 0) == lo_positive) lo = l;
      if (h < hi && (f(h) > 0) != lo_positive) hi = h;
      next = 0.5 * (lo + hi);
    }
    x = next;
  }
  return {lo, hi};
}

void push(Roots& roots, double t) {
  if (roots.count > 0 && roots.t[static_cast<std::size_t>(roots.count - 1)] == t) return;
  if (roots.count < 4) roots.t[static_cast<std::size_t>(roots.count++)] = t;
}

/// lo, the roots of f' strictly inside (lo, hi), hi: the ends of the pieces on which f is monotone.
int breakpoints(const Poly& f, double lo, double hi, std::array<double, 6>& out) {
  int n = 0;
  out[static_cast<std::size_t>(n++)] = lo;
  if (f.degree() >= 2) {
    const Roots crit = roots_in(f.derivative(), lo, hi);
    for (int i = 0; i < crit.count; ++i) {
      const double t = crit.t[static_cast<std::size_t>(i)];
      if (t > lo && t < hi) out[static_cast<std::size_t>(n++)] = t;
    }
  }
  out[static_cast<std::size_t>(n++)] = hi;
  return n;
}

}  // namespace

int Poly::degree() const {
  for (int d = 4; d > 0; --d)
    if (c[static_cast<std::size_t>(d)] != 0) return d;
  return 0;
}

Roots roots_in(const Poly& f, double lo, double hi) {
  Roots roots;
  const int degree = f.degree();
  if (degree == 0 || !(lo <= hi)) return roots;
  if (degree == 1) {
    const double t = -f.c[0] / f.c[1];
    if (t >= lo && t <= hi) push(roots, t);
    return roots;
  }
  std::array<double, 6> points{};
  const int n = breakpoints(f, lo, hi, points);
  const Poly df = f.derivative();
  double a = points[0], fa = f(a);
  if (fa == 0) push(roots, a);
  for (int i = 1; i < n; ++i) {
    const double b = points[static_cast<std::size_t>(i)], fb = f(b);
    if (fb == 0) {
      push(roots, b);
    } else if (fa != 0 && (fa > 0) != (fb > 0)) {
      const Bracket r = refine(f, df, a, b, fa > 0);
      push(roots, 0.5 * (r.lo + r.hi));
    }
    a = b;
    fa = fb;
  }
  return roots;
}

std::optional<double> first_descent(const Poly& f, double lo, double hi) {
  if (f.degree() == 0 || !(lo <= hi)) return std::nullopt;
  std::array<double, 6> points{};
  const int n = breakpoints(f, lo, hi, points);
  double a = points[0];
  for (int i = 1; i < n; ++i) {
    const double b = points[static_cast<std::size_t>(i)];
    if (f(b) <= 0) return refine(f, f.derivative(), a, b, true).lo;
    a = b;
  }
  return std::nullopt;
}

}  // namespace bsim
