// PLACEHOLDER until staging lands.
#include "output_stage.h"
#include <filesystem>
namespace bsim {
bool OutputStage::open(const std::string& dir, std::string&) {
  destination_ = staging_ = dir;
  std::filesystem::create_directories(dir);
  return open_ = true;
}
std::string OutputStage::path(const std::string& relative) const { return staging_ + "/" + relative; }
bool OutputStage::commit(std::string&) { return true; }
void OutputStage::discard() {}
OutputStage::~OutputStage() = default;
}  // namespace bsim
