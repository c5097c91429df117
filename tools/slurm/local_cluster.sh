#!/usr/bin/env bash
# A single-node Slurm cluster on this machine, in a temporary folder, for trying and testing the
# batch scripts here (render_sequence.sbatch) without a real cluster. Needs root (slurmd runs the
# jobs as their user and slurmctld's SlurmUser is root here) and the Debian packages slurm-wlm and
# munge (tools/install-deps.sh). Everything it writes, sockets, keys, state, logs and pid files,
# stays in that folder: not /etc/munge, /etc/slurm, nor the packaged services, which it neither
# starts nor talks to (munged runs on its own socket with its own key).
#
# As a command: tools/slurm/local_cluster.sh COMMAND [ARGS...] starts the cluster, runs COMMAND
# with SLURM_CONF set (sbatch, squeue, sinfo then talk to it), stops everything, and exits with
# COMMAND's status. E.g.
#   tools/slurm/local_cluster.sh sbatch --wait --array=0-3 tools/slurm/render_sequence.sbatch ...
#
# As a library: `source tools/slurm/local_cluster.sh`, then start_local_slurm (returns 1 with the
# reason on stderr when the cluster cannot start, having stopped what it started; exports
# SLURM_CONF and LOCAL_SLURM_DIR) and stop_local_slurm (cancels the jobs, stops the daemons, removes
# the folder; safe to call twice, e.g. from an EXIT trap). The functions check every step
# themselves: a caller's `if start_local_slurm` turns set -e off inside them.

LOCAL_SLURM_WAIT_S=${LOCAL_SLURM_WAIT_S:-60}  # bound on the wait for the node to come up idle

_local_slurm_fail() {
  echo "local slurm: $*" >&2
  return 1
}

# Two free TCP ports on 127.0.0.1, one a line: the kernel hands out free ones for port 0, and both
# sockets stay open until both are known, so the two differ.
_local_slurm_free_ports() {
  python3 -c '
import socket
socks = [socket.socket() for _ in range(2)]
for s in socks:
    s.bind(("127.0.0.1", 0))
for s in socks:
    print(s.getsockname()[1])
'
}

_local_slurm_write_conf() {  # DIR CTLD_PORT SLURMD_PORT
  local dir=$1 host
  host=$(hostname -s)
  # proctrack/linuxproc and task/none: no cgroups, which containers often lack. cons_tres with
  # CR_CPU: each task of an array takes one CPU, so two run at once on two cores. No accounting
  # (no slurmdbd): sacct does not work here, the jobs' exit codes come from sbatch --wait.
  cat > "$dir/slurm.conf" <<EOF
ClusterName=vkwater-local
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$2
SlurmdPort=$3
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.sock
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
# sbatch --wait polls after 2 s, then multiplies its interval by 4 (to 32 s at most) while it is
# under MinJobAge / 2, so that no finished task's record, which holds its exit code, is purged
# between two polls. The default MinJobAge, 300 s, let a 12 s array wait 42 s; 17 stops at 8 s.
MinJobAge=17
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=local Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
}

# munged refuses a socket whose folders are not searchable by all, or writable by others: the
# folder is 0711 (mktemp makes it 0700), the munge folder in it 0755.
_local_slurm_start_munge() {  # DIR
  local m=$1/munge
  mkdir -m 755 "$m" || return 1
  mungekey --create --keyfile "$m/munge.key" || _local_slurm_fail "mungekey could not make a key" || return 1
  munged --socket="$m/munge.sock" --key-file="$m/munge.key" --pid-file="$m/munged.pid" \
    --log-file="$m/munged.log" --seed-file="$m/munged.seed" ||
    _local_slurm_fail "munged did not start: $(tail -n 1 "$m/munged.log" 2>/dev/null)" || return 1
  munge -n -S "$m/munge.sock" | unmunge -S "$m/munge.sock" > /dev/null ||
    _local_slurm_fail "munged does not answer on $m/munge.sock" || return 1
}

# Polls sinfo until the node is idle; slurmd registers within a second or two.
_local_slurm_wait_idle() {
  local deadline=$((SECONDS + LOCAL_SLURM_WAIT_S)) state=""
  while ((SECONDS < deadline)); do
    state=$(sinfo --noheader --format=%t 2>/dev/null | head -n 1)
    [ "$state" = idle ] && return 0
    sleep 0.5
  done
  _local_slurm_fail "node not idle after ${LOCAL_SLURM_WAIT_S} s (state: '${state:-no answer}');" \
    "slurmctld.log: $(tail -n 2 "$LOCAL_SLURM_DIR/slurmctld.log" 2>/dev/null | tr '\n' ' ')" \
    "slurmd.log: $(tail -n 2 "$LOCAL_SLURM_DIR/slurmd.log" 2>/dev/null | tr '\n' ' ')"
}

# The cluster in DIR, step by step; returns 1 at the first step that fails, naming it.
_local_slurm_start_in() {  # DIR
  local dir=$1 ports
  chmod 711 "$dir" && mkdir "$dir/state" "$dir/spool" || return 1
  mapfile -t ports < <(_local_slurm_free_ports)
  [ "${#ports[@]}" -eq 2 ] || _local_slurm_fail "no free ports found" || return 1
  _local_slurm_write_conf "$dir" "${ports[0]}" "${ports[1]}" || return 1
  _local_slurm_start_munge "$dir" || return 1
  # -i: no saved state to recover (the folder is new).
  slurmctld -i -f "$dir/slurm.conf" ||
    _local_slurm_fail "slurmctld did not start: $(tail -n 1 "$dir/slurmctld.log" 2>/dev/null)" || return 1
  slurmd -f "$dir/slurm.conf" ||
    _local_slurm_fail "slurmd did not start: $(tail -n 1 "$dir/slurmd.log" 2>/dev/null)" || return 1
  _local_slurm_wait_idle
}

start_local_slurm() {
  [ "$(id -u)" -eq 0 ] || _local_slurm_fail "needs root (running as $(id -un))" || return 1
  local tool
  for tool in munged mungekey munge unmunge slurmctld slurmd sbatch sinfo squeue scancel python3; do
    command -v "$tool" > /dev/null ||
      _local_slurm_fail "$tool not found (tools/install-deps.sh installs slurm-wlm and munge)" || return 1
  done
  LOCAL_SLURM_DIR=$(mktemp -d -t vkwater-slurm.XXXXXX) || _local_slurm_fail "mktemp failed" || return 1
  export LOCAL_SLURM_DIR SLURM_CONF=$LOCAL_SLURM_DIR/slurm.conf
  _local_slurm_start_in "$LOCAL_SLURM_DIR" || {
    stop_local_slurm
    return 1
  }
}

# Stops the processes whose pids the PIDFILEs hold (the files that are there), together: each takes
# about 2 s to shut down. Waits up to 10 s for them, then kills what is left.
_local_slurm_kill_pidfiles() {
  local file pid pids=() i
  for file in "$@"; do
    pid=$(cat "$file" 2>/dev/null) || continue
    [[ $pid =~ ^[0-9]+$ ]] && kill "$pid" 2>/dev/null && pids+=("$pid")
  done
  for ((i = 0; i < 100 && ${#pids[@]} > 0; ++i)); do
    kill -0 "${pids[@]}" 2>/dev/null || return 0  # fails only when none is left
    sleep 0.1
  done
  [ "${#pids[@]}" -eq 0 ] || kill -KILL "${pids[@]}" 2>/dev/null || true
}

# Jobs first, so that no slurmstepd or job process outlives slurmd; then the daemons that
# start_local_slurm started, by the pids they wrote; then the folder.
stop_local_slurm() {
  local dir=${LOCAL_SLURM_DIR:-}
  [ -n "$dir" ] && [ -d "$dir" ] || return 0
  if [ -f "$dir/slurmctld.pid" ]; then
    scancel --full --quiet --user=root 2>/dev/null || true
    local i
    for ((i = 0; i < 50; ++i)); do
      [ -z "$(squeue --noheader --format=%i 2>/dev/null)" ] && break
      sleep 0.2
    done
  fi
  _local_slurm_kill_pidfiles "$dir/slurmd.pid" "$dir/slurmctld.pid" "$dir/munge/munged.pid"
  rm -rf "$dir"
  unset LOCAL_SLURM_DIR SLURM_CONF
}

if [ "${BASH_SOURCE[0]}" = "$0" ]; then
  set -euo pipefail
  [ $# -gt 0 ] || { echo "usage: $0 COMMAND [ARGS...]  (or source it: start_local_slurm, stop_local_slurm)" >&2; exit 2; }
  trap stop_local_slurm EXIT
  start_local_slurm
  status=0
  "$@" || status=$?
  exit "$status"
fi
