#!/bin/bash
# Batches that finish (docs/grading.md, "Grading a batch"): shards, merge, re-runs that skip
# what is graded, the hard cap per submission, a dangling symbolic link costing only its row,
# --fail-under, and one-line errors for bad input with nothing overwritten.
# Usage: batch_grading.sh BUILD_DIR SOURCE_DIR
set -u
build=$1
source=$2
rtlab=$build/rtlab
work=$(mktemp -d)
# mktemp makes it 0700; the sandboxed worker runs as an unprivileged user and must reach its
# executable inside.
chmod 755 "$work"
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

submissions=$work/submissions
mkdir -p "$submissions/a-correct"
cp "$source"/solutions/a0_intersect/*.cpp "$submissions/a-correct/"
ln -s "$work/no-such-folder" "$submissions/b-dangling"
echo "not a submission" > "$submissions/notes.txt"
flags=(--assignment a0 --models "$build/models" --work "$work/grading")

# grade ARGS...: rtlab grade with a hard limit, output in $work/out and $work/err.
grade() { timeout 600 "$rtlab" grade "$@" > "$work/out" 2> "$work/err"; }

# Shard 1/2 of the two folders (sorted by name) is a-correct only.
grade --submissions "$submissions" --reports "$work/reports" --shard 1/2 "${flags[@]}" || fail "shard 1/2: exit $?: $(tail -1 "$work/err")"
[ "$(ls "$work/reports")" = "a-correct.json" ] || fail "shard 1/2 wrote: $(ls "$work/reports" | tr '\n' ' ')"
grade --submissions "$submissions" --reports "$work/reports" --shard 2/2 "${flags[@]}" || fail "shard 2/2: exit $?: $(tail -1 "$work/err")"
grade merge "$work/reports" --csv "$work/merged.csv" || fail "merge: exit $?: $(cat "$work/err")"
python3 - "$work/merged.csv" <<'PY' || fail "merged CSV: $(cat "$work/merged.csv")"
import csv, sys
rows = {r["submission"]: r for r in csv.DictReader(open(sys.argv[1]))}
good, dangling = rows["a-correct"], rows["b-dangling"]
assert sorted(rows) == ["a-correct", "b-dangling"], rows
assert float(good["max_score"]) == 100 and float(good["score"]) == 100 and good["reason"] == "", good
# The broken folder: its own row, 0 of the same maximum, with the reason.
assert float(dangling["score"]) == 0 and float(dangling["max_score"]) == 100, dangling
assert "symbolic link to a missing target" in dangling["reason"], dangling
assert good["score"] == "100.00", "rounded to the rubric's 2 decimals"
PY

# A re-run skips both (no grading at all: fast) and its CSV is the merged one.
SECONDS=0
grade --submissions "$submissions" --reports "$work/reports" --csv "$work/rerun.csv" "${flags[@]}" || fail "re-run: exit $?"
grep -q "2 skipped" "$work/out" || fail "re-run did not skip: $(cat "$work/out")"
[ $SECONDS -lt 20 ] || fail "re-run took $SECONDS s"
cmp -s "$work/merged.csv" "$work/rerun.csv" || fail "the batch's CSV differs from grade merge's"

# The cap per submission: a compile that would take many minutes (hundreds of constant
# evaluations, each within GCC's limits) is killed at the cap with everything below it, and
# costs only its row; --force grades a-correct again next to it.
mkdir -p "$work/slow-submissions/b-compile-hang"
cp -r "$submissions/a-correct" "$work/slow-submissions/"
cat > "$work/slow-submissions/b-compile-hang/ray_box.cpp" <<'CPP'
constexpr long spin(long seed) {
    long s = seed;
    for (long i = 0; i < 1000; ++i)
        for (long j = 0; j < 1000; ++j) s += i ^ j;
    return s;
}
template <int K> constexpr long slow = spin(K) + slow<K - 1>;
template <> constexpr long slow<0> = 0;
static_assert(slow<900> != 0);
CPP
cap=45
grade --submissions "$work/slow-submissions" --reports "$work/reports" --csv "$work/slow.csv" --force --jobs 2 \
    --submission-time-limit $cap "${flags[@]}" || fail "batch with a compile hang: exit $?: $(tail -1 "$work/err")"
grep -q "b-compile-hang: 0.00 of 100.00 points, .*took longer than $cap s (killed)" "$work/err" || fail "compile hang: $(cat "$work/err")"
grep -q "a-correct: 100.00 of 100.00 points" "$work/err" || fail "--force did not grade a-correct again: $(cat "$work/err")"
grep -q "^\"b-compile-hang\",0.00,100.00,\"not graded: its grading took longer than $cap s (killed)" "$work/slow.csv" || fail "CSV: $(cat "$work/slow.csv")"
sleep 1
if pgrep -f -- "$work/" > /dev/null; then fail "processes outlived the cap: $(pgrep -af -- "$work/")"; fi

# Bad input: one line naming the problem, exit 1, nothing overwritten.
for shard in 0/2 3/2 x 1/0 1/2/3; do
    grade --submissions "$submissions" --reports "$work/reports" --shard "$shard" "${flags[@]}"
    code=$?
    [ $code -eq 1 ] && [ "$(wc -l < "$work/err")" -eq 1 ] && grep -q -- "--shard $shard" "$work/err" || fail "--shard $shard: exit $code: $(cat "$work/err")"
done
mkdir "$work/broken-reports"
cp "$work/reports/a-correct.json" "$work/broken-reports/"
printf '{"tests": [' > "$work/broken-reports/truncated.json"
cp "$work/merged.csv" "$work/kept.csv"
grade merge "$work/broken-reports" --csv "$work/kept.csv"
code=$?
[ $code -eq 1 ] && [ "$(wc -l < "$work/err")" -eq 1 ] && grep -q "truncated.json" "$work/err" || fail "merge of a malformed report: exit $code: $(cat "$work/err")"
cmp -s "$work/merged.csv" "$work/kept.csv" || fail "a failed merge changed the CSV"

# --fail-under: the stubs score 0 of a0's 100 points, the solution all of them.
"$build/rtlab" grade --assignment a0 --quiet --fail-under 1 > /dev/null 2> "$work/err"
code=$?
[ $code -eq 1 ] && grep -q "below --fail-under 1 %" "$work/err" || fail "stubs with --fail-under 1: exit $code: $(cat "$work/err")"
"$build/rtlab-solution" grade --assignment a0 --quiet --fail-under 100 2> "$work/err" || fail "solution with --fail-under 100: $(cat "$work/err")"

[ $failures -eq 0 ] && echo "batch_grading: passed"
exit $((failures > 0))
