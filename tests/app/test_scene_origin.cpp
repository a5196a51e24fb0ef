// Where a scene comes from (core/app's scene_file), the one choice both programs make: a file, named
// by its path and its stem, or the built-in break when no scene is given.
#include <doctest/doctest.h>

#include "builtin_scene.h"
#include "scene_file.h"
#include "support.h"

using namespace bsim;

TEST_SUITE("scene origin") {
  TEST_CASE("no path is the built-in break, a path is its file") {
    const SceneOrigin builtin = scene_origin(std::nullopt);
    CHECK_FALSE(builtin.path);
    CHECK(builtin.shown_path == "<built-in break.scn>");
    CHECK(builtin.name == kBuiltinSceneName);
    std::string error;
    CHECK(read_scene_text(builtin, error) == std::string(builtin_scene_text()));

    test::TempDir dir;
    const std::string path = dir.file("corner.scn", "ball 0 0.5 0.5\n");
    const SceneOrigin file = scene_origin(path);
    CHECK(file.path == path);
    CHECK(file.shown_path == path);
    CHECK(file.name == "corner");
    CHECK(read_scene_text(file, error) == "ball 0 0.5 0.5\n");

    const std::string missing = (dir.path / "missing.scn").string();
    CHECK_FALSE(read_scene_text(scene_origin(missing), error));
    CHECK(error == missing + ": error: cannot read the scene file: No such file or directory");
  }
}
