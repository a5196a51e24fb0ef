// Golden events.json for the scenes in scenes/: a change in the physics that moves any event shows
// here. Each tests/golden/events/NAME.json is compared with a fresh simulation of scenes/NAME.scn.
// Regenerate all of them (and add new scenes) after an intended change with:
//   BSIM_UPDATE_GOLDEN=1 build/bin/bsim_tests --source-file='*test_simulate_golden.cpp'
#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "outputs.h"
#include "shot.h"

using namespace bsim;
namespace fs = std::filesystem;

namespace {

const fs::path kScenes = fs::path(BSIM_SOURCE_DIR) / "scenes";
const fs::path kGolden = fs::path(BSIM_SOURCE_DIR) / "tests" / "golden" / "events";

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// events.json of scenes/NAME.scn, or an empty string with the diagnostics in `why` if it does not load.
std::string simulate_scene(const std::string& name, std::string& why) {
  const ShotResult loaded = load_shot(slurp(kScenes / (name + ".scn")), name);
  if (!loaded.shot) {
    for (const Diagnostic& d : loaded.diagnostics) why += format_diagnostic(d, name + ".scn") + "\n";
    return "";
  }
  std::ostringstream out;
  write_events_json(*loaded.shot, out);
  return out.str();
}

}  // namespace

TEST_SUITE("simulate: golden") {
  TEST_CASE("every golden events.json matches its scene, byte for byte") {
    if (std::getenv("BSIM_UPDATE_GOLDEN")) {
      fs::create_directories(kGolden);
      for (const auto& entry : fs::directory_iterator(kScenes)) {
        if (entry.path().extension() != ".scn") continue;
        const std::string name = entry.path().stem().string();
        std::string why;
        const std::string json = simulate_scene(name, why);
        INFO(why);
        CHECK_FALSE(json.empty());
        if (!json.empty()) std::ofstream(kGolden / (name + ".json"), std::ios::binary) << json;
        MESSAGE("wrote golden events for " << name);
      }
      return;
    }
    int compared = 0;
    for (const auto& entry : fs::directory_iterator(kGolden)) {
      if (entry.path().extension() != ".json") continue;
      const std::string name = entry.path().stem().string();
      CAPTURE(name);
      REQUIRE(fs::exists(kScenes / (name + ".scn")));
      std::string why;
      const std::string json = simulate_scene(name, why);
      INFO(why);
      CHECK(json == slurp(entry.path()));
      ++compared;
    }
    CHECK(compared > 0);
    for (const auto& entry : fs::directory_iterator(kScenes))
      if (entry.path().extension() == ".scn" && !fs::exists(kGolden / (entry.path().stem().string() + ".json")))
        MESSAGE("no golden events for scenes/" << entry.path().filename().string() << " yet: regenerate them");
  }
}
