#include "cushion_gaps.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace bsim {

namespace {

/// m: a gap this much wider than two reaches, or a passage point this far outside a drop circle,
/// counts (far below anything a person types).
constexpr double kGapTolerance = 1e-9;

/// Whether the pockets' drop circles cover the points p + t u of the table plane, t from t0 to t1.
bool covered(const Vec3& p, const Vec3& u, double t0, double t1, const std::vector<Pocket>& pockets) {
  std::vector<std::pair<double, double>> spans;
  for (const Pocket& pocket : pockets) {
    const Vec3 c = flat(pocket.center) - p;
    const double s = c.dot(u);
    const double half2 = pocket.radius * pocket.radius - (c.squaredNorm() - s * s);
    if (half2 > 0) spans.emplace_back(s - std::sqrt(half2), s + std::sqrt(half2));
  }
  std::sort(spans.begin(), spans.end());
  double reached = t0;
  for (const auto& [from, to] : spans) {
    if (reached >= t1 - kGapTolerance) break;
    if (from > reached + kGapTolerance) return false;
    reached = std::max(reached, to);
  }
  return reached >= t1 - kGapTolerance;
}

/// Whether a cut pocket's jaws close the gap from a to b: its jaw points are the gap's two ends, and the
/// facings behind them lead a ball to its hole.
bool jaws_close(const Vec3& a, const Vec3& b, const std::vector<Pocket>& pockets) {
  const auto at = [](const Vec3& p, const Vec3& q) { return (flat(p) - flat(q)).norm() <= kGapTolerance; };
  return std::any_of(pockets.begin(), pockets.end(), [&](const Pocket& p) {
    return p.cut && ((at(p.jaw[0], a) && at(p.jaw[1], b)) || (at(p.jaw[0], b) && at(p.jaw[1], a)));
  });
}

/// next[i]: the rail whose first end follows rail i's second end, the closest pairs taken first.
std::vector<int> pair_ends(const std::vector<Rail>& rails) {
  const int n = static_cast<int>(rails.size());
  std::vector<std::tuple<double, int, int>> pairs;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      pairs.emplace_back(
          (flat(rails[static_cast<std::size_t>(i)].b) - flat(rails[static_cast<std::size_t>(j)].a)).norm(), i, j);
  std::sort(pairs.begin(), pairs.end());
  std::vector<int> next(rails.size(), -1);
  std::vector<char> taken(rails.size(), 0);
  for (const auto& [distance, i, j] : pairs) {
    if (next[static_cast<std::size_t>(i)] >= 0 || taken[static_cast<std::size_t>(j)]) continue;
    next[static_cast<std::size_t>(i)] = j;
    taken[static_cast<std::size_t>(j)] = 1;
  }
  return next;
}

/// Twice the signed area of the outline through each rail's ends in `cycle` order: < 0 clockwise.
double twice_area(const std::vector<Rail>& rails, const std::vector<int>& cycle) {
  std::vector<Vec3> corners;
  for (int i : cycle) {
    corners.push_back(rails[static_cast<std::size_t>(i)].a);
    corners.push_back(rails[static_cast<std::size_t>(i)].b);
  }
  double sum = 0;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const Vec3& p = corners[k];
    const Vec3& q = corners[(k + 1) % corners.size()];
    sum += p.x() * q.y() - q.x() * p.y();
  }
  return sum;
}

}  // namespace

double nose_reach(double ball_radius, double nose_height) {
  const double lift = nose_height - ball_radius;
  return std::sqrt(std::max(0.0, ball_radius * ball_radius - lift * lift));
}

std::vector<CushionGap> open_cushion_gaps(const std::vector<Rail>& rails, const std::vector<Pocket>& pockets,
                                          double ball_radius, bool& enclosed) {
  const std::vector<int> next = pair_ends(rails);
  std::vector<double> reach;
  for (const Rail& rail : rails) reach.push_back(nose_reach(ball_radius, rail.a.z()));
  std::vector<CushionGap> gaps;
  std::vector<char> seen(rails.size(), 0);
  enclosed = false;
  for (std::size_t start = 0; start < rails.size(); ++start) {
    if (seen[start]) continue;
    std::vector<int> cycle;
    for (int i = static_cast<int>(start); !seen[static_cast<std::size_t>(i)]; i = next[static_cast<std::size_t>(i)]) {
      seen[static_cast<std::size_t>(i)] = 1;
      cycle.push_back(i);
    }
    if (!(twice_area(rails, cycle) < -kGapTolerance)) continue;  // an obstacle on the bed, not its edge
    enclosed = true;
    for (int i : cycle) {
      const auto u = static_cast<std::size_t>(i), v = static_cast<std::size_t>(next[u]);
      const Rail &from = rails[u], &to = rails[v];
      if (reach[u] == 0) gaps.push_back({i, i, flat(from.a), flat(from.b), true});
      if (reach[u] == 0 || reach[v] == 0) continue;
      const Vec3 a = flat(from.b), b = flat(to.a);
      const double width = (b - a).norm();
      if (width <= reach[u] + reach[v] + kGapTolerance || jaws_close(a, b, pockets)) continue;
      if (!covered(a, (b - a) / width, reach[u], width - reach[v], pockets)) gaps.push_back({i, next[u], a, b, false});
    }
  }
  std::sort(gaps.begin(), gaps.end(),
            [](const CushionGap& x, const CushionGap& y) { return x.from_rail < y.from_rail; });
  return gaps;
}

}  // namespace bsim
