// The test runner: doctest's, with the rendered-frame store (BSIM_CACHE_DIR) in a directory of this
// process's own, so the tests neither read nor fill the user's store and each run starts empty.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdlib>

#include "support.h"

int main(int argc, char** argv) {
  const bsim::test::TempDir store;
  setenv("BSIM_CACHE_DIR", (store.path / "frames").c_str(), 1);
  return doctest::Context(argc, argv).run();
}
