#include "timeline_picture.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "labels.h"
#include "shot.h"

namespace bsim {

namespace {

constexpr ImU32 kBackground = IM_COL32(22, 24, 28, 255);
constexpr ImU32 kRowBackground = IM_COL32(32, 35, 42, 255);
constexpr ImU32 kText = IM_COL32(230, 232, 236, 255);
constexpr ImU32 kDim = IM_COL32(150, 156, 168, 255);
constexpr ImU32 kGrid = IM_COL32(255, 255, 255, 20);
constexpr ImU32 kWindowFill = IM_COL32(255, 255, 255, 16);
constexpr ImU32 kWindowHatch = IM_COL32(255, 255, 255, 70);
constexpr ImU32 kWindowEdge = IM_COL32(255, 255, 255, 90);
constexpr ImU32 kCursor = IM_COL32(255, 70, 70, 255);
constexpr ImU32 kError = IM_COL32(226, 40, 40, 255);
constexpr ImU32 kErrorText = IM_COL32(255, 120, 110, 255);

ImVec2 text_size(ImFont* font, float size, const std::string& text) {
  return font->CalcTextSizeA(size, FLT_MAX, 0, text.c_str());
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

struct Rows {
  float labels_top = 0, label_height = 0;
  int label_levels = 0;
  float events_top = 0, events_bottom = 0;
  float drops_top = 0, drops_bottom = 0;
  float camera_top = 0, camera_bottom = 0;
  float cue_top = 0, cue_bottom = 0;
  float axis_top = 0, axis_bottom = 0;
};

void row_name(ImDrawList& list, const UiFonts& fonts, float x, float top, float bottom, const char* name) {
  list.AddText(fonts.small, fonts.small_size, ImVec2(x, (top + bottom - fonts.small_size) / 2), kDim, name);
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

std::string camera_span_label(const TimelineCameraSpan& c, bool compact) {
  const std::string event = c.event == CameraShot::kLastEvent ? "last" : std::to_string(c.event);
  return compact ? c.label : "event " + event + ": " + c.label;
}

// A description of a camera script that does not fit the shot: its label above, its error (if any)
// below in a red bar, so a wrong event number reads next to the events that do exist.
void written_bar(ImDrawList& list, const UiFonts& fonts, float x0, float x1, float top, float bottom,
                 const TimelineCameraSpan& c) {
  if (c.problem.empty()) {
    labelled_bar(list, fonts, x0, x1, top, bottom, camera_mode_color(c.mode), camera_span_label(c, false), true);
    return;
  }
  if (x1 - x0 < 3) x1 = x0 + 3;
  list.AddRectFilled(ImVec2(x0, top), ImVec2(x1, bottom), with_alpha(kError, 150), 3.f);
  list.AddRect(ImVec2(x0, top), ImVec2(x1, bottom), kError, 3.f, 0, 2.f);
  const float pad = 4, gap = (bottom - top - fonts.regular_size - fonts.small_size) / 3;
  list.PushClipRect(ImVec2(x0 + 1, top), ImVec2(x1 - 1, bottom), true);
  list.AddText(fonts.regular, fonts.regular_size, ImVec2(x0 + pad, top + gap), IM_COL32(255, 255, 255, 255),
               camera_span_label(c, false).c_str());
  list.AddText(fonts.small, fonts.small_size, ImVec2(x0 + pad, bottom - gap - fonts.small_size),
               IM_COL32(255, 226, 220, 255), c.problem.c_str());
  list.PopClipRect();
}

}  // namespace

TimelineData timeline_data(const Shot& shot) {
  TimelineData data;
  const Timeline& timeline = shot.timeline;
  data.duration = timeline.duration();
  int pocketed = 0;
  for (const PocketDrop& d : timeline.pocket_drops()) {
    data.drops.push_back({d.time, d.ball, d.pocket});
    ++pocketed;
  }
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "%s  \xE2\x80\x94  %.2f s, %zu events (0 to %zu), %d pocketed", shot.scene.name.c_str(),
                data.duration, timeline.events().size(), timeline.events().empty() ? 0 : timeline.events().size() - 1,
                pocketed);
  data.title = buffer;
  for (const Event& e : timeline.events()) data.events.push_back({e.index, e.time, e.type, event_label(e)});
  if (shot.camera) {
    for (const CameraSegment& s : shot.camera->segments()) {
      if (s.shot < 0 || s.shot >= static_cast<int>(shot.scene.camera.size())) continue;
      const CameraShot& c = shot.scene.camera[static_cast<std::size_t>(s.shot)];
      data.camera.push_back({s.begin, s.end, c.event, c.mode, camera_shot_label(c), {}, true});
    }
    for (const CameraWindow& w : shot.camera->windows()) data.windows.push_back({w.begin, w.event_time, w.end});
  }
  if (shot.cue) data.cue = shot.cue->phases();
  return data;
}

float compact_timeline_height(const UiFonts& fonts) {
  const float text = fonts.regular_size, small = fonts.small_size;
  return std::round(text * 0.3f) + (small + 2) + (small + 6) + 2 + (small + 8) + 2 + (text + 10) + 2 + (small + 6) +
         (small + 8);
}

TimelineAxis draw_timeline(ImDrawList& list, const TimelineData& data, const UiFonts& fonts, const TimelineLayout& layout) {
  const float text = fonts.regular_size, small = fonts.small_size;
  const float pad = std::round(text * 0.6f);
  const float right = layout.x + layout.width, bottom = layout.y + layout.height;
  list.AddRectFilled(ImVec2(layout.x, layout.y), ImVec2(right, bottom), kBackground);

  const bool script_failed = !data.script_errors.empty();
  float y = layout.y + pad * (layout.compact ? 0.5f : 1.f);
  if (!layout.compact) {
    list.AddText(fonts.bold, fonts.bold_size, ImVec2(layout.x + pad, y), kText, data.title.c_str());
    y += fonts.bold_size + pad;
    if (script_failed) {
      const std::size_t n = data.script_errors.size();
      const std::string note = "The camera script does not fit this shot (" + std::to_string(n) +
                               (n == 1 ? " error" : " errors") +
                               "): the camera row shows it as written, each description at the event it "
                               "names, the faulty ones in red.";
      const float wrap = right - layout.x - 2 * pad;
      list.AddText(fonts.regular, text, ImVec2(layout.x + pad, y - pad * 0.4f), kErrorText, note.c_str(), nullptr, wrap);
      y += fonts.regular->CalcTextSizeA(text, FLT_MAX, wrap, note.c_str()).y + pad * 0.6f;
    }
  }

  // Rows, top to bottom.
  Rows r;
  r.label_height = small + 2;
  // A script that failed shows each description's error under its label.
  const float camera_height = script_failed ? text + small + 12 : text + 10;
  const float fixed = (small + 6) + (small + 8) + camera_height + (small + 6) + (small + 8);
  const float spare = bottom - y - fixed - pad;
  const char* const names[] = {"events", "pockets", "camera", "cue"};
  float gutter = 0;
  for (const char* n : names) gutter = std::max(gutter, text_size(fonts.small, small, n).x);
  gutter += 2 * pad;
  const float x0 = layout.x + gutter;
  // Descriptions naming an event the shot lacks have no time: they go in a zone after the axis.
  std::vector<float> unplaced_widths;
  for (const TimelineCameraSpan& c : data.camera)
    if (!c.placed)
      unplaced_widths.push_back(std::max(text_size(fonts.regular, text, camera_span_label(c, layout.compact)).x,
                                         text_size(fonts.small, small, c.problem).x) + 2 * pad);
  float zone_wanted = 0;
  for (float w : unplaced_widths) zone_wanted += w;
  const float zone = std::min(zone_wanted, (right - x0) * 0.4f);
  const float zone_right = right - pad, zone_left = zone_right - zone;
  const float x1 = zone > 0 ? zone_left - 2 * pad : right - pad * 2.5f;
  const double duration = std::max(data.duration, 1e-6);
  TimelineAxis axis{x0, static_cast<float>((x1 - x0) / duration)};
  const auto at = [&](double t) { return x0 + static_cast<float>(t) * axis.pixels_per_second; };
  // As many label levels as the crowding needs, up to what the height allows.
  const int max_levels = layout.compact ? 1 : std::clamp(static_cast<int>(spare * 0.3f / r.label_height), 1, 4);
  r.label_levels = 1;
  for (int levels = 1; levels <= max_levels; ++levels) {
    r.label_levels = levels;
    LabelLevels trial(levels);
    bool all = true;
    for (const TimelineEventMark& e : data.events) {
      const float w = text_size(fonts.small, small, std::to_string(e.index)).x;
      all = trial.place(at(e.time) - w / 2, w, 3) >= 0 && all;
    }
    if (all) break;
  }
  r.labels_top = y;
  r.events_top = r.labels_top + r.label_levels * r.label_height;
  r.events_bottom = r.events_top + small + 6;
  r.drops_top = r.events_bottom + 2;
  r.drops_bottom = r.drops_top + small + 8;
  r.camera_top = r.drops_bottom + 2;
  r.camera_bottom = r.camera_top + camera_height;
  r.cue_top = r.camera_bottom + 2;
  r.cue_bottom = r.cue_top + small + 6;
  r.axis_top = r.cue_bottom;
  r.axis_bottom = r.axis_top + small + 8;


  for (auto [top, bottom_edge] : {std::pair{r.events_top, r.events_bottom}, std::pair{r.drops_top, r.drops_bottom},
                                  std::pair{r.camera_top, r.camera_bottom}, std::pair{r.cue_top, r.cue_bottom}})
    list.AddRectFilled(ImVec2(x0, top), ImVec2(x1, bottom_edge), kRowBackground, 2.f);
  row_name(list, fonts, layout.x + pad, r.events_top, r.events_bottom, names[0]);
  row_name(list, fonts, layout.x + pad, r.drops_top, r.drops_bottom, names[1]);
  row_name(list, fonts, layout.x + pad, r.camera_top, r.camera_bottom, names[2]);
  row_name(list, fonts, layout.x + pad, r.cue_top, r.cue_bottom, names[3]);

  // Grid and axis.
  const double step = tick_step(axis.pixels_per_second, text_size(fonts.small, small, "00.0 s").x + 4 * pad);
  list.AddLine(ImVec2(x0, r.axis_top + 1), ImVec2(x1, r.axis_top + 1), kDim, 1.f);
  for (int k = 0;; ++k) {
    const double t = k * step;
    if (t > duration + 1e-9) break;
    const float x = at(t);
    list.AddLine(ImVec2(x, r.events_top), ImVec2(x, r.cue_bottom), kGrid, 1.f);
    list.AddLine(ImVec2(x, r.axis_top + 1), ImVec2(x, r.axis_top + 5), kDim, 1.f);
    const std::string label = seconds_text(t, step);
    const float w = text_size(fonts.small, small, label).x;
    list.AddText(fonts.small, small, ImVec2(std::min(x - w / 2, right - w - 2), r.axis_top + 5), kDim, label.c_str());
  }

  // Cue phases.
  for (const CuePhaseSpan& p : data.cue)
    labelled_bar(list, fonts, at(p.begin), at(p.end), r.cue_top + 2, r.cue_bottom - 2, cue_phase_color(p.phase),
                 cue_phase_label(p.phase), false);

  // Camera descriptions. A script that failed is drawn as written: the faulty descriptions last (on
  // top), each tied to the event it names by a red line, and those naming no event in the zone.
  if (!script_failed)
    for (const TimelineCameraSpan& c : data.camera)
      labelled_bar(list, fonts, at(c.begin), at(c.end), r.camera_top + 2, r.camera_bottom - 2, camera_mode_color(c.mode),
                   camera_span_label(c, layout.compact), true);
  for (int faulty = 0; script_failed && faulty < 2; ++faulty)
    for (const TimelineCameraSpan& c : data.camera) {
      if (!c.placed || c.problem.empty() == bool(faulty)) continue;
      const float a = at(c.begin);
      if (faulty) list.AddLine(ImVec2(a, r.events_top), ImVec2(a, r.camera_top + 2), kError, 2.f);
      written_bar(list, fonts, a, at(c.end), r.camera_top + 2, r.camera_bottom - 2, c);
    }
  if (zone > 0) {
    list.AddRectFilled(ImVec2(zone_left, r.camera_top), ImVec2(zone_right, r.camera_bottom), kRowBackground, 2.f);
    list.PushClipRect(ImVec2(zone_left, r.events_top), ImVec2(zone_right, r.drops_bottom), true);
    list.AddText(fonts.small, small, ImVec2(zone_left + 2, (r.drops_top + r.drops_bottom - small) / 2), kErrorText,
                 "not in the shot:");
    list.PopClipRect();
    const float scale = zone / zone_wanted;
    float x = zone_left;
    std::size_t k = 0;
    for (const TimelineCameraSpan& c : data.camera) {
      if (c.placed) continue;
      const float w = unplaced_widths[k++] * scale;
      written_bar(list, fonts, x + 1, x + w - 1, r.camera_top + 2, r.camera_bottom - 2, c);
      x += w;
    }
  }
  if (script_failed && data.cue.empty())
    list.AddText(fonts.small, small, ImVec2(x0 + 4, (r.cue_top + r.cue_bottom - small) / 2), kDim,
                 "no stick: it is placed from the camera script");

  // Interpolation windows: shaded across every row, the event instant marked.
  for (const TimelineWindow& w : data.windows) {
    const float a = at(w.begin), b = at(w.end), e = at(w.event_time);
    list.AddRectFilled(ImVec2(a, r.events_top), ImVec2(std::max(b, a + 1), r.cue_bottom), kWindowFill);
    list.AddLine(ImVec2(a, r.events_top), ImVec2(a, r.cue_bottom), kWindowEdge, 1.f);
    list.AddLine(ImVec2(b, r.events_top), ImVec2(b, r.cue_bottom), kWindowEdge, 1.f);
    // Hatching over the camera row: the camera is between two descriptions here.
    const float top = r.camera_top + 2, low = r.camera_bottom - 2, h = low - top;
    list.PushClipRect(ImVec2(a, top), ImVec2(std::max(b, a + 1), low), true);
    for (float x = a - h; x < b; x += 7) list.AddLine(ImVec2(x, low), ImVec2(x + h, top), kWindowHatch, 1.5f);
    list.PopClipRect();
    list.AddTriangleFilled(ImVec2(e - 4, r.camera_bottom + 1), ImVec2(e + 4, r.camera_bottom + 1),
                           ImVec2(e, r.camera_bottom - 5), IM_COL32(255, 255, 255, 230));
  }

  // Events: a mark per event in its type's colour, the number above it.
  LabelLevels levels(r.label_levels);
  for (const TimelineEventMark& e : data.events) {
    const float x = at(e.time);
    const ImU32 color = event_color(e.type);
    list.AddLine(ImVec2(x, r.events_top + 1), ImVec2(x, r.events_bottom - 1), color, 2.f);
    const std::string label = std::to_string(e.index);
    const float w = text_size(fonts.small, small, label).x;
    const int level = levels.place(x - w / 2, w, 3);
    if (level < 0) continue;
    const float ly = r.events_top - (level + 1) * r.label_height;
    if (level > 0) list.AddLine(ImVec2(x, ly + small), ImVec2(x, r.events_top), with_alpha(color, 90), 1.f);
    list.AddText(fonts.small, small, ImVec2(x - w / 2, ly), color, label.c_str());
  }

  // Pocket drops.
  if (data.drops.empty())
    list.AddText(fonts.small, small, ImVec2(x0 + 4, (r.drops_top + r.drops_bottom - small) / 2), kDim, "none");
  LabelLevels drop_levels(1);
  for (const TimelineDrop& d : data.drops) {
    const float x = at(d.time), mid = (r.drops_top + r.drops_bottom) / 2;
    const float s = (r.drops_bottom - r.drops_top) * 0.32f;
    list.AddTriangleFilled(ImVec2(x - s, mid - s), ImVec2(x + s, mid - s), ImVec2(x, mid + s), pocket_color());
    const std::string label = layout.compact ? std::to_string(d.ball)
                                             : "ball " + std::to_string(d.ball) + " \xE2\x86\x92 pocket " + std::to_string(d.pocket);
    const float w = text_size(fonts.small, small, label).x;
    if (drop_levels.place(x + s + 2, w, 6) == 0 && x + s + 2 + w < x1)
      list.AddText(fonts.small, small, ImVec2(x + s + 2, (r.drops_top + r.drops_bottom - small) / 2), pocket_color(),
                   label.c_str());
  }

  if (layout.cursor >= 0) {
    const float x = at(std::clamp(layout.cursor, 0.0, duration));
    list.AddLine(ImVec2(x, r.labels_top), ImVec2(x, r.axis_bottom), kCursor, 2.f);
    list.AddTriangleFilled(ImVec2(x - 6, r.labels_top), ImVec2(x + 6, r.labels_top), ImVec2(x, r.labels_top + 8), kCursor);
  }
  if (layout.compact) return axis;

  y = r.axis_bottom + pad * 0.5f;
  // A failed script's errors as printed, first below the axis.
  for (const std::string& line : data.script_errors) {
    if (y + small > bottom - 2) break;
    list.AddText(fonts.small, small, ImVec2(x0, y), kErrorText, line.c_str());
    y += small + 3;
  }
  if (script_failed) y += pad * 0.5f;

  // Legend.
  struct Key {
    ImU32 color;
    const char* name;
    bool bar;
  };
  std::vector<Key> keys = {{event_color(EventType::start), "start / end", false},
                           {event_color(EventType::cue), "cue", false},
                           {event_color(EventType::ball_ball), "ball-ball", false},
                           {event_color(EventType::ball_rail), "ball-rail", false},
                           {pocket_color(), "pocket drop", false},
                           {camera_mode_color(CameraMode::follow), "follow", true},
                           {camera_mode_color(CameraMode::look), "look", true},
                           {camera_mode_color(CameraMode::hover), "hover", true},
                           {kWindowEdge, "interpolation window (\xE2\x96\xB2 its event)", true}};
  // A failed script has no interpolation windows, but has faults to explain.
  if (script_failed) keys.back() = {kError, "camera script error", true};
  if (y + small <= bottom - 2) {
    float x = x0;
    for (const Key& k : keys) {
      const float w = text_size(fonts.small, small, k.name).x;
      if (x + small + 4 + w > right - pad) break;
      if (k.bar) list.AddRectFilled(ImVec2(x, y + 2), ImVec2(x + small, y + small - 2), with_alpha(k.color, 200), 2.f);
      else list.AddRectFilled(ImVec2(x + small / 2 - 1.5f, y + 1), ImVec2(x + small / 2 + 1.5f, y + small - 1), k.color);
      list.AddText(fonts.small, small, ImVec2(x + small + 4, y), kDim, k.name);
      x += small + 4 + w + pad * 1.5f;
    }
    y += small + pad;
  }

  // Every event in a list, so a number in the camera script can be checked against what happened.
  const float line = small + 3;
  const int rows = static_cast<int>((bottom - pad * 0.5f - y) / line);
  if (rows < 1 || data.events.empty()) return axis;
  float column = 0;
  std::vector<std::string> entries;
  for (const TimelineEventMark& e : data.events) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%8.3f s   ", e.time);
    entries.push_back(buffer + e.label);
    column = std::max(column, text_size(fonts.small, small, "000  " + entries.back()).x);
  }
  column += pad * 2;
  const int columns = std::max(1, static_cast<int>((right - x0) / column));
  const int capacity = rows * columns;
  const int count = static_cast<int>(data.events.size());
  for (int k = 0; k < count && k < capacity; ++k) {
    const float cx = x0 + (k / rows) * column, cy = y + (k % rows) * line;
    if (k == capacity - 1 && count > capacity) {
      list.AddText(fonts.small, small, ImVec2(cx, cy), kDim,
                   ("\xE2\x80\xA6 and " + std::to_string(count - capacity + 1) + " more").c_str());
      break;
    }
    const TimelineEventMark& e = data.events[static_cast<std::size_t>(k)];
    const std::string number = std::to_string(e.index);
    const float nw = text_size(fonts.small, small, number).x;
    const float numbers_w = text_size(fonts.small, small, "000").x;
    list.AddText(fonts.small, small, ImVec2(cx + numbers_w - nw, cy), event_color(e.type), number.c_str());
    list.AddText(fonts.small, small, ImVec2(cx + numbers_w + 4, cy), kText, entries[static_cast<std::size_t>(k)].c_str());
  }
  return axis;
}

}  // namespace bsim
