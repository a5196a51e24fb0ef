// The sound track: each sound starts at its event, louder for faster hits, on the side of the
// picture where it happens; the rolling heard while a ball rolls and not after; a room under it all;
// one calibrated level for every shot (the break at -16 LUFS, a softer hit never above a harder one,
// a soft shot well under the break), or on request brought to a loudness, the true peak under
// -1 dBTP (by our meter and by ffmpeg's); exactly as long as the shot, the same bytes every time.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "builtin_scene.h"
#include "files.h"
#include "fixtures.h"
#include "hertz.h"
#include "loudness.h"
#include "mastering.h"
#include "motion.h"
#include "music_bed.h"
#include "rolling.h"
#include "room.h"
#include "shot.h"
#include "shots.h"
#include "simulate.h"
#include "sound_meter.h"
#include "sound_mix.h"
#include "sound_synth.h"
#include "soundtrack.h"
#include "support.h"
#include "tolerance.h"

using namespace bsim;

namespace {

// Two balls on the standard table: the cue ball runs into the object ball, which runs to the
// right-hand cushion; the camera looks along +y, so +x is the right of the picture.
const std::string kScene = std::string(
                               "cue 0 0\n"
                               "ball 0 -0.8 0 0.028575  1.5 0 0  1 0 0 0\n"
                               "ball 1  0.0 0 0.028575  0 0 0  1 0 0 0\n") +
                           test::fixtures::kHoverCamera;

AudioBuffer silence(double seconds) {
  AudioBuffer audio;
  const auto n = static_cast<std::size_t>(seconds * kSampleRate);
  audio.left.assign(n, 0.0f);
  audio.right.assign(n, 0.0f);
  return audio;
}

std::size_t sample_at(double t) { return static_cast<std::size_t>(std::llround(t * kSampleRate)); }

double peak(const AudioBuffer& audio, double from, double to) {
  double p = 0;
  for (std::size_t i = sample_at(std::max(from, 0.0)); i < sample_at(to) && i < audio.left.size(); ++i)
    p = std::max({p, static_cast<double>(std::abs(audio.left[i])), static_cast<double>(std::abs(audio.right[i]))});
  return p;
}

double energy(const std::vector<float>& channel, double from, double to) {
  double e = 0;
  for (std::size_t i = sample_at(from); i < sample_at(to) && i < channel.size(); ++i) e += channel[i] * channel[i];
  return e;
}

/// s: the first sample within 5 ms of `t` louder than a quarter of what follows `t`.
double onset_near(const AudioBuffer& audio, double t) {
  const double level = 0.25 * peak(audio, t, t + 0.005);
  for (std::size_t i = sample_at(std::max(t - 0.005, 0.0)); i < sample_at(t + 0.005); ++i)
    if (std::abs(audio.left[i]) > level || std::abs(audio.right[i]) > level)
      return static_cast<double>(i) / kSampleRate;
  return -1;
}

std::uint32_t le32(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = v << 8 | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(k)]);
  return v;
}

/// A two-ball shot under the hover camera: the cue ball from (-0.4, 0) at `speed` m/s along +x
/// into a ball at (0, `offset`) (0 head-on; towards 2R a thin cut).
std::string two_balls(double speed, double offset) {
  return "cue 0 0\nball 0 -0.4 0 0.028575  " + std::to_string(speed) + " 0 0  1 0 0 0\nball 1 0.0 " +
         std::to_string(offset) + " 0.028575  0 0 0  1 0 0 0\n" + test::fixtures::kHoverCamera;
}

/// The finished track of a shot, with no lead (each sound starts at its event), at `level`.
AudioBuffer track_of(const Shot& shot, const SoundLevel& level = {}, double lead = 0) {
  const auto samples = static_cast<std::size_t>(std::llround(shot.timeline.duration() * kSampleRate));
  AudioBuffer audio;
  std::string error;
  REQUIRE(mix_soundtrack({shot.scene, shot.timeline, *shot.camera}, {.lead = lead, .music_path = {}, .level = level},
                         samples, audio, error));
  return audio;
}

/// The highest peak on `audio` within 5 ms of the start of each event of type `type`.
double hit_peak(const Shot& shot, const AudioBuffer& audio, EventType type) {
  double p = 0;
  for (const Event& e : shot.timeline.events())
    if (e.type == type) p = std::max(p, peak(audio, e.time, e.time + 0.005));
  return p;
}

}  // namespace

TEST_SUITE("sound") {
  TEST_CASE("a Hertz contact is shorter the faster the balls meet (about 450, 340, 280 us at 0.5, 2, 5 m/s)") {
    const PhysicsParams physics;
    CHECK(click_contact_time(physics, 0.5) == doctest::Approx(448e-6).scale(0).epsilon(0.01));
    CHECK(click_contact_time(physics, 2.0) == doctest::Approx(340e-6).scale(0).epsilon(0.01));
    CHECK(click_contact_time(physics, 5.0) == doctest::Approx(283e-6).scale(0).epsilon(0.01));
  }

  TEST_CASE("the click is the physics' one Hertz contact: the scene's k_hertz and ball set its length and colour") {
    PhysicsParams physics;
    // k_hertz's default is the stiffness of its documented material (E = 5.84 GPa, nu = 0.34).
    CHECK(hertz_stiffness(5.84e9, 0.34, physics.ball_radius) == doctest::Approx(physics.k_hertz).epsilon(0.001));
    for (double speed : {0.5, 2.0, 5.0})
      CHECK(click_contact_time(physics, speed) == hertz_contact_time(speed, physics));
    // A ball of a four times stiffer material: a shorter contact (4^-0.4), and a brighter click, its
    // RMS frequency (from the energy of its slope) higher and its ring after 2 ms weaker.
    PhysicsParams stiff = physics;
    stiff.k_hertz *= 4;
    CHECK(click_contact_time(stiff, 2.0) == doctest::Approx(click_contact_time(physics, 2.0) * std::pow(4.0, -0.4)));
    auto rms_frequency = [](const std::vector<float>& wave) {
      double slope = 0, level = 0;
      for (std::size_t i = 1; i < wave.size(); ++i) {
        slope += (wave[i] - wave[i - 1]) * (wave[i] - wave[i - 1]);
        level += wave[i] * wave[i];
      }
      return kSampleRate / (2 * 3.141592653589793) * std::sqrt(slope / level);
    };
    auto ring = [](const std::vector<float>& wave) {
      double e = 0;
      for (std::size_t i = sample_at(0.002); i < wave.size(); ++i) e += wave[i] * wave[i];
      return e;
    };
    const std::vector<float> soft = synth_impact(SoundKind::ball_ball, 2.0, 7, physics, kSampleRate);
    const std::vector<float> hard = synth_impact(SoundKind::ball_ball, 2.0, 7, stiff, kSampleRate);
    CAPTURE(rms_frequency(soft));
    CAPTURE(rms_frequency(hard));
    CHECK(rms_frequency(hard) > 1.1 * rms_frequency(soft));
    CHECK(ring(hard) < 0.7 * ring(soft));
    // A heavier ball of the same material presses longer: a longer click.
    PhysicsParams heavy = physics;
    heavy.ball_mass *= 2;
    CHECK(click_contact_time(heavy, 2.0) > 1.2 * click_contact_time(physics, 2.0));
  }

  TEST_CASE("every kind of sound gets louder with speed, and its peak is its gain") {
    const PhysicsParams physics;
    for (SoundKind kind : {SoundKind::ball_ball, SoundKind::ball_rail, SoundKind::cue, SoundKind::pocket_fall,
                           SoundKind::pocket_knock, SoundKind::pocket_roll, SoundKind::jaw_knock}) {
      CAPTURE(static_cast<int>(kind));
      double previous = 0;
      for (double speed : {0.05, 0.3, 1.0, 3.0, 8.0}) {
        const std::vector<float> sound = synth_impact(kind, speed, 42, physics, kSampleRate);
        REQUIRE_FALSE(sound.empty());
        double p = 0;
        for (float s : sound) p = std::max(p, static_cast<double>(std::abs(s)));
        CHECK(p == doctest::Approx(impact_gain(kind, speed)).epsilon(1e-5));
        CHECK(p > previous);
        previous = p;
      }
    }
  }

  TEST_CASE("a sound starts at its cue's time, or that much earlier with a lead") {
    const PhysicsParams physics;
    const std::vector<SoundCue> cues = {
        {SoundKind::cue, 0.3, 2.0, 0, 1},          {SoundKind::ball_ball, 0.61, 1.0, 0, 2},
        {SoundKind::ball_rail, 1.02, 0.5, 0, 3},   {SoundKind::pocket_fall, 1.5, 0.8, 0, 4},
        {SoundKind::pocket_knock, 2.2, 0.8, 0, 5}, {SoundKind::jaw_knock, 2.5, 0.8, 0, jaw_seed(2, 6)}};
    for (double lead : {0.0, 0.005, 0.03}) {
      CAPTURE(lead);
      AudioBuffer audio = silence(2.9);
      mix_cues(cues, physics, lead, audio);
      for (const SoundCue& cue : cues) {
        CAPTURE(cue.time);
        CHECK(peak(audio, cue.time - lead - 0.05, cue.time - lead - 0.0005) == 0.0);  // silence before
        CHECK(std::abs(onset_near(audio, cue.time - lead) - (cue.time - lead)) <= 0.002);
      }
    }
  }

  TEST_CASE("a faster hit is louder on the track") {
    const PhysicsParams physics;
    AudioBuffer audio = silence(2.0);
    const double speeds[] = {0.2, 0.8, 2.0, 5.0};
    std::vector<SoundCue> cues;
    for (int k = 0; k < 4; ++k) cues.push_back({SoundKind::ball_ball, 0.1 + 0.4 * k, speeds[k], 0, 7});
    mix_cues(cues, physics, 0, audio);
    for (int k = 1; k < 4; ++k)
      CHECK(peak(audio, cues[static_cast<std::size_t>(k)].time, cues[static_cast<std::size_t>(k)].time + 0.1) >
            peak(audio, cues[static_cast<std::size_t>(k - 1)].time, cues[static_cast<std::size_t>(k - 1)].time + 0.1));
  }

  TEST_CASE("a sound on the right of the picture is louder on the right channel, and the other way") {
    const CameraPose camera{Vec3(0, -3, 2), Vec3(0, 0, 0), false};
    // (1, 0, 0) seen from (0, -3, 2) looking at the origin: the view direction is (0, 3, -2) / sqrt(13)
    // and the picture's right (view x up) is +x, so the point lies 1 m across and sqrt(13) m ahead,
    // atan(1 / sqrt(13)) off the axis, where the picture's edge is half the 55 degree field away.
    const double across = std::atan(1 / std::sqrt(13.0)) / (27.5 * M_PI / 180);
    CHECK(view_position(camera, Vec3(1, 0, 0), 55) == test::near(across, 1e-12));
    CHECK(view_position(camera, Vec3(-1, 0, 0), 55) == test::near(-across, 1e-12));
    CHECK(view_position(camera, Vec3(0, 0, 0), 55) == doctest::Approx(0).epsilon(1e-12));
    CHECK(view_position(camera, Vec3(50, 0, 0), 55) == 1.0);  // far outside the picture: clamped
    CHECK(view_position(camera, Vec3(1, -5, 0), 55) == 1.0);  // behind the camera, to its right

    const PhysicsParams physics;
    AudioBuffer audio = silence(1.0);
    mix_cues({{SoundKind::ball_ball, 0.2, 2, 0.8, 1}, {SoundKind::ball_ball, 0.6, 2, -0.8, 1}}, physics, 0, audio);
    CHECK(energy(audio.right, 0.2, 0.3) > 4 * energy(audio.left, 0.2, 0.3));
    CHECK(energy(audio.left, 0.6, 0.7) > 4 * energy(audio.right, 0.6, 0.7));
  }

  TEST_CASE("the shot's track: exactly its length, a sound at every hit, the cushion on its side, reproducible") {
    const auto shot = test::load_clean(kScene, "sound");
    const double duration = shot->timeline.duration();
    const auto samples = static_cast<std::size_t>(std::llround(duration * kSampleRate));
    const double lead = 0.005;
    AudioBuffer audio;
    std::string error;
    REQUIRE(mix_soundtrack({shot->scene, shot->timeline, *shot->camera}, {.lead = lead, .music_path = {}, .level = {}},
                           samples, audio, error));
    CHECK(audio.left.size() == samples);
    CHECK(audio.right.size() == samples);

    double previous_hit = -1;
    bool rail_seen = false;
    for (const Event& e : shot->timeline.events()) {
      if (e.type != EventType::cue && e.type != EventType::ball_ball && e.type != EventType::ball_rail) continue;
      CAPTURE(e.index);
      CAPTURE(e.time);
      const double t = e.time - lead;
      // A hit right after another can hide in its ring; the shot's hits are far apart but for that.
      if (previous_hit < 0 || e.time - previous_hit > 0.06) {
        CHECK(std::abs(onset_near(audio, t) - t) <= 0.002);
        CHECK(peak(audio, t + 0.001, t + 0.006) > 4 * peak(audio, t - 0.012, t - 0.003));
      }
      if (e.type == EventType::ball_rail && e.rail == 2 && !rail_seen) {  // the right-hand cushion
        rail_seen = true;
        CHECK(energy(audio.right, t, t + 0.05) > energy(audio.left, t, t + 0.05));
      }
      previous_hit = e.time;
    }
    CHECK(rail_seen);

    AudioBuffer again;
    REQUIRE(mix_soundtrack({shot->scene, shot->timeline, *shot->camera}, {.lead = lead, .music_path = {}, .level = {}},
                           samples, again, error));
    CHECK(again.left == audio.left);
    CHECK(again.right == audio.right);
  }

  TEST_CASE("a rolling ball rumbles, louder the faster it rolls, and falls silent when it stops") {
    const auto shot = test::load_clean(kScene, "sound");
    const Timeline& timeline = shot->timeline;
    const double duration = timeline.duration();
    AudioBuffer audio = silence(duration);
    mix_rolling({shot->scene, timeline, *shot->camera}, audio, nullptr);
    // Ball 1 is struck, rolls to the cushion and back out, then stops: every window of it rolling
    // holds rumble, and after the last of the balls stops there is not one sample.
    double last_stop = 0;
    for (int ball = 0; ball < timeline.ball_count(); ++ball) {
      const MotionSegment& last = timeline.segments(ball).back();
      REQUIRE(last.start.motion == Motion::stationary);
      last_stop = std::max(last_stop, last.t0);
    }
    REQUIRE(last_stop < duration - 0.2);
    CHECK(peak(audio, last_stop + kRumbleStep, duration) == 0.0);
    CHECK(peak(audio, 0, kCueLeadTime - kRumbleStep) == 0.0);  // before the stroke nothing rolls
    std::vector<double> levels;
    for (const MotionSegment& seg : timeline.segments(1)) {
      if (seg.start.motion != Motion::rolling) continue;
      const double end = seg.t0 + std::min(0.3, 0.5 * transition_time(seg.start, timeline.physics()));
      const double rms = std::sqrt((energy(audio.left, seg.t0 + 0.01, end) + energy(audio.right, seg.t0 + 0.01, end)) /
                                   ((end - seg.t0 - 0.01) * kSampleRate));
      CAPTURE(seg.t0);
      CHECK(rms > 1e-4);
      levels.push_back(rms);
    }
    REQUIRE_FALSE(levels.empty());
    CHECK(rumble_level(0.0) == 0.0);
    CHECK(rumble_level(0.5) < rumble_level(1.0));
    CHECK(rumble_level(1.0) < rumble_level(3.0));
    CHECK(slip_level(0.0) == 0.0);
    CHECK(slip_level(0.5) < slip_level(2.0));
  }

  TEST_CASE("K-weighting at 48 kHz is BS.1770-4's filter; a sine's loudness and a true peak between samples") {
    const auto k = k_weighting(48000);
    CHECK(k[0].b[0] == doctest::Approx(1.53512485958697).epsilon(1e-9));
    CHECK(k[0].b[1] == doctest::Approx(-2.69169618940638).epsilon(1e-9));
    CHECK(k[0].b[2] == doctest::Approx(1.19839281085285).epsilon(1e-9));
    CHECK(k[0].a[0] == doctest::Approx(-1.69065929318241).epsilon(1e-9));
    CHECK(k[0].a[1] == doctest::Approx(0.73248077421585).epsilon(1e-9));
    CHECK(k[1].a[0] == doctest::Approx(-1.99004745483398).epsilon(1e-9));
    CHECK(k[1].a[1] == doctest::Approx(0.99007225036621).epsilon(1e-9));

    // A 997 Hz sine at -20 dBFS in both channels: -20 LUFS (BS.1770-4: 0 dBFS in one channel is -3.01).
    AudioBuffer sine = silence(2.0);
    for (std::size_t i = 0; i < sine.left.size(); ++i)
      sine.left[i] = sine.right[i] =
          static_cast<float>(0.1 * std::sin(2 * M_PI * 997 * static_cast<double>(i) / kSampleRate));
    REQUIRE(integrated_loudness(sine).has_value());
    CHECK(*integrated_loudness(sine) == doctest::Approx(-20.0).epsilon(0.005));
    CHECK_FALSE(integrated_loudness(silence(2.0)).has_value());

    // A quarter-rate sine 45 degrees off the samples: they reach 0.707 of its true peak.
    AudioBuffer quarter = silence(0.1);
    for (std::size_t i = 0; i < quarter.left.size(); ++i)
      quarter.left[i] = static_cast<float>(0.5 * std::sin(M_PI / 2 * static_cast<double>(i) + M_PI / 4));
    CHECK(peak(quarter, 0.01, 0.09) == doctest::Approx(0.5 * std::sqrt(0.5)).epsilon(1e-3));
    CHECK(true_peak(quarter) == doctest::Approx(0.5).epsilon(0.02));
  }

  TEST_CASE("the finished track: its loudness by our meter and ffmpeg's, true peak under -1 dBTP, never silent") {
    test::require_program("ffmpeg");
    const auto shot = test::load_clean(kScene, "sound");
    const auto samples = static_cast<std::size_t>(std::llround(shot->timeline.duration() * kSampleRate));
    test::TempDir dir;
    for (double target : {kDefaultLoudness, -23.0}) {
      CAPTURE(target);
      AudioBuffer audio;
      std::string error;
      REQUIRE(mix_soundtrack(
          {shot->scene, shot->timeline, *shot->camera},
          {.lead = 0.005, .music_path = {}, .level = {.mode = LevelMode::normalised, .loudness = target}}, samples,
          audio, error));
      REQUIRE(integrated_loudness(audio).has_value());
      CHECK(std::abs(*integrated_loudness(audio) - target) < 1.0);
      CHECK(to_db(true_peak(audio)) < -1.0);
      CHECK(test::quietest_window_db(audio, 0.1) > -70.0);

      const std::string path = (dir.path / "track.wav").string();
      REQUIRE(write_wav(path, audio, error));
      const test::CommandResult r = test::run_command("ffmpeg -hide_banner -nostats -i " + test::quoted(path) +
                                                      " -af ebur128=peak=true -f null -");
      REQUIRE(r.exit_code == 0);
      // The summary at the end: "I:  -16.0 LUFS" and, under "True peak:", "Peak:  -1.6 dBFS".
      const std::size_t summary = r.err.rfind("Integrated loudness:");
      REQUIRE(summary != std::string::npos);
      const std::size_t i = r.err.find("I:", summary), p = r.err.find("Peak:", summary);
      REQUIRE(i != std::string::npos);
      REQUIRE(p != std::string::npos);
      const double ffmpeg_loudness = std::stod(r.err.substr(i + 2)), ffmpeg_peak = std::stod(r.err.substr(p + 5));
      CHECK(std::abs(ffmpeg_loudness - target) < 1.0);
      CHECK(ffmpeg_peak < -1.0);
    }
  }

  TEST_CASE("at the calibrated level the built-in break measures -16 LUFS, its true peak under -1 dBTP") {
    const auto shot = test::load_clean(builtin_scene_text(), "break");
    const AudioBuffer audio = track_of(*shot, {}, 0.005);
    REQUIRE(integrated_loudness(audio).has_value());
    CHECK(*integrated_loudness(audio) == doctest::Approx(kDefaultLoudness).scale(0).epsilon(0.5 / 16));
    CHECK(to_db(true_peak(audio)) < -1.0);
  }

  TEST_CASE("at the calibrated level a softer hit never peaks above a harder one of its kind, across shots") {
    // The cue and the click at 0.5 and at 3 m/s.
    const auto slow = test::load_clean(two_balls(0.5, 0), "slow"), fast = test::load_clean(two_balls(3.0, 0), "fast");
    const AudioBuffer slow_track = track_of(*slow), fast_track = track_of(*fast);
    for (EventType type : {EventType::cue, EventType::ball_ball}) {
      CAPTURE(static_cast<int>(type));
      const double soft = hit_peak(*slow, slow_track, type), hard = hit_peak(*fast, fast_track, type);
      REQUIRE(soft > 0);
      CHECK(soft < hard);
    }
    // Head-on and a thin cut (about 70 degrees) at one cue speed: the cut's click is the softer one.
    const auto head = test::load_clean(two_balls(1.5, 0), "head"),
               thin = test::load_clean(two_balls(1.5, 0.054), "cut");
    const AudioBuffer head_track = track_of(*head), thin_track = track_of(*thin);
    CHECK(hit_peak(*thin, thin_track, EventType::ball_ball) < hit_peak(*head, head_track, EventType::ball_ball));
  }

  TEST_CASE("at the calibrated level the compressor is gentle: a 3 m/s click stays 8 dB over a 0.5 m/s one") {
    // Synthesised, the two clicks' peaks differ by 20 log10(impact gain ratio), about 10.6 dB (the
    // slow ball arrives a little slower still); a brick wall, or a compressor that squeezes every
    // hit, would leave them a few dB apart.
    const double synthesised = to_db(impact_gain(SoundKind::ball_ball, 3.0) / impact_gain(SoundKind::ball_ball, 0.5));
    REQUIRE(synthesised > 10.0);
    const auto slow = test::load_clean(two_balls(0.5, 0), "slow"), fast = test::load_clean(two_balls(3.0, 0), "fast");
    const double soft = hit_peak(*slow, track_of(*slow), EventType::ball_ball),
                 hard = hit_peak(*fast, track_of(*fast), EventType::ball_ball);
    REQUIRE(soft > 0);
    CHECK(to_db(hard / soft) > 8.0);
  }

  TEST_CASE("at the calibrated level a softer cushion hit or pocket drop is quieter than a harder one, across shots") {
    // One ball, alone: straight into the right-hand cushion, or diagonally into the top-right corner
    // pocket from 0.52 m away, at 0.5 and at 3 m/s.
    auto alone = [](double x, double y, double vx, double vy) {
      return "cue 0 " + std::to_string(std::atan2(vy, vx) / kDegToRad) + "\nball 0 " + std::to_string(x) + " " +
             std::to_string(y) + " 0.028575  " + std::to_string(vx) + " " + std::to_string(vy) + " 0  1 0 0 0\n" +
             test::fixtures::kHoverCamera;
    };
    double previous_cushion = 0, previous_pocket = 0;
    for (double speed : {0.5, 3.0}) {
      CAPTURE(speed);
      const auto rail = test::load_clean(alone(0.6, 0, speed, 0), "cushion");
      const double cushion = hit_peak(*rail, track_of(*rail), EventType::ball_rail);
      CHECK(cushion > previous_cushion);
      previous_cushion = cushion;

      const double v = speed / std::sqrt(2.0);
      const auto corner = test::load_clean(alone(0.9, 0.265, v, v), "pocket");
      REQUIRE(corner->timeline.pocket_drops().size() == 1);
      const double drop = corner->timeline.pocket_drops().front().time;
      const double pocket = peak(track_of(*corner), drop, drop + 0.6);
      CHECK(pocket > previous_pocket);
      previous_pocket = pocket;
    }
  }

  TEST_CASE("a group's clicks reach the camera one after another, each after its own way to it") {
    // The built-in break's rack: every contact of its group clicks, delayed after the nearest
    // contact's by its extra distance to the camera over the speed of sound (343 m/s).
    const auto shot = test::load_clean(builtin_scene_text(), "break");
    const SoundSource source{shot->scene, shot->timeline, *shot->camera};
    const std::vector<SoundCue> cues = sound_cues(source);
    const Event* group = nullptr;
    for (const Event& e : shot->timeline.events())
      if (e.grouped && (!group || e.contacts.size() > group->contacts.size())) group = &e;
    REQUIRE(group != nullptr);
    const Vec3 ear = shot->camera->pose(group->time).location;
    double nearest = 1e9, farthest = 0;
    for (const Contact& c : group->contacts) {
      nearest = std::min(nearest, (c.where - ear).norm());
      farthest = std::max(farthest, (c.where - ear).norm());
    }
    CHECK((farthest - nearest) / 343.0 > 2e-4);  // a fair part of a click's 0.3-0.5 ms contact
    int found = 0;
    for (const Contact& c : group->contacts) {
      if (c.speed < kMinEventSpeed) continue;
      const double expected = c.time + ((c.where - ear).norm() - nearest) / 343.0;
      for (const SoundCue& cue : cues)
        if (cue.kind == SoundKind::ball_ball && std::abs(cue.time - expected) < 1e-12 && cue.speed == c.speed) {
          ++found;
          break;
        }
    }
    CHECK(found > 5);
    CHECK(found == std::count_if(group->contacts.begin(), group->contacts.end(),
                                 [](const Contact& c) { return c.speed >= kMinEventSpeed; }));
  }

  TEST_CASE("a click's peak stands over its ring as a recorded click's does (18 dB over the first 100 ms)") {
    // The recording (Debian's foobillardplus-data, ball_ball.raw, measured by sound_bench): its peak
    // is 17.9 dB over the RMS of the 100 ms from its onset. Ours at 2 m/s, from its start.
    const std::vector<float> click = synth_impact(SoundKind::ball_ball, 2.0, 7, PhysicsParams{}, kSampleRate);
    const auto n = static_cast<std::size_t>(0.1 * kSampleRate);
    REQUIRE(click.size() >= n);
    double top = 0, sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
      top = std::max(top, static_cast<double>(std::abs(click[i])));
      sum += static_cast<double>(click[i]) * click[i];
    }
    CHECK(to_db(top / std::sqrt(sum / static_cast<double>(n))) == doctest::Approx(17.9).scale(0).epsilon(1.5 / 17.9));
  }

  TEST_CASE("at the calibrated level a soft two-ball tap is at least 8 LU under the break, over the same room") {
    // The tap: the cue ball at 0.8 m/s from (-0.6, 0) into a ball at (0.2, 0.01).
    const auto tap = test::load_clean(std::string("cue 0 0\n"
                                                  "ball 0 -0.6 0 0.028575  0.8 0 0  1 0 0 0\n"
                                                  "ball 1 0.2 0.01 0.028575  0 0 0  1 0 0 0\n") +
                                          test::fixtures::kHoverCamera,
                                      "tap");
    const auto brk = test::load_clean(builtin_scene_text(), "break");
    const AudioBuffer tap_track = track_of(*tap), break_track = track_of(*brk);
    REQUIRE(integrated_loudness(tap_track).has_value());
    REQUIRE(integrated_loudness(break_track).has_value());
    CHECK(*integrated_loudness(tap_track) <= *integrated_loudness(break_track) - 8.0);
    // The room tone is the same in both: their quietest 100 ms (the room alone) agree, at the tone's level.
    const double tap_room = test::quietest_window_db(tap_track, 0.1);
    // Over the same stretch of time: the room tone is one noise, and a longer track has more 100 ms
    // windows of it to find a quieter one in (the break's 10 s dip to -56.1 dB where its first 8 s,
    // the tap's length, give -55.7).
    AudioBuffer break_start = break_track;
    break_start.left.resize(std::min(break_start.left.size(), tap_track.left.size()));
    break_start.right.resize(break_start.left.size());
    CHECK(tap_room == doctest::Approx(test::quietest_window_db(break_start, 0.1)).scale(0).epsilon(0.25 / 55));
    CHECK(std::abs(tap_room - kRoomToneDb) < 3.0);
  }

  TEST_CASE("at either level every contact still stands out of the rumble and the room before it") {
    // The level stage raises the rolling and the room with the clicks but compresses or limits only
    // the clicks' peaks: a hit must still rise well above the 10 ms before it (four times, 12 dB), and
    // not only in its first fraction of a millisecond (a meter reading 1 ms windows may miss that).
    const auto shot = test::load_clean(kScene, "sound");
    const double lead = 0.005;
    for (const SoundLevel& level : {SoundLevel{}, SoundLevel{.mode = LevelMode::normalised}}) {
      CAPTURE(level_mode_name(level.mode));
      const AudioBuffer audio = track_of(*shot, level, lead);
      int hits = 0;
      for (const Event& e : shot->timeline.events()) {
        if (e.type != EventType::cue && e.type != EventType::ball_ball && e.type != EventType::ball_rail) continue;
        const double t = e.time - lead;
        CAPTURE(e.time);
        CHECK(peak(audio, t + 0.001, t + 0.006) > 4 * peak(audio, t - 0.012, t - 0.003));
        ++hits;
      }
      CHECK(hits >= 3);
    }
  }

  TEST_CASE("with --loudness off the track keeps its level, only kept under the true-peak ceiling") {
    const auto shot = test::load_clean(kScene, "sound");
    const auto samples = static_cast<std::size_t>(std::llround(shot->timeline.duration() * kSampleRate));
    AudioBuffer audio;
    std::string error;
    REQUIRE(mix_soundtrack({shot->scene, shot->timeline, *shot->camera},
                           {.lead = 0.005, .music_path = {}, .level = {.mode = LevelMode::off}}, samples, audio,
                           error));
    CHECK(to_db(true_peak(audio)) <= kTruePeakCeilingDb + 0.01);
    CHECK(test::quietest_window_db(audio, 0.1) > -70.0);
  }

  TEST_CASE("the room: its tone is continuous at its level, its reverberation short and the same every time") {
    const AudioBuffer tone = room_tone(kSampleRate, 3);
    double sum = 0;
    for (std::size_t i = 0; i < tone.left.size(); ++i)
      sum += 0.5 * (tone.left[i] * tone.left[i] + tone.right[i] * tone.right[i]);
    CHECK(10 * std::log10(sum / kSampleRate) == doctest::Approx(kRoomToneDb).epsilon(0.001));
    CHECK(test::quietest_window_db(tone, 0.1) > kRoomToneDb - 3);
    CHECK(room_tone(1000, 3).left == room_tone(1000, 3).left);

    std::vector<float> send(kSampleRate, 0.0f);
    send[0] = 1.0f;
    AudioBuffer wet = silence(1.0), again = silence(1.0);
    add_reverb(send, wet);
    add_reverb(send, again);
    CHECK(wet.left == again.left);
    CHECK(peak(wet, 0, kReverbPreDelay - 0.001) == 0.0);  // nothing before the first reflections
    const double early = 0.5 * (energy(wet.left, 0, 0.1) + energy(wet.right, 0, 0.1));
    CHECK(early > 0);
    CHECK(early < std::pow(10.0, kReverbLevelDb / 10));  // under the direct sound's energy (1)
    // Well down by 0.7 s (the reverberation time is 0.45 s): under a ten-thousandth of the early energy.
    CHECK(0.5 * (energy(wet.left, 0.7, 1.0) + energy(wet.right, 0.7, 1.0)) < 1e-4 * early);
  }

  TEST_CASE("the WAV file is 48 kHz 16-bit stereo PCM holding every sample") {
    test::TempDir dir;
    AudioBuffer audio = silence(0.25);
    audio.left[100] = 0.5f;
    audio.right[101] = -0.5f;
    const std::string path = (dir.path / "t.wav").string();
    std::string error;
    REQUIRE(write_wav(path, audio, error));
    const std::string bytes = test::require_file(path);
    REQUIRE(bytes.size() > 44);
    CHECK(bytes.substr(0, 4) == "RIFF");
    CHECK(bytes.substr(8, 4) == "WAVE");
    const std::size_t fmt = bytes.find("fmt ");
    REQUIRE(fmt != std::string::npos);
    CHECK((le32(bytes, fmt + 8) & 0xffff) == 1);  // PCM
    CHECK((le32(bytes, fmt + 8) >> 16) == 2);     // stereo
    CHECK(le32(bytes, fmt + 12) == 48000);        // sample rate
    CHECK((le32(bytes, fmt + 20) >> 16) == 16);   // bits per sample
    const std::size_t data = bytes.find("data");
    REQUIRE(data != std::string::npos);
    CHECK(le32(bytes, data + 4) == audio.left.size() * 4);  // frames x 2 channels x 2 bytes
    CHECK(!write_wav((dir.path / "missing" / "t.wav").string(), audio, error));
    CHECK(error.find("missing") != std::string::npos);
  }

  TEST_CASE("music is looped or trimmed to the shot, faded in and out, under the effects") {
    test::TempDir dir;
    AudioBuffer tone;
    tone.sample_rate = 44100;
    for (int i = 0; i < 22050; ++i) {  // half a second of 440 Hz at 44.1 kHz
      const auto s = static_cast<float>(0.8 * std::sin(2 * 3.141592653589793 * 440 * i / 44100.0));
      tone.left.push_back(s);
      tone.right.push_back(s);
    }
    const std::string path = (dir.path / "tone.wav").string();
    std::string error;
    REQUIRE(write_wav(path, tone, error));

    AudioBuffer music;
    REQUIRE(load_music_bed(path, 2 * kSampleRate, music, error));
    REQUIRE(music.left.size() == static_cast<std::size_t>(2 * kSampleRate));
    CHECK(std::abs(music.left.front()) < 1e-3);  // faded in
    CHECK(std::abs(music.left.back()) < 1e-3);   // faded out
    CHECK(peak(music, 1.2, 1.3) > 0.5 * 0.8);    // the half-second tone plays on, looped

    REQUIRE(load_music_bed(path, kSampleRate / 10, music, error));  // longer than the shot: trimmed
    CHECK(music.left.size() == static_cast<std::size_t>(kSampleRate / 10));

    CHECK_FALSE(load_music_bed((dir.path / "none.ogg").string(), 100, music, error));
    CHECK(error.find("none.ogg") != std::string::npos);

    // Under the effects of a shot: the track still comes to the loudness asked for, and it is the
    // same bytes every time it is made.
    const auto shot = test::load_clean(kScene, "sound");
    const auto samples = static_cast<std::size_t>(std::llround(shot->timeline.duration() * kSampleRate));
    std::string bytes[2];
    for (int k = 0; k < 2; ++k) {
      AudioBuffer track;
      REQUIRE(mix_soundtrack(
          {shot->scene, shot->timeline, *shot->camera},
          {.lead = 0.005, .music_path = path, .level = {.mode = LevelMode::normalised, .loudness = kDefaultLoudness}},
          samples, track, error));
      REQUIRE(integrated_loudness(track).has_value());
      CHECK(std::abs(*integrated_loudness(track) - kDefaultLoudness) < 1.0);
      const std::string wav = (dir.path / ("track" + std::to_string(k) + ".wav")).string();
      REQUIRE(write_wav(wav, track, error));
      bytes[k] = test::require_file(wav);
    }
    CHECK(bytes[0] == bytes[1]);
  }
}

TEST_SUITE("sound: the tip's click follows the stroke") {
  double cue_click_speed(const std::string& stroke) {
    const auto shot = test::load_scene("cue 0 0\nstroke " + stroke + "\nball 0 -0.6 0 0.028575 0 0 0 1 0 0 0\n" +
                                       test::fixtures::kHoverCamera);
    REQUIRE(shot->camera);
    for (const SoundCue& c : sound_cues({shot->scene, shot->timeline, *shot->camera}))
      if (c.kind == SoundKind::cue) return c.speed;
    FAIL("no cue click");
    return 0;
  }

  TEST_CASE("louder for a faster stroke, the same for the same stroke speed wherever the tip meets the ball") {
    // A centre hit's ball speed (TP A-30): 1.75 x 2 / (1 + 0.170097 / 0.54) = 2.661608 m/s for 2 m/s.
    CHECK(cue_click_speed("2 0 0 0") == test::near(2.661608, 1e-6));
    CHECK(cue_click_speed("2 0 -0.45 10") == test::near(2.661608, 1e-6));  // the draw ball leaves slower
    CHECK(cue_click_speed("4 0 0 0") == test::near(2 * 2.661608, 2e-6));
    CHECK(impact_gain(SoundKind::cue, cue_click_speed("4 0 0 0")) >
          impact_gain(SoundKind::cue, cue_click_speed("2 0 0 0")));
  }
}

TEST_SUITE("sound: a scene of several shots") {
  TEST_CASE("every shot's strike clicks at its own time and stroke, and the room runs on between shots") {
    const std::optional<std::string> text = test::read_file(test::source_path("tests/scene/three_shots.scn"));
    REQUIRE(text);
    const auto shot = test::load_scene(*text, "three_shots");
    REQUIRE(shot->camera);
    const auto& shots = shot->timeline.shots();
    REQUIRE(shots.size() == 3);
    std::vector<SoundCue> clicks;
    for (const SoundCue& c : sound_cues({shot->scene, shot->timeline, *shot->camera}))
      if (c.kind == SoundKind::cue) clicks.push_back(c);
    REQUIRE(clicks.size() == 3);
    // The strokes are 2, 2.2 and 2.2 m/s: a centre hit's ball speed 1.75 V / (1 + 0.170097 / 0.54)
    // (TP A-30), 2.661608 and 2.927769 m/s.
    const double ball_speed[] = {2.661608, 2.927769, 2.927769};
    for (std::size_t k = 0; k < 3; ++k) {
      CAPTURE(k);
      CHECK(clicks[k].time == shots[k].cue);
      CHECK(clicks[k].speed == test::near(ball_speed[k], 1e-5));
    }
    // On the track: each strike stands out of the quiet before it, and no stretch of it is silent
    // (the room's tone goes on between the shots).
    const AudioBuffer audio = track_of(*shot);
    CHECK(audio.left.size() == static_cast<std::size_t>(std::llround(shot->timeline.duration() * kSampleRate)));
    for (const ShotSpan& span : shots) {
      CAPTURE(span.cue);
      CHECK(std::abs(onset_near(audio, span.cue) - span.cue) <= 0.002);
      CHECK(peak(audio, span.cue + 0.001, span.cue + 0.006) > 4 * peak(audio, span.cue - 0.012, span.cue - 0.003));
    }
    CHECK(test::quietest_window_db(audio, 0.1) > -70.0);
  }
}

TEST_SUITE("sound: a pocket's jaws") {
  /// The 1 sent by the cue ball into the top-right corner (pocket 2) 36 mm off its middle: it knocks on
  /// the near jaw and the far one and back, five times in 0.7 s (a rattle), and stays out.
  const std::string kRattle = std::string(
                                  "cue 0 45\n"
                                  "ball 0 0.5176 -0.1683 0.028575 1.7678 1.7678 0 1 0 0 0\n"
                                  "ball 1 0.9419 0.2560 0.028575 0 0 0 1 0 0 0\n") +
                              test::fixtures::kHoverCamera;
  /// The same slower: the 1 knocks twice and drops; the cue ball follows it and knocks twice on the
  /// same jaws, slowly, 0.77 s apart.
  const std::string kTwoRattles = std::string(
                                      "cue 0 45\n"
                                      "ball 0 0.5176 -0.1683 0.028575 1.2728 1.2728 0 1 0 0 0\n"
                                      "ball 1 0.9419 0.2560 0.028575 0 0 0 1 0 0 0\n") +
                                  test::fixtures::kHoverCamera;

  /// Hz, the spectral centroid of `wave` (its first 8192 samples, 171 ms): the mean frequency of its
  /// energy's spectrum, each bin weighted by its power (Goertzel's recurrence, bin by bin), so the
  /// modes that carry the sound set it rather than a faint noise floor spread up to 24 kHz.
  double spectral_centroid(const std::vector<float>& wave) {
    const std::size_t n = std::min<std::size_t>(wave.size(), 8192);
    double weighted = 0, total = 0;
    for (std::size_t k = 1; k < n / 2; ++k) {
      const double w = 2 * M_PI * static_cast<double>(k) / static_cast<double>(n), c = 2 * std::cos(w);
      double s1 = 0, s2 = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const double s0 = wave[i] + c * s1 - s2;
        s2 = s1;
        s1 = s0;
      }
      const double power = std::max(0.0, s1 * s1 + s2 * s2 - c * s1 * s2);
      weighted += power * static_cast<double>(k) * kSampleRate / static_cast<double>(n);
      total += power;
    }
    return weighted / total;
  }

  /// s until all but 5 % of the sound's energy has arrived.
  double energy_duration(const std::vector<float>& wave) {
    double total = 0;
    for (float s : wave) total += static_cast<double>(s) * s;
    double sum = 0;
    for (std::size_t i = 0; i < wave.size(); ++i) {
      sum += static_cast<double>(wave[i]) * wave[i];
      if (sum >= 0.95 * total) return static_cast<double>(i) / kSampleRate;
    }
    return static_cast<double>(wave.size()) / kSampleRate;
  }

  /// The correlation of two sounds from `from` s on (where the modes ring on alone).
  double correlation(const std::vector<float>& a, const std::vector<float>& b, double from) {
    double ab = 0, aa = 0, bb = 0;
    for (std::size_t i = sample_at(from); i < a.size() && i < b.size(); ++i) {
      ab += static_cast<double>(a[i]) * b[i];
      aa += static_cast<double>(a[i]) * a[i];
      bb += static_cast<double>(b[i]) * b[i];
    }
    return ab / std::sqrt(aa * bb);
  }

  std::vector<SoundCue> cues_of(const Shot& shot, SoundKind kind) {
    std::vector<SoundCue> out;
    for (const SoundCue& c : sound_cues({shot.scene, shot.timeline, *shot.camera}))
      if (c.kind == kind) out.push_back(c);
    return out;
  }

  TEST_CASE("a jaw's knock is shorter and brighter than a cushion's thud, at every speed") {
    const PhysicsParams physics;
    for (double speed : {0.1, 0.5, 1.5, 4.0})
      for (std::uint64_t seed : {std::uint64_t{3}, jaw_seed(2, 77)}) {
        CAPTURE(speed);
        const std::vector<float> jaw = synth_impact(SoundKind::jaw_knock, speed, seed, physics, kSampleRate);
        const std::vector<float> cushion = synth_impact(SoundKind::ball_rail, speed, seed, physics, kSampleRate);
        CAPTURE(spectral_centroid(jaw));
        CAPTURE(spectral_centroid(cushion));
        CAPTURE(energy_duration(jaw));
        CAPTURE(energy_duration(cushion));
        CHECK(spectral_centroid(jaw) > 3 * spectral_centroid(cushion));
        CHECK(energy_duration(jaw) < 0.6 * energy_duration(cushion));
      }
    // The facing's contact: a fifth of the cushion's, shorter when faster.
    CHECK(jaw_contact_time(1.0) == doctest::Approx(0.0007));
    CHECK(jaw_contact_time(3.0) < jaw_contact_time(0.5));
  }

  TEST_CASE("one pocket's jaws ring alike; each knock's own tick differs") {
    const PhysicsParams physics;
    CHECK((jaw_seed(2, 1) >> 32) == (jaw_seed(2, 99) >> 32));
    CHECK(jaw_seed(2, 1) != jaw_seed(2, 99));
    CHECK((jaw_seed(2, 1) >> 32) != (jaw_seed(3, 1) >> 32));
    const auto knock = [&](std::uint64_t seed) {
      return synth_impact(SoundKind::jaw_knock, 1.0, seed, physics, kSampleRate);
    };
    const std::vector<float> a = knock(jaw_seed(2, 1)), b = knock(jaw_seed(2, 99)), other = knock(jaw_seed(3, 1));
    CHECK(a != b);  // not one sample copied: the tick's noise is the knock's own
    // After the tick (3 ms) the pocket's modes ring on alone: the same modes in both knocks of one
    // pocket; another pocket's are a few per cent off and drift out of phase.
    CAPTURE(correlation(a, b, 0.015));
    CAPTURE(correlation(a, other, 0.015));
    CHECK(correlation(a, b, 0.015) > 0.99);
    CHECK(correlation(a, other, 0.015) < 0.97);
  }

  TEST_CASE("a ball-jaw event knocks on the track at its time, on the jaw's side, louder when faster") {
    const auto shot = test::load_clean(kRattle, "rattle");
    std::vector<const Event*> jaws;
    for (const Event& e : shot->timeline.events())
      if (e.type == EventType::ball_jaw) jaws.push_back(&e);
    REQUIRE(jaws.size() >= 3);
    const std::vector<SoundCue> knocks = cues_of(*shot, SoundKind::jaw_knock);
    REQUIRE(knocks.size() == jaws.size());
    for (std::size_t k = 0; k < jaws.size(); ++k) {
      CHECK(knocks[k].time == jaws[k]->time);
      CHECK(knocks[k].speed == jaws[k]->speed);
      CHECK(knocks[k].pan > 0.3);  // the top-right corner, on the right of the hover camera's picture
    }
    const AudioBuffer audio = track_of(*shot);
    const double t = jaws.front()->time;
    CHECK(std::abs(onset_near(audio, t) - t) <= 0.002);
    CHECK(energy(audio.right, t, t + 0.03) > 2 * energy(audio.left, t, t + 0.03));
    CHECK(impact_gain(SoundKind::jaw_knock, 2.0) > impact_gain(SoundKind::jaw_knock, 0.5));
  }

  TEST_CASE("a rattle is heard as one: its knocks die away, each softer than the one before") {
    const auto shot = test::load_clean(kRattle, "rattle");
    const std::vector<SoundCue> knocks = cues_of(*shot, SoundKind::jaw_knock);
    REQUIRE(knocks.size() >= 4);
    // One rattle: each knock within kRattleGap of the one before, on the same pocket's jaws.
    for (std::size_t k = 1; k < knocks.size(); ++k) REQUIRE(knocks[k].time - knocks[k - 1].time <= kRattleGap);
    // The physics' second knock is harder than its first; the rattle's is still softer.
    REQUIRE(knocks[1].speed > knocks[0].speed);
    const auto peak_of = [](const SoundCue& c) { return c.level * impact_gain(SoundKind::jaw_knock, c.speed); };
    CHECK(knocks[0].level == 1.0);
    for (std::size_t k = 1; k < knocks.size(); ++k) {
      CAPTURE(k);
      CHECK(peak_of(knocks[k]) <= kRattleFollow * peak_of(knocks[k - 1]) * (1 + 1e-12));
      CHECK(knocks[k].level <= 1.0);
      CHECK((knocks[k].seed >> 32) == (knocks[0].seed >> 32));  // one pocket's modes
      CHECK(knocks[k].seed != knocks[k - 1].seed);              // each its own tick
    }
    // Mixed as they come, before the room and the level stage: each knock's peak on the track under
    // the one before it, though the second is the harder hit.
    AudioBuffer audio = silence(shot->timeline.duration());
    std::vector<SoundCue> placed = knocks;
    for (SoundCue& c : placed) c.pan = 0, c.gain = 1;
    mix_cues(placed, shot->scene.physics, 0, audio);
    double previous = 1e9;
    for (const SoundCue& c : placed) {
      const double p = peak(audio, c.time, c.time + 0.003);
      CAPTURE(c.time);
      CHECK(p < previous);
      previous = p;
    }
  }

  TEST_CASE("each ball's rattle is its own, and a knock long after the last starts afresh") {
    const auto shot = test::load_clean(kTwoRattles, "two rattles");
    std::vector<const Event*> jaws;
    for (const Event& e : shot->timeline.events())
      if (e.type == EventType::ball_jaw) jaws.push_back(&e);
    // The 1's two knocks, then the cue ball's two, the second 0.77 s after the first.
    REQUIRE(jaws.size() == 4);
    REQUIRE(jaws[0]->balls[0] == 1);
    REQUIRE(jaws[1]->balls[0] == 1);
    REQUIRE(jaws[2]->balls[0] == 0);
    REQUIRE(jaws[3]->balls[0] == 0);
    REQUIRE(jaws[3]->time - jaws[2]->time > kRattleGap);
    const std::vector<SoundCue> knocks = cues_of(*shot, SoundKind::jaw_knock);
    REQUIRE(knocks.size() == 4);
    CHECK(knocks[0].level == 1.0);
    CHECK(knocks[1].level < 1.0);   // the 1's rattle goes on
    CHECK(knocks[2].level == 1.0);  // the cue ball's first knock: its own
    CHECK(knocks[3].level == 1.0);  // 0.77 s later: a knock of its own, not the rattle's tail
  }
}
