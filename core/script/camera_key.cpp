#include "camera_key.h"

#include <algorithm>
#include <cstdio>
#include <vector>

#include "check.h"

namespace bsim {

namespace {

std::string times(std::size_t count) {
  if (count == 1) return "once";
  if (count == 2) return "twice";
  return std::to_string(count) + " times";
}

/// The `ordinal`-th of `found` (kLast: the last one), if there are that many.
std::optional<KeyInstant> pick(const std::vector<KeyInstant>& found, int ordinal) {
  if (found.empty()) return std::nullopt;
  if (ordinal == CameraKey::kLast) return found.back();
  if (ordinal < 1 || static_cast<std::size_t>(ordinal) > found.size()) return std::nullopt;
  return found[static_cast<std::size_t>(ordinal - 1)];
}

/// What a key counts over: the whole scene, or one shot (`shot K`): its events, and its stretch of
/// time from its start to the next shot's start (the last shot's: to the end event).
struct Scope {
  int shot = -1;      ///< 0-based; -1: the whole scene
  double begin = 0;   ///< s
  double end = 0;     ///< s
  bool last = true;   ///< it reaches the end event
  std::string where;  ///< for messages: "" or " in shot 2"

  Scope(const CameraKey& key, const Timeline& timeline) : shot(key.shot), end(timeline.duration()) {
    const std::vector<ShotSpan>& spans = timeline.shots();
    if (shot < 0 || static_cast<std::size_t>(shot) >= spans.size()) return;
    const auto k = static_cast<std::size_t>(shot);
    begin = spans[k].start;
    last = k + 1 == spans.size();
    if (!last) end = spans[k + 1].start;
    where = " in shot " + std::to_string(shot + 1);
  }
  bool holds(const Event& e) const { return shot < 0 || e.shot == shot; }
  bool holds(double t) const { return shot < 0 || (t >= begin && (t < end || (last && t <= end))); }
};

/// Every contact between balls a and b, in time order (a contact inside a group counting).
std::vector<KeyInstant> hits(const Timeline& timeline, const Scope& scope, int a, int b) {
  const int low = std::min(a, b), high = std::max(a, b);
  std::vector<KeyInstant> found;
  for (const Event& e : timeline.events()) {
    if (e.type != EventType::ball_ball || !scope.holds(e)) continue;
    for (const Contact& c : e.contacts)
      if (std::min(c.a, c.b) == low && std::max(c.a, c.b) == high) found.push_back({c.time, e.index});
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const KeyInstant& x, const KeyInstant& y) { return x.time < y.time; });
  return found;
}

/// Every ball-rail (cushion) or ball-jaw (jaw) event of `ball`, in time order.
std::vector<KeyInstant> contacts(const Timeline& timeline, const Scope& scope, EventType type, int ball) {
  std::vector<KeyInstant> found;
  for (const Event& e : timeline.events())
    if (e.type == type && scope.holds(e) && !e.balls.empty() && e.balls[0] == ball) found.push_back({e.time, e.index});
  return found;
}

std::optional<KeyInstant> first_of(const Timeline& timeline, const Scope& scope, EventType type) {
  for (const Event& e : timeline.events())
    if (e.type == type && scope.holds(e)) return KeyInstant{e.time, e.index};
  return std::nullopt;
}

/// start or end: the scene's first or last event, or the shot's start and the next shot's start.
std::optional<KeyInstant> bound(const Timeline& timeline, const Scope& scope, bool start) {
  const auto& events = timeline.events();
  if (events.empty()) return std::nullopt;
  const int last = static_cast<int>(events.size()) - 1;
  if (start) return scope.shot <= 0 ? KeyInstant{events.front().time, 0} : KeyInstant{scope.begin, -1};
  return scope.last ? KeyInstant{events.back().time, last} : KeyInstant{scope.end, -1};
}

std::optional<KeyInstant> drop(const Timeline& timeline, const Scope& scope, int ball) {
  for (const PocketDrop& d : timeline.pocket_drops())
    if (d.ball == ball && scope.holds(d.time)) return KeyInstant{d.time, -1};
  return std::nullopt;
}

}  // namespace

SourceLoc message_loc(const SourceLoc& token, const SourceLoc& line) { return token.known() ? token : line; }

std::string counted(int count, const std::string& noun) {
  std::string text = std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
  if (count == 1) return text + " (index 0)";
  if (count > 1) text += " (0 to " + std::to_string(count - 1) + ")";
  return text;
}

std::string describe_camera_key(const CameraShot& shot) {
  if (shot.key.kind == CameraKeyKind::event) return "event " + std::to_string(shot.event);
  return camera_key_text(shot.key);
}

namespace {

/// A key's instant once its balls and shot are known to exist.
void resolve_in(const CameraKey& key, const Timeline& timeline, const Scope& scope, KeyResolution& r,
                const std::string& name) {
  const auto never = [&](const std::string& why) { r.problem = name + " never happens: " + why; };
  switch (key.kind) {
    case CameraKeyKind::event: break;
    case CameraKeyKind::start:
    case CameraKeyKind::end:
      r.instant = bound(timeline, scope, key.kind == CameraKeyKind::start);
      if (!r.instant) never("the shot has no events");
      return;
    case CameraKeyKind::cue:
      r.instant = first_of(timeline, scope, EventType::cue);
      if (!r.instant) never("the shot has no cue event");
      return;
    case CameraKeyKind::hit: {
      const std::vector<KeyInstant> found = hits(timeline, scope, key.a, key.b);
      r.instant = pick(found, key.ordinal);
      const std::string balls = "balls " + std::to_string(key.a) + " and " + std::to_string(key.b);
      if (!r.instant)
        never((found.empty() ? balls + " never touch" : balls + " touch " + times(found.size())) + scope.where);
      return;
    }
    case CameraKeyKind::cushion:
    case CameraKeyKind::jaw: {
      const bool jaw = key.kind == CameraKeyKind::jaw;
      const std::vector<KeyInstant> found =
          contacts(timeline, scope, jaw ? EventType::ball_jaw : EventType::ball_rail, key.a);
      r.instant = pick(found, key.ordinal);
      const std::string ball = "ball " + std::to_string(key.a), what = jaw ? "pocket's jaw" : "cushion";
      if (!r.instant)
        never((found.empty() ? ball + " meets no " + what : ball + " meets a " + what + " " + times(found.size())) +
              scope.where);
      return;
    }
    case CameraKeyKind::drop:
      r.instant = drop(timeline, scope, key.a);
      if (!r.instant) never("ball " + std::to_string(key.a) + " drops into no pocket" + scope.where);
      return;
    case CameraKeyKind::at: {
      const bool any = !timeline.events().empty();
      const double start = scope.shot < 0 ? (any ? timeline.events().front().time : 0.0) : scope.begin;
      const double t = start + key.seconds;
      if (any && t <= scope.end) r.instant = KeyInstant{t, -1};
      char ends[64];
      std::snprintf(ends, sizeof ends, "the shot ends at %.2f s", scope.end - start);
      if (!r.instant) never(ends);
      return;
    }
  }
  BSIM_EXPECT(false, "a camera key of no known kind");
}

}  // namespace

KeyResolution resolve_camera_key(const CameraShot& shot, const Scene& scene, const Timeline& timeline) {
  const CameraKey& key = shot.key;
  const auto& events = timeline.events();
  const int event_count = static_cast<int>(events.size());
  const int ball_count = static_cast<int>(scene.balls.size());
  KeyResolution r;
  r.where = message_loc(shot.event_loc, shot.loc);

  // Ball indices first: a key about a ball the scene does not have cannot be looked for.
  for (const auto& [ball, loc] : {std::pair{key.a, key.a_loc}, std::pair{key.b, key.b_loc}}) {
    if (ball < 0 || ball < ball_count) continue;
    r.where = message_loc(loc, r.where);
    r.problem = "ball " + std::to_string(ball) + " does not exist: the scene has " + counted(ball_count, "ball");
    return r;
  }
  if (key.kind != CameraKeyKind::event && key.shot >= timeline.shot_count()) {
    r.where = message_loc(key.shot_loc, r.where);
    r.problem = "shot " + std::to_string(key.shot + 1) + " does not exist: the scene has " +
                std::to_string(timeline.shot_count()) + (timeline.shot_count() == 1 ? " shot" : " shots");
    return r;
  }
  if (key.kind == CameraKeyKind::event) {
    const int index = shot.event == CameraShot::kLastEvent ? event_count - 1 : shot.event;
    if (index < 0 || index >= event_count) {
      r.problem =
          "event " + std::to_string(shot.event) + " does not exist: the shot has " + counted(event_count, "event");
      return r;
    }
    r.instant = KeyInstant{events[static_cast<std::size_t>(index)].time, index};
    return r;
  }
  resolve_in(key, timeline, Scope(key, timeline), r, describe_camera_key(shot));
  return r;
}

}  // namespace bsim
