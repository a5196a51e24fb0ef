// A misspelt word of an option's value gets the closest word the option takes, as misspelt options
// and scene keywords do: --camera autoo, --quality Draft, --overlay path.
#include <doctest/doctest.h>

#include <string>

#include "option_rejection.h"

using bsim::test::export_rejection;
using bsim::test::preview_rejection;

TEST_SUITE("option values") {
  TEST_CASE("--camera, in both programs") {
    const std::string message = export_rejection({"--camera", "autoo"});
    CHECK(message ==
          "bad value 'autoo' for --camera: expected auto (the automatic director's script) or scene (the scene's "
          "own); did you mean 'auto'?");
    CHECK(preview_rejection({"--camera", "autoo"}) == message);
    CHECK(export_rejection({"--camera=Scene"}).ends_with("; did you mean 'scene'? (words are lower case)"));
  }

  TEST_CASE("a value from a row's own words") {
    CHECK(export_rejection({"--quality", "finl"}).ends_with("; did you mean 'final'?"));
    CHECK(export_rejection({"--quality", "Draft"}).ends_with("; did you mean 'draft'? (words are lower case)"));
    CHECK(preview_rejection({"--overlay", "path"}).ends_with("; did you mean 'paths'?"));
    // In a list, the first word that is not one of them.
    CHECK(preview_rejection({"--overlay", "paths,tabel"}).ends_with("; did you mean 'table'?"));
  }

  TEST_CASE("nothing close: no suggestion") {
    CHECK(export_rejection({"--quality", "ultra"}).find("did you mean") == std::string::npos);
    CHECK(preview_rejection({"--overlay", "everything"}).find("did you mean") == std::string::npos);
  }
}
