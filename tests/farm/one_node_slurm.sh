#!/usr/bin/env bash
# `billiards-export --farm slurm` on a real Slurm: starts a one-node cluster on this machine (munged,
# slurmctld and slurmd in the background with a config in a temporary directory, no systemd), renders
# a tiny movie through it (a frame whose .pov is the one before's developed from that trace, with
# its own grain) and compares it byte for byte with a local render; then resubmits after frames went missing, and checks that a frame failing its retries fails the movie job with a message
# naming the frame while the frames done are kept. The daemons it started are stopped by their process
# ids however the test ends.
#   bash tests/farm/one_node_slurm.sh BILLIARDS_EXPORT
# Exits 77 (ctest: skipped) when not root or Slurm is not installed, except in CI (CI=true), where the
# test command installs Slurm and runs as root, so either is a failure.
#
# The same cluster, started to try the farm by hand (README "Rendering on a Slurm cluster"):
#   bash tests/farm/one_node_slurm.sh --start DIR   # leaves the daemons running; DIR/slurm.conf
#   bash tests/farm/one_node_slurm.sh --stop DIR    # cancels its jobs and stops the daemons
set -euo pipefail
export PATH="$PATH:/usr/sbin:/sbin"
mode=test
case "${1:-}" in
  --start | --stop)
    mode=${1#--}
    [ $# -eq 2 ] || { echo "usage: $0 --start|--stop DIR" >&2; exit 2; }
    t=$(realpath -m "$2")
    ;;
  "") echo "usage: $0 BILLIARDS_EXPORT, or $0 --start|--stop DIR" >&2; exit 2 ;;
  *) export_bin=$(realpath "$1") ;;
esac

# Stops the daemon with process id $1: SIGTERM, then SIGKILL after 10 s.
stop_pid() {
  kill -TERM "$1" 2>/dev/null || return 0
  for _ in $(seq 100); do kill -0 "$1" 2>/dev/null || break; sleep 0.1; done
  kill -KILL "$1" 2>/dev/null || true
  wait "$1" 2>/dev/null || true
}
if [ "$mode" = stop ]; then
  [ -f "$t/daemons.pids" ] || { echo "no cluster of this script runs in $t (no daemons.pids)" >&2; exit 1; }
  SLURM_CONF="$t/slurm.conf" timeout 20 scancel --full --user=root >/dev/null 2>&1 || true
  for pid in $(tac "$t/daemons.pids"); do stop_pid "$pid"; done
  rm -f "$t/daemons.pids"
  echo "stopped the one-node Slurm in $t"
  exit 0
fi

skip() {
  if [ "$mode" = start ] || [ "${CI:-}" = true ]; then
    echo "FAIL: $1 (in CI the test command installs slurm-wlm and munge and runs as root)" >&2
    exit 1
  fi
  echo "SKIP: $1" >&2
  exit 77
}
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
[ "$(id -u)" -eq 0 ] || skip "starting slurmd and munged needs root"
for program in munged mungekey slurmctld slurmd sbatch squeue sinfo scontrol scancel; do
  command -v "$program" >/dev/null || skip "$program is not installed (bash .ci/install-deps slurm-wlm munge)"
done
for program in povray ffmpeg; do
  command -v "$program" >/dev/null || fail "$program is not installed (bash .ci/install-deps)"
done

if [ "$mode" = start ]; then
  [ ! -f "$t/daemons.pids" ] || { echo "a cluster already runs in $t: stop it with $0 --stop $t" >&2; exit 1; }
  mkdir -p "$t"
else
  t=$(mktemp -d /tmp/bsim-slurm.XXXXXX)
fi
pids=()
# Starts a daemon in the background and records its process id (in start mode in its own session,
# so that it outlives this script, and in DIR/daemons.pids for --stop).
daemon() {
  local name=$1
  shift
  if [ "$mode" = start ]; then
    setsid "$@" >"$t/$name.out" 2>&1 </dev/null &
  else
    "$@" >"$t/$name.out" 2>&1 &
  fi
  pids+=($!)
  printf '%s\n' "${pids[@]}" >"$t/daemons.pids"
}
cleanup() {
  status=$?
  set +e
  if [ "$mode" = start ] && [ "$status" -eq 0 ]; then
    echo "a one-node Slurm runs in $t; use it with: export SLURM_CONF=$t/slurm.conf"
    echo "stop it with: bash $0 --stop $t"
    exit 0
  fi
  if [ -f "$t/slurm.conf" ] && [ ${#pids[@]} -gt 1 ]; then
    SLURM_CONF="$t/slurm.conf" timeout 20 scancel --full --user=root >/dev/null 2>&1
  fi
  # Stopped in reverse order of start (slurmd, slurmctld, munged), by the ids recorded at start.
  for ((i = ${#pids[@]} - 1; i >= 0; i--)); do stop_pid "${pids[i]}"; done
  rm -f "$t/daemons.pids"
  [ "$mode" = start ] && exit "$status"  # the logs stay in DIR
  if [ "$status" -ne 0 ]; then
    for log in "$t"/*.log "$t"/farm/farm/logs/*.log; do
      [ -f "$log" ] && { echo "---- $log (last lines)"; tail -n 30 "$log"; }
    done
  fi
  rm -rf "$t"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# A free TCP port: one no socket on this machine is bound to (read from /proc/net/tcp*).
free_port() {
  local port hex
  while :; do
    port=$((20000 + RANDOM % 30000))
    hex=$(printf '%04X' "$port")
    if ! cat /proc/net/tcp /proc/net/tcp6 2>/dev/null | awk '{print $2}' | grep -qi ":$hex\$"; then
      echo "$port"
      return
    fi
  done
}

# munge: its own key and socket, so no system munged is needed or disturbed.
mungekey --create --force --keyfile="$t/munge.key"
chmod 600 "$t/munge.key"
daemon munged munged --foreground --force --socket="$t/munge.socket" --key-file="$t/munge.key" \
  --pid-file="$t/munged.pid" --log-file="$t/munged.log" --seed-file="$t/munged.seed"
for _ in $(seq 300); do [ -S "$t/munge.socket" ] && break; sleep 0.1; done
[ -S "$t/munge.socket" ] || fail "munged did not start"

host=$(hostname -s)
cpus=$(nproc)
memory=$(( $(awk '/^MemTotal/ {print $2}' /proc/meminfo) / 1024 / 2 ))
ctld_port=$(free_port)
slurmd_port=$(free_port)
while [ "$slurmd_port" = "$ctld_port" ]; do slurmd_port=$(free_port); done
mkdir -p "$t/state" "$t/spool"
: >"$t/plugstack.conf"
cat >"$t/slurm.conf" <<EOF
ClusterName=bsimtest
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$t/munge.socket
StateSaveLocation=$t/state
SlurmdSpoolDir=$t/spool
SlurmctldPidFile=$t/slurmctld.pid
SlurmdPidFile=$t/slurmd.pid
SlurmctldLogFile=$t/slurmctld.log
SlurmdLogFile=$t/slurmd.log
PlugStackConfig=$t/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
SlurmdParameters=config_overrides
MinJobAge=3600
SlurmctldTimeout=300
SlurmdTimeout=300
NodeName=$host NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=bsim Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$t/slurm.conf"
daemon slurmctld slurmctld -D -c -f "$t/slurm.conf"
daemon slurmd slurmd -D -f "$t/slurm.conf"

echo "waiting for the node to be idle"
state=""
for _ in $(seq 600); do
  state=$(sinfo --noheader --Node --format=%t 2>/dev/null | head -n 1 || true)
  [ "$state" = idle ] && break
  sleep 0.5
done
[ "$state" = idle ] || fail "the Slurm node did not become idle in 5 minutes (state: '$state')"
[ "$mode" = start ] && exit 0

# A short shot (5 s): 10 tiny frames at 2 fps; the balls rest from frame 8 on, so frame 9 is frame 8.
cat >"$t/shot.scn" <<'EOF'
cue 0 0
ball 0 -0.3 0 0.028575  0.15 0 0  1 0 0 0
ball 9  0.2 0.05 0.028575  0 0 0  1 0 0 0
camera
event 0 0 0 hover -1.5 -1.2 1.2  0 0 0
endcamera
EOF
options=(--size 32x18 --fps 2 --quality draft --quiet)
export BSIM_CACHE_DIR=off # every frame really rendered, here and on the farm
"$export_bin" "$t/shot.scn" -o "$t/local" "${options[@]}"

# Submits, prints the movie job's id.
submit() {
  local output
  output=$("$export_bin" "$t/shot.scn" --farm slurm -o "$t/farm" "${options[@]}" "$@") || fail "submit failed"
  echo "$output" >&2
  echo "$output" | sed -n 's/^submitted job \([0-9]*\): checks every frame.*/\1/p'
}
# Waits until job $1 has left the queue's pending and running states (up to 10 minutes), prints its state.
finish() {
  local state=""
  for _ in $(seq 1200); do
    state=$(scontrol show job "$1" 2>/dev/null | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p')
    case "$state" in PENDING | RUNNING | CONFIGURING | COMPLETING | "") sleep 0.5 ;; *) break ;; esac
  done
  echo "$state"
}
same_movie() {
  cmp "$t/local/movie.mp4" "$t/farm/movie.mp4" || fail "$1: the farm's movie differs from the local render"
}

echo "1. the whole movie on the farm, in chunks of 3 frames, frame 9 developed from frame 8's trace"
movie=$(submit --chunk 3 --sbatch-option=--time=10 2>"$t/submit.txt")
[ -n "$movie" ] || fail "no movie job id printed"
grep -q "render 10 of 10 frames, up to 3 a task$" "$t/submit.txt" ||
  fail "every frame, each with its own grain, should be rendered"
[ "$(wc -l <"$t/farm/farm/chunks.txt")" -eq 4 ] || fail "10 frames in chunks of 3 should be 4 tasks"
[ "$(finish "$movie")" = COMPLETED ] || fail "the movie job did not complete"
same_movie "first submission"
"$export_bin" "$t/farm" --farm status | tee "$t/status.txt"
grep -q "10 of 10 frames rendered" "$t/status.txt" || fail "status does not count the frames"
[ "$(cat "$t"/farm/farm/logs/frames-*.log | grep -c "frame 8 rendered")" -eq 1 ] || fail "frame 8 was not rendered once"
[ "$(cat "$t"/farm/farm/logs/frames-*.log | grep -c "frame 9 rendered")" -eq 1 ] || fail "frame 9 was not rendered once"

echo "2. three frames gone: the same command renders only frames 5, 8 and 9"
rm "$t/farm/frames/frame_00005.png" "$t/farm/frames/frame_00008.png" "$t/farm/frames/frame_00009.png"
movie=$(submit 2>"$t/submit.txt")
grep -q "render 3 of 10 frames" "$t/submit.txt" || fail "the resubmission does not render just the 3 missing frames"
[ "$(finish "$movie")" = COMPLETED ] || fail "the second movie job did not complete"
same_movie "resubmission"

echo "3. a frame that fails every retry fails the movie job, naming it; the other frames are kept"
mkdir -p "$t/bin"
cat >"$t/bin/povray" <<EOF
#!/bin/sh
case "\$*" in *frame_00003.pov*) echo "Fatal error: the test breaks this frame"; exit 1 ;; esac
exec $(command -v povray) "\$@"
EOF
chmod +x "$t/bin/povray"
rm "$t/farm/frames/frame_00003.png" "$t/farm/frames/frame_00007.png"
movie=$(PATH="$t/bin:$PATH" submit)
[ "$(finish "$movie")" = FAILED ] || fail "the movie job should fail when a frame is missing"
grep -q "frame 3 (frames/frame_00003.png) was not rendered" "$t"/farm/farm/logs/movie-"$movie".log ||
  fail "the movie job's log does not name the missing frame"
grep -q "attempt 3 of 3" "$t"/farm/farm/logs/frames-*.log || fail "the task did not retry the frame"
[ -s "$t/farm/frames/frame_00007.png" ] || fail "frame 7, in the failed frame's chunk, was not rendered"
[ ! -e "$t/farm/movie.mp4" ] || fail "a movie is there without all its frames"
movie=$(submit 2>"$t/submit.txt")
grep -q "render 1 of 10 frames" "$t/submit.txt" || fail "the next submission should render only frame 3"
[ "$(finish "$movie")" = COMPLETED ] || fail "the movie job after the repair did not complete"
same_movie "after the failed frame"

echo "4. sbatch refusing the jobs leaves the output directory as it was"
before=$(cd "$t/farm" && find . -printf '%p %s\n' | sort)
if "$export_bin" "$t/shot.scn" --farm slurm -o "$t/farm" "${options[@]}" --sbatch-option=--partition=nowhere \
  2>"$t/refused.txt"; then
  fail "a submission to a partition that does not exist succeeded"
fi
grep -q "sbatch would not take the jobs" "$t/refused.txt" || fail "no clear message when sbatch refuses"
[ "$before" = "$(cd "$t/farm" && find . -printf '%p %s\n' | sort)" ] || fail "the refused submission changed $t/farm"
[ -z "$(find "$t" -maxdepth 2 -name '*.partial-*')" ] || fail "a staging directory was left behind"

echo "PASS: the farm's movie is byte for byte the local render's"
