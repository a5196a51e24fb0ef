#include "preview_options.h"

#include <algorithm>
#include <string_view>

#include "command_line.h"

namespace bsim {

namespace {

constexpr const char* kUsage = R"(usage: billiards-preview [SCENE] [options]

Shows SCENE (default: the built-in break) as the scene's camera sees it. With no output option it
opens the interactive window; otherwise it writes one picture or the animatic and exits.

options:
  --at SECONDS|event:N   write the frame at this time, or at the instant of event N (needs -o)
  --timeline             write the timeline of events and camera interpolation windows (needs -o)
  -o, --output FILE.png  the picture --at or --timeline writes
  --movie FILE.mp4       write the animatic: the whole shot at preview quality
  --size WxH             picture, animatic or window size in pixels (default: 1280x720)
  --fps N                animatic frames per second, 1 to 1000 (default: 30)
  --overlay LIST         draw extras, comma-separated: paths, events, camera (default: none)
  --strict               accept only the original scene language: no comments, spin, pocket or param
  --quiet                print no progress lines (errors and warnings still print)
  --quit-after SECONDS   interactive: close the window after this long (default: stay open)
  --screenshot FILE.png  interactive: save the last frame shown when the window closes
  -h, --help             show this help and exit
  --version              show the version and exit

exit status: 0 done, 1 bad scene or failed run, 2 bad command line
)";

bool parse_time(const std::string& text, TimeSpec& at) {
  if (text.starts_with("event:")) {
    const auto n = parse_int_option(std::string_view(text).substr(6), 0, 65535);
    if (!n) return false;
    at = {0, *n};
    return true;
  }
  const auto seconds = parse_real_option(text);
  if (!seconds || *seconds < 0) return false;
  at = {*seconds, -1};
  return true;
}

bool parse_overlays(const std::string& text, PreviewOverlays& overlays) {
  std::string_view rest = text;
  if (rest.empty()) return false;
  while (true) {
    const auto comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    if (item == "paths")
      overlays.paths = true;
    else if (item == "events")
      overlays.events = true;
    else if (item == "camera")
      overlays.camera = true;
    else
      return false;
    if (comma == std::string_view::npos) return true;
    rest.remove_prefix(comma + 1);
  }
}

bool apply_option(ArgReader& reader, PreviewOptions& o, std::string& message) {
  const std::string& name = reader.word();
  auto bad = [&](const std::string& text, const std::string& expected) {
    message = bad_value_message(name, text, expected);
    return false;
  };
  if (name == "--timeline") return reader.no_value(message) && (o.timeline = true);
  static constexpr std::string_view kWithValue[] = {"--at",      "-o",           "--output",    "--movie",
                                                    "--overlay", "--quit-after", "--screenshot"};
  if (std::find(std::begin(kWithValue), std::end(kWithValue), name) == std::end(kWithValue)) {
    message = unknown_option_message(name);
    return false;
  }
  const auto v = reader.value(message);
  if (!v) return false;
  if (name == "--at") {
    TimeSpec at;
    if (!parse_time(*v, at)) return bad(*v, "seconds from 0 (e.g. 2.5) or event:N (e.g. event:3)");
    o.at = at;
  } else if (name == "-o" || name == "--output") {
    if (v->empty()) return bad(*v, "a file");
    o.output = *v;
  } else if (name == "--movie") {
    if (v->empty()) return bad(*v, "a file");
    o.movie = *v;
  } else if (name == "--overlay") {
    if (!parse_overlays(*v, o.overlays)) return bad(*v, "a comma-separated list of paths, events, camera");
  } else if (name == "--quit-after") {
    const auto seconds = parse_real_option(*v);
    if (!seconds || *seconds <= 0) return bad(*v, "seconds greater than 0");
    o.quit_after = *seconds;
  } else {  // --screenshot
    if (v->empty()) return bad(*v, "a file");
    o.screenshot = *v;
  }
  return true;
}

/// Options that only make sense together (or apart).
bool check_combination(const PreviewOptions& o, std::string& message) {
  const bool at = o.at.has_value();
  if (at && o.timeline)
    message = "--at and --timeline each write one picture; give only one";
  else if (o.movie && (at || o.timeline))
    message = "--movie cannot be combined with --at or --timeline";
  else if ((at || o.timeline) && !o.output)
    message = std::string(at ? "--at" : "--timeline") + " needs -o FILE.png";
  else if (o.output && !at && !o.timeline)
    message = "-o names the picture of --at or --timeline; give one of them";
  else if ((o.screenshot || o.quit_after > 0) && (at || o.timeline || o.movie))
    message = std::string(o.screenshot ? "--screenshot" : "--quit-after") + " is for the interactive window only";
  return message.empty();
}

}  // namespace

PreviewCommandLineOutcome parse_preview_options(const std::vector<std::string>& args, PreviewOptions& options,
                                                std::string& message) {
  options = PreviewOptions{};
  const auto apply = [&](ArgReader& reader, std::string& error) { return apply_option(reader, options, error); };
  switch (read_arguments(args, options.scene_path, options, kUsage, "billiards-preview " BSIM_VERSION "\n", apply,
                         message)) {
    case ArgumentsOutcome::exit_success: return PreviewCommandLineOutcome::exit_success;
    case ArgumentsOutcome::exit_usage: return PreviewCommandLineOutcome::exit_usage;
    case ArgumentsOutcome::run: break;
  }
  return check_combination(options, message) ? PreviewCommandLineOutcome::run : PreviewCommandLineOutcome::exit_usage;
}

}  // namespace bsim
