#!/bin/bash
# What a student types, as issue 12 asked for it: an unknown command is named with the list of
# commands, bad ray files and scenes get one line naming the file, `bench --help` is called
# `rtlab bench`, bench's --accel takes settings, and a default render stopped by a stub says which file to fill in.
# Usage: student_cli.sh BUILD_DIR SOURCE_DIR
set -u
build=$1
source=$2
solution=$build/rtlab-solution
student=$build/rtlab
scene=$source/scenes/cornell-box.gltf
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$source/tests/cli/exit_checks.sh"

run 2 "unknown command" "$solution" frobnicate
one_line "unknown command 'frobnicate'" "unknown command"
grep -qF "render" "$work/stderr" && grep -qF "compare" "$work/stderr" || fail "unknown command: the commands are not listed"
# A hostile command word is escaped, never sent to the terminal as it is.
run 2 "unknown command with an escape" "$solution" $'\e]0;pwned\a'
grep -q $'\e' "$work/stderr" && fail "an escape byte of the command word reached the terminal"
run 0 "a known command still works" "$solution" info "$scene"

printf '0 0 5 0 0 -1\n0 0 5 nan 0 -1\n' > "$work/nan-rays.txt"
run 1 "nan in a ray file" "$solution" hits "$scene" --rays "$work/nan-rays.txt" -o "$work/hits.csv"
one_line "nan-rays.txt:2:" "nan in a ray file"
printf '1e40 0 5 0 0 -1\n' > "$work/big-rays.txt"
run 1 "1e40 in a ray file" "$solution" hits "$scene" --rays "$work/big-rays.txt" -o "$work/hits.csv"
one_line "big-rays.txt:1: '1e40' is out of float range" "1e40 in a ray file"
printf '0 0 5 0 0 -1 0 z\033[31mred\n' > "$work/escape-rays.txt"
run 1 "an escape in a ray file" "$solution" hits "$scene" --rays "$work/escape-rays.txt" -o "$work/hits.csv"
grep -q $'\e' "$work/stderr" && fail "an escape byte of a ray file reached the terminal"

head -c 300 /dev/urandom > "$work/garbage.glb"
printf 'not glTF' | cat - "$work/garbage.glb" > "$work/broken.glb"
run 1 "a garbage .glb" "$solution" info "$work/broken.glb"
one_line "broken.glb: not a binary glTF" "a garbage .glb"

# bench hands over to the benchmark executable; scripts/install-deps installs Embree, so a
# build without it is a broken set-up, not a reason to skip.
[ -x "$build/rtlab-solution-bench" ] || fail "$build/rtlab-solution-bench is not built (is libembree-dev installed?)"
run 0 "bench --help" "$solution" bench --help
grep -q "rtlab-solution bench" "$work/stdout" || fail "bench --help does not name rtlab-solution bench"
grep -q "rtlab-solution-bench" "$work/stdout" && fail "bench --help names the executable rtlab-solution-bench"
# bench --accel takes a structure with settings of its own, as render and hits do, and names
# what is wrong with one it cannot make.
run 0 "bench --accel with a setting" "$solution" bench --quick --scenes bunny --accel fastbvh:bins=8 \
  --no-race --no-convergence --no-parameters --no-estimators --no-render
grep -qE '^\| rtlab:fastbvh:bins=8 \| [0-9.]+ \|' "$work/stdout" || fail "bench --accel fastbvh:bins=8 measured no row of its own"
run 1 "bench --accel with a setting out of range" "$solution" bench --accel fastbvh:bins=99
one_line "--accel fastbvh:bins=99: bins must be" "bench --accel with a setting out of range"

# The student binary of this repository has every stub unfilled: a default render stops in
# a0 or a1 (no accelerator avoids those) with exit 3 and the stub's file, not in a2.
run 3 "a default render with the stubs unfilled" "$student" render "$scene" -o "$work/student.png"
one_line "assignments/a" "a default render with the stubs unfilled"
grep -q "a2_sah" "$work/stderr" && fail "a default render names an a2 stub before a0/a1"
# The reference renders a viewable PNG by default, without a note.
run 0 "a default render" "$solution" render "$scene" -o "$work/view.png"
[ -s "$work/stderr" ] && fail "a default render of the reference printed on stderr"

# Grading a few tests by name: only they run and are listed; a pattern nothing matches is an
# error, not an empty report.
run 0 "grade --test" "$solution" grade --assignment a0 --test 'a0/slab/*' --test '*/sphere/cases' --json "$work/some.json" --quiet
python3 - "$work/some.json" <<'PY' || fail "grade --test listed other tests, or not these"
import json, sys
names = sorted(t["name"] for t in json.load(open(sys.argv[1]))["tests"])
assert names == ["a0/slab/face-planes", "a0/slab/flat-boxes", "a0/slab/interval", "a0/slab/shared-edge-property", "a0/sphere/cases"], names
PY
run 1 "grade --test matching nothing" "$solution" grade --assignment a0 --test 'a9/*'
one_line "--test: no test of the graded assignments matches" "grade --test matching nothing"

if [ "$failures" -ne 0 ]; then
    echo "$failures failures"
    exit 1
fi
echo "student_cli: all passed"
