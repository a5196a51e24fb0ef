// A game in the preview, drawn from the rules' record (Shot::game) of a hand-made game laid over
// scenes/runout.scn's seven shots: the timeline's shots row names each turn's player and the rules'
// call, a foul's section in red and the winner's in gold; the window's game panel says who is at the
// table, the foul and ball in hand of the turn in play, the balls left as discs and the winner.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include <imgui.h>

#include "files.h"
#include "game_panel.h"
#include "headless_canvas.h"
#include "shot.h"
#include "support.h"
#include "timeline_picture.h"
#include "viewer_ui.h"

using namespace bsim;

namespace {

const std::string kFoul = "the cue ball went into a pocket";

GameTurn turn(int shot, int player, ShotCall planned, std::vector<int> pocketed, std::vector<int> on_table) {
  GameTurn t;
  t.shot = shot;
  t.player = player;
  t.planned = planned;
  t.verdict.shooter = player;
  t.verdict.pocketed = std::move(pocketed);
  t.verdict.continues = !t.verdict.pocketed.empty();
  t.on_table = std::move(on_table);
  return t;
}

/// A 9-ball game over the runout's seven shots: Ann breaks and makes three, scratches on the 1 (ball in
/// hand), Bo runs three and plays a safety, Ann makes the 8 and the 9 and wins.
GameRecord nine_ball_game() {
  GameRecord g;
  g.rules = RackGame::nine_ball;
  g.players = {"Ann Lee", "Bo"};
  g.noise = {1, 1};
  g.winner = 0;
  g.turns.push_back(turn(0, 0, {}, {2, 6, 7}, {1, 3, 4, 5, 8, 9}));
  g.turns[0].verdict.break_shot = true;
  g.turns.push_back(turn(1, 0, {1, 5}, {1}, {3, 4, 5, 8, 9}));
  TurnVerdict& foul = g.turns[1].verdict;
  foul.legal = false;
  foul.foul = kFoul;
  foul.continues = false;
  foul.in_hand = InHand::anywhere;
  foul.fouls_in_row = 1;
  foul.call = "foul: " + kFoul + "; ball in hand";
  g.turns.push_back(turn(2, 1, {3, 3}, {3}, {4, 5, 8, 9}));
  g.turns.push_back(turn(3, 1, {4, 4}, {4}, {5, 8, 9}));
  g.turns.push_back(turn(4, 1, {-1, -1, true}, {}, {5, 8, 9}));
  g.turns.push_back(turn(5, 0, {5, 1}, {5}, {8, 9}));
  g.turns.push_back(turn(6, 0, {9, 0}, {8, 9}, {}));
  g.turns[6].verdict.winner = 0;
  g.turns[6].verdict.call = "wins the game";
  return g;
}

/// scenes/runout.scn, loaded once (its seven shots played).
Shot& runout() {
  static const ShotResult loaded = load_shot(test::require_file(test::source_path("scenes/runout.scn")), "runout");
  REQUIRE(loaded.scripted());
  return *loaded.shot;
}

/// s, once shot k's balls rest, before the next shot starts: the rules have called it.
double after_shot(const Shot& shot, int k) {
  const std::vector<ShotSpan>& spans = shot.timeline.shots();
  return spans[static_cast<std::size_t>(k)].rest + 0.01;
}

/// s, halfway through shot k's stretch (from its strike to the next shot's start).
double in_shot(const Shot& shot, int k) {
  const std::vector<ShotSpan>& spans = shot.timeline.shots();
  const double end =
      k + 1 < static_cast<int>(spans.size()) ? spans[static_cast<std::size_t>(k + 1)].start : shot.timeline.duration();
  return (spans[static_cast<std::size_t>(k)].cue + end) / 2;
}

bool near(const unsigned char* c, unsigned colour, int tolerance) {
  const int r = colour & 0xFF, g = (colour >> 8) & 0xFF, b = (colour >> 16) & 0xFF;
  return std::abs(c[0] - r) <= tolerance && std::abs(c[1] - g) <= tolerance && std::abs(c[2] - b) <= tolerance;
}

struct Pixels {
  int width = 0, height = 0;
  std::vector<unsigned char> rgba;  ///< bottom row first, as OSMesa reads them
  /// Pixels near `colour` in the columns [x0, x1), every row.
  int count(unsigned colour, float x0, float x1, int tolerance = 4) const {
    int n = 0;
    for (int y = 0; y < height; ++y)
      for (int x = std::max(0, int(x0)); x < std::min(width, int(x1)); ++x)
        n += near(&rgba[(static_cast<std::size_t>(y) * width + x) * 4], colour, tolerance);
    return n;
  }
};

struct TimelineDrawing {
  TimelineData data;
  TimelineAxis axis;
  std::vector<TimelineDrawn> pieces;
  Pixels pixels;
};

TimelineDrawing draw_timeline_of(const Shot& shot, int width) {
  TimelineDrawing d{timeline_data(shot), {}, {}, {}};
  HeadlessCanvas canvas;
  std::string error;
  REQUIRE_MESSAGE(canvas.open(width, 700, 16, error), error);
  ImDrawList* list = canvas.begin_2d();
  TimelineLayout layout{0, 0, float(width), 700};
  layout.drawn = &d.pieces;
  d.axis = draw_timeline(*list, d.data, canvas.fonts(), layout);
  canvas.end_2d();
  d.pixels = {canvas.width(), canvas.height(), canvas.pixels()};
  return d;
}

/// px, the columns of shot k's section, a pixel in from each side.
std::pair<float, float> section_columns(const TimelineDrawing& d, int k) {
  const TimelineShotSection& s = d.data.shots[static_cast<std::size_t>(k)];
  return {d.axis.x0 + float(s.start) * d.axis.pixels_per_second + 2,
          d.axis.x0 + float(s.end) * d.axis.pixels_per_second - 2};
}

/// The window's game panel alone at time t, 1280x720 with 32 px text (thick enough for its colours to
/// be read off the pixels).
Pixels panel_picture(const Shot& shot, double t) {
  HeadlessCanvas canvas;
  std::string error;
  REQUIRE_MESSAGE(canvas.open(1280, 720, 32, error), error);
  for (int frame = 0; frame < 2; ++frame) {  // an auto-sized window shows from its second frame
    canvas.begin_2d();
    draw_game_panel(shot, t, canvas.fonts(), 1280);
    canvas.end_2d();
  }
  return {canvas.width(), canvas.height(), canvas.pixels()};
}

std::vector<std::string> texts(const std::vector<GamePanelLine>& lines) {
  std::vector<std::string> out;
  for (const GamePanelLine& l : lines) out.push_back(l.text);
  return out;
}

const GamePanelLine* line_with(const std::vector<GamePanelLine>& lines, const std::string& part) {
  for (const GamePanelLine& l : lines)
    if (l.text.find(part) != std::string::npos) return &l;
  return nullptr;
}

}  // namespace

TEST_SUITE("a game in the preview") {
  TEST_CASE("the turn's words: initials, a plan, the rules' call put together when the verdict has none") {
    CHECK(name_initials("Efren Reyes") == "ER");
    CHECK(name_initials("Player 2") == "P2");
    CHECK(name_initials("  shane  ") == "S");
    CHECK(name_initials("\xC3\x89mile Zola") == "\xC3\x89Z");
    const std::vector<Pocket>& pockets = runout().scene.pockets;
    CHECK(plan_text({3, 2}, pockets) == "3 \xE2\x86\x92 top-right");
    CHECK(plan_text({8, 4}, pockets) == "8 \xE2\x86\x92 bottom side");
    CHECK(plan_text({-1, -1, true}, pockets) == "safety");
    CHECK(plan_text({-1, -1, false, true}, pockets) == "push-out");
    CHECK(plan_text({}, pockets).empty());
    GameTurn t;
    t.verdict.legal = false;
    t.verdict.foul = "no ball hit";
    t.verdict.in_hand = InHand::anywhere;
    CHECK(turn_call_text(t) == "foul: no ball hit; ball in hand");
    CHECK(turn_tone(t) == GameTone::foul);
    t.verdict = {};
    t.verdict.pocketed = {3, 5};
    CHECK(turn_call_text(t) == "made 3, 5");
    CHECK(turn_tone(t) == GameTone::plain);
    t.verdict.push_out = true;
    CHECK(turn_call_text(t) == "push-out");
    CHECK(turn_tone(t) == GameTone::push_out);
  }

  TEST_CASE("the game panel: the player at the table, a foul during its turn, ball in hand after it, the winner") {
    Shot& shot = runout();
    shot.game.reset();
    CHECK(game_panel_lines(shot, in_shot(shot, 1)).empty());  // no game, no panel
    shot.game = nine_ball_game();

    // Shot 2 in play: Ann at the table with her plan; its foul is not told while its balls still roll.
    const std::vector<GamePanelLine> second = game_panel_lines(shot, shot.timeline.shots()[1].cue + 0.01);
    CAPTURE(texts(second));
    CHECK(second.front().text == "9-ball \xC2\xB7 shot 2 of 7");
    REQUIRE(line_with(second, "Ann Lee"));
    CHECK(line_with(second, "Ann Lee")->text.starts_with("\xE2\x96\xB6 "));  // at the table
    CHECK(line_with(second, "Ann Lee")->tone == GameTone::player);
    REQUIRE(line_with(second, "Bo"));
    CHECK_FALSE(line_with(second, "Bo")->text.starts_with("\xE2\x96\xB6"));
    CHECK_FALSE(line_with(second, kFoul));
    CHECK(line_with(second, "Plan: 1 \xE2\x86\x92 bottom-left"));
    CHECK_FALSE(line_with(second, "wins"));

    // Once its balls rest, Bo comes to the table with ball in hand, under shot 2's foul in red.
    const GamePanel after = game_panel(shot, after_shot(shot, 1));
    CAPTURE(texts(after.lines));
    CHECK(after.at_table == 1);
    REQUIRE(line_with(after.lines, kFoul));
    CHECK(line_with(after.lines, kFoul)->text.starts_with("Shot 2: "));
    CHECK(line_with(after.lines, kFoul)->tone == GameTone::foul);
    REQUIRE(line_with(after.lines, "Ball in hand"));
    CHECK(line_with(after.lines, "Ball in hand")->tone == GameTone::in_hand);

    // Bo's shot 3 played: no foul; the balls it left.
    const GamePanel third = game_panel(shot, after_shot(shot, 2));
    CAPTURE(texts(third.lines));
    CHECK(third.at_table == 1);
    CHECK(line_with(third.lines, "\xE2\x96\xB6 Bo"));
    CHECK_FALSE(line_with(third.lines, kFoul));
    CHECK(third.on_table == std::vector<int>{4, 5, 8, 9});
    REQUIRE(line_with(third.lines, "On the table: 4 5 8 9"));
    CHECK(line_with(third.lines, "On the table: 4 5 8 9")->balls);
    CHECK(line_with(third.lines, "Ann Lee \xC2\xB7 1 foul"));

    // The end: the winner, in gold.
    const std::vector<GamePanelLine> end = game_panel_lines(shot, shot.timeline.duration());
    CAPTURE(texts(end));
    REQUIRE(line_with(end, "Ann Lee wins the game"));
    CHECK(line_with(end, "Ann Lee wins the game")->tone == GameTone::winner);
    CHECK(line_with(end, "On the table: none"));
    shot.game.reset();
  }

  TEST_CASE("8-ball: the groups follow from the first legal shot after the break that makes its called ball") {
    GameRecord g;
    g.rules = RackGame::eight_ball;
    g.players = {"Ann", "Bo"};
    g.turns.push_back(turn(0, 0, {}, {3, 12}, {}));
    g.turns[0].verdict.break_shot = true;
    g.turns.push_back(turn(1, 0, {5, 1}, {}, {}));     // a miss
    g.turns.push_back(turn(2, 1, {11, 2}, {11}, {}));  // Bo makes the 11 as called: stripes
    CHECK(game_groups(g, 1) == std::vector<int>{0, 0});
    CHECK(game_groups(g, 2) == std::vector<int>{1, 2});
    Shot& shot = runout();
    shot.game = g;
    const std::vector<GamePanelLine> lines = game_panel_lines(shot, in_shot(shot, 2));
    CAPTURE(texts(lines));
    CHECK(lines.front().text.starts_with("8-ball"));
    CHECK(line_with(lines, "Ann \xE2\x80\x94 solids"));
    CHECK(line_with(lines, "Bo \xE2\x80\x94 stripes"));
    CHECK_FALSE(line_with(game_panel_lines(shot, in_shot(shot, 1)), "solids"));
    shot.game.reset();
  }

  TEST_CASE("the timeline's shots row: each turn's player and call, the foul's section red, the winner's gold") {
    for (const int width : {1600, 900}) {
      CAPTURE(width);
      Shot& shot = runout();
      shot.game.reset();
      const TimelineDrawing plain = draw_timeline_of(shot, width);
      shot.game = nine_ball_game();
      const TimelineDrawing game = draw_timeline_of(shot, width);
      shot.game.reset();

      CHECK(plain.pixels.rgba != game.pixels.rgba);
      CHECK(game.data.title.find("9-ball, Ann Lee v Bo: Ann Lee wins") != std::string::npos);
      REQUIRE(game.data.shots.size() == 7);
      CHECK(game.data.shots[2].turn->from_hand);
      CHECK(game.data.shots[2].turn->plan == "3 \xE2\x86\x92 bottom-right");
      CHECK(game.data.shots[1].turn->short_call == "foul; ball in hand");
      CHECK(game.data.shots[6].turn->short_call == "wins");
      // The foul's colour in the second shot's section and in no other; the winner's gold in the last.
      const unsigned foul = game_tone_color(GameTone::foul), gold = game_tone_color(GameTone::winner);
      for (int k = 0; k < 7; ++k) {
        CAPTURE(k);
        const auto [x0, x1] = section_columns(game, k);
        const int red = game.pixels.count(foul, x0, x1);
        if (k == 1)
          CHECK(red >= (x1 - x0) * 3);  // the bar along its foot, at least
        else
          CHECK(red == 0);
        CHECK(plain.pixels.count(foul, x0, x1) == 0);
        if (k == 6) CHECK(game.pixels.count(gold, x0, x1) >= (x1 - x0) * 3);
      }
      // Each section names its player, whole or by initials.
      for (int k = 0; k < 7; ++k) {
        const std::string& name = game.data.shots[static_cast<std::size_t>(k)].turn->name;
        const std::string initials = name_initials(name);
        const bool named = std::any_of(game.pieces.begin(), game.pieces.end(), [&](const TimelineDrawn& p) {
          return p.kind == TimelineDrawn::Kind::shot_text && p.shot == k && (p.text == name || p.text == initials);
        });
        CHECK_MESSAGE(named, "shot " << k + 1 << " does not name " << name);
      }
    }
  }

  TEST_CASE("the game panel in a picture: the foul in red, the balls left as discs in their colours, the winner") {
    Shot& shot = runout();
    shot.game = nine_ball_game();
    const Pixels foul = panel_picture(shot, after_shot(shot, 1));
    const Pixels end = panel_picture(shot, shot.timeline.duration());
    shot.game.reset();
    const unsigned red = game_tone_color(GameTone::foul), gold = game_tone_color(GameTone::winner);
    CHECK(foul.count(red, 0, 1280, 3) > 100);
    CHECK(foul.count(gold, 0, 1280, 3) == 0);
    // The 4 (purple) and the 5 (orange) among the discs of the balls left; none at the end.
    const unsigned purple = IM_COL32(86, 28, 130, 255), orange = IM_COL32(248, 108, 16, 255);
    CHECK(foul.count(purple, 0, 1280, 2) > 100);
    CHECK(foul.count(orange, 0, 1280, 2) > 100);
    CHECK(end.count(purple, 0, 1280, 2) == 0);
    CHECK(end.count(red, 0, 1280, 3) == 0);
    CHECK(end.count(gold, 0, 1280, 3) > 100);
  }
}
