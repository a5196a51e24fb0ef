#pragma once
// Slurm's client programs as a farm run uses them (sbatch, squeue, scancel): run with their output
// captured, and their answers read.
#include <string>
#include <vector>

#include "farm_files.h"

namespace bsim::farm {

/// Runs argv (argv[0] a full path), its standard output and error together in `output` (by way of a
/// file in $TMPDIR, else /tmp); true when it exited with status 0.
bool run_captured(const std::vector<std::string>& argv, std::string& output, std::string& error);

/// The job ids of `conf` still in the queue (empty when squeue is missing or knows none of them).
std::string jobs_in_queue(const std::string& squeue, const FarmConf& conf);

/// The job id sbatch --parsable printed: its last line's digits before any ';cluster'.
std::string job_id(const std::string& output);

}  // namespace bsim::farm
