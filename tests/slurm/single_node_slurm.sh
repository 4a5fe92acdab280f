# shellcheck shell=bash
# A single-node Slurm (munged, slurmctld, slurmd from Debian's packages) in a temporary folder, for
# tests. Source it, then: start_slurm DIR (exports SLURM_CONF; fails with one line naming the
# reason) and stop_slurm (scontrol shutdown, stop munged; safe to call twice, from a trap).
# Needs root: the daemons run as root, munged as the munge user.

# The daemons live in sbin, which a non-login PATH may lack.
PATH=$PATH:/usr/sbin:/sbin

slurm_fail() {
  echo "single-node Slurm did not start: $*" >&2
  return 1
}

# The last lines of a daemon's log, joined into one line for a failure message.
slurm_log_tail() {
  [[ -f $1 ]] && tail -n 3 "$1" | tr '\n' ' '
}

start_munged() {
  local dir=$1
  mkdir -p "$dir/munge"
  chown munge:munge "$dir/munge"
  chmod 755 "$dir/munge"  # munged wants its socket folder searchable by all
  runuser -u munge -- munged --socket="$dir/munge/munge.socket" --pid-file="$dir/munge/munged.pid" \
    --log-file="$dir/munge/munged.log" --seed-file="$dir/munge/munged.seed" ||
    slurm_fail "munged failed: $(slurm_log_tail "$dir/munge/munged.log")" || return 1
  munge -n --socket="$dir/munge/munge.socket" | unmunge --socket="$dir/munge/munge.socket" >/dev/null ||
    slurm_fail "munge cannot encode and decode a credential" || return 1
}

write_slurm_conf() {
  local dir=$1 host node port=$((20000 + $$ % 20000))
  host=$(hostname -s)
  # slurmd -C: the node as slurmd sees it (CPUs, sockets, cores, memory), so it is never drained
  # for a mismatch.
  node=$(slurmd -C | head -n 1)
  [[ $node == NodeName=* ]] || slurm_fail "slurmd -C printed no node line: $node" || return 1
  cat >"$dir/slurm.conf" <<CONF
ClusterName=hdpriortest
SlurmctldHost=$host
SlurmUser=root
SlurmdUser=root
SlurmctldPort=$port
SlurmdPort=$((port + 1))
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/slurmctld.pid
SlurmdPidFile=$dir/slurmd.pid
SlurmctldLogFile=$dir/log/slurmctld.log
SlurmdLogFile=$dir/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
JobCompType=jobcomp/none
MpiDefault=none
ReturnToService=2
SchedulerType=sched/backfill
$node State=UNKNOWN
PartitionName=test Nodes=$host Default=YES MaxTime=INFINITE State=UP
CONF
}

start_slurm() {
  local dir=$1
  SLURM_TEST_DIR=$dir
  [[ $(id -u) -eq 0 ]] || slurm_fail "needs root (the daemons run as root, munged as munge)" || return 1
  for tool in munged munge slurmctld slurmd sbatch scontrol sinfo; do
    command -v "$tool" >/dev/null || slurm_fail "$tool not found (scripts/install-deps.sh installs it)" || return 1
  done
  id munge >/dev/null 2>&1 || slurm_fail "no munge user (the munge package creates it)" || return 1
  mkdir -p "$dir/state" "$dir/spool" "$dir/log"
  start_munged "$dir" || return 1
  write_slurm_conf "$dir" || return 1
  export SLURM_CONF=$dir/slurm.conf
  slurmctld -f "$SLURM_CONF" || slurm_fail "slurmctld failed: $(slurm_log_tail "$dir/log/slurmctld.log")" || return 1
  slurmd -f "$SLURM_CONF" || slurm_fail "slurmd failed: $(slurm_log_tail "$dir/log/slurmd.log")" || return 1
  local state=""
  for _ in $(seq 60); do
    state=$(sinfo -h -N -o %t 2>/dev/null | head -n 1)
    [[ $state == idle* ]] && return 0
    sleep 1
  done
  slurm_fail "the node is not idle after 60 s (state '$state'): $(slurm_log_tail "$dir/log/slurmctld.log")"
}

stop_slurm() {
  local dir=${SLURM_TEST_DIR:-}
  [[ -n $dir ]] || return 0
  if [[ -f $dir/slurm.conf ]]; then
    # Every job of this private controller is the test's: cancel what is left, then stop.
    SLURM_CONF=$dir/slurm.conf scancel --quiet --user="$(id -un)" >/dev/null 2>&1 || true
    SLURM_CONF=$dir/slurm.conf scontrol shutdown >/dev/null 2>&1 || true
  fi
  # scontrol shutdown asks; wait for the daemons to go, then make sure.
  local pidfile pid
  for pidfile in "$dir/slurmctld.pid" "$dir/slurmd.pid" "$dir/munge/munged.pid"; do
    # The daemon may remove its pid file between the test and the read (it is shutting down).
    pid=$(cat "$pidfile" 2>/dev/null) || continue
    [[ $pidfile == */munged.pid ]] && kill "$pid" 2>/dev/null
    for _ in $(seq 20); do kill -0 "$pid" 2>/dev/null || break; sleep 0.5; done
    kill -9 "$pid" 2>/dev/null || true
  done
  SLURM_TEST_DIR=""
}
