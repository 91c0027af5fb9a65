#!/usr/bin/env bash
# A one-node Slurm cluster for tests, on a fresh Debian 12 machine, as root:
#
#   scripts/slurm-test-cluster.sh COMMAND [ARGS...]
#
# installs slurm-wlm and munge if missing (without starting their system services), writes a
# one-node configuration into a temporary directory (controller and compute daemon on localhost,
# no cgroups, 2 CPUs, partition `debug`, ports picked free), starts munged, slurmctld and slurmd
# from it, waits for the node to be idle, runs COMMAND with SLURM_CONF pointing at the
# configuration (sbatch, squeue, scancel ... then talk to this cluster only), and on exit, also
# on failure or interruption, cancels the cluster's jobs and stops the three daemons it started,
# by their process ids, and removes the directory (KEEP_SLURM_DIR=1 keeps it, with the logs).
#
# Exit status: COMMAND's; 77 when this machine cannot run the cluster (not root, no apt-get,
# packages that cannot be installed, daemons that do not come up), with the reason on stderr.
set -uo pipefail

say() { echo "slurm-test-cluster: $*" >&2; }
cannot() {
  say "cannot run a Slurm cluster on this machine: $*"
  exit 77
}
if [ $# -lt 1 ]; then
  echo "usage: $0 COMMAND [ARGS...]" >&2
  exit 2
fi
[ "$(id -u)" = 0 ] || cannot "it needs root (the daemons run as root), and this is uid $(id -u)"

# --- packages -----------------------------------------------------------------------------------
missing=()
for package in slurm-wlm munge; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  command -v apt-get > /dev/null || cannot "${missing[*]} are not installed and there is no apt-get"
  say "installing ${missing[*]}"
  # The packages would start system-wide munged and Slurm services: a policy denies that while
  # they are installed (unless the machine already has a policy of its own).
  policy=/usr/sbin/policy-rc.d
  own_policy=0
  if [ ! -e "$policy" ]; then
    printf '#!/bin/sh\nexit 101\n' > "$policy" && chmod 755 "$policy" && own_policy=1
  fi
  export DEBIAN_FRONTEND=noninteractive
  install_packages() { apt-get install -y -q --no-install-recommends "${missing[@]}"; }
  install_packages > /dev/null 2>&1 || { apt-get update -q > /dev/null 2>&1 && install_packages > /dev/null 2>&1; }
  installed=$?
  [ "$own_policy" = 1 ] && rm -f "$policy"
  [ "$installed" = 0 ] || cannot "apt-get could not install ${missing[*]}"
fi
for program in munged mungekey slurmctld slurmd sbatch squeue sinfo scancel; do
  command -v "$program" > /dev/null || cannot "$program is not on PATH after installing slurm-wlm and munge"
done

# --- configuration ------------------------------------------------------------------------------
dir=$(mktemp -d /tmp/columba-slurm.XXXXXX) || cannot "no temporary directory"
chmod 711 "$dir"  # munged's socket must be reachable through it
mkdir -p "$dir/state" "$dir/spool"
pids=()
names=()
command_pid=""

stop_all() {
  local status=$?
  trap - EXIT INT TERM
  if [ -n "${command_pid:-}" ] && kill -0 "$command_pid" 2> /dev/null; then
    say "stopping the command (pid $command_pid)"
    kill -TERM "$command_pid" 2> /dev/null
    wait "$command_pid" 2> /dev/null
  fi
  if [ ${#pids[@]} -gt 0 ]; then
    # The cluster's jobs first (their processes belong to slurmd's job steps), then the daemons,
    # last started first.
    if [ -n "${SLURM_CONF:-}" ] && kill -0 "${pids[1]:-0}" 2> /dev/null; then
      scancel --quiet --user=root > /dev/null 2>&1
      for _ in $(seq 20); do
        [ -z "$(squeue -h -o %i 2> /dev/null)" ] && break
        sleep 0.5
      done
    fi
    for ((i = ${#pids[@]} - 1; i >= 0; i--)); do
      kill -TERM "${pids[i]}" 2> /dev/null
    done
    for ((i = ${#pids[@]} - 1; i >= 0; i--)); do
      for _ in $(seq 50); do
        kill -0 "${pids[i]}" 2> /dev/null || break
        sleep 0.2
      done
      if kill -0 "${pids[i]}" 2> /dev/null; then
        say "${names[i]} (pid ${pids[i]}) did not stop within 10 s: killing it"
        kill -KILL "${pids[i]}" 2> /dev/null
      fi
      wait "${pids[i]}" 2> /dev/null
    done
    say "stopped ${names[*]}"
  fi
  if [ "${KEEP_SLURM_DIR:-0}" = 1 ]; then say "kept $dir"; else rm -rf "$dir"; fi
  exit "$status"
}
trap stop_all EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# Two free TCP ports for slurmctld and slurmd.
read -r ctld_port slurmd_port < <(/usr/bin/python3 -c '
import socket
socks = [socket.socket() for _ in range(2)]
for s in socks: s.bind(("127.0.0.1", 0))
print(*[s.getsockname()[1] for s in socks])') || cannot "no free TCP ports"

cat > "$dir/slurm.conf" << EOF
# One-node test cluster written by scripts/slurm-test-cluster.sh.
ClusterName=columbatest
SlurmctldHost=localhost
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge.socket
MailProg=/bin/true
MpiDefault=none
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
SchedulerParameters=sched_interval=2
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/slurmctld.log
SlurmdLogFile=$dir/slurmd.log
SlurmdParameters=config_overrides
ReturnToService=2
KillWait=10
NodeName=localhost NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$dir/slurm.conf"

logs() {
  for log in munged.log slurmctld.log slurmd.log; do
    [ -f "$dir/$log" ] && { say "--- the end of $log:"; tail -n 15 "$dir/$log" >&2; }
  done
}

# --- daemons --------------------------------------------------------------------------------------
mungekey --create --keyfile="$dir/munge.key" > /dev/null 2>&1 || cannot "mungekey could not create a key"
munged --foreground --force --socket="$dir/munge.socket" --key-file="$dir/munge.key" \
  --log-file="$dir/munged.log" --pid-file="$dir/munged.pid" --seed-file="$dir/munged.seed" > /dev/null 2>&1 &
pids+=($!)
names+=(munged)
for _ in $(seq 50); do
  [ -S "$dir/munge.socket" ] && break
  kill -0 "${pids[0]}" 2> /dev/null || break
  sleep 0.1
done
munge --socket="$dir/munge.socket" --no-input 2> /dev/null | unmunge --socket="$dir/munge.socket" > /dev/null 2>&1 ||
  { logs; cannot "munged did not start (see its log above)"; }

slurmctld -D -f "$SLURM_CONF" > "$dir/slurmctld.out" 2>&1 &
pids+=($!)
names+=(slurmctld)
slurmd -D -N localhost -f "$SLURM_CONF" > "$dir/slurmd.out" 2>&1 &
pids+=($!)
names+=(slurmd)

say "waiting for the node to be idle (config $SLURM_CONF)"
state=""
for _ in $(seq 120); do
  for i in 1 2; do
    kill -0 "${pids[i]}" 2> /dev/null || { logs; cannot "${names[i]} exited at start (see its log above)"; }
  done
  state=$(sinfo -h -N -o %T 2> /dev/null | head -n 1)
  [ "$state" = idle ] && break
  sleep 0.5
done
[ "$state" = idle ] || { logs; cannot "the node did not become idle within 60 s (state: '${state:-none}')"; }
say "the one-node cluster is up (munged, slurmctld, slurmd: pids ${pids[*]}); running: $*"

# In the background, so that a signal to this script is acted on at once (stop_all stops COMMAND).
"$@" &
command_pid=$!
wait "$command_pid"
