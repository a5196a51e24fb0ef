#include "export_options.h"

#include "command_line.h"
#include "mastering.h"

namespace bsim {

namespace {

constexpr const char* kUsage = R"(usage: billiards-export [SCENE] [-o DIR] [options]

Simulates SCENE (default: the built-in break) and writes into DIR events.json, trajectory.csv,
camera.csv, the POV-Ray frames, soundtrack.wav, the rendered frames and movie.mp4.

options:
  -o, --output DIR       output directory (default: out/<scene name>)
  --events-only          write only events.json, trajectory.csv and camera.csv
  --no-render            write the .pov frames and soundtrack.wav, but run neither POV-Ray nor ffmpeg
  --fps N                frames per second, 1 to 1000 (default: 30)
  --size WxH             frame size in pixels (default: 1280x720)
  --quality draft|final  POV-Ray quality: draft is fast, final antialiased (default: final)
  --jobs N               POV-Ray processes run in parallel, 1 to 1024 (default: one per core)
  --audio-lead SECONDS   sounds start this long before their event, 0 to 1 (default: 0.005)
  --music FILE           a music file mixed under the sound track (default: none)
  --loudness LUFS|off    the sound track's integrated loudness, -40 to -10, or off (default: -16)
  --strict               accept only the original scene language: no comments, spin, pocket or param
  --quiet                print no progress or closing lines (errors and warnings still print)
  --camera auto|scene    auto: film with the automatic director's camera script instead of the
                         scene's own (default: scene)
  -h, --help             show this help and exit
  --version              show the version and exit

rendering on a Slurm cluster (see README):
  --farm slurm           write the inputs into DIR (on a shared file system) and submit the frames as
                         a job array and the movie as a job that waits for it; print the job ids
  --chunk N              frames a task renders (default: about three minutes of work)
  --sbatch-option ARG    passed to sbatch, e.g. --sbatch-option=--partition=short (repeatable)
  billiards-export DIR --farm status     frames rendered so far and the jobs in the queue
  billiards-export DIR --farm assemble   check every frame and make movie.mp4 (the movie job)
  billiards-export DIR --farm render --frames A-B   render the missing frames A to B (a task)

exit status: 0 done, 1 bad scene or failed run, 2 bad command line
)";

/// One option of this program's own (the shared ones are read by read_arguments); false with
/// `message` set when it is unknown or its value is bad.
bool apply_option(ArgReader& reader, ExportOptions& o, std::string& message) {
  const std::string& name = reader.word();
  auto value = [&]() { return reader.value(message); };
  auto bad = [&](const std::string& text, const std::string& expected) {
    message = bad_value_message(name, text, expected);
    return false;
  };
  if (name == "--events-only") return reader.no_value(message) && (o.events_only = true);
  if (name == "--no-render") return reader.no_value(message) && (o.no_render = true);
  if (name == "-o" || name == "--output") {
    const auto v = value();
    if (!v) return false;
    if (v->empty()) return bad(*v, "a directory");
    o.out_dir = *v;
    return true;
  }
  if (name == "--quality") {
    const auto v = value();
    if (!v) return false;
    if (*v == "draft")
      o.quality = Quality::draft;
    else if (*v == "final")
      o.quality = Quality::final;
    else
      return bad(*v, "draft or final");
    return true;
  }
  if (name == "--jobs") {
    const auto v = value();
    if (!v) return false;
    const auto jobs = parse_int_option(*v, 1, kMaxJobs);
    if (!jobs) return bad(*v, "a number of processes from 1 to " + std::to_string(kMaxJobs));
    o.jobs = *jobs;
    return true;
  }
  if (name == "--audio-lead") {
    const auto v = value();
    if (!v) return false;
    const auto lead = parse_real_option(*v);
    if (!lead || *lead < 0 || *lead > kMaxAudioLead) return bad(*v, "seconds from 0 to 1");
    o.audio_lead = *lead;
    return true;
  }
  if (name == "--music") {
    const auto v = value();
    if (!v) return false;
    if (v->empty()) return bad(*v, "a file");
    o.music_path = *v;
    return true;
  }
  if (name == "--loudness") {
    const auto v = value();
    if (!v) return false;
    if (*v == "off") {
      o.loudness.reset();
      return true;
    }
    const auto lufs = parse_real_option(*v);
    if (!lufs || *lufs < kMinLoudness || *lufs > kMaxLoudness) return bad(*v, "LUFS from -40 to -10, or off");
    o.loudness = *lufs;
    return true;
  }
  if (name == "--farm") {
    const auto v = value();
    if (!v) return false;
    static const std::vector<std::pair<std::string, FarmMode>> modes = {{"slurm", FarmMode::slurm},
                                                                        {"status", FarmMode::status},
                                                                        {"render", FarmMode::render},
                                                                        {"assemble", FarmMode::assemble}};
    for (const auto& [word, mode] : modes)
      if (*v == word) return (o.farm = mode), true;
    return bad(*v, "slurm, status, assemble or render");
  }
  if (name == "--chunk") {
    const auto v = value();
    if (!v) return false;
    const auto chunk = parse_int_option(*v, 1, kMaxFarmChunk);
    if (!chunk) return bad(*v, "a number of frames from 1 to " + std::to_string(kMaxFarmChunk));
    o.chunk = *chunk;
    return true;
  }
  if (name == "--sbatch-option") {
    const auto v = value();
    if (!v) return false;
    if (v->empty()) return bad(*v, "an sbatch option");
    o.sbatch_options.push_back(*v);
    return true;
  }
  if (name == "--frames") {
    const auto v = value();
    if (!v) return false;
    const std::size_t dash = v->find('-');
    const auto first = parse_int_option(v->substr(0, dash), 0, 100000000);
    const auto last = dash == std::string::npos ? first : parse_int_option(v->substr(dash + 1), 0, 100000000);
    if (!first || !last || *last < *first) return bad(*v, "frames FIRST-LAST");
    o.first_frame = *first;
    o.last_frame = *last;
    return true;
  }
  message = unknown_option_message(
      name, {"-o", "--output", "--events-only", "--no-render", "--quality", "--jobs", "--audio-lead", "--music",
             "--loudness", "--farm", "--chunk", "--sbatch-option", "--frames"});
  return false;
}

}  // namespace

CommandLineOutcome parse_export_options(const std::vector<std::string>& args, ExportOptions& options,
                                        std::string& message) {
  options = ExportOptions{};
  options.audio_lead = kDefaultAudioLead;
  options.loudness = kDefaultLoudness;
  const auto apply = [&](ArgReader& reader, std::string& error) { return apply_option(reader, options, error); };
  switch (read_arguments(args, options.scene_path, options, kUsage, "billiards-export " BSIM_VERSION "\n", apply,
                         message)) {
    case ArgumentsOutcome::exit_success: return CommandLineOutcome::exit_success;
    case ArgumentsOutcome::exit_usage: return CommandLineOutcome::exit_usage;
    case ArgumentsOutcome::run: break;
  }
  const bool submit = options.farm == FarmMode::slurm;
  if (!submit && (options.chunk > 0 || !options.sbatch_options.empty()))
    message = std::string(options.chunk > 0 ? "--chunk" : "--sbatch-option") + " needs --farm slurm";
  else if (options.farm != FarmMode::render && options.last_frame >= 0)
    message = "--frames needs --farm render";
  else if (submit && (options.events_only || options.no_render))
    message = std::string("--farm slurm renders on the cluster; it cannot go with ") +
              (options.events_only ? "--events-only" : "--no-render");
  else if (options.farm != FarmMode::none && !submit && !options.scene_path)
    message =
        "--farm status, assemble and render need the farm's output directory, as in `billiards-export DIR "
        "--farm status`";
  if (!message.empty()) return CommandLineOutcome::exit_usage;
  return CommandLineOutcome::run;
}

}  // namespace bsim
