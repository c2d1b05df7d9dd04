#!/bin/bash
# The Gradescope autograder end to end, from a scratch repository with uncommitted changes:
# the zip holds exactly the committed files a student release keeps (no solutions/, fast/,
# fixtures, nothing uncommitted) plus setup.sh and run_autograder at its root; run_autograder
# gives the reference solutions, handed in as a submission, full marks, and an empty
# submission 0 of the same points, with results.json as Gradescope specifies it.
# Usage: gradescope_autograder.sh BUILD_DIR SOURCE_DIR
set -eu
build=$1
source=$2
. "$source/tests/cli/scratch_repository.sh"  # $work, fail
repo=$work/repo
scratch_repository "$source" "$repo"

RTLAB="$build/rtlab" "$repo/scripts/make-gradescope" "$work/gradescope.zip" > /dev/null
(released_files "$repo"; printf '%s\n' setup.sh run_autograder) | sort > "$work/expected.files"
unzip -Z1 "$work/gradescope.zip" | grep -v '/$' | sort > "$work/zip.files"
diff "$work/expected.files" "$work/zip.files" > "$work/files.diff" ||
    fail "the zip's files are not HEAD's released files: $(head -5 "$work/files.diff")"
mkdir "$work/unpacked"
(cd "$work/unpacked" && unzip -q ../gradescope.zip)
! grep -rq "$UNCOMMITTED_MARKER" "$work/unpacked" || fail "an uncommitted change is in the zip"

# grade NAME: run_autograder on $work/NAME through the zip; results in $work/NAME.json.
grade() {
    RESULTS_COPY="$work/$1.json" RTLAB="$build/rtlab" "$repo/scripts/make-gradescope" --test "$work/$1" > /dev/null
}
mkdir -p "$work/reference/assignments" "$work/empty"
cp -r "$source"/solutions/. "$work/reference/assignments/"
grade reference
grade empty
python3 - "$work/reference.json" "$work/empty.json" <<'PY'
import json, sys
reference, empty = (json.load(open(p)) for p in sys.argv[1:])
for results in (reference, empty):
    assert results["tests"], "results.json has no tests"
    for t in results["tests"]:
        for field in ("name", "score", "max_score", "output", "visibility"):
            assert field in t, f"test {t.get('name')} lacks '{field}'"
total = sum(t["max_score"] for t in reference["tests"])
failed = [t["name"] + ": " + (t["output"].splitlines() or [""])[0] for t in reference["tests"] if t["score"] < t["max_score"]]
assert not failed, "the reference solutions as a submission lost points:\n" + "\n".join(failed)
assert abs(reference["score"] - total) < 1e-9, f"score {reference['score']} != {total}"
assert total > 0
empty_total = sum(t["max_score"] for t in empty["tests"])
assert abs(empty_total - total) < 1e-9, f"the empty submission is graded out of {empty_total}, not {total}"
assert empty["score"] == 0, f"the empty submission scored {empty['score']}"
scored = [t["name"] for t in empty["tests"] if t["score"] != 0]
assert not scored, "the empty submission scored in " + ", ".join(scored[:5])
print(f"1 passed: {len(reference['tests'])} tests; the reference as a submission {reference['score']} of {total}, "
      f"an empty submission 0 of {empty_total}")
PY
