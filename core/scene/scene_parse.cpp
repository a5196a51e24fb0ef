// The seed's scene grammar plus the extensions, read statement by statement in any order. Each
// error names the token it is about, says what was expected and what was found, and the parser
// skips to the next statement so one run reports every independent mistake.
#include "scene_parse.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "camera_key_text.h"
#include "rack.h"
#include "scene_lexer.h"
#include "scene_validate.h"
#include "spelling.h"

namespace bsim {

namespace {

// Beyond this many errors the rest is most likely noise (a binary file, a wrong file).
constexpr std::size_t kMaxErrors = 30;

constexpr std::string_view kSeedKeywords[] = {"cue", "ball", "rail", "camera"};
constexpr std::string_view kExtensionKeywords[] = {"pocket", "spin",  "param", "rack",
                                                   "stroke", "place", "game",  "player"};
/// The games `game` plays (rules.h): a subset of the racks.
constexpr std::string_view kGameNames[] = {"9ball", "8ball"};
enum class NumberStatus { ok, not_number, not_finite };

NumberStatus parse_double(std::string_view text, double& out) {
  std::string_view digits = text;
  if (digits.size() > 1 && digits[0] == '+' && digits[1] != '-' && digits[1] != '+') digits.remove_prefix(1);
  const char* first = digits.data();
  const char* last = first + digits.size();
  auto [end, ec] = std::from_chars(first, last, out, std::chars_format::general);
  if (end != last || (ec != std::errc() && ec != std::errc::result_out_of_range)) return NumberStatus::not_number;
  if (ec == std::errc::result_out_of_range) {
    // Either an overflow (not finite) or an underflow, which is just a very small number.
    out = std::strtod(std::string(digits).c_str(), nullptr);
  }
  return std::isfinite(out) ? NumberStatus::ok : NumberStatus::not_finite;
}

/// Decimal integers only: "3", "-1", "+2". Values beyond long long saturate (and fail range checks).
bool parse_integer(std::string_view text, long long& out) {
  std::string_view digits = text;
  if (digits.size() > 1 && digits[0] == '+') digits.remove_prefix(1);
  std::size_t start = digits.size() > 1 && digits[0] == '-' ? 1 : 0;
  if (start == digits.size()) return false;
  for (std::size_t i = start; i < digits.size(); ++i)
    if (digits[i] < '0' || digits[i] > '9') return false;
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), out);
  (void)end;
  if (ec == std::errc::result_out_of_range) out = start ? LLONG_MIN : LLONG_MAX;
  return true;
}

std::string keyword_list(bool strict) {
  std::string out;
  auto add = [&](std::string_view k) { out.append(out.empty() ? "" : ", ").append(k); };
  for (auto k : kSeedKeywords) add(k);
  if (!strict)
    for (auto k : kExtensionKeywords) add(k);
  return out;
}

/// The keywords a statement may start with here, for "did you mean".
std::vector<std::string_view> keywords(bool strict) {
  std::vector<std::string_view> out(std::begin(kSeedKeywords), std::end(kSeedKeywords));
  if (!strict) out.insert(out.end(), std::begin(kExtensionKeywords), std::end(kExtensionKeywords));
  return out;
}

std::vector<std::string_view> param_name_list() {
  std::vector<std::string_view> out;
  for (const ParamSpec& spec : param_specs()) out.push_back(spec.name);
  return out;
}

std::string param_names() {
  std::string out;
  for (const ParamSpec& spec : param_specs()) out.append(out.empty() ? "" : ", ").append(spec.name);
  return out;
}

/// "the ball's {} position" with {} -> "x".
std::string component(std::string_view pattern, std::string_view axis) {
  const std::size_t at = pattern.find("{}");
  if (at == std::string_view::npos) return std::string(pattern);
  return std::string(pattern.substr(0, at)).append(axis).append(pattern.substr(at + 2));
}

/// Thrown inside one statement to abandon it; caught by the statement loop, never escapes parse_scene.
struct StatementFailed {};

class Parser {
 public:
  Parser(std::string_view text, const ParseOptions& options, std::vector<Diagnostic>& diagnostics)
      : lexed_(lex_scene(text)), options_(options), diagnostics_(diagnostics) {}

  void run() {
    map_.end = lexed_.end;
    if (options_.strict)
      for (const SourceLoc& loc : lexed_.comments) error(loc, "'#' comments are an extension that --strict rejects");
    while (pos_ < lexed_.tokens.size() && !too_many_errors_) {
      try {
        statement();
      } catch (const StatementFailed&) {
        skip_to_statement();
      }
    }
  }

  Scene& scene() { return scene_; }
  SceneSourceMap& source_map() { return map_; }
  bool empty() const { return lexed_.tokens.empty(); }
  bool camera_seen() const { return camera_seen_; }

 private:
  // ---- diagnostics
  void error(SourceLoc loc, std::string message) {
    if (too_many_errors_) return;
    if (++error_count_ > kMaxErrors) {
      diagnostics_.push_back({Severity::error, loc, "too many errors; stopping here"});
      too_many_errors_ = true;
      return;
    }
    diagnostics_.push_back({Severity::error, loc, std::move(message)});
  }
  [[noreturn]] void fail(SourceLoc loc, std::string message) {
    error(loc, std::move(message));
    throw StatementFailed{};
  }

  // ---- tokens
  bool at_end() const { return pos_ >= lexed_.tokens.size(); }
  const Token& peek() const { return lexed_.tokens[pos_]; }

  /// The next token, or a located "found end of file" error for `expected`.
  const Token& take(const std::string& expected) {
    if (at_end()) fail(lexed_.end, "expected " + expected + ", found end of file");
    return lexed_.tokens[pos_++];
  }

  double number(const std::string& what, SourceLoc* where = nullptr) {
    const Token& t = take("a number for " + what);
    if (where) *where = t.loc;
    double value = 0;
    switch (parse_double(t.text, value)) {
      case NumberStatus::ok: return value;
      case NumberStatus::not_finite:
        fail(t.loc, "expected a finite number for " + what + ", found " + quote_token(t.text) + " (not finite)");
      case NumberStatus::not_number: break;
    }
    fail_at_value(t, "expected a number for " + what + ", found " + quote_token(t.text));
  }

  /// A bad value that is really the next statement's keyword (the line is short): leave it to start
  /// that statement, so the short line costs one error, not two.
  /// Reported just past the short line's last token, so it points at the line that is short.
  [[noreturn]] void fail_at_value(const Token& t, std::string message) {
    if (is_top_keyword(t.text) || t.text == "endcamera" || (in_camera_ && t.text == "event")) {
      --pos_;
      if (pos_ > 0) {
        const Token& last = lexed_.tokens[pos_ - 1];
        const SourceLoc past{last.loc.line, last.loc.column + static_cast<int>(last.text.size())};
        fail(past, message + ", which starts the next statement (line " + std::to_string(t.loc.line) +
                       "): the statement ends early");
      }
    }
    fail(t.loc, std::move(message));
  }

  long long integer(const std::string& what, SourceLoc* where = nullptr) {
    const Token& t = take("an integer for " + what);
    if (where) *where = t.loc;
    long long value = 0;
    if (!parse_integer(t.text, value))
      fail_at_value(t, "expected an integer for " + what + ", found " + quote_token(t.text));
    return value;
  }

  /// A file-order ball index (range checked once every ball is known).
  int ball_index(const std::string& what, SourceLoc& where) {
    const long long value = integer(what, &where);
    if (value < 0)
      fail(where,
           "expected a ball index of 0 or more for " + what + ", found " + quote_token(lexed_.tokens[pos_ - 1].text));
    return static_cast<int>(std::min<long long>(value, INT_MAX));
  }

  Vec3 vector(std::string_view pattern, SourceLoc* first = nullptr, SourceLoc* z_loc = nullptr) {
    Vec3 v;
    v.x() = number(component(pattern, "x"), first);
    v.y() = number(component(pattern, "y"));
    v.z() = number(component(pattern, "z"), z_loc);
    return v;
  }

  /// Skips to the next token that can start a statement here, so one mistake gives one error.
  void skip_to_statement() {
    while (!at_end()) {
      const std::string_view t = peek().text;
      if (in_camera_ && (t == "event" || t == "endcamera")) return;
      // Inside the camera, 'cue' or 'pocket' after another token on its line is a key, not a statement.
      if (in_camera_ && pos_ > 0 && lexed_.tokens[pos_ - 1].loc.line == peek().loc.line &&
          (t == "cue" || t == "pocket")) {
        ++pos_;
        continue;
      }
      if (is_top_keyword(t) || t == "endcamera") return;
      ++pos_;
    }
  }

  static bool is_top_keyword(std::string_view t) {
    return std::find(std::begin(kSeedKeywords), std::end(kSeedKeywords), t) != std::end(kSeedKeywords) ||
           std::find(std::begin(kExtensionKeywords), std::end(kExtensionKeywords), t) != std::end(kExtensionKeywords);
  }

  // ---- statements
  void statement() {
    if (in_camera_) return camera_entry();
    const Token& t = lexed_.tokens[pos_++];
    const std::string_view k = t.text;
    if (options_.strict && (k == "pocket" || k == "spin" || k == "param" || k == "rack" || k == "stroke" ||
                            k == "place" || k == "game" || k == "player"))
      fail(t.loc, "'" + std::string(k) + "' is an extension that --strict rejects");
    if (k == "cue") return cue(t);
    if (k == "ball") return ball(t);
    if (k == "rail") return rail(t);
    if (k == "camera") return camera(t);
    if (k == "pocket") return pocket(t);
    if (k == "spin") return spin(t);
    if (k == "param") return param(t);
    if (k == "rack") return rack(t);
    if (k == "stroke") return stroke(t);
    if (k == "place") return place(t);
    if (k == "game") return game(t);
    if (k == "player") return player(t);
    if (k == "endcamera") fail(t.loc, "found 'endcamera' without a 'camera' before it");
    if (k == "event" || k == "hover" || k == "look" || k == "follow")
      fail(t.loc, "found '" + std::string(k) + "' outside a camera description; expected one of " +
                      keyword_list(options_.strict) + " (camera lines go between 'camera' and 'endcamera')");
    double ignored = 0;
    if (parse_double(k, ignored) != NumberStatus::not_number)
      fail(t.loc, "expected a keyword (" + keyword_list(options_.strict) + "), found the number " + quote_token(k) +
                      " (too many values on the line before?)");
    fail(t.loc, "unknown keyword " + quote_token(k) + "; expected one of " + keyword_list(options_.strict) +
                    did_you_mean(k, keywords(options_.strict), "keywords"));
  }

  void cue(const Token& keyword) {
    broken_cue_ = true;  // until the line is read whole: its stroke and places then raise no errors of their own
    Cue c;
    c.loc = keyword.loc;
    c.target = ball_index("the cue's target ball", c.target_loc);
    if (!at_end() && peek().text == "pot") {
      const Token& pot = take("'pot'");
      if (options_.strict) fail(pot.loc, "'pot' is an extension that --strict rejects");
      c.heading_loc = pot.loc;
      c.pot_ball = ball_index("the ball to pot", c.pot_ball_loc);
      c.pot_pocket = pot_pocket(c.pot_pocket_loc);
    } else {
      c.heading_deg = number("the cue's heading in degrees", &c.heading_loc);
      if (!at_end() && peek().text == "call") shooter_call(c);
    }
    if (map_.has_cue && options_.strict)
      fail(keyword.loc,
           "several shots (a second 'cue' line) are an extension that --strict rejects; the first cue is "
           "on line " +
               std::to_string(scene_.cues.front().loc.line));
    if (!map_.has_cue) scene_.cues.clear();  // the default cue of a scene built in code
    scene_.cues.push_back(c);
    map_.has_cue = true;
    broken_cue_ = false;
  }

  /// `call B P`, `call safety` or `call push-out` after a cue's heading (games): what the shooter called.
  void shooter_call(Cue& c) {
    const Token& call = take("'call'");
    c.call_loc = call.loc;
    if (options_.strict) fail(call.loc, "'call' is an extension that --strict rejects");
    if (!at_end() && (peek().text == "safety" || peek().text == "push-out")) {
      (take("a call").text == "safety" ? c.call_safety : c.call_push_out) = true;
      return;
    }
    SourceLoc ball_loc, pocket_loc;
    c.call_ball = ball_index("the called ball (or safety, or push-out)", ball_loc);
    c.call_pocket = pot_pocket(pocket_loc);
  }

  /// The pocket after `pot B`: its number, or a standard pocket's name (top-right); a name on a scene
  /// with its own pocket lines is an error in finish(), once every line is read.
  int pot_pocket(SourceLoc& where) {
    const Token& t = take("the pocket to pot into (its number, or a name such as top-right)");
    where = t.loc;
    long long value = 0;
    if (parse_integer(t.text, value)) {
      if (value < 0) fail(where, "expected a pocket number of 0 or more for 'pot', found " + quote_token(t.text));
      return static_cast<int>(std::min<long long>(value, INT_MAX));
    }
    if (const std::optional<int> named = standard_pocket_number(t.text)) {
      named_pockets_.push_back(t.loc);
      return *named;
    }
    std::string names;
    for (std::string_view w : standard_pocket_words()) names.append(names.empty() ? "" : ", ").append(w);
    fail_at_value(t, "expected the pocket to pot into, its number or its name (" + names + "), found " +
                         quote_token(t.text) + did_you_mean(t.text, standard_pocket_words(true)));
  }

  /// `place <ball> [<x> <y>]` under a later shot's `cue` line: the ball is put at rest there before that
  /// shot (without coordinates, back where its `ball` line or the rack put it).
  void place(const Token& keyword) {
    BallPlacement p;
    p.loc = keyword.loc;
    p.ball = ball_index("the ball to place", p.ball_loc);
    if (!at_end() && !is_top_keyword(peek().text)) {
      SourceLoc y_loc;
      const double x = number("the place's x in metres", &p.at_loc);
      const double y = number("the place's y in metres", &y_loc);
      p.at = Vec3(x, y, 0);
    }
    if (broken_cue_) return;  // the cue line above has its error already
    if (!map_.has_cue)
      fail(keyword.loc, "expected the 'cue' line of the shot this place belongs to above it, found none");
    Cue& cue = scene_.cues.back();
    if (scene_.cues.size() == 1)
      fail(keyword.loc,
           "the first shot's balls stand where their 'ball' lines put them; 'place' belongs under a "
           "later 'cue' line (the cue on line " +
               std::to_string(cue.loc.line) + " is the first)");
    for (const BallPlacement& other : cue.places)
      if (other.ball == p.ball)
        fail(p.ball_loc, "ball index " + std::to_string(p.ball) + " is already placed for this shot on line " +
                             std::to_string(other.loc.line));
    cue.places.push_back(p);
  }

  /// `stroke <speed> <side> <height> <elevation>`: strikes the ball of the `cue` line above it.
  void stroke(const Token& keyword) {
    Stroke s;
    s.loc = keyword.loc;
    SourceLoc height_loc;
    s.speed = number("the stroke's speed in m/s", &s.speed_loc);
    const std::string speed_text = quote_token(lexed_.tokens[pos_ - 1].text);
    s.side = number("the stroke's side offset (a fraction of the ball's radius)", &s.side_loc);
    s.height = number("the stroke's height offset (a fraction of the ball's radius)", &height_loc);
    s.elevation_deg = number("the stroke's elevation in degrees", &s.elevation_loc);
    const std::string elevation_text = quote_token(lexed_.tokens[pos_ - 1].text);
    if (!map_.has_cue && !broken_cue_)
      fail(keyword.loc, "expected the 'cue' line this stroke strikes with above it, found none");
    Cue unread;  // the cue line above has its error already: the stroke's own values are still checked
    Cue& cue = broken_cue_ ? unread : scene_.cues.back();
    if (cue.stroke)
      fail(keyword.loc, "the cue on line " + std::to_string(cue.loc.line) + " already has a stroke on line " +
                            std::to_string(cue.stroke->loc.line));
    if (!(s.speed > 0 && s.speed <= Stroke::kMaxSpeed))
      fail(s.speed_loc, "expected a stroke speed greater than 0 and at most 15 m/s, found " + speed_text);
    if (!(s.elevation_deg >= 0 && s.elevation_deg < 90))
      fail(s.elevation_loc, "expected a stroke elevation of at least 0 and below 90 degrees, found " + elevation_text);
    const double offset = std::hypot(s.side, s.height);
    if (offset > Stroke::kMiscueOffset + 1e-12)
      fail(s.side_loc, "miscue: the tip meets the ball " + format_fraction(offset) +
                           " of its radius from centre; expected at most 0.5 (sqrt(side^2 + height^2))");
    cue.stroke = s;
  }

  static std::string format_fraction(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3g", v);
    return buffer;
  }

  void ball(const Token& keyword) {
    Ball b;
    SceneSourceMap::BallTokens tokens;
    b.loc = keyword.loc;
    const long long painted = integer("the ball number", &tokens.number);
    const std::string found = quote_token(lexed_.tokens[pos_ - 1].text);
    if (painted < 0 || painted > 15) fail(tokens.number, "expected a ball number from 0 to 15, found " + found);
    b.number = static_cast<int>(painted);
    if (auto seen = ball_lines_.find(b.number); seen != ball_lines_.end())
      fail(tokens.number, "ball number " + std::to_string(b.number) + " is already used by the ball on line " +
                              std::to_string(seen->second));
    if (rack_ && b.number >= 1 && b.number <= rack_ball_count(rack_->spec.game))
      fail(tokens.number, "ball number " + std::to_string(b.number) + " is already in the " +
                              std::string(rack_game_name(rack_->spec.game)) + " rack on line " +
                              std::to_string(rack_->loc.line));
    b.position.x() = number("the ball's x position", &tokens.position_x);
    b.position.y() = number("the ball's y position");
    // `ball N X Y` then a keyword (or the end of the file): at rest on the bed, upright.
    if (at_end() || is_top_keyword(peek().text)) {
      if (options_.strict)
        fail(keyword.loc,
             "the short ball line ('ball N X Y', at rest on the bed) is an extension that --strict "
             "rejects; expected 'ball N X Y Z VX VY VZ W QX QY QZ'");
      tokens.position_z = tokens.position_x;
      tokens.short_form = true;
      short_balls_.push_back(scene_.balls.size());
      ball_lines_[b.number] = keyword.loc.line;
      scene_.balls.push_back(b);
      map_.balls.push_back(tokens);
      return;
    }
    b.position.z() = number("the ball's z position", &tokens.position_z);
    b.velocity = vector("the ball's {} velocity");
    SourceLoc w_loc;
    double q[4];
    q[0] = number("the ball's orientation w", &w_loc);
    q[1] = number("the ball's orientation x");
    q[2] = number("the ball's orientation y");
    q[3] = number("the ball's orientation z");
    // Scale first so that huge or tiny components neither overflow nor vanish when squared.
    double largest = 0;
    for (double c : q) largest = std::max(largest, std::abs(c));
    if (largest == 0) fail(w_loc, "expected a non-zero orientation quaternion (w x y z, e.g. 1 0 0 0), found 0 0 0 0");
    b.orientation = Quat(q[0] / largest, q[1] / largest, q[2] / largest, q[3] / largest).normalized();
    ball_lines_[b.number] = keyword.loc.line;
    scene_.balls.push_back(b);
    map_.balls.push_back(tokens);
  }

  void rail(const Token& keyword) {
    Rail r;
    SceneSourceMap::RailTokens tokens;
    r.loc = keyword.loc;
    r.a = vector("the rail's first end {}", nullptr, &tokens.a_z);
    r.b = vector("the rail's second end {}", nullptr, &tokens.b_z);
    scene_.rails.push_back(r);
    map_.rails.push_back(tokens);
  }

  void pocket(const Token& keyword) {
    Pocket p;
    p.loc = keyword.loc;
    SourceLoc z_loc, radius_loc;
    p.center = vector("the pocket's {} centre", nullptr, &z_loc);
    p.radius = number("the pocket's radius", &radius_loc);
    if (std::abs(p.center.z()) > kPlacementTolerance)
      fail(z_loc,
           "expected the pocket's centre on the bed (z = 0), found z = " + quote_token(lexed_.tokens[pos_ - 2].text));
    if (p.radius <= 0)
      fail(radius_loc, "expected a pocket radius greater than 0, found " + quote_token(lexed_.tokens[pos_ - 1].text));
    p.center.z() = 0;
    scene_.pockets.push_back(p);
  }

  void spin(const Token& keyword) {
    SceneSourceMap::SpinLine line;
    line.loc = keyword.loc;
    line.ball = ball_index("the spinning ball", line.ball_loc);
    const Vec3 w = vector("the ball's {} spin in rad/s");
    for (const auto& other : map_.spins)
      if (other.ball == line.ball)
        fail(keyword.loc, "ball index " + std::to_string(line.ball) + " already has a spin on line " +
                              std::to_string(other.loc.line));
    map_.spins.push_back(line);
    spins_.push_back(w);
  }

  void param(const Token& keyword) {
    const Token& name = take("a parameter name (" + param_names() + ")");
    const std::optional<ParamSpec> spec = find_param(name.text);
    if (!spec)
      fail_at_value(name, "unknown parameter " + quote_token(name.text) + "; expected one of " + param_names() +
                              did_you_mean(name.text, param_name_list()));
    SourceLoc value_loc;
    const double value = number("parameter '" + std::string(spec->name) + "'", &value_loc);
    if (!param_in_range(*spec, value))
      fail(value_loc, "expected a value " + describe_range(*spec) + " for parameter '" + std::string(spec->name) +
                          "', found " + quote_token(lexed_.tokens[pos_ - 1].text));
    // table_speed is another way to write mu_roll, so the two count as one setting.
    const std::string_view key = spec->name == "table_speed" ? "mu_roll" : spec->name;
    if (auto seen = param_lines_.find(key); seen != param_lines_.end())
      diagnostics_.push_back({Severity::warning, keyword.loc,
                              "parameter '" + std::string(spec->name) + "' sets " + std::string(key) +
                                  " again (first on line " + std::to_string(seen->second) +
                                  "); the last value is used"});
    param_lines_[key] = keyword.loc.line;
    params_.emplace_back(spec->name, value);
  }

  /// `rack <game> [seed <n>] [tight]` (rack.h): the balls are made in finish(), once params are known.
  void rack(const Token& keyword) {
    RackLine line;
    line.loc = keyword.loc;
    const Token& game = take("a game (8ball, 9ball or 10ball)");
    const std::optional<RackGame> known = rack_game(game.text);
    if (!known)
      fail_at_value(game, "expected a game (8ball, 9ball or 10ball), found " + quote_token(game.text) +
                              did_you_mean(game.text, {kRackGameNames.begin(), kRackGameNames.end()}));
    line.spec.game = *known;
    bool seeded = false;
    while (!at_end() && (peek().text == "seed" || peek().text == "tight")) {
      const Token& option = take("a rack option");
      if (option.text == "tight") {
        line.spec.tight = true;
        continue;
      }
      SourceLoc seed_loc;
      const long long seed = integer("the rack's seed", &seed_loc);
      if (seed < 0 || seeded)
        fail(seed_loc, seeded ? "the rack has a seed already"
                              : "expected a seed of 0 or more, found " + quote_token(lexed_.tokens[pos_ - 1].text));
      line.spec.seed = static_cast<std::uint64_t>(seed);
      seeded = true;
    }
    if (rack_)
      fail(keyword.loc, "a scene has one rack, and there is already one on line " + std::to_string(rack_->loc.line));
    for (const auto& [number, ball_line] : ball_lines_)
      if (number >= 1 && number <= rack_ball_count(line.spec.game))
        fail(game.loc, "the " + std::string(game.text) + " rack holds ball " + std::to_string(number) +
                           ", which the ball on line " + std::to_string(ball_line) + " already paints");
    line.at = scene_.balls.size();
    rack_ = line;
  }

  /// `game <rules> [seed <n>] [shots <m>]` (extension): the scene is a game.
  void game(const Token& keyword) {
    GameLine line;
    line.loc = keyword.loc;
    const Token& rules = take("a game (9ball or 8ball)");
    line.rules_loc = rules.loc;
    const std::vector<std::string_view> names(std::begin(kGameNames), std::end(kGameNames));
    const std::optional<RackGame> known = rack_game(rules.text);
    if (!known || std::find(names.begin(), names.end(), rules.text) == names.end())
      fail_at_value(
          rules, "expected a game (9ball or 8ball), found " + quote_token(rules.text) +
                     (known ? " (a rack this program has, but not a game it plays)" : did_you_mean(rules.text, names)));
    line.rules = *known;
    bool seeded = false, limited = false;
    while (!at_end() && (peek().text == "seed" || peek().text == "shots")) {
      const bool seed = take("a game option").text == "seed";
      SourceLoc& loc = seed ? line.seed_loc : line.shots_loc;
      const long long value = integer(seed ? "the game's seed" : "the game's most shots", &loc);
      const std::string found = quote_token(lexed_.tokens[pos_ - 1].text);
      if (seed ? seeded : limited)
        fail(loc, std::string("the game has ") + (seed ? "a seed" : "a shot limit") + " already");
      if (seed && value < 0) fail(loc, "expected a seed of 0 or more, found " + found);
      if (!seed && value < 1) fail(loc, "expected the game's most shots as 1 or more, found " + found);
      (seed ? seeded : limited) = true;
      if (seed)
        line.seed = static_cast<std::uint64_t>(value);
      else
        line.shots = static_cast<int>(std::min<long long>(value, 100000));
    }
    if (scene_.game)
      fail(keyword.loc,
           "a scene is one game, and there is already a 'game' line on line " + std::to_string(scene_.game->loc.line));
    line.players = std::move(players_);
    players_.clear();
    scene_.game = std::move(line);
  }

  /// `player <name> [noise <k>]` (games): at most two, in order of play.
  void player(const Token& keyword) {
    PlayerLine line;
    line.loc = keyword.loc;
    const Token& name = take("the player's name");
    if (name.text == "noise" || is_top_keyword(name.text))
      fail_at_value(name, "expected the player's name, found " + quote_token(name.text));
    line.name = std::string(name.text);
    if (!at_end() && peek().text == "noise") {
      take("'noise'");
      line.noise = number("the player's noise", &line.noise_loc);
      if (line.noise < 0)
        fail(line.noise_loc, "expected the player's noise as 0 or more (times the Olympiad's errors), found " +
                                 quote_token(lexed_.tokens[pos_ - 1].text));
    }
    std::vector<PlayerLine>& players = scene_.game ? scene_.game->players : players_;
    if (players.size() >= 2)
      fail(keyword.loc, "a game has two players, and they are on lines " + std::to_string(players[0].loc.line) +
                            " and " + std::to_string(players[1].loc.line));
    players.push_back(std::move(line));
  }

  void camera(const Token& keyword) {
    if (camera_seen_)
      fail(keyword.loc, "a scene has one camera description, and there is already one on line " +
                            std::to_string(scene_.camera_loc.line));
    camera_seen_ = true;
    scene_.camera_loc = keyword.loc;
    in_camera_ = true;
  }

  /// Inside camera ... endcamera: an event line or the end of the description.
  void camera_entry() {
    if (at_end()) return;
    const Token& t = lexed_.tokens[pos_++];
    if (t.text == "endcamera") {
      in_camera_ = false;
      return;
    }
    if (t.text == "event") return event(t);
    if (is_top_keyword(t.text)) {
      // Most likely a forgotten endcamera: say so once and read the rest of the file normally.
      error(t.loc, "expected 'event' or 'endcamera', found " + quote_token(t.text) +
                       " (the camera description on line " + std::to_string(scene_.camera_loc.line) +
                       " has no 'endcamera')");
      in_camera_ = false;
      --pos_;
      return;
    }
    fail(t.loc, "expected 'event' or 'endcamera' in the camera description, found " + quote_token(t.text) +
                    did_you_mean(t.text, {"event", "endcamera"}));
  }

  void event(const Token& keyword) {
    CameraShot s;
    s.loc = keyword.loc;
    event_key(s);
    s.pre = fraction("the pre-event interpolation time");
    s.post = fraction("the post-event interpolation time");
    const Token& mode = take("a camera mode (hover, look or follow)");
    if (mode.text == "hover") {
      s.mode = CameraMode::hover;
      s.location = vector("the hover camera's {} location");
      s.target = vector("the hover camera's {} look-at point");
      if ((s.location - s.target).norm() <= kPlacementTolerance)
        fail(mode.loc,
             "expected a hover camera that looks at a point away from itself, found location and look-at point equal");
    } else if (mode.text == "look") {
      s.mode = CameraMode::look;
      s.location = vector("the look camera's {} location");
      s.ball = ball_index("the ball the camera looks at", s.ball_loc);
    } else if (mode.text == "follow") {
      s.mode = CameraMode::follow;
      s.ball = ball_index("the ball the camera follows", s.ball_loc);
      s.location = vector("the follow camera's {} offset");
      if (s.location.norm() <= kPlacementTolerance)
        fail(mode.loc, "expected a follow camera offset away from the ball, found 0 0 0");
    } else {
      fail(mode.loc, "expected a camera mode (hover, look or follow), found " + quote_token(mode.text) +
                         did_you_mean(mode.text, {"hover", "look", "follow"}));
    }
    scene_.camera.push_back(s);
  }

  /// The seed's event number, or a camera key (an extension): what the description starts at.
  void event_key(CameraShot& s) {
    const Token& t = take("an event number or a camera key");
    s.event_loc = t.loc;
    long long n = 0;
    double ignored = 0;
    if (parse_integer(t.text, n)) {
      if (n < 0 || n > CameraShot::kLastEvent)
        fail(s.event_loc,
             "expected an event number from 0 to 65535 (65535 is the last event), found " + quote_token(t.text));
      s.event = static_cast<int>(n);
      return;
    }
    const std::vector<std::string_view> first_words = camera_key_first_words();
    const bool known = std::find(first_words.begin(), first_words.end(), t.text) != first_words.end();
    if (!known && (options_.strict || parse_double(t.text, ignored) != NumberStatus::not_number))
      fail_at_value(t, "expected an integer for the event number, found " + quote_token(t.text));
    if (!known)
      fail_at_value(t, "expected an event number or a camera key (" + camera_key_list() + "), found " +
                           quote_token(t.text) + did_you_mean(t.text, first_words));
    if (options_.strict)
      fail(t.loc, "the camera key '" + std::string(t.text) +
                      "' is an extension that --strict rejects (the seed names an event by its number)");
    CameraKey& key = s.key;
    std::string_view word = t.text;
    if (word == kShotWord) word = shot_prefix(key);
    if (const std::optional<int> ordinal = camera_key_ordinal(word)) {
      key.ordinal = *ordinal;
      const std::vector<std::string_view> kinds = camera_key_ordinal_kinds();
      const std::string choice = word_choice(kinds, "'") + " after '" + std::string(word) + "'";
      const Token& what = take(choice);
      const std::optional<CameraKeyKind> kind = camera_key_kind(what.text);
      if (!kind || !takes_ordinal(*kind))
        fail_at_value(what,
                      "expected " + choice + ", found " + quote_token(what.text) + did_you_mean(what.text, kinds));
      word = what.text;
    }
    key.kind = *camera_key_kind(word);
    key_operands(key);
  }

  /// `shot K` before a key: the shot it counts within (K from 1; checked against the scene's shots once
  /// they are all read). Gives the key's own first word, after it.
  std::string_view shot_prefix(CameraKey& key) {
    long long k = 0;
    const Token& number = take("a shot number after 'shot'");
    key.shot_loc = number.loc;
    if (!parse_integer(number.text, k))
      fail_at_value(number,
                    "expected an integer for the shot number after 'shot' (from 1, one shot per 'cue' line), "
                    "found " +
                        quote_token(number.text));
    if (k < 1)
      fail(number.loc, "expected a shot from 1 (the first 'cue' line's shot), found " + quote_token(number.text));
    key.shot = static_cast<int>(std::min<long long>(k, INT_MAX) - 1);
    const Token& word = take("a camera key after 'shot " + std::string(number.text) + "'");
    if (!camera_key_ordinal(word.text) && !camera_key_kind(word.text)) {
      std::vector<std::string_view> words = camera_key_first_words();
      words.pop_back();  // not `shot` again
      fail_at_value(word, "expected a camera key after 'shot " + std::string(number.text) + "' (" + camera_key_list() +
                              "), found " + quote_token(word.text) + did_you_mean(word.text, words));
    }
    return word.text;
  }

  /// The balls or seconds after a key's word (camera_key_text.h: ball_operands, takes_seconds).
  void key_operands(CameraKey& key) {
    switch (key.kind) {
      case CameraKeyKind::hit:
        key.a = ball_index("the first ball of the hit", key.a_loc);
        key.b = ball_index("the second ball of the hit", key.b_loc);
        if (key.a == key.b)
          fail(key.b_loc, "expected two different balls for 'hit', found ball " + std::to_string(key.a) + " twice");
        break;
      case CameraKeyKind::cushion: key.a = ball_index("the ball that meets the cushion", key.a_loc); break;
      case CameraKeyKind::jaw: key.a = ball_index("the ball that meets a pocket's jaw", key.a_loc); break;
      case CameraKeyKind::drop: key.a = ball_index("the pocketed ball", key.a_loc); break;
      case CameraKeyKind::at: {
        SourceLoc loc;
        key.seconds = number("the seconds after the start of the shot", &loc);
        if (key.seconds < 0)
          fail(loc, "expected the seconds after the start of the shot as 0 or more, found " +
                        quote_token(lexed_.tokens[pos_ - 1].text));
        break;
      }
      case CameraKeyKind::event:
      case CameraKeyKind::start:
      case CameraKeyKind::cue:
      case CameraKeyKind::end: break;
    }
  }

  double fraction(const std::string& what) {
    SourceLoc loc;
    const double v = number(what, &loc);
    if (v < 0 || v > 1)
      fail(loc, "expected " + what + " as a fraction from 0 to 1, found " + quote_token(lexed_.tokens[pos_ - 1].text));
    return v;
  }

 public:
  /// Fills what the statements could not: spins, the standard table, the camera's end.
  void finish() {
    if (in_camera_ && !too_many_errors_)
      error(scene_.camera_loc, "the camera description has no 'endcamera'; expected 'endcamera', found end of file");
    for (const auto& [name, value] : params_) apply_param(scene_.physics, name, value);
    for (std::size_t i : short_balls_) scene_.balls[i].position.z() = scene_.physics.ball_radius;
    const bool own_rails = !scene_.rails.empty();
    if (!own_rails) scene_.rails = standard_rails(scene_.physics);
    if (!scene_.pockets.empty())
      for (const SourceLoc& loc : named_pockets_)
        error(loc,
              "pocket names name the standard table's six pockets, and this scene has its own 'pocket' lines "
              "(the first on line " +
                  std::to_string(scene_.pockets.front().loc.line) + "): give the pocket's number, 0 to " +
                  std::to_string(scene_.pockets.size() - 1) + " in file order");
    // The standard pockets' jaws end the standard cushions; round a table of the scene's own cushions
    // they are plain drop circles.
    if (scene_.pockets.empty()) scene_.pockets = own_rails ? bare_standard_pockets() : standard_pockets(scene_.physics);
    if (!players_.empty())
      error(players_.front().loc, "a 'player' plays a game, and this scene has no 'game' line (game 9ball, say)");
    if (scene_.game && !map_.has_cue) scene_.cues.clear();  // the players play every shot
    if (scene_.game) rack_game_balls();
    if (rack_) add_rack();
    if (scene_.game) add_cue_ball();
    for (std::size_t i = 0; i < map_.spins.size(); ++i) {
      const auto index = static_cast<std::size_t>(map_.spins[i].ball);
      if (index < scene_.balls.size()) scene_.balls[index].spin = spins_[i];
    }
  }

 private:
  /// A game's object balls: the rack line's or the ball lines', which must be the game's; with neither,
  /// the game's own rack, seeded by the game.
  void rack_game_balls() {
    const GameLine& game = *scene_.game;
    const std::string name(rack_game_name(game.rules));
    if (rack_ && rack_->spec.game != game.rules)
      error(rack_->loc, "the rack is " + std::string(rack_game_name(rack_->spec.game)) + " and the game (line " +
                            std::to_string(game.loc.line) + ") is " + name +
                            ": rack the game's balls, or leave the rack out");
    bool object_lines = false;
    for (const auto& [number, line] : ball_lines_) {
      object_lines = object_lines || number >= 1;
      if (number > rack_ball_count(game.rules))
        error(game.loc, "the ball on line " + std::to_string(line) + " is the " + std::to_string(number) + ", and " +
                            name + " is played with the balls 1 to " + std::to_string(rack_ball_count(game.rules)));
    }
    if (rack_ || object_lines) return;
    RackLine line;
    line.spec.game = game.rules;
    line.spec.seed = game.seed;
    line.loc = game.loc;
    line.at = 0;
    rack_ = line;
  }

  /// A game's cue ball: its `ball 0` line's, or on the head spot (the player then chooses where in the
  /// kitchen to break from), first in file order when the scene writes no ball lines.
  void add_cue_ball() {
    if (ball_lines_.count(0)) return;
    Ball cue;
    cue.position = Vec3(-0.635, 0, scene_.physics.ball_radius);
    cue.loc = scene_.game->loc;
    const bool first = ball_lines_.empty();
    scene_.balls.insert(first ? scene_.balls.begin() : scene_.balls.end(), cue);
    const SceneSourceMap::BallTokens tokens{cue.loc, cue.loc, cue.loc};
    map_.balls.insert(first ? map_.balls.begin() : map_.balls.end(), tokens);
  }

  /// The rack's balls at the rack line's place in file order, by painted number; an error at the rack
  /// line when they do not all fit inside the cushions.
  void add_rack() {
    const RackLine& line = *rack_;
    RackSpec spec = line.spec;
    spec.radius = scene_.physics.ball_radius;
    Scene alone;         // the rack by itself on the scene's table, checked as ball lines are
    alone.cues.clear();  // so only the balls' places are checked
    alone.physics = scene_.physics;
    alone.rails = scene_.rails;
    SceneSourceMap alone_map;
    alone_map.rails = map_.rails;
    std::vector<SceneSourceMap::BallTokens> tokens;
    bool finite = true;
    for (const RackedBall& r : rack_balls(spec)) {
      Ball b;
      b.number = r.number;
      b.position = Vec3(r.x, r.y, spec.radius);
      b.loc = line.loc;
      finite = finite && b.position.allFinite();
      alone.balls.push_back(b);
      tokens.push_back({line.loc, line.loc, line.loc});
    }
    alone_map.balls = tokens;
    std::vector<Diagnostic> found;
    if (finite) validate_scene(alone, alone_map, found);
    const auto misfit = std::find_if(found.begin(), found.end(), [&](const Diagnostic& d) {
      return d.severity == Severity::error && d.loc.line == line.loc.line && d.loc.column == line.loc.column;
    });
    const std::string game(rack_game_name(spec.game));
    if (!finite) error(line.loc, "the " + game + " rack does not fit inside the cushions (ball radius too large)");
    if (misfit != found.end())
      error(line.loc, "the " + game + " rack does not fit inside the cushions: " + misfit->message);
    const auto at = static_cast<std::ptrdiff_t>(std::min(line.at, scene_.balls.size()));
    scene_.balls.insert(scene_.balls.begin() + at, alone.balls.begin(), alone.balls.end());
    map_.balls.insert(map_.balls.begin() + at, tokens.begin(), tokens.end());
  }

 public:
 private:
  LexedText lexed_;
  const ParseOptions& options_;
  std::vector<Diagnostic>& diagnostics_;
  std::size_t pos_ = 0;
  bool in_camera_ = false;
  bool camera_seen_ = false;
  bool too_many_errors_ = false;
  bool broken_cue_ = false;               ///< the last `cue` line had an error
  std::vector<std::size_t> short_balls_;  ///< `ball N X Y` lines: z is the ball radius, once params are read
  std::size_t error_count_ = 0;
  Scene scene_;
  SceneSourceMap map_;
  std::vector<Vec3> spins_;  ///< parallel to map_.spins
  std::map<int, int> ball_lines_;
  struct RackLine {
    RackSpec spec;
    SourceLoc loc;       ///< the `rack` keyword
    std::size_t at = 0;  ///< how many balls come before it in the file
  };
  std::optional<RackLine> rack_;
  std::map<std::string_view, int> param_lines_;
  std::vector<std::pair<std::string_view, double>> params_;
  std::vector<SourceLoc> named_pockets_;  ///< each pocket written by name after `pot`
  std::vector<PlayerLine> players_;       ///< `player` lines before the `game` line
};

}  // namespace

ParseResult parse_scene(std::string_view text, std::string_view name, const ParseOptions& options) {
  ParseResult result;
  Parser parser(text, options, result.diagnostics);
  parser.run();
  parser.finish();
  Scene& scene = parser.scene();
  scene.name = std::string(name);
  const SceneSourceMap& map = parser.source_map();

  if (parser.empty()) {
    result.diagnostics.push_back(
        {Severity::error, map.end, "the scene is empty; expected a cue description and at least one ball"});
  } else if (!has_errors(result.diagnostics)) {
    if (!map.has_cue && !scene.game)
      result.diagnostics.push_back(
          {Severity::error, map.end, "expected a cue description ('cue <ball index> <heading>'), found none"});
    if (scene.balls.empty())
      result.diagnostics.push_back({Severity::error, map.end,
                                    "expected at least one ball description ('ball <number> <position> <velocity> "
                                    "<orientation>'), found none"});
    if (options.strict && !parser.camera_seen())
      result.diagnostics.push_back(
          {Severity::error, map.end, "expected a camera description ('camera' ... 'endcamera'), found none"});
  }
  if (!has_errors(result.diagnostics)) validate_scene(scene, map, result.diagnostics);

  std::stable_sort(result.diagnostics.begin(), result.diagnostics.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return a.loc.line != b.loc.line ? a.loc.line < b.loc.line : a.loc.column < b.loc.column;
  });
  if (!has_errors(result.diagnostics)) result.scene = std::move(scene);
  return result;
}

}  // namespace bsim
