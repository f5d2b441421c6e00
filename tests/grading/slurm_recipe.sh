#!/usr/bin/env bash
# The Slurm recipe of docs/grading.md ("A Slurm job array"), run exactly as
# written: the three submission commands and the two batch scripts are taken
# from the Markdown, on a single-node Slurm started here from Debian's
# packages (slurmctld, slurmd, MUNGE; scripts/setup.sh --slurm installs them)
# with the machine's real CPUs and memory (`slurmd -C`), every daemon's state
# in a temporary folder, no systemd. The merged grades.csv must equal an
# unsharded run's byte for byte. Needs root (slurmd starts jobs as their
# user). Usage: slurm_recipe.sh RAYLAB_BINARY
set -euo pipefail
RAYLAB=$(readlink -f "${1:?usage: slurm_recipe.sh RAYLAB_BINARY}")
SRC=$(cd "$(dirname "$0")/../.." && pwd)
WAIT_SECONDS=${RAYLAB_SLURM_WAIT:-600}  # the whole array and the merge; about 1 minute on 2 cores

fail() { echo "slurm_recipe: $*" >&2; exit 1; }
for tool in slurmctld slurmd sbatch squeue scancel munged mungekey python3; do
  command -v "$tool" >/dev/null || fail "$tool is missing: scripts/setup.sh --slurm installs Slurm and MUNGE"
done
[ "$(id -u)" -eq 0 ] || fail "run as root: slurmd starts each job as the user who submitted it"

T=$(mktemp -d /tmp/raylab_slurm.XXXXXX)
pids=()
cleanup() {
  status=$?
  SLURM_CONF="$T/slurm.conf" scancel --quiet --user root 2>/dev/null || true
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
  if [ "$status" -ne 0 ]; then
    for log in "$T"/slurmctld.log "$T"/slurmd.log "$T"/work/logs/*; do
      [ -f "$log" ] && { echo "--- $log"; tail -n 30 "$log"; }
    done
    echo "slurm_recipe: failed; everything is kept in $T" >&2
  else
    rm -rf "$T"
  fi
}
trap cleanup EXIT

# Two free TCP ports for the daemons.
read -r CTLD_PORT SLURMD_PORT < <(python3 -c '
import socket
socks = [socket.socket() for _ in range(2)]
for s in socks: s.bind(("127.0.0.1", 0))
print(*[s.getsockname()[1] for s in socks])')

# MUNGE, on its own socket and key.
mkdir -p "$T/munge"
chmod 700 "$T/munge"
mungekey --create --keyfile="$T/munge/munge.key" --force
munged --force --foreground --socket="$T/munge/munge.socket" --key-file="$T/munge/munge.key" \
  --pid-file="$T/munge/munged.pid" --log-file="$T/munge/munged.log" --seed-file="$T/munge/munged.seed" \
  > "$T/munge/munged.out" 2>&1 &
pids+=($!)

# The node as slurmd sees the machine: its real CPUs, sockets, cores and memory.
NODE=$(slurmd -C | head -n 1 | sed -e 's/^NodeName=[^ ]*/NodeName=localhost NodeAddr=127.0.0.1/' -e 's/ UpTime=.*//')
mkdir -p "$T/state" "$T/spool"
cat > "$T/slurm.conf" <<EOF
ClusterName=raylabtest
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$CTLD_PORT
SlurmdPort=$SLURMD_PORT
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$T/munge/munge.socket
StateSaveLocation=$T/state
SlurmdSpoolDir=$T/spool
SlurmctldPidFile=$T/slurmctld.pid
SlurmdPidFile=$T/slurmd.pid
SlurmctldLogFile=$T/slurmctld.log
SlurmdLogFile=$T/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
ReturnToService=2
$NODE State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$T/slurm.conf"
for _ in $(seq 50); do [ -S "$T/munge/munge.socket" ] && break; sleep 0.1; done
slurmctld -D -i -f "$SLURM_CONF" > "$T/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -N localhost -f "$SLURM_CONF" > "$T/slurmd.out" 2>&1 &
pids+=($!)
for _ in $(seq 100); do
  sinfo -h -o '%T' 2>/dev/null | grep -qE '^(idle|mixed|allocated)' && break
  sleep 0.2
done
sinfo -h -o '%T' | grep -qE '^(idle|mixed|allocated)' || fail "the node did not come up: $(sinfo -h -o '%T %E' 2>&1)"

# The class: a few cheap students (stubs and a few exercises), a checkout named raylab/.
W="$T/work"
# raylab/ stands for the checkout: its ./raylab wrapper and the binary under
# test; the sources are read from this repository (sbatch passes RAYLAB_ROOT on).
mkdir -p "$W/raylab/build/bin" "$W/submissions"
ln -s "$RAYLAB" "$W/raylab/build/bin/raylab"
cp "$SRC/raylab" "$W/raylab/raylab"
export RAYLAB_ROOT="$SRC"
cp -r "$SRC/exercises" "$W/submissions/stubs"
mkdir -p "$W/submissions/ann" "$W/submissions/bob" "$W/submissions/empty"
cp "$SRC"/solutions/0[1-3]-*.glsl "$W/submissions/ann/"
cp "$SRC"/solutions/01-*.glsl "$W/submissions/bob/"

# The recipe's code blocks, in order: the commands, grade.sbatch, merge.sbatch.
python3 - "$SRC/docs/grading.md" "$W" <<'EOF'
import pathlib, re, sys
text = pathlib.Path(sys.argv[1]).read_text()
section = text.split("### A Slurm job array", 1)[1].split("\n## ", 1)[0]
blocks = re.findall(r"```bash\n(.*?)```", section, re.S)
if len(blocks) != 3:
    sys.exit("slurm_recipe: expected 3 bash blocks in the Slurm section, found %d" % len(blocks))
work = pathlib.Path(sys.argv[2])
(work / "submit.sh").write_text(blocks[0])
for block in blocks[1:]:
    name = re.match(r"#!/bin/bash\n# (\S+):", block).group(1)
    (work / name).write_text(block)
EOF
[ -f "$W/grade.sbatch" ] && [ -f "$W/merge.sbatch" ] || fail "the recipe names no grade.sbatch and merge.sbatch"

cd "$W"
bash -euo pipefail submit.sh
deadline=$((SECONDS + WAIT_SECONDS))
while [ -n "$(squeue -h -o '%i' 2>/dev/null)" ]; do
  [ "$SECONDS" -lt "$deadline" ] || fail "jobs still queued after $WAIT_SECONDS s: $(squeue -o '%i %j %T %r' 2>&1)"
  if squeue -h -o '%r' | grep -q 'DependencyNeverSatisfied'; then fail "a grading task failed: see logs/"; fi
  sleep 1
done
[ -f out/class/grades.csv ] || fail "the merge wrote no out/class/grades.csv (logs: $(ls logs))"

"$RAYLAB" grade submissions -o unsharded --timeout 30 > unsharded.log 2>&1 || fail "the unsharded run failed: $(tail -n 5 unsharded.log)"
cmp out/class/grades.csv unsharded/grades.csv || fail "the merged grades.csv differs from the unsharded run's"
[ "$(ls out | grep -c '^shard-')" -eq 8 ] || fail "expected 8 shards in out/, found: $(ls out)"
echo "slurm_recipe: 8 array tasks and the merge, as docs/grading.md writes them: grades.csv identical to the unsharded run"
