#include "camera_key_text.h"

#include <algorithm>
#include <charconv>
#include <iterator>

#include "number_format.h"

namespace bsim {

namespace {

struct KindWord {
  CameraKeyKind kind;
  std::string_view word;
};

/// The kinds in the order messages list them.
constexpr KindWord kKindWords[] = {{CameraKeyKind::start, "start"},     {CameraKeyKind::cue, "cue"},
                                   {CameraKeyKind::end, "end"},         {CameraKeyKind::hit, "hit"},
                                   {CameraKeyKind::cushion, "cushion"}, {CameraKeyKind::jaw, "jaw"},
                                   {CameraKeyKind::drop, "drop"},       {CameraKeyKind::at, "at"}};

/// The older spelling of `drop I`, read as it and never written: `pocket I` (a ball I, not a pocket).
constexpr KindWord kOlderDropWord = {CameraKeyKind::drop, "pocket"};

/// The ordinals that pick a later hit, cushion or jaw contact: `second` is 2, ..., `fifth` 5; `last` the last.
constexpr std::string_view kOrdinalWords[] = {"second", "third", "fourth", "fifth", "last"};

template <class Number>
bool read_number(std::string_view text, Number& out) {
  if (text.empty()) return false;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && end == text.data() + text.size();
}

std::vector<std::string_view> split_words(std::string_view text) {
  std::vector<std::string_view> words;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t space = std::min(text.find(' ', start), text.size());
    words.push_back(text.substr(start, space - start));
    start = space + 1;
  }
  return words;
}

}  // namespace

std::optional<CameraKeyKind> camera_key_kind(std::string_view word) {
  for (const KindWord& k : kKindWords)
    if (k.word == word) return k.kind;
  if (word == kOlderDropWord.word) return kOlderDropWord.kind;
  return std::nullopt;
}

std::string_view camera_key_word(CameraKeyKind kind) {
  for (const KindWord& k : kKindWords)
    if (k.kind == kind) return k.word;
  return {};
}

std::optional<int> camera_key_ordinal(std::string_view word) {
  const auto* o = std::find(std::begin(kOrdinalWords), std::end(kOrdinalWords), word);
  if (o == std::end(kOrdinalWords)) return std::nullopt;
  return word == "last" ? CameraKey::kLast : static_cast<int>(o - std::begin(kOrdinalWords)) + 2;
}

std::string_view camera_key_ordinal_word(int ordinal) {
  if (ordinal == CameraKey::kLast) return "last";
  if (ordinal >= 2 && ordinal <= 5) return kOrdinalWords[ordinal - 2];
  return "";
}

bool takes_ordinal(CameraKeyKind kind) {
  return kind == CameraKeyKind::hit || kind == CameraKeyKind::cushion || kind == CameraKeyKind::jaw;
}

int ball_operands(CameraKeyKind kind) {
  if (kind == CameraKeyKind::hit) return 2;
  return kind == CameraKeyKind::cushion || kind == CameraKeyKind::jaw || kind == CameraKeyKind::drop ? 1 : 0;
}

std::vector<std::string_view> camera_key_ordinal_kinds() {
  std::vector<std::string_view> words;
  for (const KindWord& k : kKindWords)
    if (takes_ordinal(k.kind)) words.push_back(k.word);
  return words;
}

std::string word_choice(const std::vector<std::string_view>& words, std::string_view quote) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i)
    out.append(i == 0 ? "" : (i + 1 == words.size() ? " or " : ", ")).append(quote).append(words[i]).append(quote);
  return out;
}

bool takes_seconds(CameraKeyKind kind) { return kind == CameraKeyKind::at; }

std::vector<std::string_view> camera_key_first_words() {
  std::vector<std::string_view> words;
  for (const KindWord& k : kKindWords) words.push_back(k.word);
  words.push_back(kOlderDropWord.word);
  words.insert(words.end(), std::begin(kOrdinalWords), std::end(kOrdinalWords));
  words.push_back(kShotWord);
  return words;
}

std::string camera_key_list() {
  std::string out;
  for (const KindWord& k : kKindWords) out.append(out.empty() ? "" : ", ").append(k.word);
  return out + " ('pocket I' is the older spelling of 'drop I'), with second, third, fourth, fifth or last before " +
         word_choice(camera_key_ordinal_kinds(), "") + ", and 'shot K' before any";
}

std::string camera_key_text(const CameraKey& key, int event) {
  return camera_key_text(key, event, [](int ball) { return std::to_string(ball); });
}

std::string camera_key_text(const CameraKey& key, int event, const std::function<std::string(int)>& ball) {
  if (key.kind == CameraKeyKind::event) return std::to_string(event);
  std::string text = key.shot >= 0 ? std::string(kShotWord) + " " + std::to_string(key.shot + 1) + " " : "";
  const std::string_view ordinal = takes_ordinal(key.kind) ? camera_key_ordinal_word(key.ordinal) : "";
  if (!ordinal.empty()) text.append(ordinal).append(" ");
  text.append(camera_key_word(key.kind));
  const int balls[] = {key.a, key.b};
  for (int k = 0; k < ball_operands(key.kind); ++k) text += " " + ball(balls[k]);
  if (takes_seconds(key.kind)) text += " " + format_number(key.seconds);
  return text;
}

std::optional<CameraKey> parse_camera_key(std::string_view text, int* event) {
  const std::vector<std::string_view> words = split_words(text);
  CameraKey key;
  std::size_t next = 0;
  if (int n = 0; words.size() == 1 && read_number(words[0], n)) {
    if (n < 0 || n > CameraShot::kLastEvent) return std::nullopt;
    if (event) *event = n;
    return key;
  }
  if (int k = 0; words.size() > 2 && words[0] == kShotWord && read_number(words[1], k)) {
    if (k < 1) return std::nullopt;
    key.shot = k - 1;
    next = 2;
  }
  if (const std::optional<int> ordinal = camera_key_ordinal(words[next])) {
    key.ordinal = *ordinal;
    ++next;
  }
  const std::optional<CameraKeyKind> kind = next < words.size() ? camera_key_kind(words[next++]) : std::nullopt;
  if (!kind || (key.ordinal != 1 && !takes_ordinal(*kind))) return std::nullopt;
  key.kind = *kind;
  const std::size_t operands = static_cast<std::size_t>(ball_operands(key.kind)) + (takes_seconds(key.kind) ? 1 : 0);
  if (words.size() != next + operands) return std::nullopt;
  if (ball_operands(key.kind) >= 1 && !read_number(words[next++], key.a)) return std::nullopt;
  if (ball_operands(key.kind) >= 2 && !read_number(words[next++], key.b)) return std::nullopt;
  if (takes_seconds(key.kind) && !read_number(words[next++], key.seconds)) return std::nullopt;
  return key;
}

bool same_camera_key(const CameraKey& a, const CameraKey& b) {
  if (a.kind != b.kind || a.shot != b.shot) return false;
  if (takes_ordinal(a.kind) && a.ordinal != b.ordinal) return false;
  if (ball_operands(a.kind) >= 1 && a.a != b.a) return false;
  if (ball_operands(a.kind) >= 2 && a.b != b.b) return false;
  return !takes_seconds(a.kind) || a.seconds == b.seconds;
}

}  // namespace bsim
