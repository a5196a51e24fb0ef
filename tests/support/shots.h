#pragma once
// Loading a scene text into a Shot inside a test case.
#include <memory>
#include <string_view>

#include "shot.h"

namespace bsim::test {

/// The shot of `text`; fails the test case, listing every diagnostic, if it does not load.
/// Warnings are allowed.
std::unique_ptr<Shot> load_scene(std::string_view text, std::string_view name = "test");

/// As load_scene, but any diagnostic at all, a warning too, fails the test case.
std::unique_ptr<Shot> load_clean(std::string_view text, std::string_view name = "test");

}  // namespace bsim::test
