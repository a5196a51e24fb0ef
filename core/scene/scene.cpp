#include "scene.h"

#include <algorithm>
#include <array>
#include <numbers>

namespace bsim {

namespace {

/// The standard pockets in their numbering's order: the word typed, where it is, and its kind.
struct StandardPocketName {
  std::string_view word;   ///< "top-right"
  std::string_view where;  ///< "top-right", "top"
  bool corner;
};
constexpr std::array<StandardPocketName, 6> kStandardPocketNames = {{{"top-left", "top-left", true},
                                                                     {"top-side", "top", false},
                                                                     {"top-right", "top-right", true},
                                                                     {"bottom-right", "bottom-right", true},
                                                                     {"bottom-side", "bottom", false},
                                                                     {"bottom-left", "bottom-left", true}}};

/// Other words for the side pockets: the table's numbering calls them the middle ones.
struct PocketAlias {
  std::string_view word;
  int pocket;
};
constexpr PocketAlias kPocketAliases[] = {{"top-middle", 1}, {"bottom-middle", 4}};

/// The standard name's entry for pocket `k` of `pockets`, or none (a scene's own pockets, no such pocket).
const StandardPocketName* standard_name(const std::vector<Pocket>& pockets, int k) {
  if (k < 0 || k >= static_cast<int>(kStandardPocketNames.size()) || !standard_pocket_set(pockets)) return nullptr;
  return &kStandardPocketNames[static_cast<std::size_t>(k)];
}

}  // namespace

std::vector<Rail> standard_rails(const PhysicsParams& params) {
  const TableSpec& t = kStandardTable;
  // The rails end at the jaw points: a corner's two mouth / sqrt 2 from the noses' corner.
  const double h = t.nose_height, x = t.half_length, y = t.half_width, c = params.corner_mouth / std::numbers::sqrt2,
               s = params.side_mouth / 2;
  auto rail = [h](double ax, double ay, double bx, double by) { return Rail{Vec3(ax, ay, h), Vec3(bx, by, h), {}}; };
  return {rail(-x + c, y, -s, y), rail(s, y, x - c, y),     rail(x, y - c, x, -y + c),
          rail(x - c, -y, s, -y), rail(-s, -y, -x + c, -y), rail(-x, -y + c, -x, y - c)};
}

std::vector<Pocket> standard_pockets(const PhysicsParams& params) {
  const TableSpec& t = kStandardTable;
  const double x = t.half_length, y = t.half_width, c = params.corner_mouth / std::numbers::sqrt2,
               s = params.side_mouth / 2;
  // The hole's centre lies on the axis, the shelf and the hole's radius behind the mouth line's middle.
  auto cut = [&](PocketKind kind, Vec3 jaw0, Vec3 jaw1, Vec3 axis) {
    const bool corner = kind == PocketKind::corner;
    const double hole = corner ? t.jaws.corner_hole : t.jaws.side_hole;
    const double shelf = corner ? params.corner_shelf : params.side_shelf;
    Pocket p;
    p.radius = hole;
    p.center = (jaw0 + jaw1) / 2 + (shelf + hole) * axis;
    p.cut = true;
    p.kind = kind;
    p.jaw[0] = jaw0;
    p.jaw[1] = jaw1;
    p.axis = axis;
    p.jaw_radius = params.jaw_radius;
    return p;
  };
  const double d = std::numbers::sqrt2 / 2;
  const PocketKind corner = PocketKind::corner, side = PocketKind::side;
  return {cut(corner, Vec3(-x + c, y, 0), Vec3(-x, y - c, 0), Vec3(-d, d, 0)),
          cut(side, Vec3(s, y, 0), Vec3(-s, y, 0), Vec3(0, 1, 0)),
          cut(corner, Vec3(x, y - c, 0), Vec3(x - c, y, 0), Vec3(d, d, 0)),
          cut(corner, Vec3(x - c, -y, 0), Vec3(x, -y + c, 0), Vec3(d, -d, 0)),
          cut(side, Vec3(-s, -y, 0), Vec3(s, -y, 0), Vec3(0, -1, 0)),
          cut(corner, Vec3(-x, -y + c, 0), Vec3(-x + c, -y, 0), Vec3(-d, -d, 0))};
}

std::vector<Pocket> bare_standard_pockets() {
  const TableSpec& t = kStandardTable;
  const double x = t.half_length, y = t.half_width, c = t.jaws.bare_corner_radius, s = t.jaws.bare_side_radius;
  auto pocket = [](double px, double py, double r) { return Pocket{Vec3(px, py, 0), r, {}}; };
  return {pocket(-x, y, c), pocket(0, y, s), pocket(x, y, c), pocket(x, -y, c), pocket(0, -y, s), pocket(-x, -y, c)};
}

std::vector<std::string_view> standard_pocket_words(bool aliases) {
  std::vector<std::string_view> words;
  for (const StandardPocketName& n : kStandardPocketNames) words.push_back(n.word);
  if (aliases)
    for (const PocketAlias& a : kPocketAliases) words.push_back(a.word);
  return words;
}

std::optional<int> standard_pocket_number(std::string_view word) {
  for (const PocketAlias& a : kPocketAliases)
    if (a.word == word) return a.pocket;
  for (std::size_t k = 0; k < kStandardPocketNames.size(); ++k)
    if (kStandardPocketNames[k].word == word) return static_cast<int>(k);
  return std::nullopt;
}

bool standard_pocket_set(const std::vector<Pocket>& pockets) {
  if (pockets.size() != kStandardPocketNames.size()) return false;
  return std::none_of(pockets.begin(), pockets.end(), [](const Pocket& p) { return p.loc.known(); });
}

std::string pocket_name(const std::vector<Pocket>& pockets, int pocket) {
  const std::string number = "pocket " + std::to_string(pocket);
  const StandardPocketName* n = standard_name(pockets, pocket);
  if (!n) return number;
  return "the " + std::string(n->where) + (n->corner ? " corner (" : " side pocket (") + number + ")";
}

std::string pocket_short_name(const std::vector<Pocket>& pockets, int pocket) {
  const StandardPocketName* n = standard_name(pockets, pocket);
  if (!n) return "pocket " + std::to_string(pocket);
  return std::string(n->where) + (n->corner ? " corner" : " side");
}

}  // namespace bsim
