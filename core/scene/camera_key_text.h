#pragma once
// Camera keys as scene text: the words a key is written with, the shape of each kind (an ordinal
// before it, the balls or seconds after it), writing a key (format) and reading one back (parse).
// The scene parser reads keys with these words and shapes; the director and the preview write
// theirs with camera_key_text(). Where a key falls in a simulated shot, and which key names a
// moment, is the script's (script/camera_moment.h).
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene.h"

namespace bsim {

/// The kind a key's word names ("start", "hit", ...; "drop" and its older spelling "pocket" both name
/// CameraKeyKind::drop); none for any other word, `event` included (an event number is written as the
/// number alone).
std::optional<CameraKeyKind> camera_key_kind(std::string_view word);
/// The word of a kind ("hit", "drop": keys are written with it, never with an older spelling); empty
/// for CameraKeyKind::event.
std::string_view camera_key_word(CameraKeyKind kind);

/// The ordinal a word before `hit`, `cushion` or `jaw` names: 2 for "second" to 5 for "fifth",
/// CameraKey::kLast for "last"; none for any other word.
std::optional<int> camera_key_ordinal(std::string_view word);
/// The word of an ordinal: "" for 1 (the first, written without one), "second" to "fifth", "last".
std::string_view camera_key_ordinal_word(int ordinal);
/// Whether an ordinal word may stand before the kind: hit, cushion and jaw.
bool takes_ordinal(CameraKeyKind kind);
/// The words of the kinds an ordinal may stand before, in the order messages list them: hit, cushion, jaw.
std::vector<std::string_view> camera_key_ordinal_kinds();
/// "a, b or c" (each word between `quote`s: "'hit', 'cushion' or 'jaw'"), for messages.
std::string word_choice(const std::vector<std::string_view>& words, std::string_view quote);
/// How many ball indices follow the kind's word: 2 for hit, 1 for cushion, jaw and drop, else 0.
int ball_operands(CameraKeyKind kind);
/// Whether seconds follow the kind's word: at.
bool takes_seconds(CameraKeyKind kind);

/// The word before a shot number that makes a key count within that shot: `shot 2 cue`.
inline constexpr std::string_view kShotWord = "shot";

/// Every word a key may start with: the kinds' words, the older "pocket", then the ordinals, then kShotWord.
std::vector<std::string_view> camera_key_first_words();
/// The keys for a message: "start, cue, end, hit, cushion, jaw, drop, at ('pocket I' is ...), with second, ...".
std::string camera_key_list();

/// A key as it is written after `event`: "start", "second hit 0 5", "last cushion 3", "jaw 2", "at 1.5" (its
/// seconds as the shortest text that reads back exactly), "shot 2 cue" (a key with a shot, its number
/// from 1); an event number (kind event) as `event` ("7", "65535").
std::string camera_key_text(const CameraKey& key, int event = 0);
/// The same with each ball index written by `ball` (a label's "5 (8)", the painted number beside it).
std::string camera_key_text(const CameraKey& key, int event, const std::function<std::string(int)>& ball);

/// A key read back from camera_key_text()'s form (words separated by single spaces, numbers as
/// decimal integers and C numbers). An event number gives kind event with the number in `*event`.
/// None when the text is no key. No source locations.
std::optional<CameraKey> parse_camera_key(std::string_view text, int* event = nullptr);

/// Whether two keys are written the same (the same kind, shot, ordinal, balls and seconds as their kind
/// takes; not where they were written). Event numbers are not part of a key: compare them beside it.
bool same_camera_key(const CameraKey& a, const CameraKey& b);

}  // namespace bsim
