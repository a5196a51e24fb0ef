#include "preview_options.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <set>
#include <string_view>

#include "command_line.h"

namespace bsim {

namespace {

constexpr const char* kUsageHead = R"(usage: billiards-preview [SCENE] [options]

Shows SCENE (default: the built-in break) as the scene's camera sees it. With no output option it
opens the interactive window; otherwise it writes one picture or the animatic and exits.

options:
)";

constexpr const char* kUsageTail = R"(
exit status: 0 done, 1 bad scene or failed run, 2 bad command line
)";

bool bad(std::string& message, const std::string& name, const std::string& text, const std::string& expected) {
  message = bad_value_message(name, text, expected);
  return false;
}

/// What a file option does: a value that is not empty stored in `to`.
auto store_file(std::optional<std::string>& to, const char* expected = "a file") {
  return [&to, expected](const std::string& name, const std::string& v, std::string& m) {
    if (v.empty()) return bad(m, name, v, expected);
    to = v;
    return true;
  };
}

bool parse_time(const std::string& text, TimeSpec& at) {
  if (text.starts_with("event:")) {
    const auto n = parse_int_option(std::string_view(text).substr(6), 0, 65535);
    if (!n) return false;
    at = {0, *n};
    return true;
  }
  if (text.starts_with("shot:")) {
    const auto k = parse_int_option(std::string_view(text).substr(5), 1, 65535);
    if (!k) return false;
    at = {0, -1, *k};
    return true;
  }
  const auto seconds = parse_real_option(text);
  if (!seconds || *seconds < 0) return false;
  at = {*seconds, -1};
  return true;
}

/// --overlay's names, in the order of the flags below.
constexpr std::string_view kOverlayNames = "paths|events|camera|table|aim";

bool parse_overlays(const std::string& text, PreviewOverlays& overlays) {
  std::string_view rest = text;
  if (rest.empty()) return false;
  bool PreviewOverlays::*const flags[] = {&PreviewOverlays::paths, &PreviewOverlays::events, &PreviewOverlays::camera,
                                          &PreviewOverlays::table, &PreviewOverlays::aim};
  while (true) {
    const auto comma = rest.find(',');
    const auto index = choice_index(kOverlayNames, rest.substr(0, comma));
    if (!index) return false;
    overlays.*flags[*index] = true;
    if (comma == std::string_view::npos) return true;
    rest.remove_prefix(comma + 1);
  }
}

/// Whether `path` ends in `extension` (".png"), in any case.
bool has_extension(std::string_view path, std::string_view extension) {
  if (path.size() <= extension.size()) return false;
  const std::string_view end = path.substr(path.size() - extension.size());
  return std::equal(end.begin(), end.end(), extension.begin(), [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
  });
}

/// The file each --at writes: -o itself, DIR/at_LABEL.png, or the pattern with %t replaced by LABEL.
bool name_pictures(PreviewOptions& o, std::string& message) {
  const std::string& out = *o.output;
  std::error_code ignored;
  const bool directory = out.ends_with('/') || std::filesystem::is_directory(out, ignored);
  const bool pattern = !directory && out.find("%t") != std::string::npos;
  if (directory) {
    o.picture_dir = out;
    for (const TimeSpec& at : o.at)
      o.pictures.push_back(out + (out.ends_with('/') ? "" : "/") + "at_" + time_label(at) + ".png");
  } else if (pattern) {
    if (!has_extension(out, ".png")) {
      message = bad_value_message("-o", out, "a name ending in .png (e.g. shot_%t.png)");
      return false;
    }
    for (const TimeSpec& at : o.at) {
      std::string name = out;
      for (auto p = name.find("%t"); p != std::string::npos; p = name.find("%t", p)) {
        name.replace(p, 2, time_label(at));
        p += time_label(at).size();
      }
      o.pictures.push_back(name);
    }
  } else if (o.at.size() > 1) {
    message =
        "several --at write one picture each: -o needs a directory (e.g. shots/) or a name with %t (e.g. "
        "shot_%t.png), found '" +
        out + "'";
    return false;
  } else if (!has_extension(out, ".png")) {
    message = bad_value_message("-o", out, "a file name ending in .png (or, for --at, a directory or a name with %t)");
    return false;
  } else {
    o.pictures.push_back(out);
  }
  std::set<std::string> seen;
  for (const std::string& picture : o.pictures)
    if (!seen.insert(picture).second) {
      message = "two --at times would both write '" + picture + "'; give each time once";
      return false;
    }
  return true;
}

/// Options that only make sense together (or apart), and the extensions of the files they write.
bool check_combination(PreviewOptions& o, std::string& message) {
  if (o.write_camera && !o.camera_given) o.auto_camera = true;  // the script written is the one filmed
  const bool at = !o.at.empty();
  if (at && o.timeline)
    message = "--at and --timeline each write one picture; give only one";
  else if (o.movie && (at || o.timeline))
    message = "--movie cannot be combined with --at or --timeline";
  else if ((at || o.timeline) && !o.output)
    message = std::string(at ? "--at" : "--timeline") + " needs -o FILE.png";
  else if (o.output && !at && !o.timeline)
    message = "-o names the picture of --at or --timeline; give one of them";
  else if (o.write_camera && o.camera_given && !o.auto_camera)
    message = "--write-camera writes the automatic director's script, which --camera scene turns off";
  else if ((o.screenshot || o.quit_after > 0) && (at || o.timeline || o.movie || o.write_camera || o.write_scene))
    message = std::string(o.screenshot ? "--screenshot" : "--quit-after") + " is for the interactive window only";
  else if (o.fps_given && (at || o.timeline))
    message = std::string("--fps does nothing with ") + (at ? "--at" : "--timeline") +
              " (it draws instants, not frames); leave one of them out";
  else if (o.overlays.any() && o.timeline)
    message = "--overlay does nothing with --timeline (it draws no view of the table); leave one of them out";
  else if ((o.write_camera || o.write_scene) && !at && !o.timeline && !o.movie &&
           (o.fps_given || o.size_given || o.overlays.any()))
    message = std::string(o.fps_given    ? "--fps"
                          : o.size_given ? "--size"
                                         : "--overlay") +
              " does nothing with " + (o.write_camera ? "--write-camera" : "--write-scene") +
              " alone (it writes text); leave one of them out";
  else if (o.movie && !has_extension(*o.movie, ".mp4"))
    message = bad_value_message("--movie", *o.movie, "a file name ending in .mp4");
  else if (o.timeline && !has_extension(*o.output, ".png"))
    message = bad_value_message("-o", *o.output, "a file name ending in .png");
  else if (at)
    return name_pictures(o, message);
  return message.empty();
}

}  // namespace

OptionTable preview_option_table(PreviewOptions& o) {
  using S = const std::string&;
  return {
      {"--at", "SECONDS|event:N|shot:K",
       "write the frame at this time, at the instant of event N, or at shot K's\n"
       "strike (needs -o); give it several times for one picture per time",
       [&o](S n, S v, std::string& m) {
         TimeSpec at;
         if (!parse_time(v, at))
           return bad(m, n, v, "seconds from 0 (e.g. 2.5), event:N (e.g. event:3) or shot:K from 1 (e.g. shot:2)");
         o.at.push_back(at);
         return true;
       }},
      {"--timeline", "", "write the timeline of events and camera interpolation windows (needs -o)",
       [&o](S, S, std::string&) { return o.timeline = true; }},
      {"-o, --output", "FILE.png",
       "the picture --at or --timeline writes; for several --at, a directory\n"
       "(DIR/: pictures at_2.500.png, at_event_3.png, at_shot_2.png) or a name\n"
       "with %t (shot_%t.png: shot_2.500.png, shot_event_3.png)",
       store_file(o.output)},
      {"--movie", "FILE.mp4", "write the animatic: the whole shot at preview quality", store_file(o.movie)},
      {"--size",
       "WxH",
       "picture, animatic or window size in pixels (default: 1280x720)\n"
       "without --size the window's picture is smaller if need be, to fit the screen",
       {}},
      {"--fps", "N", "animatic frames per second, 1 to 1000 (default: 30)", {}},
      {"--overlay", "LIST",
       "draw extras, comma-separated: paths, events, camera, table\n"
       "(the rails' and balls' numbers, the pockets' names), aim (for 'cue I pot B P': the\n"
       "ghost ball, the aim line, the ball's path to the pocket) (default: none)",
       [&o](S n, S v, std::string& m) {
         if (!parse_overlays(v, o.overlays))
           return bad(m, n, v, "a comma-separated list of paths, events, camera, table, aim");
         return true;
       },
       true, kOverlayNames},
      {"--strict", "", kStrictHelp, {}},
      {"--quiet", "", "print no progress or closing lines (errors and warnings still print)", {}},
      {"--camera",
       kCameraChoices,
       "auto: film with the automatic director's camera script instead of the\nscene's own (default: scene)",
       {}},
      replay_option_row(o.replay),
      {"--write-camera", "FILE",
       "write the automatic director's camera script as scene text (camera ...\n"
       "endcamera) to FILE, or to standard output for -; implies --camera auto",
       store_file(o.write_camera, "a file, or - for standard output")},
      {"--write-scene", "FILE",
       "write the scene with every 'cue I pot B P' resolved to the heading found\n"
       "(and the struck ball's velocity and spin turned to it) to FILE, or to\n"
       "standard output for -",
       store_file(o.write_scene, "a file, or - for standard output")},
      {"--quit-after", "SECONDS", "interactive: close the window after this long (default: stay open)",
       [&o](S n, S v, std::string& m) {
         const auto seconds = parse_real_option(v);
         if (!seconds || *seconds <= 0) return bad(m, n, v, "seconds greater than 0");
         o.quit_after = *seconds;
         return true;
       }},
      {"--screenshot", "FILE.png", "interactive: save the last frame shown when the window closes",
       store_file(o.screenshot)},
      {"-h, --help", "", "show this help and exit", {}},
      {"--version", "", "show the version and exit", {}},
  };
}

std::string time_label(const TimeSpec& at) {
  if (at.event >= 0) return "event_" + std::to_string(at.event);
  if (at.shot >= 1) return "shot_" + std::to_string(at.shot);
  char text[64];
  std::snprintf(text, sizeof text, "%.3f", at.seconds);
  return text;
}

PreviewCommandLineOutcome parse_preview_options(const std::vector<std::string>& args, PreviewOptions& options,
                                                std::string& message) {
  options = PreviewOptions{};
  const OptionTable table = preview_option_table(options);
  const auto apply = [&](ArgReader& reader, std::string& error) { return apply_table_option(reader, table, error); };
  switch (read_arguments(args, options.scene_path, options, usage_text(kUsageHead, table, kUsageTail),
                         "billiards-preview " BSIM_VERSION "\n", apply, message)) {
    case ArgumentsOutcome::exit_success: return PreviewCommandLineOutcome::exit_success;
    case ArgumentsOutcome::exit_usage: return PreviewCommandLineOutcome::exit_usage;
    case ArgumentsOutcome::run: break;
  }
  return check_combination(options, message) ? PreviewCommandLineOutcome::run : PreviewCommandLineOutcome::exit_usage;
}

}  // namespace bsim
