#!/bin/bash
# Adding an assignment is one folder per side and one registry entry (docs/adding-an-assignment.md).
# A scratch copy of the tree gets the page's example, a7 (a ray against a disk), from the page's
# own file blocks and its registry entry. It configures and builds with this build's compiler
# cache, so only what the example adds or changes is compiled. Then: git sees nothing changed
# outside the new folders but the registry's two lines; the reference earns every point and the
# stub is not started on every test; a submission, once the example is committed (its stubs are
# read at HEAD), earns every point as the reference and loses the test that pins the rule it
# breaks as a common mistake.
# Usage: new_assignment.sh BUILD_DIR SOURCE_DIR
set -eu
build=$1
source=$2
. "$source/tests/cli/scratch_repository.sh"  # $work, fail
tree=$work/tree
scratch_copy "$source" "$tree"
python3 "$source/tests/cli/write_example_assignment.py" "$source/docs/adding-an-assignment.md" "$tree" > "$work/written.txt" ||
    fail "the page's files were not written: $(cat "$work/written.txt")"

# Nothing changed but new files in the new folders, and two lines of the registry.
tab=$'\t'
new_folders='(framework/interface/a7_disk\.h|assignments/a7_disk/|solutions/a7_disk/|grader/a7_disk/)'
git -C "$tree" add --all
git -C "$tree" diff --cached --name-status > "$work/changes.txt"
grep -Ev "^A${tab}${new_folders}" "$work/changes.txt" > "$work/outside.txt" || true
[ "$(cat "$work/outside.txt")" = "M${tab}grader/assignment_registry.cpp" ] ||
    fail "the example changed more than its folders and the registry: $(tr '\n' ' ' < "$work/outside.txt")"
[ "$(git -C "$tree" diff --cached --numstat grader/assignment_registry.cpp | cut -f1-2)" = "2${tab}0" ] ||
    fail "the registry's change is not two added lines: $(git -C "$tree" diff --cached grader/assignment_registry.cpp)"
[ "$(grep -c "^A" "$work/changes.txt")" -ge 8 ] || fail "the page wrote too few files: $(cat "$work/written.txt")"

(cd "$tree" && cmake --preset release -DRTLAB_COMPILER_CACHE="$build/compiler-cache" > "$work/configure.log" 2>&1) ||
    fail "the tree with a7 does not configure: $(tail -5 "$work/configure.log")"
started=$SECONDS
nice cmake --build "$tree/build" -j 2 --target rtlab-grader rtlab-worker rtlab-worker-solution rtlab-sandbox-start rtlab_workers \
    > "$work/build.log" 2>&1 || fail "the tree with a7 does not build: $(grep -m3 -A3 error "$work/build.log")"
built_in=$((SECONDS - started))

grade() { "$tree/build/rtlab-grader" grade --quiet --assignment a7 "$@"; }
grade --worker "$tree/build/rtlab-worker-solution" --json "$work/solution.json"
grade --json "$work/stub.json" || true
mkdir -p "$work/submission/assignments/a7_disk" "$work/rim/assignments/a7_disk"
cp "$tree/solutions/a7_disk/ray_disk.cpp" "$work/submission/assignments/a7_disk/"
# A submission is built against the stubs at HEAD: before the commit, one line says so.
if grade --submission "$work/submission" > "$work/uncommitted.out" 2> "$work/uncommitted.err"; then
    fail "a submission was graded against a stub that is not committed"
fi
[ "$(wc -l < "$work/uncommitted.err")" -eq 1 ] && grep -q "assignments/a7_disk/ has no committed stub" "$work/uncommitted.err" ||
    fail "grading before the commit did not say why in one line: $(head -c 600 "$work/uncommitted.err")"
git -C "$tree" -c user.name=test -c user.email=test@localhost commit --quiet -m "a7: a ray against a disk"
grade --submission "$work/submission" --json "$work/submission.json"
# A common mistake: the rim does not count.
sed 's/<= radius \* radius/< radius * radius/' "$tree/solutions/a7_disk/ray_disk.cpp" > "$work/rim/assignments/a7_disk/ray_disk.cpp"
! cmp -s "$tree/solutions/a7_disk/ray_disk.cpp" "$work/rim/assignments/a7_disk/ray_disk.cpp" || fail "the rim mutant is the solution"
grade --submission "$work/rim" --json "$work/rim.json" || true

python3 - "$work" "$built_in" <<'PY'
import json, sys
work, built_in = sys.argv[1], int(sys.argv[2])
def tests(name):
    report = json.load(open(f"{work}/{name}.json"))
    return report, {t["name"]: t for t in report["tests"] if t["name"].startswith("a7/")}
expected = {"a7/disk/cases", "a7/disk/random-rays"}
for name in ("solution", "submission"):
    report, a7 = tests(name)
    assert set(a7) == expected, (name, sorted(a7))
    bad = [f'{t["name"]}: {t["status"]} {t["reason"][:160]}' for t in a7.values() if t["status"] != "passed"]
    assert not bad, f"the reference as {name} does not pass: {bad}"
    assert report["score"] == report["max_score"] == 100, (name, report["score"], report["max_score"])
report, a7 = tests("stub")
assert set(a7) == expected, sorted(a7)
started = [f'{t["name"]}: {t["status"]}' for t in a7.values() if t["status"] != "not started" or t["score"] != 0]
assert not started, f"the stub is not 'not started' everywhere: {started}"
report, a7 = tests("rim")
rim = a7["a7/disk/cases"]
assert rim["status"] == "failed" and "DSK-04" in rim["reason"], ("the rim mutant", rim["status"], rim["reason"][:200])
assert a7["a7/disk/random-rays"]["status"] == "passed", a7["a7/disk/random-rays"]["reason"][:200]
print(f"1 passed: a7 added in its folders and two registry lines; built through the compiler cache in {built_in} s; "
      f"the reference scores 100 of 100 (linked and as a submission), the stub is not started, the rim mutant fails {rim['name']}")
PY
