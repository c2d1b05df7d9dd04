#!/bin/bash
# rtlab release end to end: a scratch repository holding this source tree, committed, then
# changed without committing; its release must hold the committed files only, none of the
# solutions, fast paths, fixtures or benchmarks, must refuse to overwrite, and must configure,
# build and grade as a student's first `make grade` does: every test not started, 0 points.
# Builds the release (a few minutes on two cores).
# Usage: student_release.sh BUILD_DIR SOURCE_DIR
set -eu
build=$1
source=$2
. "$source/tests/cli/scratch_repository.sh"  # $work, fail
repo=$work/repo
scratch_repository "$source" "$repo"
marker=$UNCOMMITTED_MARKER

release=$work/release
"$build/rtlab" release --from "$repo" "$release" > "$work/release.log" || fail "rtlab release: $(cat "$work/release.log")"

! grep -rq --exclude-dir=.git "$marker" "$release" || fail "an uncommitted change is in the release"
[ ! -e "$release/assignments/staged-notes.txt" ] && [ ! -e "$release/untracked-notes.txt" ] ||
    fail "an uncommitted file is in the release"
for left_out in solutions fast grader/fixtures bench tests .ci; do
    [ ! -e "$release/$left_out" ] || fail "$left_out/ is in the release"
done
# No file of the answers under another name either: no release file has the content of a
# solutions/, fast/ or grader/fixtures/ file.
(cd "$release" && git ls-files -z | xargs -0 sha256sum | cut -d' ' -f1 | sort -u) > "$work/release.sums"
(cd "$repo" && find solutions fast grader/fixtures -type f -size +0 -print0 | xargs -0 sha256sum | cut -d' ' -f1 | sort -u) > "$work/answers.sums"
[ -s "$work/answers.sums" ] || fail "the scratch repository has no solutions/ to leave out"
shared=$(comm -12 "$work/release.sums" "$work/answers.sums" | wc -l)
[ "$shared" -eq 0 ] || fail "$shared release files have the content of a solutions/, fast/ or fixtures file"
# Exactly the committed files, less those left out.
released_files "$repo" > "$work/expected.files"
(cd "$release" && git ls-files | sort) > "$work/release.files"
diff "$work/expected.files" "$work/release.files" > "$work/files.diff" || fail "release files differ from HEAD's: $(head -5 "$work/files.diff")"
[ "$(git -C "$release" rev-list --count HEAD)" -eq 1 ] || fail "the release is not one commit"
[ -z "$(git -C "$release" status --porcelain)" ] || fail "the release has uncommitted files"

# A folder that is not empty is refused with one line, and left as it was.
before=$(cd "$release" && find . -path ./.git -prune -o -type f -print | sort | xargs sha256sum | sha256sum)
if "$build/rtlab" release --from "$repo" "$release" 2> "$work/refused.err"; then fail "a non-empty folder was accepted"; fi
[ "$(wc -l < "$work/refused.err")" -eq 1 ] && grep -q "not empty" "$work/refused.err" ||
    fail "the refusal is not one line saying the folder is not empty: $(cat "$work/refused.err")"
after=$(cd "$release" && find . -path ./.git -prune -o -type f -print | sort | xargs sha256sum | sha256sum)
[ "$before" = "$after" ] || fail "the refused release changed the folder"

# Configure and build as `make grade` does (cmake --preset release), with this build's compiler
# cache (only what the release changes compiles), then grade the stubs.
(cd "$release" && cmake --preset release -DRTLAB_COMPILER_CACHE="$build/compiler-cache" > "$work/configure.log" 2>&1) || fail "the release does not configure: $(tail -5 "$work/configure.log")"
nice cmake --build "$release/build" -j 2 > "$work/build.log" 2>&1 || fail "the release does not build: $(grep -m3 error "$work/build.log")"
[ ! -e "$release/build/rtlab-solution" ] || fail "the release built an rtlab-solution"
# The same models for both, so both grade the same tests (the bunny's, if it is there).
"$release/build/rtlab" grade --quiet --models "$build/models" --json "$work/release-grade.json"
"$build/rtlab" grade --quiet --models "$build/models" --json "$work/tree-grade.json"
python3 - "$work/release-grade.json" "$work/tree-grade.json" <<'PY'
import json, sys
release, tree = (json.load(open(p)) for p in sys.argv[1:])
tests = release["tests"]
assert tests, "the release grades no tests"
started = [f'{t["name"]} ({t["status"]}, {t["score"]} points: {t["reason"][:120]})' for t in tests
           if t["status"] != "not started" or t["score"] != 0]
assert not started, "tests not 'not started' with 0 points:\n" + "\n".join(started[:5])
assert release["score"] == 0 and release["max_score"] > 0, (release["score"], release["max_score"])
names = sorted(t["name"] for t in tests)
assert names == sorted(t["name"] for t in tree["tests"]), "the release grades other tests than the source tree"
assert release["max_score"] == tree["max_score"], (release["max_score"], tree["max_score"])
print(f"1 passed: the release grades {len(tests)} tests, all not started, 0 of {release['max_score']} points")
PY
