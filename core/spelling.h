#pragma once
// "Did you mean ...?": the closest known word to a misspelled one, for the scene parser and both
// command lines.
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bsim {

/// The number of single-character insertions, deletions, substitutions and swaps of two neighbours
/// that turn `a` into `b` (the optimal string alignment distance). Compares bytes, case-sensitive.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The known word closest to `word` when it is a likely misspelling: one that differs from it only in
/// case (ASCII), else one at most 2 edits away and fewer edits than half the length of `word`. The
/// first of equally close words wins; none when `word` is itself known or nothing is close enough.
std::optional<std::string> closest_word(std::string_view word, const std::vector<std::string_view>& known);

/// "; did you mean 'WORD'?" for the closest known word, or "" when there is none. When the two differ
/// only in case it adds "(WHAT are lower case)" ("(case matters)" for a known word with capitals).
std::string did_you_mean(std::string_view word, const std::vector<std::string_view>& known,
                         std::string_view what = "words");

}  // namespace bsim
