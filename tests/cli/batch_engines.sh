#!/bin/bash
# The two fan-out recipes of docs/grading.md ("Course scale") on three small submissions (a
# correct a0, a compile error, a dangling symbolic link): GNU parallel over `--shard K/2`, and
# a 2-task Slurm job array on a single-node Slurm started here (scripts/slurm-local). Each run's
# shards are joined with `rtlab grade merge`; both CSVs must be identical and hold the expected
# rows. Prints the minutes per submission each engine took. Needs root (slurmd).
# Usage: batch_engines.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(realpath "$1")
source=$(realpath "$2")
rtlab=$build/rtlab
work=$(mktemp -d /tmp/rtlab-batch-engines.XXXXXX)
# mktemp makes it 0700; the sandboxed worker runs as an unprivileged user and must reach its
# executable inside.
chmod 755 "$work"
slurm_state=$work/slurm
cleanup() {
    "$source/scripts/slurm-local" stop "$slurm_state" || true
    rm -rf "$work"
}
trap cleanup EXIT
# Hard limits: no step of this check may wait longer.
engine_timeout=600

submissions=$work/submissions
mkdir -p "$submissions/a-correct"
cp "$source"/solutions/a0_intersect/*.cpp "$submissions/a-correct/"
cp -r "$source/grader/fixtures/compile-error" "$submissions/b-compile-error"
ln -s "$work/no-such-folder" "$submissions/c-dangling"
flags=(--assignment a0 --models "$build/models")

elapsed_minutes_per_submission() {  # START_SECONDS
    awk -v s="$1" -v e="$(date +%s.%N)" 'BEGIN { printf "%.2f", (e - s) / 60 / 3 }'
}

echo "batch-engines: GNU parallel, 2 shards"
start=$(date +%s.%N)
timeout $engine_timeout parallel --halt now,fail=1 -j2 \
    "$rtlab" grade --submissions "$submissions" --reports "$work/parallel-reports" --shard {}/2 --jobs 1 "${flags[@]}" ::: 1 2
parallel_minutes=$(elapsed_minutes_per_submission "$start")
"$rtlab" grade merge "$work/parallel-reports" --csv "$work/parallel.csv"

echo "batch-engines: Slurm job array, 2 tasks"
timeout 120 "$source/scripts/slurm-local" start "$slurm_state"
export SLURM_CONF=$slurm_state/slurm.conf
start=$(date +%s.%N)
timeout $engine_timeout sbatch --wait --array=1-2 --cpus-per-task=1 --time=10 --output="$work/slurm-%a.log" \
    "$source/scripts/slurm-grade.sbatch" "$rtlab" "$submissions" "$work/slurm-reports" "${flags[@]}" > /dev/null || {
    echo "batch-engines: the job array failed:"
    cat "$work"/slurm-*.log
    exit 1
}
slurm_minutes=$(elapsed_minutes_per_submission "$start")
"$rtlab" grade merge "$work/slurm-reports" --csv "$work/slurm.csv"

python3 - "$work/slurm.csv" "$work/parallel.csv" <<'EOF'
import csv, sys
rows = {r["submission"]: r for r in csv.DictReader(open(sys.argv[1]))}
problems = []
# Same scores either way; reasons may name the temporary folders each run graded in.
other = {r["submission"]: r for r in csv.DictReader(open(sys.argv[2]))}
def scores(table):
    return {name: {k: v for k, v in row.items() if k != "reason"} for name, row in table.items()}
if scores(rows) != scores(other):
    problems.append("GNU parallel and Slurm merged different scores")
if sorted(rows) != ["a-correct", "b-compile-error", "c-dangling"]:
    problems.append(f"rows {sorted(rows)}")
else:
    maximum = float(rows["a-correct"]["max_score"])
    if not maximum > 0 or float(rows["a-correct"]["score"]) != maximum or rows["a-correct"]["reason"]:
        problems.append(f"a-correct: {rows['a-correct']['score']} of {maximum}, reason {rows['a-correct']['reason']!r}")
    for name, why in (("b-compile-error", "compile"), ("c-dangling", "symbolic link")):
        r = rows[name]
        if float(r["score"]) != 0 or float(r["max_score"]) != maximum or why not in r["reason"]:
            problems.append(f"{name}: {r['score']} of {r['max_score']}, reason {r['reason']!r}")
for p in problems:
    print("FAIL:", p)
sys.exit(1 if problems else 0)
EOF
echo "batch-engines: passed; minutes per submission (a0 only, 2 shards on $(nproc) cores): GNU parallel $parallel_minutes, Slurm $slurm_minutes"
