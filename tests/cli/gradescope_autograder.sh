#!/bin/bash
# The Gradescope autograder end to end: build the zip, unpack it into an /autograder layout,
# run run_autograder on a sample submission (the reference solutions in the repository layout)
# and check that results.json follows the spec and gives full marks.
# Usage: gradescope_autograder.sh BUILD_DIR SOURCE_DIR
set -eu
build=$1
source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/submission/assignments"
cp -r "$source"/solutions/. "$work/submission/assignments/"
RESULTS_COPY="$work/results.json" RTLAB="$build/rtlab" "$source/scripts/make-gradescope" --test "$work/submission"
python3 - "$work/results.json" <<'PY'
import json, sys
results = json.load(open(sys.argv[1]))
tests = results["tests"]
assert tests, "results.json has no tests"
for t in tests:
    for field in ("name", "score", "max_score", "output", "visibility"):
        assert field in t, f"test {t.get('name')} lacks '{field}'"
total = sum(t["max_score"] for t in tests)
failed = [t["name"] + ": " + t["output"].splitlines()[0] for t in tests if t["score"] < t["max_score"]]
assert not failed, "the reference solutions lost points:\n" + "\n".join(failed)
assert abs(results["score"] - total) < 1e-9, f"score {results['score']} != {total}"
print(f"1 passed, 0 failed: results.json has {len(tests)} tests, score {results['score']} of {total}")
PY
