#pragma once
// The timeline of a shot as a picture: events (coloured by type, numbered), pocket drops, the camera
// descriptions as labelled spans starting at the event or key they name, the interpolation windows, the cue
// phases, and a list of every event. Used for --timeline and, compact, as the window's scrub bar.
#include <optional>
#include <string>
#include <vector>

#include "cue_script.h"
#include "event.h"
#include "fonts.h"
#include "game_panel.h"
#include "scene.h"

struct ImDrawList;

namespace bsim {

struct Shot;

struct TimelineEventMark {
  int index = 0;
  double time = 0;  ///< s
  EventType type = EventType::start;
  std::string label;  ///< "ball 0 – ball 5"
};

struct TimelineDrop {
  double time = 0;  ///< s
  int ball = 0;     ///< file-order index
  int pocket = 0;
  std::string pocket_name;  ///< the pocket in words: "the top-right corner (pocket 2)" (scene.h: pocket_name)
};

struct TimelineCameraSpan {
  double begin = 0, end = 0;  ///< s
  int event = 0;              ///< the event number the description names (65535: the last)
  CameraMode mode = CameraMode::hover;
  std::string label;    ///< "follow ball 0", "look ball 11 (12)"
  std::string problem;  ///< why the description does not fit the shot (drawn in red); empty when it does
  bool placed = true;   ///< false: the event it names does not exist (drawn after the time axis)
  std::string key;      ///< the camera key as written ("hit 0 5"), empty when it names an event number
};

/// A game's turn, shown in its shot's section: who is at the table, what they meant, the rules' call.
struct TimelineTurn {
  int player = 0;          ///< 0 or 1 (each has its colour)
  std::string name;        ///< the player at the table
  std::string initials;    ///< the name in a section too narrow for it
  bool from_hand = false;  ///< the shooter had the cue ball in hand: "from hand · " before the plan where it fits
  std::string plan;        ///< "3 → top-right", "safety", "push-out"; empty when nothing was called
  std::string call;        ///< the rules' call: "foul: ...; ball in hand", "wins the game", "made 3"
  std::string short_call;  ///< the call for a narrow section: "foul; ball in hand"
  GameTone tone = GameTone::plain;  ///< the call's colour, and a bar along the section's foot unless plain
};

/// One shot of a scene of several: its stretch of the timeline and its stroke.
struct TimelineShotSection {
  double start = 0, cue = 0, end = 0;  ///< s: the stick may come in, the strike, the next shot's start (or the end)
  std::string label;                   ///< "shot 2"
  std::string detail;                  ///< "cue 0 pot 2 into top-right corner at 41.2°\nstrike at 10.87 s" (two lines)
  std::optional<Stroke> stroke;        ///< drawn as a small diagram in its section
  std::optional<TimelineTurn> turn;    ///< a scene with a game: the turn this shot is
};

struct TimelineWindow {
  double begin = 0, event_time = 0, end = 0;  ///< s
};

/// A game's replay (Shot::movie): after the game's end, its winning shot again, slowed. The picture's
/// time axis is then the movie's: the replay is a box after the end, and the stretch it shows again is
/// marked on the axis.
struct TimelineReplay {
  double start = 0, end = 0;  ///< s of simulation shown again
  double length = 0;          ///< s of movie it lasts
  std::string label;          ///< "replay"
  std::string detail;         ///< "shot 11 at half speed"
  std::string camera;         ///< the replay's camera in words
};

/// What the picture shows, as plain values (so it can be drawn for a made-up shot too).
struct TimelineData {
  std::string title;
  double duration = 0;  ///< s
  std::vector<TimelineEventMark> events;
  std::vector<TimelineDrop> drops;
  std::vector<TimelineCameraSpan> camera;
  std::vector<TimelineWindow> windows;
  std::vector<CuePhaseSpan> cue;
  /// Every ball's painted number by file-order index, written beside the indices the picture shows
  /// where the two differ (keys, pocket drops); empty: indices alone.
  std::vector<int> painted;
  /// Set when the camera script does not fit the shot: every error as printed. The camera row then
  /// shows the script as written (see script_as_written.h), and there are no windows or cue phases.
  std::vector<std::string> script_errors;
  /// The scene's stroke, drawn as a small ball diagram at the right end of the title; none: no diagram
  /// (a scene of several shots draws each shot's in its section instead).
  std::optional<Stroke> stroke;
  /// A scene of several shots: one section per shot, drawn as a band of labelled sections above the
  /// rows and separators through them; empty for a scene of one shot (its picture as before).
  std::vector<TimelineShotSection> shots;
  std::optional<TimelineReplay> replay;  ///< a game's replay, drawn after the game's end
  /// Stretches of the simulation (s, start and end) the movie cuts out: a game's broadcast edit drops
  /// the waits on balls that only spin in place (shot.h, broadcast_edit). Drawn darkened over every row.
  std::vector<std::pair<double, double>> cuts;
};

TimelineData timeline_data(const Shot& shot);

/// A piece of the picture drawn, as the tests check it: what and where.
struct TimelineDrawn {
  enum class Kind { shot_text, stroke, lane_label, list_line, list_more, legend_key };
  Kind kind = Kind::shot_text;
  std::string text;                          ///< as drawn (elided text ends in "…"); empty for a stroke diagram
  float x0 = 0, y0 = 0, x1 = 0, y1 = 0;      ///< px
  int shot = -1;                             ///< shot_text and stroke: the section's index
  const TimelineCameraSpan* span = nullptr;  ///< lane_label: the description it names
};

struct TimelineLayout {
  float x = 0, y = 0, width = 0, height = 0;  ///< px, the area to fill
  bool compact = false;                       ///< scrub bar: only the rows and the axis, no title, list or legend
  double cursor = -1;                         ///< s, a playhead drawn when >= 0
  /// The height is timeline_height()'s: as many levels of event numbers and lanes of camera labels as
  /// the crowding needs. Otherwise they take a share of the room the height leaves.
  bool fit_all = false;
  /// When set, the labels, the stroke diagrams and the list's lines are recorded here as they are drawn.
  std::vector<TimelineDrawn>* drawn = nullptr;
};

/// Draws the timeline. Returns the x of time 0 and the pixels per second used (for hit testing).
struct TimelineAxis {
  float x0 = 0;
  float pixels_per_second = 1;
  double time_at(float x) const { return (x - x0) / pixels_per_second; }
};
/// px a compact timeline needs with these fonts.
float compact_timeline_height(const UiFonts& fonts);

/// px a full timeline picture `width` px wide needs with these fonts (fit_all): every row with all its
/// labels, the legend and the event list complete.
float timeline_height(const TimelineData& data, const UiFonts& fonts, float width);

TimelineAxis draw_timeline(ImDrawList& list, const TimelineData& data, const UiFonts& fonts,
                           const TimelineLayout& layout);

}  // namespace bsim
