#include "room.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "sound_synth.h"

namespace bsim {

namespace {

/// Paul Kellet's pink-noise filter ("refined" version): white noise through parallel one-pole
/// filters whose sum falls 3 dB per octave within 0.05 dB from 9 Hz up.
class PinkNoise {
 public:
  explicit PinkNoise(std::uint64_t seed) : random_(seed) {}
  double next() {
    const double white = random_.signed_unit();
    b_[0] = 0.99886 * b_[0] + white * 0.0555179;
    b_[1] = 0.99332 * b_[1] + white * 0.0750759;
    b_[2] = 0.96900 * b_[2] + white * 0.1538520;
    b_[3] = 0.86650 * b_[3] + white * 0.3104856;
    b_[4] = 0.55000 * b_[4] + white * 0.5329522;
    b_[5] = -0.7616 * b_[5] - white * 0.0168980;
    const double pink = b_[0] + b_[1] + b_[2] + b_[3] + b_[4] + b_[5] + b_[6] + white * 0.5362;
    b_[6] = white * 0.115926;
    return pink;
  }

 private:
  SoundRandom random_;
  std::array<double, 7> b_{};
};

/// Freeverb's tuning at 44.1 kHz, in samples: the combs, the all-passes, the right channel's offset.
constexpr std::array<int, 8> kCombTuning = {1116, 1188, 1277, 1356, 1422, 1491, 1557, 1617};
constexpr std::array<int, 4> kAllpassTuning = {556, 441, 341, 225};
constexpr int kStereoSpread = 23;
constexpr double kDamping = 0.4;  ///< share of the comb loop's low-pass: highs die sooner
constexpr double kAllpassFeedback = 0.5;

class Comb {
 public:
  Comb(int length, double feedback) : buffer_(static_cast<std::size_t>(length), 0.0), feedback_(feedback) {}
  double process(double input) {
    const double output = buffer_[index_];
    store_ = output * (1 - kDamping) + store_ * kDamping;
    buffer_[index_] = input + store_ * feedback_;
    if (++index_ == buffer_.size()) index_ = 0;
    return output;
  }

 private:
  std::vector<double> buffer_;
  double feedback_;
  double store_ = 0;
  std::size_t index_ = 0;
};

class Allpass {
 public:
  explicit Allpass(int length) : buffer_(static_cast<std::size_t>(length), 0.0) {}
  double process(double input) {
    const double delayed = buffer_[index_];
    buffer_[index_] = input + delayed * kAllpassFeedback;
    if (++index_ == buffer_.size()) index_ = 0;
    return delayed - input;
  }

 private:
  std::vector<double> buffer_;
  std::size_t index_ = 0;
};

/// One channel of the reverberator at `sample_rate`; `spread` lengthens every delay (the right channel).
class Reverberator {
 public:
  Reverberator(int sample_rate, int spread) {
    const double scale = sample_rate / 44100.0;
    for (int tuning : kCombTuning) {
      const int length = static_cast<int>(std::lround((tuning + spread) * scale));
      // Feedback for a 60 dB decay in kReverbTime: g^(T fs / L) = 10^-3.
      combs_.emplace_back(length, std::pow(10.0, -3.0 * length / (kReverbTime * sample_rate)));
    }
    for (int tuning : kAllpassTuning) allpasses_.emplace_back(static_cast<int>(std::lround((tuning + spread) * scale)));
  }
  double process(double input) {
    double sum = 0;
    for (Comb& c : combs_) sum += c.process(input);
    for (Allpass& a : allpasses_) sum = a.process(sum);
    return sum;
  }

 private:
  std::vector<Comb> combs_;
  std::vector<Allpass> allpasses_;
};

/// Runs both channels of the reverberator over `send` (delayed by the pre-delay) and adds
/// `gain` times their output into `out`.
void run_reverb(const std::vector<float>& send, double gain, AudioBuffer& out) {
  Reverberator left(out.sample_rate, 0), right(out.sample_rate, kStereoSpread);
  const auto delay = static_cast<std::size_t>(std::lround(kReverbPreDelay * out.sample_rate));
  const std::size_t n = std::min(out.left.size(), out.right.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double x = i >= delay && i - delay < send.size() ? send[i - delay] : 0.0;
    out.left[i] += static_cast<float>(gain * left.process(x));
    out.right[i] += static_cast<float>(gain * right.process(x));
  }
}

/// The gain that puts the reverberation of a unit impulse kReverbLevelDb under the impulse's energy
/// (the mean of the two channels' energies).
double reverb_gain(int sample_rate) {
  std::vector<float> impulse(static_cast<std::size_t>(sample_rate) * 2, 0.0f);
  impulse[0] = 1.0f;
  AudioBuffer response;
  response.sample_rate = sample_rate;
  response.left.assign(impulse.size(), 0.0f);
  response.right.assign(impulse.size(), 0.0f);
  run_reverb(impulse, 1.0, response);
  double energy = 0;
  for (std::size_t i = 0; i < impulse.size(); ++i)
    energy += 0.5 * (static_cast<double>(response.left[i]) * response.left[i] +
                     static_cast<double>(response.right[i]) * response.right[i]);
  return std::sqrt(std::pow(10.0, kReverbLevelDb / 10) / energy);
}

}  // namespace

AudioBuffer room_tone(std::size_t sample_count, std::uint64_t seed, int sample_rate) {
  AudioBuffer tone;
  tone.sample_rate = sample_rate;
  tone.left.resize(sample_count);
  tone.right.resize(sample_count);
  PinkNoise common(seed), left(seed ^ 0x5bd1e995ULL), right(seed ^ 0x27d4eb2fULL);
  // Second-order roll-off above 2.5 kHz: two one-pole low-passes.
  const double alpha = 1.0 - std::exp(-2 * std::numbers::pi * 2500.0 / sample_rate);
  double l1 = 0, l2 = 0, r1 = 0, r2 = 0;
  double sum = 0;
  for (std::size_t i = 0; i < sample_count; ++i) {
    const double c = 0.45 * common.next();
    l1 += alpha * (c + left.next() - l1);
    l2 += alpha * (l1 - l2);
    r1 += alpha * (c + right.next() - r1);
    r2 += alpha * (r1 - r2);
    tone.left[i] = static_cast<float>(l2);
    tone.right[i] = static_cast<float>(r2);
    sum += 0.5 * (l2 * l2 + r2 * r2);
  }
  if (sample_count == 0 || sum <= 0) return tone;
  const double gain = std::pow(10.0, kRoomToneDb / 20) / std::sqrt(sum / static_cast<double>(sample_count));
  for (std::size_t i = 0; i < sample_count; ++i) {
    tone.left[i] = static_cast<float>(gain * tone.left[i]);
    tone.right[i] = static_cast<float>(gain * tone.right[i]);
  }
  return tone;
}

void add_reverb(const std::vector<float>& send, AudioBuffer& out) {
  static const double gain = reverb_gain(kSampleRate);
  run_reverb(send, out.sample_rate == kSampleRate ? gain : reverb_gain(out.sample_rate), out);
}

}  // namespace bsim
