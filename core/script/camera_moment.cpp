#include "camera_moment.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <tuple>
#include <utility>

#include "check.h"
#include "number_format.h"

namespace bsim {

// --- A shot's stretch of the timeline --------------------------------------------------------------

ShotStretch shot_stretch(const Timeline& timeline, int shot) {
  const std::vector<ShotSpan>& spans = timeline.shots();
  ShotStretch s;
  s.end = timeline.duration();
  if (shot < 0 || static_cast<std::size_t>(shot) >= spans.size()) {
    s.strike = timeline.cue_time();
    s.rest = spans.empty() ? s.end : spans.back().rest;
    return s;
  }
  const auto k = static_cast<std::size_t>(shot);
  s.shot = shot;
  s.start = spans[k].start;
  s.strike = spans[k].cue;
  s.rest = spans[k].rest;
  s.last = k + 1 == spans.size();
  if (!s.last) s.end = spans[k + 1].start;
  return s;
}

// --- The contacts keys count ------------------------------------------------------------------------

std::vector<BallContact> ball_contacts(const Timeline& timeline, int shot, int ball, int with) {
  std::vector<BallContact> found;
  for (const Event& e : timeline.events()) {
    if (e.type != EventType::ball_ball || (shot >= 0 && e.shot != shot)) continue;
    for (const Contact& c : e.contacts) {
      const BallContact contact{c.time, e.index, c.a, c.b};
      if (ball >= 0 && c.a != ball && c.b != ball) continue;
      if (ball >= 0 && with >= 0 && contact.other(ball) != with) continue;
      found.push_back(contact);
    }
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const BallContact& x, const BallContact& y) { return x.time < y.time; });
  return found;
}

std::vector<const Event*> ball_touches(const Timeline& timeline, EventType type, int ball, int shot) {
  std::vector<const Event*> found;
  for (const Event& e : timeline.events())
    if (e.type == type && (shot < 0 || e.shot == shot) && !e.balls.empty() && e.balls[0] == ball) found.push_back(&e);
  return found;
}

// --- Resolving a name -------------------------------------------------------------------------------

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

/// What a key counts over: the whole scene, or one shot (`shot K`): its events, and its stretch.
struct Scope {
  int shot = -1;  ///< 0-based; -1: the whole scene
  ShotStretch stretch;
  std::string where;  ///< for messages: "" or " in shot 2"

  Scope(const CameraKey& key, const Timeline& timeline) : shot(key.shot), stretch(shot_stretch(timeline, key.shot)) {
    if (stretch.shot >= 0) where = " in shot " + std::to_string(shot + 1);
  }
  bool holds(double t) const { return shot < 0 || stretch.holds(t); }
};

std::vector<KeyInstant> instants(const std::vector<BallContact>& contacts) {
  std::vector<KeyInstant> found;
  for (const BallContact& c : contacts) found.push_back({c.time, c.event});
  return found;
}

std::vector<KeyInstant> instants(const std::vector<const Event*>& events) {
  std::vector<KeyInstant> found;
  for (const Event* e : events) found.push_back({e->time, e->index});
  return found;
}

std::optional<KeyInstant> first_of(const Timeline& timeline, const Scope& scope, EventType type) {
  for (const Event& e : timeline.events())
    if (e.type == type && (scope.shot < 0 || e.shot == scope.shot)) return KeyInstant{e.time, e.index};
  return std::nullopt;
}

/// start or end: the scene's first or last event, or the shot's start and the next shot's start.
std::optional<KeyInstant> bound(const Timeline& timeline, const Scope& scope, bool start) {
  const auto& events = timeline.events();
  if (events.empty()) return std::nullopt;
  const int last = static_cast<int>(events.size()) - 1;
  if (start) return scope.shot <= 0 ? KeyInstant{events.front().time, 0} : KeyInstant{scope.stretch.start, -1};
  return scope.stretch.last ? KeyInstant{events.back().time, last} : KeyInstant{scope.stretch.end, -1};
}

std::optional<KeyInstant> drop(const Timeline& timeline, const Scope& scope, int ball) {
  for (const PocketDrop& d : timeline.pocket_drops())
    if (d.ball == ball && scope.holds(d.time)) return KeyInstant{d.time, -1};
  return std::nullopt;
}

/// A contact key's instant (hit, cushion, jaw), or why the shot never reaches it.
std::optional<KeyInstant> resolve_contact(const CameraKey& key, const Timeline& timeline, const Scope& scope,
                                          std::string& why) {
  if (key.kind == CameraKeyKind::hit) {
    const std::vector<KeyInstant> found = instants(ball_contacts(timeline, scope.shot, key.a, key.b));
    const std::string balls = "balls " + std::to_string(key.a) + " and " + std::to_string(key.b);
    why = (found.empty() ? balls + " never touch" : balls + " touch " + times(found.size())) + scope.where;
    return pick(found, key.ordinal);
  }
  const bool jaw = key.kind == CameraKeyKind::jaw;
  const std::vector<KeyInstant> found =
      instants(ball_touches(timeline, jaw ? EventType::ball_jaw : EventType::ball_rail, key.a, scope.shot));
  const std::string ball = "ball " + std::to_string(key.a), what = jaw ? "pocket's jaw" : "cushion";
  why = (found.empty() ? ball + " meets no " + what : ball + " meets a " + what + " " + times(found.size())) +
        scope.where;
  return pick(found, key.ordinal);
}

/// A key's instant once its balls and shot are known to exist, or why the shot never reaches it.
std::optional<KeyInstant> resolve_in(const CameraKey& key, const Timeline& timeline, const Scope& scope,
                                     std::string& why) {
  switch (key.kind) {
    case CameraKeyKind::event: break;
    case CameraKeyKind::start:
    case CameraKeyKind::end:
      why = "the shot has no events";
      return bound(timeline, scope, key.kind == CameraKeyKind::start);
    case CameraKeyKind::cue: why = "the shot has no cue event"; return first_of(timeline, scope, EventType::cue);
    case CameraKeyKind::hit:
    case CameraKeyKind::cushion:
    case CameraKeyKind::jaw: return resolve_contact(key, timeline, scope, why);
    case CameraKeyKind::drop:
      why = "ball " + std::to_string(key.a) + " drops into no pocket" + scope.where;
      return drop(timeline, scope, key.a);
    case CameraKeyKind::at: {
      const bool any = !timeline.events().empty();
      const double start = scope.shot < 0 ? (any ? timeline.events().front().time : 0.0) : scope.stretch.start;
      const double t = start + key.seconds;
      char ends[64];
      std::snprintf(ends, sizeof ends, "the shot ends at %.2f s", scope.stretch.end - start);
      why = ends;
      if (any && t <= scope.stretch.end) return KeyInstant{t, -1};
      return std::nullopt;
    }
  }
  BSIM_EXPECT(false, "a camera key of no known kind");
  return std::nullopt;
}

/// The instant of event number `event` (CameraShot::kLastEvent: the last), if the timeline has it.
std::optional<KeyInstant> numbered(const Timeline& timeline, int event) {
  const auto& events = timeline.events();
  const int index = event == CameraShot::kLastEvent ? static_cast<int>(events.size()) - 1 : event;
  if (index < 0 || index >= static_cast<int>(events.size())) return std::nullopt;
  return KeyInstant{events[static_cast<std::size_t>(index)].time, index};
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
    r.instant = numbered(timeline, shot.event);
    if (!r.instant)
      r.problem = "event " + std::to_string(shot.event) + " does not exist: the shot has " +
                  counted(static_cast<int>(timeline.events().size()), "event");
    return r;
  }
  std::string why;
  r.instant = resolve_in(key, timeline, Scope(key, timeline), why);
  if (!r.instant) r.problem = describe_camera_key(shot) + " never happens: " + why;
  return r;
}

std::optional<KeyInstant> moment_instant(const CameraKey& key, int event, const Timeline& timeline) {
  if (key.kind == CameraKeyKind::event) return numbered(timeline, event);
  const int balls = timeline.ball_count();
  if (key.a >= balls || key.b >= balls || key.shot >= timeline.shot_count()) return std::nullopt;
  std::string why;
  return resolve_in(key, timeline, Scope(key, timeline), why);
}

// --- Naming a moment --------------------------------------------------------------------------------

CameraKey shot_key(const Timeline& timeline, int shot, CameraKeyKind kind, int a, int b, int ordinal, double seconds) {
  CameraKey key;
  key.kind = kind;
  key.a = a;
  key.b = b;
  key.ordinal = ordinal;
  key.seconds = seconds;
  key.shot = timeline.shot_count() > 1 ? shot : -1;
  return key;
}

namespace {

/// The ordinal of the k-th (1-based) of n contacts: k up to the fifth, CameraKey::kLast for the last
/// of more than five; nothing when it has no name.
std::optional<int> key_ordinal(std::size_t k, std::size_t n) {
  if (k >= 1 && k <= 5) return static_cast<int>(k);
  if (k == n) return CameraKey::kLast;
  return std::nullopt;
}

/// The moments the events themselves name (start, end, each shot's first cue), in event order, and
/// every contact gathered by shot and balls.
struct Gathered {
  std::vector<NamedMoment> moments;
  std::map<std::tuple<int, int, int>, std::vector<KeyInstant>> hits;  // by shot and the two balls
  std::map<std::pair<int, int>, std::vector<KeyInstant>> cushions;    // by shot and ball
  std::map<std::pair<int, int>, std::vector<KeyInstant>> jaws;        // by shot and ball
};

Gathered gather(const Timeline& timeline) {
  Gathered g;
  std::vector<int> cues_named;
  const int last = std::max(1, timeline.shot_count()) - 1;
  for (const Event& e : timeline.events()) {
    switch (e.type) {
      case EventType::start: g.moments.push_back({shot_key(timeline, 0, CameraKeyKind::start), e.time, e.index}); break;
      case EventType::end: g.moments.push_back({shot_key(timeline, last, CameraKeyKind::end), e.time, e.index}); break;
      case EventType::cue:
        if (std::find(cues_named.begin(), cues_named.end(), e.shot) == cues_named.end())
          g.moments.push_back({shot_key(timeline, e.shot, CameraKeyKind::cue), e.time, e.index});
        cues_named.push_back(e.shot);
        break;
      case EventType::ball_ball:
        for (const Contact& c : e.contacts)
          g.hits[{e.shot, std::min(c.a, c.b), std::max(c.a, c.b)}].push_back({c.time, e.index});
        break;
      case EventType::ball_rail:
        if (!e.balls.empty()) g.cushions[{e.shot, e.balls[0]}].push_back({e.time, e.index});
        break;
      case EventType::ball_jaw:
        if (!e.balls.empty()) g.jaws[{e.shot, e.balls[0]}].push_back({e.time, e.index});
        break;
    }
  }
  return g;
}

}  // namespace

std::vector<NamedMoment> nameable_moments(const Timeline& timeline) {
  Gathered g = gather(timeline);
  std::vector<NamedMoment>& moments = g.moments;
  for (int k = 1; k < timeline.shot_count(); ++k)
    moments.push_back({shot_key(timeline, k, CameraKeyKind::start), shot_stretch(timeline, k).start, -1});
  // Counted in time order, as the keys resolve.
  for (auto& [balls, found] : g.hits) {
    std::stable_sort(found.begin(), found.end(),
                     [](const KeyInstant& x, const KeyInstant& y) { return x.time < y.time; });
    const auto [shot, a, b] = balls;
    for (std::size_t k = 0; k < found.size(); ++k)
      if (const auto ordinal = key_ordinal(k + 1, found.size()))
        moments.push_back(
            {shot_key(timeline, shot, CameraKeyKind::hit, a, b, *ordinal), found[k].time, found[k].event});
  }
  for (const auto& [kind, contacts] :
       {std::pair{CameraKeyKind::cushion, &g.cushions}, std::pair{CameraKeyKind::jaw, &g.jaws}})
    for (const auto& [ball, found] : *contacts)
      for (std::size_t k = 0; k < found.size(); ++k)
        if (const auto ordinal = key_ordinal(k + 1, found.size()))
          moments.push_back(
              {shot_key(timeline, ball.first, kind, ball.second, -1, *ordinal), found[k].time, found[k].event});
  std::vector<std::pair<int, int>> dropped;  // shot and ball: a key names a ball's first drop in a shot
  for (const PocketDrop& d : timeline.pocket_drops()) {
    const std::pair<int, int> which{timeline.shot_count() > 1 ? timeline.shot_at(d.time) : 0, d.ball};
    if (std::find(dropped.begin(), dropped.end(), which) != dropped.end()) continue;
    dropped.push_back(which);
    moments.push_back({shot_key(timeline, which.first, CameraKeyKind::drop, d.ball), d.time, -1});
  }
  return moments;
}

std::optional<NamedMoment> name_at(const Timeline& timeline, int shot, double seconds) {
  NamedMoment m;
  m.key = shot_key(timeline, shot, CameraKeyKind::at, -1, -1, 1, seconds);
  const std::optional<KeyInstant> at = moment_instant(m.key, -1, timeline);
  if (!at) return std::nullopt;
  m.time = at->time;
  return m;
}

NamedMoment name_moment(const Timeline& timeline, double t, double snap) {
  const std::vector<NamedMoment> moments = nameable_moments(timeline);
  const NamedMoment* nearest = nullptr;
  for (const NamedMoment& m : moments)
    if (!nearest || std::abs(m.time - t) < std::abs(nearest->time - t)) nearest = &m;
  if (nearest && std::abs(nearest->time - t) <= snap) return *nearest;
  // `at T` counts from the start of the shot (in a scene of several, of the shot in play: `shot K at
  // T`); T rounded down to the millisecond stays in the shot.
  const bool several = timeline.shot_count() > 1;
  const int shot = several ? timeline.shot_at(t) : -1;
  const double start = several                     ? shot_stretch(timeline, shot).start
                       : timeline.events().empty() ? 0.0
                                                   : timeline.events().front().time;
  const double seconds = std::max(0.0, std::floor((t - start) * 1000 + 1e-6) / 1000);
  NamedMoment fallback{shot_key(timeline, shot, CameraKeyKind::at, -1, -1, 1, seconds), start + seconds, -1};
  return name_at(timeline, shot, seconds).value_or(fallback);
}

std::optional<NamedMoment> name_event(const Timeline& timeline, int event) {
  const std::optional<KeyInstant> at = numbered(timeline, event);
  if (!at || event == CameraShot::kLastEvent) return std::nullopt;
  for (const NamedMoment& m : nameable_moments(timeline))
    if (m.event == at->event && m.time == at->time) return m;
  NamedMoment m;
  m.key.kind = CameraKeyKind::event;
  m.time = at->time;
  m.event = at->event;
  return m;
}

namespace {

/// `key` with the instant it resolves to, if it does.
std::optional<NamedMoment> resolved(const Timeline& timeline, const CameraKey& key) {
  const std::optional<KeyInstant> at = moment_instant(key, -1, timeline);
  if (!at) return std::nullopt;
  return NamedMoment{key, at->time, at->event};
}

}  // namespace

std::optional<NamedMoment> first_hit(const Timeline& timeline, int ball, int shot) {
  const std::vector<BallContact> contacts = ball_contacts(timeline, shot, ball);
  if (contacts.empty()) return std::nullopt;
  return resolved(timeline, shot_key(timeline, shot, CameraKeyKind::hit, contacts.front().other(ball), ball));
}

std::optional<NamedMoment> last_contact(const Timeline& timeline, int ball, int shot) {
  double latest = -1;
  std::optional<CameraKey> key;
  for (const Event& e : timeline.events()) {
    const bool rail = e.type == EventType::ball_rail, jaw = e.type == EventType::ball_jaw;
    if ((rail || jaw) && e.shot == shot && !e.balls.empty() && e.balls[0] == ball && e.time > latest) {
      latest = e.time;
      key = shot_key(timeline, shot, jaw ? CameraKeyKind::jaw : CameraKeyKind::cushion, ball, -1, CameraKey::kLast);
    }
  }
  const std::vector<BallContact> contacts = ball_contacts(timeline, shot, ball);
  if (!contacts.empty() && contacts.back().time > latest)
    key = shot_key(timeline, shot, CameraKeyKind::hit, contacts.back().other(ball), ball, CameraKey::kLast);
  if (!key) return std::nullopt;
  return resolved(timeline, *key);
}

std::optional<NamedMoment> first_drop(const Timeline& timeline, int ball, int shot) {
  return resolved(timeline, shot_key(timeline, shot, CameraKeyKind::drop, ball));
}

// --- Writing a description ----------------------------------------------------------------------------

double to_millimetre(double value) { return std::round(value * 1000.0) / 1000.0; }

Vec3 to_millimetre(const Vec3& v) { return {to_millimetre(v.x()), to_millimetre(v.y()), to_millimetre(v.z())}; }

namespace {

void append_vector(std::string& out, const Vec3& v) {
  for (int i = 0; i < 3; ++i) {
    out += ' ';
    append_number(out, v[i]);
  }
}

}  // namespace

std::string camera_mode_text(const CameraShot& shot) {
  std::string text;
  switch (shot.mode) {
    case CameraMode::hover:
      text = "hover";
      append_vector(text, shot.location);
      text += ' ';
      append_vector(text, shot.target);
      break;
    case CameraMode::look:
      text = "look";
      append_vector(text, shot.location);
      text += "  " + std::to_string(shot.ball);
      break;
    case CameraMode::follow:
      text = "follow " + std::to_string(shot.ball) + " ";
      append_vector(text, shot.location);
      break;
  }
  return text;
}

std::string camera_description_text(const CameraShot& shot) {
  std::string text = "event " + camera_key_text(shot.key, shot.event) + " ";
  append_number(text, shot.pre);
  text += ' ';
  append_number(text, shot.post);
  return text + " " + camera_mode_text(shot);
}

}  // namespace bsim
