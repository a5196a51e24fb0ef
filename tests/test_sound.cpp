// The sound track: each sound starts at its event, louder for faster hits, on the side of the
// picture where it happens, exactly as long as the shot, the same bytes every time.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "fixtures.h"
#include "music_bed.h"
#include "shot.h"
#include "shots.h"
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

}  // namespace

TEST_SUITE("sound") {
  TEST_CASE("a Hertz contact is shorter the faster the balls meet (about 460, 350, 290 us at 0.5, 2, 5 m/s)") {
    const PhysicsParams physics;
    CHECK(hertz_contact_time(physics, 0.5) == doctest::Approx(461e-6).epsilon(0.03));
    CHECK(hertz_contact_time(physics, 2.0) == doctest::Approx(349e-6).epsilon(0.03));
    CHECK(hertz_contact_time(physics, 5.0) == doctest::Approx(291e-6).epsilon(0.03));
  }

  TEST_CASE("every kind of sound gets louder with speed, and its peak is its gain") {
    const PhysicsParams physics;
    for (SoundKind kind : {SoundKind::ball_ball, SoundKind::ball_rail, SoundKind::cue, SoundKind::pocket}) {
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
    const std::vector<SoundCue> cues = {{SoundKind::cue, 0.3, 2.0, 0, 1},
                                        {SoundKind::ball_ball, 0.61, 1.0, 0, 2},
                                        {SoundKind::ball_rail, 1.02, 0.5, 0, 3},
                                        {SoundKind::pocket, 1.5, 0.8, 0, 4}};
    for (double lead : {0.0, 0.005, 0.03}) {
      CAPTURE(lead);
      AudioBuffer audio = silence(2.2);
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
    AudioBuffer audio;
    std::string error;
    REQUIRE(mix_soundtrack({shot->scene, shot->timeline, *shot->camera}, {}, samples, audio, error));
    CHECK(audio.left.size() == samples);
    CHECK(audio.right.size() == samples);

    const double loudest = peak(audio, 0, duration);
    CHECK(loudest > 0.05);
    CHECK(loudest <= 0.9);
    double previous_hit = -1;
    bool rail_seen = false;
    for (const Event& e : shot->timeline.events()) {
      if (e.type != EventType::cue && e.type != EventType::ball_ball && e.type != EventType::ball_rail) continue;
      CAPTURE(e.index);
      CAPTURE(e.time);
      // A hit right after another can hide in its ring; the shot's hits are far apart but for that.
      if (previous_hit < 0 || e.time - previous_hit > 0.06) {
        CHECK(std::abs(onset_near(audio, e.time) - e.time) <= 0.002);
        CHECK(peak(audio, e.time, e.time + 0.006) > 4 * peak(audio, e.time - 0.012, e.time - 0.003));
      }
      if (e.type == EventType::ball_rail && e.rail == 2 && !rail_seen) {  // the right-hand cushion
        rail_seen = true;
        CHECK(energy(audio.right, e.time, e.time + 0.05) > energy(audio.left, e.time, e.time + 0.05));
      }
      previous_hit = e.time;
    }
    CHECK(rail_seen);

    AudioBuffer again;
    REQUIRE(mix_soundtrack({shot->scene, shot->timeline, *shot->camera}, {}, samples, again, error));
    CHECK(again.left == audio.left);
    CHECK(again.right == audio.right);
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
    CHECK(peak(music, 0, 2) == doctest::Approx(kMusicLevel).epsilon(0.01));
    CHECK(peak(music, 1.2, 1.3) > 0.5 * kMusicLevel);  // the half-second tone plays on, looped

    REQUIRE(load_music_bed(path, kSampleRate / 10, music, error));  // longer than the shot: trimmed
    CHECK(music.left.size() == static_cast<std::size_t>(kSampleRate / 10));

    CHECK_FALSE(load_music_bed((dir.path / "none.ogg").string(), 100, music, error));
    CHECK(error.find("none.ogg") != std::string::npos);
  }
}
