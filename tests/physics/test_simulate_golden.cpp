// Golden events.json for the scenes in scenes/: a change in the physics that moves any event shows
// here. Each tests/golden/events/NAME.json is compared with a fresh simulation of scenes/NAME.scn,
// and every scene must have one. Regenerate them (and add new scenes) after an intended change with:
//   BSIM_UPDATE_GOLDENS=1 build/bin/bsim_tests
#include <doctest/doctest.h>

#include <filesystem>
#include <set>
#include <sstream>

#include "files.h"
#include "golden.h"
#include "outputs.h"
#include "shot.h"
#include "support.h"

using namespace bsim;
namespace fs = std::filesystem;

namespace {

const fs::path kScenes = test::source_path("scenes");

/// events.json of scenes/NAME.scn, or an empty string with the diagnostics in `why` if it does not load.
std::string simulate_scene(const std::string& name, std::string& why) {
  const ShotResult loaded = load_shot(test::require_file(kScenes / (name + ".scn")), name);
  if (!loaded.shot) {
    for (const Diagnostic& d : loaded.diagnostics) why += format_diagnostic(d, name + ".scn") + "\n";
    return "";
  }
  std::ostringstream out;
  write_events_json(*loaded.shot, out);
  return out.str();
}

/// The stems of the files in `dir` ending in `extension`, sorted.
std::set<std::string> stems(const fs::path& dir, const std::string& extension) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == extension) names.insert(entry.path().stem().string());
  return names;
}

}  // namespace

TEST_SUITE("simulate: golden") {
  TEST_CASE("every scene has a golden events.json and matches it, byte for byte") {
    const std::set<std::string> scenes = stems(kScenes, ".scn");
    REQUIRE_FALSE(scenes.empty());
    for (const std::string& name : scenes) {
      CAPTURE(name);
      std::string why;
      const std::string json = simulate_scene(name, why);
      INFO(why);
      CHECK_FALSE(json.empty());
      if (!json.empty()) test::check_golden_text(test::golden_path("events", name + ".json"), json);
    }
    // A golden file whose scene is gone would be compared with nothing.
    for (const std::string& name : stems(test::golden_path("events", ""), ".json"))
      CHECK_MESSAGE(scenes.count(name) == 1, "tests/golden/events/" << name << ".json has no scenes/" << name
                                                                    << ".scn: remove it or restore the scene");
  }
}
