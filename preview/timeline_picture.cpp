#include "timeline_picture.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <imgui.h>

#include "camera_key_text.h"
#include "labels.h"
#include "shot.h"
#include "stroke_diagram.h"

namespace bsim {

namespace {

constexpr ImU32 kBackground = IM_COL32(22, 24, 28, 255);
constexpr ImU32 kRowBackground = IM_COL32(32, 35, 42, 255);
constexpr ImU32 kGrid = IM_COL32(255, 255, 255, 20);
constexpr ImU32 kWindowFill = IM_COL32(255, 255, 255, 16);
constexpr ImU32 kWindowHatch = IM_COL32(255, 255, 255, 70);
constexpr ImU32 kWindowEdge = IM_COL32(255, 255, 255, 90);
constexpr ImU32 kCursor = IM_COL32(255, 70, 70, 255);
constexpr ImU32 kError = IM_COL32(226, 40, 40, 255);
constexpr ImU32 kErrorText = IM_COL32(255, 120, 110, 255);
constexpr ImU32 kSectionEven = IM_COL32(44, 50, 64, 255);
constexpr ImU32 kSectionOdd = IM_COL32(36, 40, 50, 255);
constexpr ImU32 kSeparator = IM_COL32(240, 200, 110, 220);
constexpr ImU32 kReplayFill = IM_COL32(120, 70, 150, 110);
constexpr ImU32 kReplayEdge = IM_COL32(210, 160, 255, 230);
constexpr ImU32 kCutFill = IM_COL32(0, 0, 0, 120);
constexpr ImU32 kCutEdge = IM_COL32(150, 150, 150, 200);

constexpr ImU32 kPlayerColors[2] = {IM_COL32(130, 210, 255, 255), IM_COL32(180, 236, 140, 255)};
constexpr float kToneBar = 4;  // px, the bar of a game's call along a section's foot

bool has_turns(const TimelineData& data) {
  return std::any_of(data.shots.begin(), data.shots.end(), [](const TimelineShotSection& s) { return s.turn; });
}

/// px the band of shot sections needs: the shot's name, two lines of detail (a game's turn: two more
/// and the bar of its call), or the stroke's diagram.
float sections_height(const UiFonts& fonts, const TimelineData& data) {
  if (data.shots.empty()) return 0;
  if (has_turns(data))
    return std::max(fonts.bold_size + 4 * fonts.small_size + 10 + kToneBar, stroke_diagram_size(fonts).y) + 8;
  return std::max(fonts.bold_size + 2 * fonts.small_size + 8, stroke_diagram_size(fonts).y) + 8;
}

ImVec2 text_size(ImFont* font, float size, const std::string& text) {
  return font->CalcTextSizeA(size, FLT_MAX, 0, text.c_str());
}

/// `text` cut to fit `width` px, ending in an ellipsis when cut (never inside a character); empty when
/// not even the ellipsis fits.
std::string elided(ImFont* font, float size, const std::string& text, float width) {
  if (text_size(font, size, text).x <= width) return text;
  static const std::string kEllipsis = "\xE2\x80\xA6";
  std::string cut = text;
  while (!cut.empty()) {
    while (!cut.empty() && (static_cast<unsigned char>(cut.back()) & 0xC0) == 0x80) cut.pop_back();
    if (!cut.empty()) cut.pop_back();
    while (!cut.empty() && cut.back() == ' ') cut.pop_back();
    if (text_size(font, size, cut + kEllipsis).x <= width) return cut + kEllipsis;
  }
  return text_size(font, size, kEllipsis).x <= width ? kEllipsis : std::string();
}

/// Each line of `text` elided to `width` px.
std::string elided_lines(ImFont* font, float size, const std::string& text, float width) {
  std::string out;
  std::size_t from = 0;
  for (;;) {
    const std::size_t end = text.find('\n', from);
    out += elided(font, size, text.substr(from, end == std::string::npos ? end : end - from), width);
    if (end == std::string::npos) return out;
    out += '\n';
    from = end + 1;
  }
}

ImU32 with_alpha(ImU32 color, int alpha) {
  return (color & ~IM_COL32_A_MASK) | (static_cast<ImU32>(alpha) << IM_COL32_A_SHIFT);
}

// The tick step: the smallest "nice" number of seconds that leaves `min_pixels` between ticks.
double tick_step(double pixels_per_second, double min_pixels) {
  static const double kSteps[] = {0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.5, 1, 2, 5, 10, 15, 30, 60, 120, 300};
  for (double step : kSteps)
    if (step * pixels_per_second >= min_pixels) return step;
  return 600;
}

std::string seconds_text(double t, double step) {
  char buffer[32];
  const int decimals = step >= 1 ? 0 : step >= 0.1 ? 1 : 2;
  std::snprintf(buffer, sizeof buffer, "%.*f s", decimals, t);
  return buffer;
}

// Labels set in levels above a row: each goes on the first level where it does not overlap.
class LabelLevels {
 public:
  explicit LabelLevels(int levels) : right_(static_cast<std::size_t>(std::max(levels, 1)), -FLT_MAX) {}
  /// The level for a label, or -1 when every level is taken there (the event list still names it).
  int place(float left, float width, float gap) {
    for (std::size_t k = 0; k < right_.size(); ++k)
      if (left >= right_[k] + gap) {
        right_[k] = left + width;
        return static_cast<int>(k);
      }
    return -1;
  }

 private:
  std::vector<float> right_;
};

// The rows, top to bottom, and the margins around them: the levels of event numbers, the four bands
// (events, pockets, camera, cue) and the time axis. Drawing the picture and sizing the compact one
// (compact_timeline_height) both read it, so the scrub bar is as tall as what is drawn in it.
struct RowLayout {
  // Each band's height over the small text, and the gap between two bands.
  static constexpr float kEventsExtra = 6, kDropsExtra = 8, kCueExtra = 6, kAxisExtra = 8;
  static constexpr float kGap = 2;

  float sections_height = 0;  ///< px of the band of shot sections (0: one shot, or the scrub bar)
  float small = 0;            ///< px, the small text the rows are measured in
  float pad = 0;              ///< px, the picture's spacing unit
  float top_margin = 0;       ///< px above the title, or above the rows when compact
  float label_height = 0;     ///< px, one level of event numbers
  float camera_height = 0;    ///< px of the camera band, its lanes included
  float lane_height = 0;      ///< px of one lane under the camera bars, for the labels too long for their bar
  float lane = 0;             ///< px of all the lanes (0 for the scrub bar and for a script that failed)

  // Set by place().
  int label_levels = 0;
  int lanes = 0;
  float sections_top = 0, sections_bottom = 0;
  float labels_top = 0;
  float events_top = 0, events_bottom = 0;
  float drops_top = 0, drops_bottom = 0;
  float camera_top = 0, camera_bottom = 0;
  float cue_top = 0, cue_bottom = 0;
  float axis_top = 0, axis_bottom = 0;

  RowLayout(const UiFonts& fonts, bool compact, bool script_failed, float sections = 0)
      : sections_height(sections),
        small(fonts.small_size),
        pad(std::round(fonts.regular_size * 0.6f)),
        top_margin(pad * (compact ? 0.5f : 1.f)),
        label_height(small + 2),
        // A script that failed shows each description's error under its label.
        camera_height(script_failed ? fonts.regular_size + small + 12 : fonts.regular_size + 10),
        lane_height(compact || script_failed ? 0 : small + 4) {}

  /// px the band of shot sections takes with the gap under it.
  float sections_gap() const { return sections_height > 0 ? sections_height + 2 * kGap : 0; }

  /// px, the bottom of the camera bars (above the lane).
  float bars_bottom() const { return camera_bottom - lane; }

  /// px the four bands and the axis take, gaps aside: the height the label levels cannot have.
  float bands_height(int lane_count) const {
    return sections_gap() + (small + kEventsExtra) + (small + kDropsExtra) + camera_height + lanes_px(lane_count) +
           (small + kCueExtra) + (small + kAxisExtra);
  }

  /// px `n` lanes take under the camera bars.
  float lanes_px(int n) const { return n > 0 && lane_height > 0 ? n * lane_height + 2 : 0; }

  /// Places the rows from `top` down, with `levels` levels of event numbers above the events band and
  /// `lane_count` lanes of labels under the camera bars.
  void place(float top, int levels, int lane_count) {
    label_levels = levels;
    lanes = lane_height > 0 ? lane_count : 0;
    lane = lanes_px(lanes);
    sections_top = top;
    sections_bottom = top + sections_height;
    labels_top = top + sections_gap();
    events_top = labels_top + label_levels * label_height;
    events_bottom = events_top + small + kEventsExtra;
    drops_top = events_bottom + kGap;
    drops_bottom = drops_top + small + kDropsExtra;
    camera_top = drops_bottom + kGap;
    camera_bottom = camera_top + camera_height + lane;
    cue_top = camera_bottom + kGap;
    cue_bottom = cue_top + small + kCueExtra;
    axis_top = cue_bottom;
    axis_bottom = axis_top + small + kAxisExtra;
  }

  struct Band {
    float top, bottom;
  };
  /// The four bands, in the order of kRowNames.
  std::array<Band, 4> bands() const {
    return {
        {{events_top, events_bottom}, {drops_top, drops_bottom}, {camera_top, camera_bottom}, {cue_top, cue_bottom}}};
  }
};

constexpr const char* kRowNames[] = {"events", "pockets", "camera", "cue"};
/// The most levels of event numbers over the events row, and lanes of labels under the camera bars.
constexpr int kMaxLevels = 4, kMaxLanes = 8;

// Where things go across: the row names' gutter, then the time axis, then (when descriptions name an
// event the shot lacks) the zone where those go, having no time.
struct Across {
  float x0 = 0, x1 = 0;                 ///< px, the axis: time 0 and the end of the shot
  float zone_left = 0, zone_right = 0;  ///< px
  float zone = 0;                       ///< px wide, 0 when every description is placed
  float zone_wanted = 0;                ///< px the zone's descriptions would take at full size
  std::vector<float> unplaced_widths;   ///< px, each of them at full size
  double duration = 0;                  ///< s, never 0
  TimelineAxis axis;
};

struct LegendKey {
  ImU32 color;
  const char* name;
  bool bar;
};

void row_name(ImDrawList& list, const UiFonts& fonts, float x, float top, float bottom, const char* name) {
  list.AddText(fonts.small, fonts.small_size, ImVec2(x, (top + bottom - fonts.small_size) / 2), kLabelDim, name);
}

// A bar with its label clipped to it.
void labelled_bar(ImDrawList& list, const UiFonts& fonts, float x0, float x1, float top, float bottom, ImU32 color,
                  const std::string& label, bool bold_text) {
  if (x1 - x0 < 1) x1 = x0 + 1;
  list.AddRectFilled(ImVec2(x0, top), ImVec2(x1, bottom), with_alpha(color, 200), 3.f);
  list.AddRect(ImVec2(x0, top), ImVec2(x1, bottom), with_alpha(color, 255), 3.f);
  ImFont* font = bold_text ? fonts.regular : fonts.small;
  const float size = bold_text ? fonts.regular_size : fonts.small_size;
  const float pad = 4;
  if (x1 - x0 < 2 * pad + 4) return;
  list.PushClipRect(ImVec2(x0 + 1, top), ImVec2(x1 - 1, bottom), true);
  list.AddText(font, size, ImVec2(x0 + pad, (top + bottom - size) / 2), IM_COL32(255, 255, 255, 255), label.c_str());
  list.PopClipRect();
}

/// "hit 0 5 (8): follow ball 5 (8)", "event 3: hover": what the description starts at and does.
std::string camera_span_label(const TimelineCameraSpan& c, const std::vector<int>& painted) {
  if (!c.key.empty()) return camera_key_label(c.key, painted) + ": " + c.label;
  const std::string event = c.event == CameraShot::kLastEvent ? "last" : std::to_string(c.event);
  return "event " + event + ": " + c.label;
}

// A description of a camera script that does not fit the shot: its label above, its error (if any)
// below in a red bar, so a wrong event number reads next to the events that do exist.
void written_bar(ImDrawList& list, const UiFonts& fonts, float x0, float x1, float top, float bottom,
                 const TimelineCameraSpan& c, const std::vector<int>& painted) {
  if (c.problem.empty()) {
    labelled_bar(list, fonts, x0, x1, top, bottom, camera_mode_color(c.mode), camera_span_label(c, painted), true);
    return;
  }
  if (x1 - x0 < 3) x1 = x0 + 3;
  list.AddRectFilled(ImVec2(x0, top), ImVec2(x1, bottom), with_alpha(kError, 150), 3.f);
  list.AddRect(ImVec2(x0, top), ImVec2(x1, bottom), kError, 3.f, 0, 2.f);
  const float pad = 4, gap = (bottom - top - fonts.regular_size - fonts.small_size) / 3;
  list.PushClipRect(ImVec2(x0 + 1, top), ImVec2(x1 - 1, bottom), true);
  list.AddText(fonts.regular, fonts.regular_size, ImVec2(x0 + pad, top + gap), IM_COL32(255, 255, 255, 255),
               camera_span_label(c, painted).c_str());
  list.AddText(fonts.small, fonts.small_size, ImVec2(x0 + pad, bottom - gap - fonts.small_size),
               IM_COL32(255, 226, 220, 255), c.problem.c_str());
  list.PopClipRect();
}

// What the legend explains.
std::vector<LegendKey> legend_keys(bool script_failed) {
  std::vector<LegendKey> keys = {{event_color(EventType::start), "start / end", false},
                                 {event_color(EventType::cue), "cue", false},
                                 {event_color(EventType::ball_ball), "ball-ball", false},
                                 {event_color(EventType::ball_rail), "ball-rail", false},
                                 {event_color(EventType::ball_jaw), "ball-jaw", false},
                                 {pocket_color(), "ball drops in a pocket (its key: drop I)", false},
                                 {camera_mode_color(CameraMode::follow), "follow", true},
                                 {camera_mode_color(CameraMode::look), "look", true},
                                 {camera_mode_color(CameraMode::hover), "hover", true},
                                 {kWindowEdge, "interpolation window (\xE2\x96\xB2 its event)", true}};
  // A failed script has no interpolation windows, but has faults to explain.
  if (script_failed) keys.back() = {kError, "camera script error", true};
  return keys;
}

// One line of the event list: a numbered event, or a pocket drop (which has no number).
struct ListEntry {
  const TimelineEventMark* event = nullptr;  ///< null for a pocket drop
  std::string text;                          ///< without the number: "  1.234 s   ball 0 – ball 5"
};

// The event list's lines in time order, the pocket drops among the events by their key:
// "  4.900 s   drop 3 (12): into the top-right corner (pocket 2)".
std::vector<ListEntry> event_list_entries(const TimelineData& data) {
  std::vector<ListEntry> entries;
  std::size_t drop = 0;
  const auto add_drops_until = [&](double t) {
    for (; drop < data.drops.size() && data.drops[drop].time < t; ++drop) {
      const TimelineDrop& d = data.drops[drop];
      char buffer[48];
      std::snprintf(buffer, sizeof buffer, "%8.3f s   ", d.time);
      entries.push_back(
          {nullptr, buffer + ("drop " + ball_index_text(d.ball, data.painted)) + ": into " + d.pocket_name});
    }
  };
  for (const TimelineEventMark& e : data.events) {
    add_drops_until(e.time);
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%8.3f s   ", e.time);
    entries.push_back({&e, buffer + e.label});
  }
  add_drops_until(INFINITY);
  return entries;
}

// Draws one timeline picture. draw_timeline calls the steps top to bottom and back to front: a later
// step draws over an earlier one.
class TimelinePainter {
 public:
  TimelinePainter(ImDrawList& list, const TimelineData& data, const UiFonts& fonts, const TimelineLayout& layout)
      : list_(list),
        data_(data),
        fonts_(fonts),
        layout_(layout),
        right_(layout.x + layout.width),
        bottom_(layout.y + layout.height),
        script_failed_(!data.script_errors.empty()),
        rows_(fonts, layout.compact, script_failed_, layout.compact ? 0.f : sections_height(fonts, data)) {}

  const TimelineAxis& axis() const { return across_.axis; }

  void draw_background() { list_.AddRectFilled(ImVec2(layout_.x, layout_.y), ImVec2(right_, bottom_), kBackground); }

  /// The title and, for a script that failed, a note on how it is shown (neither when compact).
  /// Returns where the rows begin.
  float draw_header() {
    float y = layout_.y + rows_.top_margin;
    if (layout_.compact) return y;
    float title_right = right_;
    float bottom = y + fonts_.bold_size;
    if (data_.stroke) {
      // The stroke's ball diagram at the right end, the title clipped short of it.
      const ImVec2 size = stroke_diagram_size(fonts_);
      const ImVec2 at(right_ - rows_.pad - size.x, y);
      draw_stroke_diagram(list_, *data_.stroke, fonts_, at);
      title_right = at.x - rows_.pad;
      bottom = std::max(bottom, y + size.y);
    }
    // Cut short of the diagram (or the edge) with an ellipsis.
    const std::string title =
        elided(fonts_.bold, fonts_.bold_size, data_.title, title_right - rows_.pad - (layout_.x + rows_.pad));
    list_.AddText(fonts_.bold, fonts_.bold_size, ImVec2(layout_.x + rows_.pad, y), kLabelText, title.c_str());
    if (script_failed_) draw_failure_note(bottom + rows_.pad);
    return header_bottom();
  }

  /// Where the rows begin: under the title (and the stroke's diagram) and the failure note.
  float header_bottom() const {
    const float y = layout_.y + rows_.top_margin;
    if (layout_.compact) return y;
    float bottom = y + fonts_.bold_size;
    if (data_.stroke) bottom = std::max(bottom, y + stroke_diagram_size(fonts_).y);
    return bottom + rows_.pad + (script_failed_ ? failure_note().y + rows_.pad * 0.6f : 0.f);
  }

  /// Sets where everything goes, the rows starting at `top`.
  void lay_out(float top) {
    across_ = measure_across();
    const float spare = bottom_ - top - rows_.bands_height(0) - rows_.pad;
    const int lanes = lanes_needed(spare);
    rows_.place(top, label_levels_needed(top, lanes), lanes);
  }

  void draw_row_backgrounds() {
    const std::array<RowLayout::Band, 4> bands = rows_.bands();
    for (const RowLayout::Band& band : bands)
      list_.AddRectFilled(ImVec2(across_.x0, band.top), ImVec2(across_.x1, band.bottom), kRowBackground, 2.f);
    for (std::size_t k = 0; k < bands.size(); ++k)
      row_name(list_, fonts_, layout_.x + rows_.pad, bands[k].top, bands[k].bottom, kRowNames[k]);
  }

  // A scene of several shots: a band above the rows with a section per shot, its name and what it
  // does on the left (each line cut with an ellipsis when it is too long) and its stroke's diagram at
  // the right end: whole where the name and the strike's time fit beside it, else the ball alone,
  // shrunk to the section when even that is too wide.
  void draw_shot_sections() {
    const float top = rows_.sections_top, bottom = rows_.sections_bottom, pad = rows_.pad;
    if (bottom <= top) return;
    row_name(list_, fonts_, layout_.x + rows_.pad, top, bottom, "shots");
    const ImVec2 size = stroke_diagram_size(fonts_);
    for (std::size_t k = 0; k < data_.shots.size(); ++k) {
      const TimelineShotSection& s = data_.shots[k];
      const float a = at(s.start), b = std::max(at(s.end), a + 2);
      list_.AddRectFilled(ImVec2(a, top), ImVec2(b, bottom), k % 2 ? kSectionOdd : kSectionEven, 2.f);
      if (s.turn) draw_turn_tone(*s.turn, a, b);
      float text_right = b - pad / 2;
      if (s.stroke) {
        // A game's turn: the player's whole name too (before the speed beside the diagram).
        const float name = text_size(fonts_.bold, fonts_.bold_size, s.turn ? s.label + "  " + s.turn->name : s.label).x;
        const StrokeDiagramBall whole = stroke_diagram_ball(fonts_, ImVec2(b - pad - size.x, 0));
        // The whole diagram when the name and the strike's line fit beside it.
        const std::string strike = s.detail.substr(s.detail.find('\n') + 1);
        const float line = std::max(name, text_size(fonts_.small, fonts_.small_size, strike).x);
        if (b - pad - size.x >= a + pad + line + pad) {
          const ImVec2 corner(b - pad - size.x, top + (bottom - top - size.y) / 2);
          draw_stroke_diagram(list_, *s.stroke, fonts_, corner);
          note({TimelineDrawn::Kind::stroke, {}, corner.x, corner.y, corner.x + size.x, corner.y + size.y, int(k)});
          text_right = b - pad - size.x - pad / 2;
        } else {
          // As large as leaves the strike's line whole (at most the whole diagram's ball, at least
          // 8 px), and within the section however narrow.
          float r = std::clamp((b - a - 2 * pad - line - pad / 2) / 2 - 1, std::min(8.f, whole.radius), whole.radius);
          r = std::max(2.f, std::min(r, (b - a - pad) / 2 - 1));
          const ImVec2 centre(b - pad / 2 - r - 1, (top + bottom) / 2);
          draw_stroke_ball(list_, *s.stroke, centre, r);
          note({TimelineDrawn::Kind::stroke, {}, centre.x - r, centre.y - r, centre.x + r, centre.y + r, int(k)});
          text_right = b - pad / 2 - (2 * r + 2) - pad / 2;
        }
      }
      const float room = text_right - (a + pad);
      const ImVec2 at_name(a + pad, top + 3), at_detail(a + pad, top + 3 + fonts_.bold_size + 2);
      if (s.turn)
        draw_turn_name(static_cast<int>(k), s, at_name, room);
      else
        section_text(static_cast<int>(k), fonts_.bold, fonts_.bold_size, at_name, kLabelText,
                     elided(fonts_.bold, fonts_.bold_size, s.label, room));
      section_text(static_cast<int>(k), fonts_.small, fonts_.small_size, at_detail, kLabelDim,
                   elided_lines(fonts_.small, fonts_.small_size, s.detail, room));
      if (s.turn)
        draw_turn_call(static_cast<int>(k), *s.turn, ImVec2(at_detail.x, at_detail.y + 2 * fonts_.small_size + 2),
                       room);
    }
  }

  /// One text of a shot's section, drawn and noted.
  void section_text(int k, ImFont* font, float px, ImVec2 where, ImU32 color, const std::string& text) {
    list_.AddText(font, px, where, color, text.c_str());
    const ImVec2 extent = text_size(font, px, text);
    note({TimelineDrawn::Kind::shot_text, text, where.x, where.y, where.x + extent.x, where.y + extent.y, k});
  }

  // A game's call that stands out (a foul, ball in hand, a push-out, the winner): the section tinted
  // in its colour and a bar of it along the section's foot, seen however narrow the section.
  void draw_turn_tone(const TimelineTurn& turn, float a, float b) {
    if (turn.tone == GameTone::plain) return;
    const ImU32 color = game_tone_color(turn.tone);
    const float top = rows_.sections_top, bottom = rows_.sections_bottom;
    list_.AddRectFilled(ImVec2(a, top), ImVec2(b, bottom), with_alpha(color, 36), 2.f);
    list_.AddRectFilled(ImVec2(a, bottom - kToneBar), ImVec2(b, bottom), color);
  }

  // The shot's name and the player at the table in their colour: the whole name, its initials where
  // the section is narrow, the initials alone where even the shot's name does not fit beside them.
  void draw_turn_name(int k, const TimelineShotSection& s, ImVec2 where, float room) {
    const TimelineTurn& turn = *s.turn;
    const ImU32 color = kPlayerColors[turn.player == 1 ? 1 : 0];
    const float label = text_size(fonts_.bold, fonts_.bold_size, s.label + "  ").x;
    for (const std::string& who : {turn.name, turn.initials}) {
      if (label + text_size(fonts_.bold, fonts_.bold_size, who).x > room) continue;
      list_.AddText(fonts_.bold, fonts_.bold_size, where, kLabelText, s.label.c_str());
      section_text(k, fonts_.bold, fonts_.bold_size, ImVec2(where.x + label, where.y), color, who);
      return;
    }
    section_text(k, fonts_.bold, fonts_.bold_size, where, color,
                 elided(fonts_.bold, fonts_.bold_size, turn.initials, room));
  }

  // Under the shot's detail: what the player meant, then the rules' call in its tone's colour, each in
  // the most words that fit (the plan without "from hand"; the call without the foul's reason, then
  // its first part alone: "foul").
  void draw_turn_call(int k, const TimelineTurn& turn, ImVec2 where, float room) {
    const auto fitted = [&](std::vector<std::string> texts) {
      for (const std::string& text : texts)
        if (text_size(fonts_.small, fonts_.small_size, text).x <= room) return text;
      return elided(fonts_.small, fonts_.small_size, texts.back(), room);
    };
    const std::string from_hand = "from hand";
    const std::string plan = !turn.from_hand     ? turn.plan
                             : turn.plan.empty() ? from_hand
                                                 : from_hand + " \xC2\xB7 " + turn.plan;
    if (!plan.empty()) {
      section_text(k, fonts_.small, fonts_.small_size, where, kLabelText,
                   fitted({plan, turn.plan.empty() ? plan : turn.plan}));
      where.y += fonts_.small_size + 1;
    }
    const ImU32 color = turn.tone == GameTone::plain ? kLabelDim : game_tone_color(turn.tone);
    section_text(k, fonts_.small, fonts_.small_size, where, color,
                 fitted({turn.call, turn.short_call, turn.short_call.substr(0, turn.short_call.find(';'))}));
  }

  // Where each later shot begins: a line through every row (the scrub bar too).
  void draw_shot_separators() {
    const float top = rows_.sections_bottom > rows_.sections_top ? rows_.sections_top : rows_.events_top;
    for (std::size_t k = 1; k < data_.shots.size(); ++k) {
      const float x = at(data_.shots[k].start);
      list_.AddLine(ImVec2(x, top), ImVec2(x, rows_.axis_top + 5), kSeparator, 2.f);
    }
  }

  void draw_grid_and_axis() {
    const float small = fonts_.small_size;
    const double step =
        tick_step(across_.axis.pixels_per_second, text_size(fonts_.small, small, "00.0 s").x + 4 * rows_.pad);
    list_.AddLine(ImVec2(across_.x0, rows_.axis_top + 1), ImVec2(across_.x1, rows_.axis_top + 1), kLabelDim, 1.f);
    const double last = data_.replay ? data_.duration : across_.duration;  // the replay's box has no ticks
    for (int k = 0;; ++k) {
      const double t = k * step;
      if (t > last + 1e-9) break;
      const float x = at(t);
      list_.AddLine(ImVec2(x, rows_.events_top), ImVec2(x, rows_.cue_bottom), kGrid, 1.f);
      list_.AddLine(ImVec2(x, rows_.axis_top + 1), ImVec2(x, rows_.axis_top + 5), kLabelDim, 1.f);
      const std::string label = seconds_text(t, step);
      const float w = text_size(fonts_.small, small, label).x;
      list_.AddText(fonts_.small, small, ImVec2(std::min(x - w / 2, right_ - w - 2), rows_.axis_top + 5), kLabelDim,
                    label.c_str());
    }
  }

  void draw_cue_phases() {
    for (const CuePhaseSpan& p : data_.cue)
      labelled_bar(list_, fonts_, at(p.begin), at(p.end), rows_.cue_top + 2, rows_.cue_bottom - 2,
                   cue_phase_color(p.phase), cue_phase_label(p.phase), false);
  }

  // A script that failed is drawn as written: the faulty descriptions last (on top), each tied to the
  // event it names by a red line, and those naming no event in the zone (draw_unplaced_descriptions).
  void draw_camera_descriptions() {
    const float top = rows_.camera_top + 2, low = rows_.bars_bottom() - 2;
    if (!script_failed_) {
      // A label too long for its bar goes in a lane under the bars (the scrub bar: the mode alone).
      for (const TimelineCameraSpan& c : data_.camera) {
        const bool fits = label_fits_bar(c);
        labelled_bar(list_, fonts_, at(c.begin), at(c.end), top, low, camera_mode_color(c.mode),
                     fits              ? camera_span_label(c, data_.painted)
                     : layout_.compact ? c.label
                                       : "",
                     true);
      }
      draw_lane_labels();
    }
    for (int faulty = 0; script_failed_ && faulty < 2; ++faulty)
      for (const TimelineCameraSpan& c : data_.camera) {
        if (!c.placed || c.problem.empty() == bool(faulty)) continue;
        const float a = at(c.begin);
        if (faulty) list_.AddLine(ImVec2(a, rows_.events_top), ImVec2(a, top), kError, 2.f);
        written_bar(list_, fonts_, a, at(c.end), top, low, c, data_.painted);
      }
  }

  // The labels of short bars in the lanes under them, each starting at its bar and tied to it by a
  // thin line (draw_camera_descriptions).
  void draw_lane_labels() {
    const float small = fonts_.small_size;
    const std::vector<LaneLabel> placed = lane_labels(rows_.lanes).labels;
    for (const LaneLabel& l : placed) {
      const float start = at(l.span->begin) + 1, y = lane_y(l.lane);
      const ImU32 color = with_alpha(camera_mode_color(l.span->mode), 150);
      list_.AddLine(ImVec2(start, rows_.bars_bottom() - 2), ImVec2(start, y + small), color, 1.f);
      if (l.x < start - 1) list_.AddLine(ImVec2(l.x, y + small), ImVec2(start, y + small), color, 1.f);
    }
    // The text over the ties of the lanes below it, on the row's ground.
    for (const LaneLabel& l : placed) {
      const float y = lane_y(l.lane), w = text_size(fonts_.small, small, l.text).x;
      list_.AddRectFilled(ImVec2(l.x - 1, y), ImVec2(l.x + w + 1, y + small), kRowBackground);
      list_.AddText(fonts_.small, small, ImVec2(l.x, y), camera_mode_color(l.span->mode), l.text.c_str());
      note({TimelineDrawn::Kind::lane_label, l.text, l.x, y, l.x + w, y + small, -1, l.span});
    }
  }

  // The zone after the axis: the descriptions naming an event the shot lacks, side by side, narrowed
  // together when they do not fit.
  void draw_unplaced_descriptions() {
    const Across& z = across_;
    if (z.zone <= 0) return;
    const float small = fonts_.small_size;
    list_.AddRectFilled(ImVec2(z.zone_left, rows_.camera_top), ImVec2(z.zone_right, rows_.camera_bottom),
                        kRowBackground, 2.f);
    list_.PushClipRect(ImVec2(z.zone_left, rows_.events_top), ImVec2(z.zone_right, rows_.drops_bottom), true);
    list_.AddText(fonts_.small, small, ImVec2(z.zone_left + 2, (rows_.drops_top + rows_.drops_bottom - small) / 2),
                  kErrorText, "not in the shot:");
    list_.PopClipRect();
    const float scale = z.zone / z.zone_wanted;
    float x = z.zone_left;
    std::size_t k = 0;
    for (const TimelineCameraSpan& c : data_.camera) {
      if (c.placed) continue;
      const float w = z.unplaced_widths[k++] * scale;
      written_bar(list_, fonts_, x + 1, x + w - 1, rows_.camera_top + 2, rows_.camera_bottom - 2, c, data_.painted);
      x += w;
    }
  }

  void draw_no_stick_note() {
    if (!script_failed_ || !data_.cue.empty()) return;
    const float small = fonts_.small_size;
    list_.AddText(fonts_.small, small, ImVec2(across_.x0 + 4, (rows_.cue_top + rows_.cue_bottom - small) / 2),
                  kLabelDim, "no stick: it is placed from the camera script");
  }

  // The stretches the movie cuts out: darkened over every row, edged, "cut" above them where it fits.
  void draw_cuts() {
    const float top = rows_.events_top, low = rows_.cue_bottom, small = fonts_.small_size;
    for (const auto& [start, end] : data_.cuts) {
      const float a = at(start), b = std::max(at(end), a + 1);
      list_.AddRectFilled(ImVec2(a, top), ImVec2(b, low), kCutFill);
      list_.AddLine(ImVec2(a, top), ImVec2(a, low), kCutEdge, 1.f);
      list_.AddLine(ImVec2(b, top), ImVec2(b, low), kCutEdge, 1.f);
      if (text_size(fonts_.small, small, "cut").x + 2 < b - a)
        list_.AddText(fonts_.small, small, ImVec2(a + 2, low - small - 2), kLabelDim, "cut");
    }
  }

  // A game's replay: a box after the game's end over every row, its label and camera inside, and the
  // stretch it shows again marked along the axis and tied to the box.
  void draw_replay() {
    if (!data_.replay) return;
    const TimelineReplay& r = *data_.replay;
    const float a = at(data_.duration), b = at(data_.duration + r.length), top = rows_.events_top;
    const float low = rows_.cue_bottom, small = fonts_.small_size;
    list_.AddRectFilled(ImVec2(a, top), ImVec2(b, low), kReplayFill, 3.f);
    list_.AddRect(ImVec2(a, top), ImVec2(b, low), kReplayEdge, 3.f, 0, 1.5f);
    const float room = b - a - 6;
    float y = top + 3;
    for (const std::string& text : {r.label, r.detail, r.camera}) {
      if (room < small || y + small > low - 2) break;
      list_.AddText(fonts_.small, small, ImVec2(a + 3, y), text == r.label ? kLabelText : kLabelDim,
                    elided(fonts_.small, small, text, room).c_str());
      y += small + 2;
    }
    const float s0 = at(r.start), s1 = at(r.end), axis = rows_.axis_top + 1;
    list_.AddLine(ImVec2(s0, axis), ImVec2(s1, axis), kReplayEdge, 3.f);
    list_.AddBezierCubic(ImVec2((s0 + s1) / 2, axis), ImVec2((s0 + s1) / 2, axis - (low - top) * 0.4f),
                         ImVec2(a, axis - (low - top) * 0.4f), ImVec2(a, axis - 2), with_alpha(kReplayEdge, 140), 1.f);
  }

  // Shaded across every row, the event instant marked.
  void draw_interpolation_windows() {
    for (const TimelineWindow& w : data_.windows) {
      const float a = at(w.begin), b = at(w.end), e = at(w.event_time);
      list_.AddRectFilled(ImVec2(a, rows_.events_top), ImVec2(std::max(b, a + 1), rows_.cue_bottom), kWindowFill);
      list_.AddLine(ImVec2(a, rows_.events_top), ImVec2(a, rows_.cue_bottom), kWindowEdge, 1.f);
      list_.AddLine(ImVec2(b, rows_.events_top), ImVec2(b, rows_.cue_bottom), kWindowEdge, 1.f);
      // Hatching over the camera row: the camera is between two descriptions here.
      const float top = rows_.camera_top + 2, low = rows_.bars_bottom() - 2, h = low - top;
      list_.PushClipRect(ImVec2(a, top), ImVec2(std::max(b, a + 1), low), true);
      for (float x = a - h; x < b; x += 7) list_.AddLine(ImVec2(x, low), ImVec2(x + h, top), kWindowHatch, 1.5f);
      list_.PopClipRect();
      list_.AddTriangleFilled(ImVec2(e - 4, rows_.bars_bottom() + 1), ImVec2(e + 4, rows_.bars_bottom() + 1),
                              ImVec2(e, rows_.bars_bottom() - 5), IM_COL32(255, 255, 255, 230));
    }
  }

  // A mark per event in its type's colour, the number above it.
  void draw_events() {
    const float small = fonts_.small_size;
    LabelLevels levels(rows_.label_levels);
    for (const TimelineEventMark& e : data_.events) {
      const float x = at(e.time);
      const ImU32 color = event_color(e.type);
      list_.AddLine(ImVec2(x, rows_.events_top + 1), ImVec2(x, rows_.events_bottom - 1), color, 2.f);
      const std::string label = std::to_string(e.index);
      const float w = text_size(fonts_.small, small, label).x;
      const int level = levels.place(x - w / 2, w, 3);
      if (level < 0) continue;
      const float ly = rows_.events_top - (level + 1) * rows_.label_height;
      if (level > 0) list_.AddLine(ImVec2(x, ly + small), ImVec2(x, rows_.events_top), with_alpha(color, 90), 1.f);
      list_.AddText(fonts_.small, small, ImVec2(x - w / 2, ly), color, label.c_str());
    }
  }

  void draw_pocket_drops() {
    const float small = fonts_.small_size;
    const float text_y = (rows_.drops_top + rows_.drops_bottom - small) / 2;
    if (data_.drops.empty()) list_.AddText(fonts_.small, small, ImVec2(across_.x0 + 4, text_y), kLabelDim, "none");
    LabelLevels drop_levels(1);
    for (const TimelineDrop& d : data_.drops) {
      const float x = at(d.time), mid = (rows_.drops_top + rows_.drops_bottom) / 2;
      const float s = (rows_.drops_bottom - rows_.drops_top) * 0.32f;
      list_.AddTriangleFilled(ImVec2(x - s, mid - s), ImVec2(x + s, mid - s), ImVec2(x, mid + s), pocket_color());
      // A key on the time axis: a faint line down to a diamond on it, unlike the events' ticks.
      const float axis = rows_.axis_top + 1, r = layout_.compact ? 3.f : 4.5f;
      list_.AddLine(ImVec2(x, mid + s), ImVec2(x, axis - r), with_alpha(pocket_color(), 70), 1.f);
      list_.AddQuadFilled(ImVec2(x, axis - r), ImVec2(x + r, axis), ImVec2(x, axis + r), ImVec2(x - r, axis),
                          pocket_color());
      // Named by its key, as a camera description would start at it: "drop 3 (12)".
      const std::string label =
          layout_.compact ? ball_index_text(d.ball, data_.painted) : "drop " + ball_index_text(d.ball, data_.painted);
      const float w = text_size(fonts_.small, small, label).x;
      if (drop_levels.place(x + s + 2, w, 6) == 0 && x + s + 2 + w < across_.x1)
        list_.AddText(fonts_.small, small, ImVec2(x + s + 2, text_y), pocket_color(), label.c_str());
    }
  }

  void draw_cursor() {
    if (layout_.cursor < 0) return;
    const float x = at(std::clamp(layout_.cursor, 0.0, across_.duration));
    const float top = rows_.labels_top;
    list_.AddLine(ImVec2(x, top), ImVec2(x, rows_.axis_bottom), kCursor, 2.f);
    list_.AddTriangleFilled(ImVec2(x - 6, top), ImVec2(x + 6, top), ImVec2(x, top + 8), kCursor);
  }

  /// A failed script's errors as printed, first below the axis. Returns where the next part begins.
  float draw_script_errors() {
    const float small = fonts_.small_size;
    float y = rows_.axis_bottom + rows_.pad * 0.5f;
    for (const std::string& line : data_.script_errors) {
      if (y + small > bottom_ - 2) break;
      list_.AddText(fonts_.small, small, ImVec2(across_.x0, y), kErrorText, line.c_str());
      y += small + 3;
    }
    return errors_bottom();
  }

  /// Where the part under the errors begins (right under the axis when there are none).
  float errors_bottom() const {
    const float small = fonts_.small_size;
    float y = rows_.axis_bottom + rows_.pad * 0.5f;
    for (std::size_t k = 0; k < data_.script_errors.size() && y + small <= bottom_ - 2; ++k) y += small + 3;
    return script_failed_ ? y + rows_.pad * 0.5f : y;
  }

  /// The legend on one line at `y`, as many keys as fit. Returns where the next part begins.
  float draw_legend(float y) {
    const float small = fonts_.small_size;
    if (y + small > bottom_ - 2) return y;
    float x = across_.x0;
    for (const LegendKey& k : legend_keys(script_failed_)) {
      const float w = text_size(fonts_.small, small, k.name).x;
      if (x + small + 4 + w > right_ - rows_.pad) break;
      if (k.bar)
        list_.AddRectFilled(ImVec2(x, y + 2), ImVec2(x + small, y + small - 2), with_alpha(k.color, 200), 2.f);
      else
        list_.AddRectFilled(ImVec2(x + small / 2 - 1.5f, y + 1), ImVec2(x + small / 2 + 1.5f, y + small - 1), k.color);
      list_.AddText(fonts_.small, small, ImVec2(x + small + 4, y), kLabelDim, k.name);
      note({TimelineDrawn::Kind::legend_key, k.name, x, y, x + small + 4 + w, y + small});
      x += small + 4 + w + rows_.pad * 1.5f;
    }
    return y + (small + rows_.pad);
  }

  // Every event in a list from `y` down, in columns, so a number in the camera script can be checked
  // against what happened. A picture too short for all of them (a --size chosen by hand) ends the
  // list with "… and N more".
  void draw_event_list(float y) {
    const EventList l = event_list(y);
    if (l.lines < 1) return;
    const float small = fonts_.small_size;
    for (int k = 0; k < l.count && k < l.capacity; ++k) {
      const float cx = across_.x0 + static_cast<float>(k / l.lines) * l.column;
      const float cy = y + static_cast<float>(k % l.lines) * l.line;
      if (k == l.capacity - 1 && l.count > l.capacity) {
        const std::string more = "\xE2\x80\xA6 and " + std::to_string(l.count - l.capacity + 1) + " more";
        list_.AddText(fonts_.small, small, ImVec2(cx, cy), kLabelDim, more.c_str());
        note({TimelineDrawn::Kind::list_more, more, cx, cy, cx + l.column, cy + small});
        break;
      }
      const ListEntry& entry = l.entries[static_cast<std::size_t>(k)];
      draw_event_list_line(cx, cy, entry);
      note({TimelineDrawn::Kind::list_line, entry.text, cx, cy, cx + l.column, cy + small});
    }
  }

  /// px from the top of the picture that the whole of it needs, the event list complete: what the
  /// rows, the errors and the legend take at this layout's width, and the list in as many columns as
  /// fit across.
  float needed_height() {
    lay_out(header_bottom());
    const float y = errors_bottom() + fonts_.small_size + rows_.pad;  // the legend's line
    const EventList l = event_list(y);
    const int lines = l.count == 0 ? 0 : (l.count + l.columns - 1) / l.columns;
    return y + static_cast<float>(lines) * l.line + rows_.pad * 0.5f - layout_.y;
  }

 private:
  struct EventList {
    std::vector<ListEntry> entries;
    int count = 0;               ///< entries
    int lines = 0;               ///< lines per column that fit below the list's top
    int columns = 1;             ///< columns that fit across
    int capacity = 0;            ///< lines * columns
    float line = 0, column = 0;  ///< px
  };

  EventList event_list(float y) const {
    EventList l;
    const float small = fonts_.small_size, pad = rows_.pad;
    l.line = small + 3;
    l.lines = std::max(0, static_cast<int>((bottom_ - pad * 0.5f - y) / l.line));
    if (data_.events.empty()) return l;
    l.entries = event_list_entries(data_);
    l.count = static_cast<int>(l.entries.size());
    for (const ListEntry& entry : l.entries)
      l.column = std::max(l.column, text_size(fonts_.small, small, "000  " + entry.text).x);
    l.column += pad * 2;
    l.columns = std::max(1, static_cast<int>((right_ - across_.x0) / l.column));
    l.capacity = l.lines * l.columns;
    return l;
  }

  void note(TimelineDrawn drawn) const {
    if (layout_.drawn) layout_.drawn->push_back(std::move(drawn));
  }

  float at(double t) const { return across_.x0 + static_cast<float>(t) * across_.axis.pixels_per_second; }

  std::string failure_note_text() const {
    const std::size_t n = data_.script_errors.size();
    return "The camera script does not fit this shot (" + std::to_string(n) + (n == 1 ? " error" : " errors") +
           "): the camera row shows it as written, each description at the event it names, the faulty ones in red.";
  }
  float failure_note_wrap() const { return right_ - layout_.x - 2 * rows_.pad; }
  /// px the note takes, wrapped.
  ImVec2 failure_note() const {
    return fonts_.regular->CalcTextSizeA(fonts_.regular_size, FLT_MAX, failure_note_wrap(),
                                         failure_note_text().c_str());
  }

  void draw_failure_note(float y) {
    const float pad = rows_.pad;
    list_.AddText(fonts_.regular, fonts_.regular_size, ImVec2(layout_.x + pad, y - pad * 0.4f), kErrorText,
                  failure_note_text().c_str(), nullptr, failure_note_wrap());
  }

  /// px, the top of lane `k` under the camera bars.
  float lane_y(int k) const { return rows_.bars_bottom() + 1 + static_cast<float>(k) * rows_.lane_height; }

  bool label_fits_bar(const TimelineCameraSpan& c) const {
    const std::string label = camera_span_label(c, data_.painted);
    return text_size(fonts_.regular, fonts_.regular_size, label).x + 8 <= at(c.end) - at(c.begin);
  }

  /// px, where the shot section holding time t begins (time 0 for a scene of one shot).
  float section_start(double t) const {
    float x = across_.x0;
    for (const TimelineShotSection& s : data_.shots)
      if (s.start <= t) x = at(s.start);
    return x;
  }

  struct LaneLabel {
    const TimelineCameraSpan* span = nullptr;
    std::string text;  ///< the label, elided with an ellipsis when cut
    float x = 0;       ///< px, where it starts: its bar's start, or left of it at the picture's right edge
    int lane = 0;
  };
  struct LanePlan {
    std::vector<LaneLabel> labels;
    bool whole = true;  ///< every label whole
  };

  // The labels too long for their bars in `lanes` lanes, from the last bar back: each starts at its bar
  // in the first lane free there, never over another; the last ones may move left of their bars to
  // stay whole before the picture's right edge, but never out of their shot's section. One for which
  // no lane has room is cut, with an ellipsis, to the room of the lane with the most.
  LanePlan lane_labels(int lanes) const {
    LanePlan plan;
    if (lanes <= 0 || layout_.compact || script_failed_) return plan;
    const float edge = right_ - rows_.pad, gap = rows_.pad * 0.75f, small = fonts_.small_size;
    std::vector<float> free_to(static_cast<std::size_t>(lanes), edge);  // px, each lane is free left of this
    for (auto it = data_.camera.rbegin(); it != data_.camera.rend(); ++it) {
      if (label_fits_bar(*it)) continue;
      const std::string label = camera_span_label(*it, data_.painted);
      const float x = at(it->begin), w = text_size(fonts_.small, small, label).x;
      LaneLabel placed{&*it, label, x, -1};
      for (std::size_t k = 0; k < free_to.size() && placed.lane < 0; ++k) {
        if (x + w + gap <= free_to[k]) placed.lane = static_cast<int>(k);
        // At the right edge: moved left to stay whole, within its own shot.
        else if (free_to[k] == edge && edge - w >= std::max(section_start(it->begin), across_.x0)) {
          placed.lane = static_cast<int>(k);
          placed.x = std::min(x, edge - w);
        }
      }
      if (placed.lane < 0) {
        const auto most = std::max_element(free_to.begin(), free_to.end());
        placed.lane = static_cast<int>(most - free_to.begin());
        placed.text = elided(fonts_.small, small, label, *most - gap - x);
        plan.whole = false;
      }
      free_to[static_cast<std::size_t>(placed.lane)] = placed.x;
      if (!placed.text.empty()) plan.labels.push_back(std::move(placed));
    }
    return plan;
  }

  // As many lanes as the labels need to be whole, up to what the height allows (none when every
  // label fits its bar).
  int lanes_needed(float spare) const {
    if (layout_.compact || script_failed_ || rows_.lane_height <= 0) return 0;
    const bool any = std::any_of(data_.camera.begin(), data_.camera.end(),
                                 [&](const TimelineCameraSpan& c) { return !label_fits_bar(c); });
    if (!any) return 0;
    const int max_lanes =
        layout_.fit_all ? kMaxLanes : std::clamp(static_cast<int>(spare * 0.3f / rows_.lane_height), 1, kMaxLanes);
    for (int lanes = 1; lanes < max_lanes; ++lanes)
      if (lane_labels(lanes).whole) return lanes;
    return max_lanes;
  }

  Across measure_across() const {
    const float text = fonts_.regular_size, small = fonts_.small_size, pad = rows_.pad;
    Across a;
    float gutter = 0;
    for (const char* n : kRowNames) gutter = std::max(gutter, text_size(fonts_.small, small, n).x);
    gutter += 2 * pad;
    a.x0 = layout_.x + gutter;
    // Descriptions naming an event the shot lacks have no time: they go in a zone after the axis.
    for (const TimelineCameraSpan& c : data_.camera)
      if (!c.placed)
        a.unplaced_widths.push_back(std::max(text_size(fonts_.regular, text, camera_span_label(c, data_.painted)).x,
                                             text_size(fonts_.small, small, c.problem).x) +
                                    2 * pad);
    for (float w : a.unplaced_widths) a.zone_wanted += w;
    a.zone = std::min(a.zone_wanted, (right_ - a.x0) * 0.4f);
    a.zone_right = right_ - pad;
    a.zone_left = a.zone_right - a.zone;
    a.x1 = a.zone > 0 ? a.zone_left - 2 * pad : right_ - pad * 2.5f;
    a.duration = std::max(data_.duration + (data_.replay ? data_.replay->length : 0.0), 1e-6);
    a.axis = {a.x0, static_cast<float>((a.x1 - a.x0) / a.duration)};
    return a;
  }

  // As many label levels as the crowding needs, up to what the height allows.
  int label_levels_needed(float top, int lanes) const {
    const float spare = bottom_ - top - rows_.bands_height(lanes) - rows_.pad;
    const int max_levels = layout_.compact ? 1
                           : layout_.fit_all
                               ? kMaxLevels
                               : std::clamp(static_cast<int>(spare * 0.3f / rows_.label_height), 1, kMaxLevels);
    for (int levels = 1; levels < max_levels; ++levels)
      if (event_numbers_fit(levels)) return levels;
    return max_levels;
  }

  bool event_numbers_fit(int levels) const {
    LabelLevels trial(levels);
    for (const TimelineEventMark& e : data_.events) {
      const float w = text_size(fonts_.small, fonts_.small_size, std::to_string(e.index)).x;
      if (trial.place(at(e.time) - w / 2, w, 3) < 0) return false;
    }
    return true;
  }

  // One line of the event list: the number right-aligned in its type's colour (a pocket drop: a
  // diamond, as on the axis, and its line in the drops' colour), then time and label.
  void draw_event_list_line(float cx, float cy, const ListEntry& entry) {
    const float small = fonts_.small_size;
    const float numbers_w = text_size(fonts_.small, small, "000").x;
    if (entry.event) {
      const std::string number = std::to_string(entry.event->index);
      const float nw = text_size(fonts_.small, small, number).x;
      list_.AddText(fonts_.small, small, ImVec2(cx + numbers_w - nw, cy), event_color(entry.event->type),
                    number.c_str());
    } else {
      const float r = small * 0.3f, x = cx + numbers_w - r - 1, y = cy + small / 2;
      list_.AddQuadFilled(ImVec2(x, y - r), ImVec2(x + r, y), ImVec2(x, y + r), ImVec2(x - r, y), pocket_color());
    }
    list_.AddText(fonts_.small, small, ImVec2(cx + numbers_w + 4, cy), entry.event ? kLabelText : pocket_color(),
                  entry.text.c_str());
  }

  ImDrawList& list_;
  const TimelineData& data_;
  const UiFonts& fonts_;
  const TimelineLayout& layout_;
  const float right_, bottom_;
  const bool script_failed_;
  RowLayout rows_;
  Across across_;
};

/// A game: each shot's section gets its turn (who, what they meant, the rules' call).
void add_turns(const GameRecord& game, const std::vector<Pocket>& pockets, std::vector<TimelineShotSection>& sections) {
  for (std::size_t k = 0; k < sections.size() && k < game.turns.size(); ++k) {
    const GameTurn& turn = game.turns[k];
    TimelineTurn t;
    t.player = turn.player;
    t.name = game_player_name(game, turn.player);
    t.initials = name_initials(t.name);
    t.plan = plan_text(turn.planned, pockets);
    // The shooter had the cue ball in hand: the call before said so.
    t.from_hand = k > 0 && game.turns[k - 1].verdict.in_hand != InHand::none;
    t.call = turn_call_text(turn);
    t.short_call = turn_short_call(turn);
    t.tone = turn_tone(turn);
    sections[k].turn = std::move(t);
  }
}

/// The title's words on a game: "9-ball, Ann v Bo: Ann wins".
std::string game_title(const GameRecord& game) {
  const auto name = [&](int p) { return game_player_name(game, p); };
  return game_rules_name(game.rules) + ", " + name(0) + " v " + name(1) + ": " +
         (game.winner       ? name(*game.winner) + " wins"
          : game.shot_limit ? "no winner (the shot limit)"
                            : "no winner");
}

/// A scene of several shots: each shot's section, named as a `shot K` camera key counts ("shot 2").
std::vector<TimelineShotSection> shot_sections(const Shot& shot, const std::vector<int>& painted) {
  std::vector<TimelineShotSection> sections;
  const std::vector<ShotSpan>& spans = shot.timeline.shots();
  for (std::size_t k = 0; k < spans.size() && k < shot.scene.cues.size(); ++k) {
    const Cue& cue = shot.scene.cues[k];
    TimelineShotSection s;
    s.start = spans[k].start;
    s.cue = spans[k].cue;
    s.end = k + 1 < spans.size() ? spans[k + 1].start : shot.timeline.duration();
    s.label = "shot " + std::to_string(k + 1);
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "%.1f\xC2\xB0\nstrike at %.2f s", cue.heading_deg, s.cue);
    s.detail = "cue " + ball_index_text(cue.target, painted) +
               (cue.aims() ? " pot " + ball_index_text(cue.pot_ball, painted) + " into " +
                                 pocket_short_name(shot.scene.pockets, cue.pot_pocket) + " at "
                           : " at ") +
               buffer;
    s.stroke = cue.stroke;
    sections.push_back(std::move(s));
  }
  if (shot.game) add_turns(*shot.game, shot.scene.pockets, sections);
  return sections;
}

/// The events, the camera's descriptions and windows, and the stick's phases.
void add_events_and_camera(const Shot& shot, TimelineData& data) {
  for (const Event& e : shot.timeline.events())
    data.events.push_back({e.index, e.time, e.type, event_label(e, data.painted)});
  if (shot.camera) {
    for (const CameraSegment& s : shot.camera->segments()) {
      if (s.shot < 0 || s.shot >= static_cast<int>(shot.scene.camera.size())) continue;
      const CameraShot& c = shot.scene.camera[static_cast<std::size_t>(s.shot)];
      const std::string key = c.key.kind == CameraKeyKind::event ? std::string() : camera_key_text(c.key);
      data.camera.push_back({s.begin, s.end, c.event, c.mode, camera_shot_label(c, data.painted), {}, true, key});
    }
    for (const CameraWindow& w : shot.camera->windows()) data.windows.push_back({w.begin, w.event_time, w.end});
  }
  if (shot.cue) data.cue = shot.cue->phases();
}

/// A game's replay (Shot::movie), and the movie's length in the title.
void add_replay(const Shot& shot, TimelineData& data) {
  const std::optional<MovieSegment> replay = shot.movie.replay();
  if (!replay) return;
  const int shot_number = shot.timeline.shot_at(replay->end) + 1;
  data.replay = TimelineReplay{replay->start,
                               replay->end,
                               replay->length(),
                               "replay",
                               "shot " + std::to_string(shot_number) + " at half speed",
                               shot.replay_what};
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "; the movie %.0f s with the replay", shot.movie.duration());
  data.title += buffer;
  data.cuts = shot.movie.cuts(shot.timeline.duration());  // the broadcast edit's
}

}  // namespace

TimelineData timeline_data(const Shot& shot) {
  TimelineData data;
  const Timeline& timeline = shot.timeline;
  data.duration = timeline.duration();
  int pocketed = 0;
  for (const PocketDrop& d : timeline.pocket_drops()) {
    data.drops.push_back({d.time, d.ball, d.pocket, pocket_name(shot.scene.pockets, d.pocket)});
    ++pocketed;
  }
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "%s  \xE2\x80\x94  %.2f s, %zu events (0 to %zu), %d pocketed",
                shot.scene.name.c_str(), data.duration, timeline.events().size(),
                timeline.events().empty() ? 0 : timeline.events().size() - 1, pocketed);
  data.title = buffer;
  data.painted = painted_numbers(shot.scene);
  if (timeline.shot_count() > 1) {
    // Each shot's stroke goes in its section.
    data.title += ", " + std::to_string(timeline.shot_count()) + " shots";
    data.shots = shot_sections(shot, data.painted);
  } else if (const auto& stroke = shot.scene.cue().stroke) {
    // The stroke: the tip's speed, where it meets the ball (fractions of the radius) and the elevation.
    std::snprintf(buffer, sizeof buffer, ", stroke %.2f m/s at side %+.2f height %+.2f, %.0f\xC2\xB0 up", stroke->speed,
                  stroke->side, stroke->height, stroke->elevation_deg);
    data.title += buffer;
    data.stroke = stroke;
  }
  if (shot.game) data.title += "  \xE2\x80\x94  " + game_title(*shot.game);
  add_events_and_camera(shot, data);
  add_replay(shot, data);
  return data;
}

float timeline_height(const TimelineData& data, const UiFonts& fonts, float width) {
  ImDrawList unused(nullptr);  // measured, not drawn
  TimelineLayout layout{0, 0, width, 1e6f};
  layout.fit_all = true;
  return TimelinePainter(unused, data, fonts, layout).needed_height();
}

float compact_timeline_height(const UiFonts& fonts) {
  RowLayout rows(fonts, true, false);
  rows.place(rows.top_margin, 1, 0);
  return rows.axis_bottom;
}

TimelineAxis draw_timeline(ImDrawList& list, const TimelineData& data, const UiFonts& fonts,
                           const TimelineLayout& layout) {
  TimelinePainter painter(list, data, fonts, layout);
  painter.draw_background();
  painter.lay_out(painter.draw_header());
  painter.draw_row_backgrounds();
  painter.draw_shot_sections();
  painter.draw_grid_and_axis();
  painter.draw_cue_phases();
  painter.draw_camera_descriptions();
  painter.draw_unplaced_descriptions();
  painter.draw_no_stick_note();
  painter.draw_interpolation_windows();
  painter.draw_shot_separators();
  painter.draw_events();
  painter.draw_pocket_drops();
  painter.draw_cuts();
  painter.draw_replay();
  painter.draw_cursor();
  if (layout.compact) return painter.axis();
  float y = painter.draw_script_errors();
  y = painter.draw_legend(y);
  painter.draw_event_list(y);
  return painter.axis();
}

}  // namespace bsim
