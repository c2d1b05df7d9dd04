#!/bin/bash
# A test whose stub the code holds exactly as committed is reported not started without running
# it (grader/engine/worker_sources.h); its verdict is the one running every phase gives
# (--run-every-phase). Compared test by test (status, reason, score) on:
#   - rtlab-worker as built: in a clean checkout, the committed stubs of every assignment;
#   - a submission of the reference solutions without four traversals, whose degenerate scenes
#     ask queries with no rays (a phase that calls no stub, so no committed stub decides it).
# Usage: committed_stubs.sh BUILD_DIR SOURCE_DIR
set -u
build=$1
source=$2
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
failures=0
[ -s "$build/rtlab-worker.sources" ] || { echo "FAIL: $build/rtlab-worker.sources is missing"; exit 1; }

# Grades twice with ARGS, with and without the shortcut, and compares the verdicts.
compare() {
    local name=$1
    shift
    "$build/rtlab-grader" grade "$@" --quiet --json "$scratch/$name-decided.json" > /dev/null
    "$build/rtlab-grader" grade "$@" --quiet --run-every-phase --json "$scratch/$name-run.json" > /dev/null
    python3 - "$name" "$scratch/$name-decided.json" "$scratch/$name-run.json" <<'PY' || failures=$((failures + 1))
import json, sys
name = sys.argv[1]
decided, run = (json.load(open(path)) for path in sys.argv[2:4])
verdict = lambda t: (t["status"], t.get("reason", ""), t.get("score"))
a = {t["name"]: verdict(t) for t in decided["tests"]}
b = {t["name"]: verdict(t) for t in run["tests"]}
differ = [f"{test}: {a.get(test)} decided, {b.get(test)} run" for test in sorted(set(a) | set(b)) if a.get(test) != b.get(test)]
for line in differ[:20]:
    print(f"FAIL ({name}):", line)
started = sum(1 for t in decided["tests"] if t["status"] == "not started")
print(f"{name}: {len(a)} tests, {started} not started, {len(differ)} verdicts differ")
sys.exit(1 if differ or not a or started == 0 else 0)
PY
}

compare stubs --worker "$build/rtlab-worker"

mkdir -p "$scratch/submission/assignments"
cp -r "$source/solutions/." "$scratch/submission/assignments/"
rm "$scratch/submission/assignments/"{a1_bvh/bvh_traverse.cpp,a3_grid/grid_traverse.cpp,a4_octree/octree_traverse.cpp,a5_kdtree/kd_traverse.cpp}
compare traversals-left-out --submission "$scratch/submission" --assignment a1 --assignment a3 --assignment a4 --assignment a5

exit $((failures > 0))
