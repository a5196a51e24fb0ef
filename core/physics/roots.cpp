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

/// f(x) for f of degree D, by Horner's rule over c[0..D] alone. The same bits as Poly::operator(): there
/// the coefficients above D are zeros, and adding a zero to the nonzero c[D] changes no bit.
template <int D>
double value(const Poly& f, double x) {
  double v = f.c[D];
  for (int k = D - 1; k >= 0; --k) v = f.c[static_cast<std::size_t>(k)] + x * v;
  return v;
}

/// Narrows [lo, hi] around the one root of f (of degree D) inside, keeping which side is positive:
/// (f(lo) > 0) == lo_positive and (f(hi) > 0) != lo_positive throughout.
template <int D>
Bracket refine(const Poly& f, double lo, double hi, bool lo_positive) {
  const Poly df = f.derivative();
  double x = 0.5 * (lo + hi);
  for (int i = 0; i < 200 && hi - lo > tolerance(hi); ++i) {
    const double fx = value<D>(f, x);
    if ((fx > 0) == lo_positive)
      lo = x;
    else
      hi = x;
    const double d = value<D - 1>(df, x);
    double next = d != 0 ? x - fx / d : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) {
      next = 0.5 * (lo + hi);
    } else if (std::abs(next - x) <= tolerance(next)) {
      // Newton has converged from one side: probe just either side of its answer to close the bracket.
      const double tol = tolerance(next);
      const double l = std::max(lo, next - tol), h = std::min(hi, next + tol);
      if (l > lo && (value<D>(f, l) > 0) == lo_positive) lo = l;
      if (h < hi && (value<D>(f, h) > 0) != lo_positive) hi = h;
      next = 0.5 * (lo + hi);
    }
    x = next;
  }
  return {lo, hi};
}

/// refine for f of degree 1 to 4, f's degree given.
Bracket refine(const Poly& f, int degree, double lo, double hi, bool lo_positive) {
  switch (degree) {
    case 1: return refine<1>(f, lo, hi, lo_positive);
    case 2: return refine<2>(f, lo, hi, lo_positive);
    case 3: return refine<3>(f, lo, hi, lo_positive);
    default: return refine<4>(f, lo, hi, lo_positive);
  }
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

bool clearly_positive(const Poly& f, double h) {
  std::array<double, 5> p{};
  double power = 1, size = 0;
  for (std::size_t k = 0; k < 5; ++k) {
    p[k] = f.c[k] * power;
    size += std::abs(p[k]);
    power *= h;
  }
  const double margin = 1e-12 * size;
  const double b1 = p[0] + p[1] / 4, b2 = p[0] + p[1] / 2 + p[2] / 6;
  const double b3 = p[0] + 0.75 * p[1] + p[2] / 2 + p[3] / 4, b4 = p[0] + p[1] + p[2] + p[3] + p[4];
  return p[0] > margin && b1 > margin && b2 > margin && b3 > margin && b4 > margin;
}

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
  double a = points[0], fa = f(a);
  if (fa == 0) push(roots, a);
  for (int i = 1; i < n; ++i) {
    const double b = points[static_cast<std::size_t>(i)], fb = f(b);
    if (fb == 0) {
      push(roots, b);
    } else if (fa != 0 && (fa > 0) != (fb > 0)) {
      const Bracket r = refine(f, degree, a, b, fa > 0);
      push(roots, 0.5 * (r.lo + r.hi));
    }
    a = b;
    fa = fb;
  }
  return roots;
}

std::optional<double> first_descent(const Poly& f, double lo, double hi) {
  const int degree = f.degree();
  if (degree == 0 || !(lo <= hi)) return std::nullopt;
  // Clearly positive all along: the search below could only find no descent.
  if (lo == 0 && hi > 0 && clearly_positive(f, hi)) return std::nullopt;
  std::array<double, 6> points{};
  const int n = breakpoints(f, lo, hi, points);
  double a = points[0];
  for (int i = 1; i < n; ++i) {
    const double b = points[static_cast<std::size_t>(i)];
    if (f(b) <= 0) return refine(f, degree, a, b, true).lo;
    a = b;
  }
  return std::nullopt;
}

}  // namespace bsim
