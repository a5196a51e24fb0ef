#include "spelling.h"

#include <algorithm>

namespace bsim {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Three rows of the dynamic programme: the one before the previous is needed for swaps.
  const std::size_t n = b.size();
  std::vector<std::size_t> before(n + 1), previous(n + 1), current(n + 1);
  for (std::size_t j = 0; j <= n; ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= n; ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        current[j] = std::min(current[j], before[j - 2] + 1);
    }
    std::swap(before, previous);
    std::swap(previous, current);
  }
  return previous[n];
}

namespace {

/// The same letters but for case (ASCII).
bool same_but_case(std::string_view a, std::string_view b) {
  auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [&](char x, char y) { return lower(x) == lower(y); });
}

}  // namespace

std::optional<std::string> closest_word(std::string_view word, const std::vector<std::string_view>& known) {
  if (std::find(known.begin(), known.end(), word) != known.end()) return std::nullopt;
  for (std::string_view candidate : known)
    if (same_but_case(word, candidate)) return std::string(candidate);
  constexpr std::size_t kMaxEdits = 2;
  std::optional<std::string> best;
  std::size_t best_distance = kMaxEdits + 1;
  for (std::string_view candidate : known) {
    const std::size_t d = edit_distance(word, candidate);
    if (d == 0) return std::nullopt;
    if (d < best_distance && 2 * d < word.size()) {
      best = std::string(candidate);
      best_distance = d;
    }
  }
  return best;
}

std::string did_you_mean(std::string_view word, const std::vector<std::string_view>& known, std::string_view what) {
  const std::optional<std::string> best = closest_word(word, known);
  if (!best) return std::string();
  const bool lower = std::none_of(best->begin(), best->end(), [](char c) { return c >= 'A' && c <= 'Z'; });
  const std::string case_note =
      same_but_case(word, *best) ? (lower ? " (" + std::string(what) + " are lower case)" : " (case matters)") : "";
  return "; did you mean '" + *best + "'?" + case_note;
}

}  // namespace bsim
