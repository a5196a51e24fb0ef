// PLACEHOLDER until the sound track lands.
#include "soundtrack.h"
namespace bsim {
bool mix_soundtrack(const Shot&, const SoundOptions&, std::size_t, AudioBuffer&, std::string& error) {
  error = "sound is not built yet";
  return false;
}
bool write_wav(const std::string&, const AudioBuffer&, std::string& error) {
  error = "sound is not built yet";
  return false;
}
}  // namespace bsim
