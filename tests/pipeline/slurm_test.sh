#!/usr/bin/env bash
# The Snakemake pipeline on a real Slurm: starts a single-node cluster on this machine (munged,
# slurmctld and slurmd run directly in the foreground from a temporary folder: generated key and
# slurm.conf, loopback addresses, no systemd, no cgroups), submits the pipeline with
# `snakemake --cluster sbatch`, and checks every output is byte-identical to a local run of the
# same config. Daemons are stopped on exit; every wait is bounded.
# Usage: slurm_test.sh SOURCE_DIR BIN_DIR. Exit 77 (skipped) when snakemake, slurm-wlm or munge
# are not installed or the daemons cannot start.
set -euo pipefail
SRC=$1 BIN=$2
skip() { echo "SKIP: $*"; exit 77; }
for cmd in snakemake munged mungekey slurmctld slurmd sbatch squeue scontrol sinfo python3; do
  command -v "$cmd" >/dev/null || skip "$cmd is not installed (apt-get install snakemake slurm-wlm munge)"
done

WORK=$(mktemp -d "${TMPDIR:-/tmp}/kdpm-slurm.XXXXXX")
pids=()
stop_daemons() {
  local pid
  [ -z "${SLURM_CONF:-}" ] || timeout 5 scancel --user "$(id -un)" >/dev/null 2>&1 || true
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
  # KDPM_TEST_LOGS=DIR keeps the daemons' and snakemake's logs for a post-mortem.
  [ -z "${KDPM_TEST_LOGS:-}" ] || cp -r "$WORK/logs/." "$KDPM_TEST_LOGS/" 2>/dev/null || true
  rm -rf "$WORK"
}
trap stop_daemons EXIT
trap 'exit 1' INT TERM
source "$SRC/tests/pipeline/pipeline_lib.sh"

# Each daemon dies on its own after LIFETIME seconds, even if this script is killed outright.
LIFETIME=280
daemon() { timeout -k 5 "$LIFETIME" "$@" & pids+=($!); }

# wait_for SECONDS COMMAND...: true once COMMAND succeeds, false after SECONDS.
wait_for() {
  local deadline=$((SECONDS + $1))
  shift
  until "$@" >/dev/null 2>&1; do
    [ $SECONDS -lt $deadline ] || return 1
    sleep 0.2
  done
}

# munged refuses a socket folder that others cannot search; the key stays private.
chmod 755 "$WORK"
mkdir -m 700 "$WORK/munge-key"
mkdir -m 755 "$WORK/munge" "$WORK/state" "$WORK/spool" "$WORK/logs"
mungekey --create --keyfile="$WORK/munge-key/munge.key" >/dev/null 2>&1 || skip "mungekey cannot create a key"
SOCKET=$WORK/munge/munge.socket
daemon munged --foreground --socket="$SOCKET" --key-file="$WORK/munge-key/munge.key" --pid-file="$WORK/munge/munged.pid" \
  --log-file="$WORK/logs/munged.log" --seed-file="$WORK/munge/munged.seed" > "$WORK/logs/munged.out" 2>&1
wait_for 10 test -S "$SOCKET" || skip "munged does not start ($(tail -n 1 "$WORK/logs/munged.out"))"

read -r CTLD_PORT SLURMD_PORT < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*(x.getsockname()[1] for x in s))')
CPUS=$(nproc)
MEMORY=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 / 2 ))
export SLURM_CONF=$WORK/slurm.conf
cat > "$SLURM_CONF" <<CONF
ClusterName=kdpmtest
SlurmctldHost=localhost(127.0.0.1)
CommunicationParameters=NoInAddrAny,NoCtldInAddrAny
SlurmctldPort=$CTLD_PORT
SlurmdPort=$SLURMD_PORT
AuthType=auth/munge
AuthInfo=socket=$SOCKET
CredType=cred/munge
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$WORK/state
SlurmdSpoolDir=$WORK/spool
SlurmctldPidFile=$WORK/state/slurmctld.pid
SlurmdPidFile=$WORK/spool/slurmd.pid
SlurmctldLogFile=$WORK/logs/slurmctld.log
SlurmdLogFile=$WORK/logs/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
SwitchType=switch/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
SlurmdParameters=config_overrides
ReturnToService=2
SlurmctldTimeout=30
SlurmdTimeout=30
InactiveLimit=0
MinJobAge=60
KillWait=5
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$CPUS RealMemory=$MEMORY State=UNKNOWN
PartitionName=kdpm Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF

# The daemons find themselves in slurm.conf by the machine's name, and bind to what it resolves to.
# In a UTS namespace of their own that name is "localhost", whatever this machine is called and
# whether or not its name resolves (a debootstrapped root has no /etc/hosts entry for it).
as_localhost=()
if unshare --uts true 2>/dev/null; then
  as_localhost=(unshare --uts bash -c 'echo localhost > /proc/sys/kernel/hostname && exec "$@"' as_localhost)
fi
daemon "${as_localhost[@]}" slurmctld -D -i > "$WORK/logs/slurmctld.out" 2>&1
wait_for 20 scontrol ping || skip "slurmctld does not start ($(tail -n 1 "$WORK/logs/slurmctld.log" 2>/dev/null))"
daemon "${as_localhost[@]}" slurmd -D -N localhost > "$WORK/logs/slurmd.out" 2>&1
node_idle() { [ "$(sinfo -h -n localhost -o %T 2>/dev/null)" = idle ]; }
wait_for 30 node_idle || skip "slurmd does not join ($(tail -n 1 "$WORK/logs/slurmd.log" 2>/dev/null))"
# The daemons listen on the loopback address only (NoInAddrAny, NoCtldInAddrAny).
if command -v ss >/dev/null; then
  listening=$(ss -Hltn "( sport = :$CTLD_PORT or sport = :$SLURMD_PORT )" 2>/dev/null | awk '{print $4}' || true)
  if [ -n "$listening" ] && grep -qv "^127\.0\.0\.1:" <<< "$listening"; then
    echo "FAIL: a Slurm daemon listens beyond the loopback: $listening"
    exit 1
  fi
fi
echo "single-node Slurm cluster up (slurmctld :$CTLD_PORT, slurmd :$SLURMD_PORT, $CPUS CPUs)"

make_library
NAMES=a  # the Cornell box (one copy: every job costs a snakemake start-up on the node)
sponza=()
scenes=${KDPM_SCENES:-$SRC/../shared/scenes}
if [ -f "$scenes/sponza/sponza.obj" ]; then
  sponza=("  sponza: {input: $SRC/scenes/sponza/sponza.json, photons: $PHOTONS, shards: 4, bounces: $BOUNCES, seed: $SEED}")
  export KDPM_SCENES=$scenes
fi
write_config "$WORK/local.yaml" "$WORK/local" "${sponza[@]}"
write_config "$WORK/slurm.yaml" "$WORK/slurm" "${sponza[@]}"

# run NAME SECONDS SNAKEMAKE-ARGS...
run() {
  local name=$1 limit=$2 start=$SECONDS
  shift 2
  timeout -k 5 "$limit" snakemake -s "$SRC/pipeline/Snakefile" --configfile "$WORK/$name.yaml" --directory "$WORK" \
    "$@" > "$WORK/logs/$name.log" 2>&1 \
    || { tail -n 30 "$WORK/logs/$name.log"; tail -n 5 "$WORK/logs/slurmctld.log"; echo "FAIL: $name run"; exit 1; }
  echo "$name run: $((SECONDS - start)) s"
}
run local 150 --cores all
# Snakemake 7 polls cluster jobs every 10 s, every 1 s when CI=true (snakemake/executors): the
# pipeline's six levels of jobs would spend a minute waiting.
export CI=true
run slurm 150 --jobs 8 --latency-wait 30 \
  --cluster "sbatch --parsable --job-name=kdpm-{rule} --cpus-per-task={threads} --mem={resources.mem_mb} --output=$WORK/logs/slurm-%j.out"

submitted=$(grep -c "Submitted job .* with external jobid" "$WORK/logs/slurm.log" || true)
[ "$submitted" -gt 0 ] || { tail -n 20 "$WORK/logs/slurm.log"; echo "FAIL: no job went through sbatch"; exit 1; }
for scene in $NAMES ${sponza:+sponza}; do
  same_files "$WORK/local/$scene" "$WORK/slurm/$scene" $OUTPUTS
done
echo "$submitted Slurm jobs; outputs byte-identical to the local run (scenes: $NAMES ${sponza:+sponza})"
