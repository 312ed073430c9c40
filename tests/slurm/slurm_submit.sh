#!/usr/bin/env bash
# scripts/slurm/submit against a real Slurm: a single-node cluster started here (Debian's slurm-wlm
# and munge, installed by scripts/install-deps): munged on a private socket with a generated key,
# slurmctld and slurmd on 127.0.0.1 with a generated slurm.conf on non-default ports, as the user
# running the test (SlurmUser: root in a container, or any other user: both checked),
# proctrack/linuxproc, task/none. A small sweep (the tiny scene at three
# resolutions: 3 groups, 9 cases) is submitted: a reference job per group, 2 timing shards after
# them and a dependent merge; the test waits
# for the merge and checks that the merged results equal a single-process run's cases (same ids in
# the same order, the same error values, timing statistics present, each shard's node recorded),
# then stops its daemons.
# Usage: slurm_submit.sh CANOPY DATA_DIR SUBMIT_SCRIPT
# Exit 77 (ctest: skipped) only where slurm-wlm or munge is not installed; where they are and
# Slurm does not start, the test fails.
set -uo pipefail
canopy=$1
data=$2
submit=$3
for tool in munged slurmctld slurmd sbatch squeue; do
  command -v "$tool" >/dev/null || { echo "SKIPPED: $tool is not installed (scripts/install-deps installs slurm-wlm and munge)"; exit 77; }
done
work=$(mktemp -d)
fail() { echo "FAIL: $*" >&2; for f in "$work"/slurm/log/*.log "$work"/run/logs/*.log; do [ -f "$f" ] && { echo "== $f"; tail -20 "$f"; }; done >&2; exit 1; }
stop() {
  for pid in "$work/slurm/slurmd.pid" "$work/slurm/slurmctld.pid" "$work/slurm/munge/munged.pid"; do
    [ -f "$pid" ] && kill "$(cat "$pid")" 2>/dev/null
  done
  sleep 1
  [ -n "${KEEP:-}" ] || rm -rf "$work"
}
trap stop EXIT

# Ports from this process's id, so two checkouts testing at once do not collide.
port=$((20000 + ($$ % 20000) * 2))
mkdir -p "$work/slurm/munge" "$work/slurm/state" "$work/slurm/spool" "$work/slurm/log"
head -c 1024 /dev/urandom >"$work/slurm/munge/munge.key"
chmod 600 "$work/slurm/munge/munge.key"
munged --force --key-file="$work/slurm/munge/munge.key" --socket="$work/slurm/munge/munge.socket" \
  --pid-file="$work/slurm/munge/munged.pid" --log-file="$work/slurm/munge/munged.log" \
  --seed-file="$work/slurm/munge/seed" || fail "munged did not start"
cpus=$(nproc)
memory=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 / 2 ))
cat >"$work/slurm/slurm.conf" <<EOF
ClusterName=canopytest
SlurmctldHost=localhost(127.0.0.1)
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
AuthType=auth/munge
AuthInfo=socket=$work/slurm/munge/munge.socket
CredType=cred/munge
SlurmctldPort=$port
SlurmdPort=$((port + 1))
StateSaveLocation=$work/slurm/state
SlurmdSpoolDir=$work/slurm/spool
SlurmctldPidFile=$work/slurm/slurmctld.pid
SlurmdPidFile=$work/slurm/slurmd.pid
SlurmctldLogFile=$work/slurm/log/slurmctld.log
SlurmdLogFile=$work/slurm/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=$memory State=UNKNOWN
PartitionName=canopy Nodes=localhost Default=YES MaxTime=INFINITE State=UP OverSubscribe=YES
EOF
export SLURM_CONF="$work/slurm/slurm.conf"
slurmctld -f "$SLURM_CONF" || fail "slurmctld did not start"
slurmd -f "$SLURM_CONF" -N localhost || fail "slurmd did not start"
for _ in $(seq 1 30); do
  sinfo -h -o "%t" 2>/dev/null | grep -q idle && break
  sleep 1
done
sinfo -h -o "%t" | grep -q idle || fail "the node did not come up: $(sinfo 2>&1)"

sed -e 's/^name = "tiny"/name = "tiny-slurm"/' -e 's/resolutions = \[\[96, 64\]\]/resolutions = [[96, 64], [64, 48], [48, 32]]/' \
  -e "s|\.\./scenes/|$data/scenes/|" "$data/experiments/tiny.toml" >"$work/three.toml"
"$submit" "$work/three.toml" --shards 2 --quick --out "$work/run" --cache "$work/cache" --canopy "$canopy" \
  >"$work/submitted" 2>&1 || fail "submit failed: $(cat "$work/submitted")"
cat "$work/submitted"
read -r references array merge < <(sed -n 's/^jobs: //p' "$work/submitted")
[ -n "$references" ] && [ -n "$array" ] && [ -n "$merge" ] || fail "submit printed no job ids"
grep -q "squeue -j $array,$merge" "$work/submitted" || fail "submit does not say how to watch the jobs"
for _ in $(seq 1 240); do
  [ -z "$(squeue -h -j "$references,$array,$merge" 2>/dev/null)" ] && break
  sleep 1
done
[ -z "$(squeue -h -j "$references,$array,$merge" 2>/dev/null)" ] || fail "the jobs did not finish in 4 minutes: $(squeue)"
# One reference job per group, each rendering its group's reference into the shared cache.
for g in 1 2 3; do grep -q "^reference tiny .*: rendered" "$work/run/logs/references-$g.log" || fail "reference job $g rendered nothing"; done
[ -s "$work/run/merged/results.json" ] || fail "the merge job wrote no results"

CANOPY_CACHE_DIR="$work/cache" "$canopy" run "$work/three.toml" --out "$work/single" --quick --no-progress --images png \
  >/dev/null 2>&1 || fail "the single-process run failed"
python3 - "$work/single/results.json" "$work/run/merged/results.json" <<'PY' || fail "the merged results differ from a single run's"
import json, sys
single, merged = (json.load(open(p)) for p in sys.argv[1:])
assert [c["id"] for c in merged["cases"]] == [c["id"] for c in single["cases"]], "case ids or order"
for a, b in zip(single["cases"], merged["cases"]):
    assert a["image_error"] == b["image_error"], (a["id"], "error values")
    assert b["timing"]["gpu_frame"]["stats_ms"]["count"] > 0, (b["id"], "no timing statistics")
    assert b["node"], (b["id"], "no node recorded")
assert merged["status"] == "complete", merged["status"]
shards = merged["merged_from"]
assert [s["shard"] for s in shards] == ["1/2", "2/2"], shards
assert all(s["hostname"] and s["groups"] for s in shards), shards
# The shards found every reference in the cache: the reference jobs rendered them.
assert all(r["from_cache"] and r["pixel_visibility"]["from_cache"] for r in merged["references"]), merged["references"]
print(f"Slurm: merged == single run: {len(merged['cases'])} cases; shards on", [s["hostname"] for s in shards])
PY
echo "slurm: ok"
