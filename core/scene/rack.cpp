#include "rack.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "check.h"

namespace bsim {

namespace {

/// Balls in each row, from the apex. 8-ball and 10-ball: a triangle; 9-ball: a diamond.
std::vector<int> row_widths(RackGame game) {
  switch (game) {
    case RackGame::eight_ball: return {1, 2, 3, 4, 5};
    case RackGame::nine_ball: return {1, 2, 3, 2, 1};
    case RackGame::ten_ball: return {1, 2, 3, 4};
  }
  return {};
}

/// A place in the rack, in units of the nominal radius, the apex at the origin: the perfect rack's.
struct Slot {
  int row = 0, column = 0;
  double x = 0, y = 0;
};

std::vector<Slot> slots(RackGame game) {
  const double row_step = std::sqrt(3.0);  // rows of touching balls are sqrt(3) radii apart
  std::vector<Slot> out;
  const std::vector<int> widths = row_widths(game);
  for (int row = 0; row < static_cast<int>(widths.size()); ++row) {
    const int width = widths[static_cast<std::size_t>(row)];
    for (int column = 0; column < width; ++column)
      out.push_back({row, column, row * row_step, 2.0 * column - (width - 1)});
  }
  return out;
}

/// The slot index of (row, column).
std::size_t slot_at(const std::vector<Slot>& all, int row, int column) {
  for (std::size_t i = 0; i < all.size(); ++i)
    if (all[i].row == row && all[i].column == column) return i;
  BSIM_EXPECT(false, "no such place in the rack");
  return 0;
}

/// Which painted number goes in each slot, by the game's rules (WPA World Standardized Rules, the racks
/// of Eight Ball, Nine Ball and Ten Ball, rule 9.2: "the one ball at the apex ... the ten ball in the
/// middle of the triangle", the others "without purposeful or intentional pattern"), the rest at random:
/// 8-ball the 8 in the middle of the third row, a stripe and a solid in the back corners (which corner
/// from the seed); 9-ball the 1 at the apex, the 9 in the middle of the diamond; 10-ball the 1 at the
/// apex, the 10 in the middle of the third row.
std::vector<int> placement(RackGame game, const std::vector<Slot>& all, SplitMix64& random) {
  std::vector<int> number(all.size(), 0);
  const std::size_t middle = slot_at(all, 2, 1);
  if (game == RackGame::eight_ball) {
    number[middle] = 8;
    const int solid = 1 + static_cast<int>(random.below(7));
    const int stripe = 9 + static_cast<int>(random.below(7));
    const bool solid_first = random.below(2) == 0;
    number[slot_at(all, 4, 0)] = solid_first ? solid : stripe;
    number[slot_at(all, 4, 4)] = solid_first ? stripe : solid;
  } else {
    number[0] = 1;
    number[middle] = game == RackGame::nine_ball ? 9 : 10;
  }
  std::vector<int> rest;
  for (int n = 1; n <= rack_ball_count(game); ++n)
    if (std::find(number.begin(), number.end(), n) == number.end()) rest.push_back(n);
  // Fisher-Yates, then the shuffled numbers fill the open slots in order.
  for (std::size_t i = rest.size(); i > 1; --i) std::swap(rest[i - 1], rest[random.below(i)]);
  std::size_t next = 0;
  for (int& n : number)
    if (n == 0) n = rest[next++];
  return number;
}

struct Point {
  double x = 0, y = 0;
};

double distance(Point a, Point b) { return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y)); }

/// A side of the frame: the centres of a ball of radius r may lie where normal . (p - corner) >= r.
struct FrameSide {
  Point corner, normal;  ///< normal: unit, pointing into the rack
};

/// Settles balls one at a time: each comes to rest as far toward the apex (-x) as the balls already in
/// place and the frame's sides let it, touching two of them, near its own place in the perfect rack.
class Settler {
 public:
  Settler(double apex_radius) {
    // The apex ball sits in the frame's 60-degree corner touching both sides, 2 r from the corner.
    const double half = 0.5, root3_half = std::sqrt(3.0) / 2;
    const Point corner{-2.0 * apex_radius, 0.0};
    sides_[0] = {corner, {half, root3_half}};   // the -y side
    sides_[1] = {corner, {half, -root3_half}};  // the +y side
  }

  /// Where a ball of `radius` near `slot` comes to rest; the first ball (the apex) at the origin.
  Point settle(double radius, const Slot& slot) {
    Point best{0, 0};
    if (!placed_.empty()) best = lowest_candidate(radius, slot);
    placed_.push_back({best, radius});
    return best;
  }

 private:
  struct Placed {
    Point centre;
    double radius = 0;
  };

  /// Centre distance at contact with a placed ball: the drawn radii, never under two nominal radii.
  static double contact(double radius, const Placed& other) { return std::max(2.0, radius + other.radius); }

  bool feasible(Point p, double radius, const Slot& slot) const {
    constexpr double kSlack = 1e-12;
    if (distance(p, {slot.x, slot.y}) > 1.0) return false;
    for (const Placed& other : placed_)
      if (distance(p, other.centre) < contact(radius, other) - kSlack) return false;
    for (const FrameSide& side : sides_)
      if (side.normal.x * (p.x - side.corner.x) + side.normal.y * (p.y - side.corner.y) < radius - kSlack) return false;
    return true;
  }

  void consider(Point p, double radius, const Slot& slot, Point& best, bool& found) const {
    if (!feasible(p, radius, slot)) return;
    const bool better = !found || p.x < best.x || (p.x == best.x && std::abs(p.y - slot.y) < std::abs(best.y - slot.y));
    if (better) best = p;
    found = true;
  }

  /// The two points at distances a from A and b from B (none when the circles miss).
  void circles(Point A, double a, Point B, double b, double radius, const Slot& slot, Point& best, bool& found) const {
    const double d = distance(A, B);
    if (d == 0 || d > a + b || d < std::abs(a - b)) return;
    const double along = (a * a - b * b + d * d) / (2 * d);
    const double h = std::sqrt(std::max(0.0, a * a - along * along));
    const Point u{(B.x - A.x) / d, (B.y - A.y) / d};
    const Point m{A.x + along * u.x, A.y + along * u.y};
    consider({m.x - h * u.y, m.y + h * u.x}, radius, slot, best, found);
    consider({m.x + h * u.y, m.y - h * u.x}, radius, slot, best, found);
  }

  /// The two points at distance a from A and `radius` inside the frame side.
  void against_side(Point A, double a, const FrameSide& side, double radius, const Slot& slot, Point& best,
                    bool& found) const {
    const Point n = side.normal;
    const double t = n.x * (A.x - side.corner.x) + n.y * (A.y - side.corner.y) - radius;
    if (std::abs(t) > a) return;
    const double h = std::sqrt(a * a - t * t);
    const Point foot{A.x - t * n.x, A.y - t * n.y};
    consider({foot.x - h * n.y, foot.y + h * n.x}, radius, slot, best, found);
    consider({foot.x + h * n.y, foot.y - h * n.x}, radius, slot, best, found);
  }

  Point lowest_candidate(double radius, const Slot& slot) const {
    Point best{slot.x, slot.y};
    bool found = false;
    for (std::size_t i = 0; i < placed_.size(); ++i) {
      const Placed& a = placed_[i];
      for (const FrameSide& side : sides_) against_side(a.centre, contact(radius, a), side, radius, slot, best, found);
      for (std::size_t j = i + 1; j < placed_.size(); ++j)
        circles(a.centre, contact(radius, a), placed_[j].centre, contact(radius, placed_[j]), radius, slot, best,
                found);
    }
    BSIM_EXPECT(found, "a racked ball found no place to rest");
    return best;
  }

  FrameSide sides_[2];
  std::vector<Placed> placed_;
};

}  // namespace

std::optional<RackGame> rack_game(std::string_view name) {
  if (name == "8ball") return RackGame::eight_ball;
  if (name == "9ball") return RackGame::nine_ball;
  if (name == "10ball") return RackGame::ten_ball;
  return std::nullopt;
}

std::string_view rack_game_name(RackGame game) {
  switch (game) {
    case RackGame::eight_ball: return kRackGameNames[0];
    case RackGame::nine_ball: return kRackGameNames[1];
    case RackGame::ten_ball: return kRackGameNames[2];
  }
  return {};
}

int rack_ball_count(RackGame game) {
  switch (game) {
    case RackGame::eight_ball: return 15;
    case RackGame::nine_ball: return 9;
    case RackGame::ten_ball: return 10;
  }
  return 0;
}

std::vector<RackedBall> rack_balls(const RackSpec& spec) {
  SplitMix64 random(spec.seed);
  const std::vector<Slot> all = slots(spec.game);
  const std::vector<int> number = placement(spec.game, all, random);
  // Each ball's radius in nominal radii, by painted number, uniform within the tolerance.
  std::vector<double> radius(all.size() + 1, 1.0);
  for (std::size_t n = 1; n < radius.size(); ++n) {
    const double drawn = 1.0 + (2.0 * random.uniform() - 1.0) * spec.tolerance;
    if (!spec.tight) radius[n] = drawn;
  }
  std::vector<RackedBall> out;
  Settler settler(radius[static_cast<std::size_t>(number[0])]);
  for (std::size_t i = 0; i < all.size(); ++i) {
    const double r = radius[static_cast<std::size_t>(number[i])];
    const Point p = spec.tight ? Point{all[i].x, all[i].y} : settler.settle(r, all[i]);
    out.push_back({number[i], all[i].row, all[i].column, kFootSpotX + p.x * spec.radius, kFootSpotY + p.y * spec.radius,
                   2.0 * r * spec.radius});
  }
  std::sort(out.begin(), out.end(), [](const RackedBall& a, const RackedBall& b) { return a.number < b.number; });
  return out;
}

}  // namespace bsim
