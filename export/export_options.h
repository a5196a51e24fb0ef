#pragma once
// The command line of billiards-export (see README and --help).
#include <optional>
#include <string>
#include <vector>

#include "command_line.h"
#include "mastering.h"

namespace bsim {

enum class Quality { draft, final };

/// The preset's name as the command line spells it.
inline const char* quality_name(Quality quality) { return quality == Quality::final ? "final" : "draft"; }

/// --farm: render on a Slurm cluster (see farm_slurm.h); `none` renders here.
enum class FarmMode { none, slurm, status, render, assemble };

/// s: how long before its event each sound starts, unless --audio-lead says otherwise.
inline constexpr double kDefaultAudioLead = 0.005;
inline constexpr double kMaxAudioLead = 1.0;  ///< s
/// LUFS: the loudness --loudness accepts.
inline constexpr double kMinLoudness = -40.0;
inline constexpr double kMaxLoudness = -10.0;
inline constexpr int kMaxJobs = 1024;
inline constexpr int kMaxFarmChunk = 100000;  ///< frames

/// fps, width, height and strict are the options both programs share (SharedOptions).
struct ExportOptions : SharedOptions {
  std::optional<std::string> scene_path;  ///< none: the built-in break
  std::optional<std::string> out_dir;     ///< none: out/<scene name>
  bool events_only = false;
  bool no_render = false;
  Quality quality = Quality::final;
  int jobs = 0;               ///< 0: one per core
  bool whole_frames = false;  ///< --whole-frames: trace every pixel of every frame
  bool captions = true;       ///< --captions: a game's movie has captions
  double audio_lead = 0.0;    ///< s; set to the documented default by the parser
  std::string music_path;
  SoundLevel level;    ///< how the sound track's level is set (default: calibrated)
  bool replay = true;  ///< --replay off: a game's movie ends with the game, without its winning shot again
  FarmMode farm = FarmMode::none;
  int chunk = 0;                            ///< --chunk: frames a farm task renders; 0: chosen from size and quality
  std::vector<std::string> sbatch_options;  ///< --sbatch-option, in order
  int first_frame = 0, last_frame = -1;     ///< --frames A-B (--farm render)
  std::vector<std::string> given;           ///< set by the parser: the program's own options given, as typed
};

/// The program's option table (command_line.h): every option in --help's order, with what it does
/// to `options`; it drives the dispatch, the usage and the "did you mean" suggestions.
OptionTable export_option_table(ExportOptions& options);

enum class CommandLineOutcome { run, exit_success, exit_usage };

/// Parses argv[1..]. On exit_success (--help, --version) `message` is what to print on stdout;
/// on exit_usage `message` is the one-line reason for stderr (exit 2).
CommandLineOutcome parse_export_options(const std::vector<std::string>& args, ExportOptions& options,
                                        std::string& message);

}  // namespace bsim
