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

/// Every contact between balls a and b, in time order (a contact inside a group counting).
std::vector<KeyInstant> hits(const Timeline& timeline, int a, int b) {
  const int low = std::min(a, b), high = std::max(a, b);
  std::vector<KeyInstant> found;
  for (const Event& e : timeline.events()) {
    if (e.type != EventType::ball_ball) continue;
    for (const Contact& c : e.contacts)
      if (std::min(c.a, c.b) == low && std::max(c.a, c.b) == high) found.push_back({c.time, e.index});
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const KeyInstant& x, const KeyInstant& y) { return x.time < y.time; });
  return found;
}

std::vector<KeyInstant> cushions(const Timeline& timeline, int ball) {
  std::vector<KeyInstant> found;
  for (const Event& e : timeline.events())
    if (e.type == EventType::ball_rail && !e.balls.empty() && e.balls[0] == ball) found.push_back({e.time, e.index});
  return found;
}

std::optional<KeyInstant> first_of(const Timeline& timeline, EventType type) {
  for (const Event& e : timeline.events())
    if (e.type == type) return KeyInstant{e.time, e.index};
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

KeyResolution resolve_camera_key(const CameraShot& shot, const Scene& scene, const Timeline& timeline) {
  const CameraKey& key = shot.key;
  const auto& events = timeline.events();
  const int event_count = static_cast<int>(events.size());
  const int ball_count = static_cast<int>(scene.balls.size());
  KeyResolution r;
  r.where = message_loc(shot.event_loc, shot.loc);
  const std::string name = describe_camera_key(shot);
  const auto never = [&](const std::string& why) { r.problem = name + " never happens: " + why; };

  // Ball indices first: a key about a ball the scene does not have cannot be looked for.
  for (const auto& [ball, loc] : {std::pair{key.a, key.a_loc}, std::pair{key.b, key.b_loc}}) {
    if (ball < 0 || ball < ball_count) continue;
    r.where = message_loc(loc, r.where);
    r.problem = "ball " + std::to_string(ball) + " does not exist: the scene has " + counted(ball_count, "ball");
    return r;
  }

  switch (key.kind) {
    case CameraKeyKind::event: {
      const int index = shot.event == CameraShot::kLastEvent ? event_count - 1 : shot.event;
      if (index < 0 || index >= event_count) {
        r.problem =
            "event " + std::to_string(shot.event) + " does not exist: the shot has " + counted(event_count, "event");
        return r;
      }
      r.instant = KeyInstant{events[static_cast<std::size_t>(index)].time, index};
      return r;
    }
    case CameraKeyKind::start:
      if (event_count > 0) r.instant = KeyInstant{events.front().time, 0};
      if (!r.instant) never("the shot has no events");
      return r;
    case CameraKeyKind::cue:
      r.instant = first_of(timeline, EventType::cue);
      if (!r.instant) never("the shot has no cue event");
      return r;
    case CameraKeyKind::end:
      if (event_count > 0) r.instant = KeyInstant{events.back().time, event_count - 1};
      if (!r.instant) never("the shot has no events");
      return r;
    case CameraKeyKind::hit: {
      const std::vector<KeyInstant> found = hits(timeline, key.a, key.b);
      r.instant = pick(found, key.ordinal);
      const std::string balls = "balls " + std::to_string(key.a) + " and " + std::to_string(key.b);
      if (!r.instant) never(found.empty() ? balls + " never touch" : balls + " touch " + times(found.size()));
      return r;
    }
    case CameraKeyKind::cushion: {
      const std::vector<KeyInstant> found = cushions(timeline, key.a);
      r.instant = pick(found, key.ordinal);
      const std::string ball = "ball " + std::to_string(key.a);
      if (!r.instant)
        never(found.empty() ? ball + " meets no cushion" : ball + " meets a cushion " + times(found.size()));
      return r;
    }
    case CameraKeyKind::pocket:
      for (const PocketDrop& d : timeline.pocket_drops())
        if (d.ball == key.a) {
          r.instant = KeyInstant{d.time, -1};
          break;
        }
      if (!r.instant) never("ball " + std::to_string(key.a) + " drops into no pocket");
      return r;
    case CameraKeyKind::at: {
      const double start = event_count > 0 ? events.front().time : 0.0;
      const double t = start + key.seconds;
      if (event_count > 0 && t <= timeline.duration()) r.instant = KeyInstant{t, -1};
      char ends[64];
      std::snprintf(ends, sizeof ends, "the shot ends at %.2f s", timeline.duration() - start);
      if (!r.instant) never(ends);
      return r;
    }
  }
  BSIM_EXPECT(false, "a camera key of no known kind");
  return r;
}

}  // namespace bsim
