#!/usr/bin/env bash
# scripts/slurm/rlpos-workers.sbatch on a one-node Slurm cluster that this test starts and stops
# (munged, slurmctld, slurmd from Debian, every file in its temporary folder, every address
# 127.0.0.1): the sbatch job's worker serves a standalone coordinator's campaign to the end, with
# the node's CPUs as its slots; scancel stops it cleanly. Root only; skips (77) without Slurm.
source "$(dirname "$0")/lib.sh"
[ "$(id -u)" -eq 0 ] || { echo "skip: a private Slurm cluster needs root"; exit 77; }
for tool in munged slurmctld slurmd sbatch squeue scancel sinfo; do
  command -v "$tool" >/dev/null || { echo "skip: no $tool (slurmctld, slurmd, slurm-client, munge)"; exit 77; }
done
id munge >/dev/null 2>&1 || { echo "skip: no munge user"; exit 77; }

# The cluster's files; munged checks that its folder belongs to it and no one else.
chmod 755 "$WORK"
M=$WORK/munge
S=$WORK/slurm
mkdir -p "$M" "$S/state" "$S/spool"
chown munge:munge "$M"
chmod 700 "$M"
head -c 1024 /dev/urandom >"$M/munge.key"
chown munge:munge "$M/munge.key"
chmod 400 "$M/munge.key"
stop_cluster() {
  # Each daemon by its pid file, then a bounded wait for it to go.
  for pidfile in "$S/slurmd.pid" "$S/slurmctld.pid" "$M/munged.pid"; do
    [ -s "$pidfile" ] || continue
    pid=$(cat "$pidfile")
    kill "$pid" 2>/dev/null || continue
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
}
trap 'stop_cluster; cleanup' EXIT
runuser -u munge -- munged --force --key-file="$M/munge.key" --socket="$M/munge.socket" \
  --pid-file="$M/munged.pid" --log-file="$M/munged.log" --seed-file="$M/munged.seed" \
  || fail "munged did not start: $(tail -3 "$M/munged.log" 2>/dev/null)"

HOST=$(hostname -s)
# The node is declared with one CPU fewer than the machine has (at least 1): the worker's slots
# must follow Slurm's count, not the machine's.
CPUS=$(($(nproc) > 1 ? $(nproc) - 1 : 1))
# Ports of its own, so that a cluster already on this machine is left alone.
PORT=$((20000 + $$ % 20000))
cat >"$S/slurm.conf" <<CONF
ClusterName=rlpos-test
SlurmctldHost=$HOST(127.0.0.1)
SlurmctldPort=$PORT
SlurmdPort=$((PORT + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$M/munge.socket
CredType=cred/munge
StateSaveLocation=$S/state
SlurmdSpoolDir=$S/spool
SlurmctldPidFile=$S/slurmctld.pid
SlurmdPidFile=$S/slurmd.pid
SlurmctldLogFile=$S/slurmctld.log
SlurmdLogFile=$S/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
ReturnToService=2
NodeName=$HOST NodeAddr=127.0.0.1 CPUs=$CPUS RealMemory=1000 State=UNKNOWN
PartitionName=rlpos Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF=$S/slurm.conf
slurmctld -c || fail "slurmctld did not start: $(tail -3 "$S/slurmctld.log")"
slurmd || fail "slurmd did not start: $(tail -3 "$S/slurmd.log")"
node_idle() { sinfo -h -N -o '%T' 2>/dev/null | grep -qx idle; }
wait_until 60 node_idle || fail "the node never became idle: $(sinfo -N 2>&1; tail -5 "$S/slurmd.log")"

# A coordinator outside Slurm, on loopback with the test's tag.
DB=$WORK/rlpos.db
DDS=(--loopback "$TAG" --domain $((1 + $$ % 200)))
mkdir -p "$WORK/logs/daemons"
"$BIN/rlpos-coordinator" --db "$DB" "${DDS[@]}" 2>"$WORK/logs/daemons/coordinator.log" &
BG_PIDS+=("$!")
ID=$("$CAMPAIGN" submit "$SRC/tests/e2e/campaigns/tiny_b.json" "${DDS[@]}" 2>"$WORK/submit.err") \
  || fail "submit: $(cat "$WORK/submit.err")"

# The workers as a Slurm job, from the repository as a user submits it.
JOB=$(cd "$WORK" && RLPOS_BIN=$BIN RLPOS_WORK_DIR=$WORK/work sbatch --parsable \
  --output="$WORK/logs/daemons/slurm-%j.log" "$SRC/scripts/slurm/rlpos-workers.sbatch" \
  "${DDS[@]}") || fail "sbatch refused the script"
WORKER=slurm-$JOB-$HOST
# Until the campaign is finished, or the Slurm job is gone (then it failed: no need to wait).
finished_or_gone() {
  [ "$(sql "$DB" "SELECT state FROM campaigns WHERE id = '$ID'" 2>/dev/null)" = finished ] ||
    [ -z "$(squeue -h -j "$JOB" 2>/dev/null)" ]
}
wait_until 300 finished_or_gone || fail "the campaign did not finish: $(squeue 2>&1)"
expect_eq "Slurm job $JOB while the campaign ends" "$(squeue -h -j "$JOB" -o %T)" RUNNING
expect_complete "$DB" 6
expect_eq "the worker that ran the jobs" "$(sql "$DB" "SELECT group_concat(DISTINCT worker_id)
  FROM jobs")" "$WORKER"
expect_eq "its slots" "$(sql "$DB" "SELECT slots FROM workers WHERE id = '$WORKER'")" "$CPUS"

# scancel: the worker stops cleanly (its status disposed: 'stopped', not 'lost') and the job ends.
scancel "$JOB"
stopped() { [ "$(sql "$DB" "SELECT state FROM workers WHERE id = '$WORKER'")" = stopped ]; }
wait_until 60 stopped || fail "the worker was not stopped cleanly: $(sql "$DB" "SELECT state FROM workers")"
gone() { [ -z "$(squeue -h -j "$JOB" 2>/dev/null)" ]; }
wait_until 60 gone || fail "Slurm job $JOB did not end"
echo "ok: Slurm job $JOB ran worker $WORKER with $CPUS slots; campaign $ID complete; scancel stopped it"
