// Where a frame can differ from another of the same camera (export/changed_region.h), from geometry
// alone: every point of what changed lands in a rectangle, the rectangles do not overlap, and a long
// thin part is held by a chain of rectangles, not by the box round it.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "builtin_scene.h"
#include "camera_view.h"
#include "changed_region.h"
#include "pocket_fall.h"
#include "scene_parse.h"
#include "table.h"

using namespace bsim;

namespace {

constexpr int kWidth = 640, kHeight = 360;

/// The built-in break's table and room.
RegionScene standard_room() {
  const ParseResult parsed = parse_scene(builtin_scene_text(), "break");
  REQUIRE(parsed.scene);
  return region_scene(*parsed.scene);
}

/// Two frames of one camera in which one part, seen as `seen` and casting `casts`, changed.
std::pair<FrameContent, FrameContent> one_change(const CameraPose& pose, const std::vector<BoundCapsule>& seen,
                                                 const std::vector<BoundCapsule>& casts) {
  FrameContent a;
  a.camera = "camera";
  a.camera_pose = pose;
  a.parts.push_back({"before", seen, casts, false});
  FrameContent b = a;
  b.parts[0].text = "after";
  return {a, b};
}

/// The pixel `p` lands on, or none when it is not in the picture.
std::optional<std::pair<int, int>> pixel_of(const CameraPose& pose, const Vec3& p) {
  const CameraView view(pose, kCameraFovDeg, static_cast<double>(kWidth) / kHeight);
  const std::optional<PicturePoint> at = view.project(p);
  if (!at || std::abs(at->x) >= 1 || std::abs(at->y) >= 1) return std::nullopt;
  return std::pair{static_cast<int>(0.5 * kWidth * (1 + at->x)), static_cast<int>(0.5 * kHeight * (1 - at->y))};
}

bool in_some(const std::vector<PixelRect>& rects, std::pair<int, int> pixel) {
  return std::any_of(rects.begin(), rects.end(), [&](const PixelRect& r) {
    return pixel.first >= r.x0 && pixel.first < r.x1 && pixel.second >= r.y0 && pixel.second < r.y1;
  });
}

bool overlap(const PixelRect& a, const PixelRect& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

long total_area(const std::vector<PixelRect>& rects) {
  long area = 0;
  for (const PixelRect& r : rects) area += r.area();
  return area;
}

}  // namespace

TEST_SUITE("changed region") {
  TEST_CASE("a stick lying across the picture is held by a chain of rectangles, far less than its box") {
    const RegionScene room = standard_room();
    const CameraPose pose{Vec3(0, -2.2, 0.95), Vec3(0, 0, 0), false};  // below the shade's rim
    // The stick from over the cloth's middle up to the far right, as a player holds it: 1.47 m.
    const BoundCapsule stick{{Vec3(-0.6, -0.3, 0.05), 0.017}, {Vec3(0.75, 0.25, 0.45), 0.017}};
    const auto [before, after] = one_change(pose, {stick}, {});
    const auto rects = changed_region(before, after, room, kWidth, kHeight);
    REQUIRE(rects);
    REQUIRE(!rects->empty());
    for (int k = 0; k <= 200; ++k) {
      const double u = k / 200.0;
      const auto pixel = pixel_of(pose, stick.a.centre + u * (stick.b.centre - stick.a.centre));
      REQUIRE(pixel);
      CAPTURE(u);
      CHECK(in_some(*rects, *pixel));
    }
    // The box round the stick's two ends in the picture.
    const auto a = *pixel_of(pose, stick.a.centre), b = *pixel_of(pose, stick.b.centre);
    const long box = static_cast<long>(std::abs(a.first - b.first)) * std::abs(a.second - b.second);
    CHECK(rects->size() >= 3);
    CHECK(total_area(*rects) < box * 6 / 10);
    for (std::size_t i = 0; i < rects->size(); ++i)
      for (std::size_t j = i + 1; j < rects->size(); ++j) CHECK_FALSE(overlap((*rects)[i], (*rects)[j]));
  }

  TEST_CASE("a ball's shadow near a pocket takes in all the lamp lights inside that pocket's cup") {
    const RegionScene room = standard_room();
    REQUIRE(room.pockets.size() == 6);
    const RegionScene::Opening pocket = room.pockets[0];
    // A ball on the cloth by that pocket, seen from across the table, below the shade's rim.
    const Vec3 ball(pocket.x * 0.93, pocket.y * 0.86, 0.028575);
    const BoundSphere s{ball, 0.03};
    const CameraPose pose{Vec3(-pocket.x, -pocket.y * 3, 0.95), Vec3(pocket.x, pocket.y, 0), false};
    const auto [before, after] = one_change(pose, {{s, s}}, {{s, s}});
    const auto rects = changed_region(before, after, room, kWidth, kHeight);
    REQUIRE(rects);
    // The cup's floor right under the opening's edge, where light falling through it lands.
    for (double angle = 0; angle < 6.28; angle += 0.5) {
      const Vec3 floor(pocket.x + 0.9 * pocket.radius * std::cos(angle),
                       pocket.y + 0.9 * pocket.radius * std::sin(angle), room.cup_floor);
      const auto pixel = pixel_of(pose, floor);
      if (!pixel) continue;
      CAPTURE(angle);
      CHECK(in_some(*rects, *pixel));
    }
    // A ball in the middle of the cloth reaches no cup: the rectangles stay round it and its shadow.
    const BoundSphere middle{Vec3(0.1, 0.05, 0.028575), 0.03};
    const auto [b2, a2] = one_change(pose, {{middle, middle}}, {{middle, middle}});
    const auto small = changed_region(b2, a2, room, kWidth, kHeight);
    REQUIRE(small);
    CHECK(total_area(*small) < kWidth * kHeight / 50);
  }

  TEST_CASE("the lamp's light reaches a corner's cup through its hole alone, not over its shelf or jaws") {
    const RegionScene room = standard_room();
    const ParseResult parsed = parse_scene(builtin_scene_text(), "break");
    REQUIRE(parsed.scene);
    const PocketMouth m = table_layout(*parsed.scene).pockets[2];  // the top-right corner
    REQUIRE(m.cut);
    // Looking straight down at the corner from below the shade's rim.
    const CameraPose pose{Vec3(1.2, 0.6, 1.0), Vec3(1.2, 0.6, 0), false};
    // The cup's floor at the back of the hole, under where the light through it can fall.
    std::vector<Vec3> cup;
    for (double a = -1; a <= 1; a += 0.5) {
      const Vec3 side(-m.axis.y(), m.axis.x(), 0);
      cup.push_back(m.centre + 0.8 * m.drop_radius * (std::cos(a) * m.axis + std::sin(a) * side) +
                    Vec3(0, 0, -kPocketDepth));
    }
    const auto region_of = [&](const Vec3& ball) {
      const BoundSphere s{ball, 0.03};
      const auto [before, after] = one_change(pose, {{s, s}}, {{s, s}});
      const auto rects = changed_region(before, after, room, kWidth, kHeight);
      REQUIRE(rects);
      return *rects;
    };
    // A ball on the shelf throws its shadow into the hole: the cup behind it is in the region.
    const auto on_shelf = region_of((m.nose[0] + m.nose[1]) / 2 + m.axis * 0.015 + Vec3(0, 0, 0.028575));
    for (const Vec3& p : cup) {
      const auto pixel = pixel_of(pose, p);
      REQUIRE(pixel);
      CHECK(in_some(on_shelf, *pixel));
    }
    // A ball by the top cushion short of the jaw: its shadow may reach the mouth and the jaws but not
    // the hole, so nothing in the cup changes and the region stays round the ball and its shadow.
    const auto by_jaw = region_of(Vec3(1.05, 0.6, 0.028575));
    for (const Vec3& p : cup) {
      const auto pixel = pixel_of(pose, p);
      REQUIRE(pixel);
      CHECK(!in_some(by_jaw, *pixel));
    }
  }

  TEST_CASE("a ball seen in the lamp shade's lacquer, from above its rim, is in the region") {
    const RegionScene room = standard_room();
    REQUIRE(room.shade_faces.size() == 8);
    const RegionScene::Mirror& side = room.shade_faces[0];  // the side facing +y
    REQUIRE(side.normal.y() > 0.5);
    // An eye above the rim and close to that side, looking down at it: a point Q on the face mirrors
    // what lies along the view reflected there, which goes down to the cloth.
    const Vec3 eye = side.point + Vec3(0.0, 0.1, 0.8);
    const Vec3 q = side.point + 0.05 * Vec3(0, -side.normal.z(), side.normal.y()) + Vec3(0.1, 0, 0);  // up the face
    const Vec3 d = (q - eye).normalized();
    const Vec3 r = d - 2 * d.dot(side.normal) * side.normal;
    REQUIRE(r.z() < 0);
    const Vec3 ball = q + ((0.028575 - q.z()) / r.z()) * r;  // where that reflected ray meets a ball's centre height
    const CameraPose pose{eye, q, false};
    const BoundSphere s{ball, 0.03};
    const auto [before, after] = one_change(pose, {{s, s}}, {});
    const auto rects = changed_region(before, after, room, kWidth, kHeight);
    REQUIRE(rects);
    const auto pixel = pixel_of(pose, q);
    REQUIRE(pixel);
    CHECK(in_some(*rects, *pixel));
    // Seen from below the rim the shade shows nothing of the table: only the ball itself is traced.
    const CameraPose low{Vec3(0, 2.0, 0.5), ball, false};
    const auto [b2, a2] = one_change(low, {{s, s}}, {});
    const auto ball_only = changed_region(b2, a2, room, kWidth, kHeight);
    REQUIRE(ball_only);
    CHECK(ball_only->size() == 1);
  }

  TEST_CASE("the stick swinging down through the lamp's light beside the lamp still has a bounded shadow") {
    const RegionScene room = standard_room();
    // A player's stick behind the head rail, its butt up at the height of the lamp's light, well
    // beside the lamp seen from above: the lamp's cone cannot reach far beyond it.
    const BoundCapsule stick{{Vec3(-1.45, 0.0, 0.08), 0.017}, {Vec3(-2.25, 0.0, room.light_z + 0.05), 0.017}};
    const CameraPose pose{Vec3(0.5, -2.5, 0.95), Vec3(-0.8, 0, 0.2), false};
    const auto [before, after] = one_change(pose, {stick}, {stick});
    const auto rects = changed_region(before, after, room, kWidth, kHeight);
    REQUIRE(rects);
    CHECK(total_area(*rects) < kWidth * kHeight / 2);
    // Straight over the lamp's light the same height is not bounded: the frame is traced whole.
    const BoundCapsule over{{Vec3(0.0, 0.0, 0.5), 0.017}, {Vec3(0.1, 0.0, room.light_z + 0.05), 0.017}};
    const auto [b2, a2] = one_change(pose, {over}, {over});
    CHECK_FALSE(changed_region(b2, a2, room, kWidth, kHeight));
  }

  TEST_CASE("a ball's clear coat shows a sphere only within its mirror patch, grazing angles included") {
    // Points all over a ball's surface, seen from the eye: wherever the view reflected there meets the
    // target, the point lies in the patch. Targets all round the ball (beside it, behind it as seen
    // from the eye, where it shows at the rim at grazing angles, above it, near and far, small and
    // large).
    constexpr double kR = 0.028575;
    const BoundSphere ball{Vec3(0, 0, kR), kR + kBoundSlack};
    const Vec3 eye(0.05, -0.55, 0.09);
    constexpr int kPoints = 40000;
    int targets = 0, partial = 0;
    for (double azimuth = 0; azimuth < 360; azimuth += 15) {
      for (const double distance : {0.065, 0.1, 0.3, 1.0}) {
        for (const double radius : {0.005, 0.03, 0.1}) {
          if (distance <= ball.radius + radius) continue;
          const double a = azimuth * std::numbers::pi / 180;
          const BoundSphere target{ball.centre + distance * Vec3(std::sin(a), std::cos(a), 0.2), radius};
          const BoundSphere patch = mirror_patch(ball, eye, target);
          CHECK(patch.radius <= ball.radius + 1e-12);
          partial += patch.radius < 0.5 * kR;
          int shown = 0;
          for (int k = 0; k < kPoints; ++k) {  // a Fibonacci lattice over the sphere
            const double z = 1 - (2 * k + 1.0) / kPoints, ring = std::sqrt(1 - z * z);
            const double turn = k * std::numbers::pi * (3 - std::sqrt(5.0));
            const Vec3 n(ring * std::cos(turn), ring * std::sin(turn), z);
            const Vec3 p = ball.centre + kR * n;
            const Vec3 view = (p - eye).normalized();
            if (view.dot(n) >= 0) continue;  // not seen from the eye
            const Vec3 r = view - 2 * view.dot(n) * n;
            const Vec3 to = target.centre - p;
            const double along = to.dot(r);
            if (along <= 0 || (to - along * r).norm() > target.radius) continue;  // the reflection misses it
            ++shown;
            CAPTURE(azimuth);
            CAPTURE(distance);
            CAPTURE(radius);
            CHECK((p - patch.centre).norm() <= patch.radius);
          }
          targets += shown > 0;
        }
      }
    }
    CHECK(targets > 200);  // most targets show on the ball
    CHECK(partial > 100);  // and for many of them the patch is far smaller than the ball
  }

  TEST_CASE("a ball that stays still is traced only where it can mirror the ball that moved") {
    // Seen close, a still ball beside one rolling away from it: the still ball's side towards the
    // rolling ball is traced, its far side is not.
    const RegionScene room = standard_room();
    constexpr double kR = 0.028575;
    const CameraPose pose{Vec3(0, -0.45, 0.12), Vec3(0, 0, kR), false};
    const BoundSphere still{Vec3(0, 0, kR), kR + kBoundSlack};
    const BoundSphere from{Vec3(0.25, 0.1, kR), kR + kBoundSlack}, to{Vec3(0.35, 0.1, kR), kR + kBoundSlack};
    FrameContent before;
    before.camera = "camera";
    before.camera_pose = pose;
    before.parts.push_back({"rolling", {{from, from}}, {{from, from}}, true});
    before.parts.push_back({"still", {{still, still}}, {{still, still}}, true});
    FrameContent after = before;
    after.parts[0] = {"rolled", {{to, to}}, {{to, to}}, true};
    const auto rects = changed_region(before, after, room, kWidth, kHeight);
    REQUIRE(rects);
    const auto near_side = pixel_of(pose, still.centre + 0.8 * kR * Vec3(1, -0.3, 0.2).normalized());
    const auto far_side = pixel_of(pose, still.centre + 0.9 * kR * Vec3(-1, -0.3, 0.2).normalized());
    REQUIRE(near_side);
    REQUIRE(far_side);
    CHECK(in_some(*rects, *near_side));
    CHECK_FALSE(in_some(*rects, *far_side));
    // With more than one reflection traced, a ball touching the still one could show the change
    // anywhere it meets the still one's view of it: then the still ball counts whole.
    const BoundSphere touching{Vec3(-2 * kR, 0, kR), kR + kBoundSlack};
    before.parts.push_back({"touching", {{touching, touching}}, {{touching, touching}}, true});
    after.parts.push_back(before.parts.back());
    const auto with_touching = changed_region(before, after, room, kWidth, kHeight);
    REQUIRE(with_touching);
    CHECK(in_some(*with_touching, *far_side));
  }

  TEST_CASE("the include's trace level is the one the region reckons with") {
    CHECK(standard_room().reflections == 5);  // settings.inc: max_trace_level 6
  }

  TEST_CASE("the standard room lies outside the lamp's cone: a shadow leaving the table falls on nothing lit") {
    CHECK_FALSE(standard_room().lamp_lights_room);
  }

  TEST_CASE("regions: rectangles on the grid merge when one round both costs less") {
    // Two blocks side by side: one rectangle of two blocks costs less than two starts.
    const std::vector<PixelRect> two = merge_regions({{0, 0, 32, 32}, {32, 0, 64, 32}});
    REQUIRE(two.size() == 1);
    CHECK(two[0] == PixelRect{0, 0, 64, 32});
    // Far apart (the box round both would trace 40 blocks more): kept apart.
    CHECK(merge_regions({{0, 0, 32, 32}, {320, 320, 352, 352}}).size() == 2);
    // One inside another goes; empty ones go.
    CHECK(merge_regions({{0, 0, 128, 128}, {32, 32, 64, 64}, {64, 64, 64, 96}}).size() == 1);
  }

  TEST_CASE("regions: overlapping rectangles become ones that do not overlap, covering the same pixels") {
    const std::vector<PixelRect> in = {{0, 0, 64, 64}, {40, 40, 400, 104}, {600, 0, 608, 8}};
    const std::vector<PixelRect> out = merge_regions(in);
    for (std::size_t i = 0; i < out.size(); ++i)
      for (std::size_t j = i + 1; j < out.size(); ++j) CHECK_FALSE(overlap(out[i], out[j]));
    for (const PixelRect& r : in)
      for (int y = r.y0; y < r.y1; y += 4)
        for (int x = r.x0; x < r.x1; x += 4) CHECK(in_some(out, {x, y}));
    // Traced less than the box round the first two, and not joined to the far one.
    CHECK(total_area(out) < 400 * 104);
    CHECK(std::any_of(out.begin(), out.end(), [](const PixelRect& r) { return r == PixelRect{600, 0, 608, 8}; }));
  }
}
