#!/bin/bash
# rtlab view's command line (docs/viewer.md#the-command): a viewer from rtlab and rtlab-solution,
# exit 2 for usage errors, exit 1 with one line naming the problem for bad input (an unknown
# accelerator, a ray index out of range, a folder that exists and is not a viewer), and nothing
# overwritten.
# Usage: viewer_cli.sh BUILD_DIR SOURCE_DIR
set -u
build=$1
source=$2
solution=$build/rtlab-solution
student=$build/rtlab
scene=$source/scenes/cornell-box.gltf
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$source/tests/cli/exit_checks.sh"
ray="0.13 1.17 3.5 0.031 -0.107 -1"
printf '0 1 3 0 0 -1\n0.2 1 3 0 0 -1\n' > "$work/two.rays"

run 0 "rtlab view --help" "$solution" view --help
run 0 "a ray through the BVH" "$solution" view "$scene" --accel bvh --ray "$ray" -o "$work/v"
[ -f "$work/v/index.html" ] && [ -f "$work/v/.rtlab-viewer" ] || fail "no viewer written"
run 0 "the same folder again (a viewer is replaced)" "$solution" view "$scene" --accel kdtree --rays "$work/two.rays" --index 1 -o "$work/v"
grep -q "kdtree" "$work/v/index.html" || fail "the viewer was not replaced"
# The student's binary writes a viewer too: its stub stops the walk, which the page says.
run 0 "rtlab (the stubs) on the brute force" "$student" view "$scene" --accel brute --ray "$ray" -o "$work/s"
grep -q "not implemented yet" "$work/s/index.html" || fail "the student's viewer does not name the stub"

run 1 "an unknown accelerator" "$solution" view "$scene" --accel trie --ray "$ray" -o "$work/u"
one_line "trie is not an accelerator" "an unknown accelerator"
[ -e "$work/u" ] && fail "a folder was written for an unknown accelerator"
run 1 "a ray index out of range" "$solution" view "$scene" --rays "$work/two.rays" --index 2 -o "$work/r"
one_line "ray index 2 is out of range (the file has 2 rays" "a ray index out of range"
mkdir "$work/mine" && echo keep > "$work/mine/notes.txt"
run 1 "a folder that is not a viewer" "$solution" view "$scene" --ray "$ray" -o "$work/mine"
one_line "is not a viewer folder" "a folder that is not a viewer"
[ "$(ls -A "$work/mine")" = "notes.txt" ] || fail "the folder that is not a viewer was changed"
echo x > "$work/file"
run 1 "a file as the folder" "$solution" view "$scene" --ray "$ray" -o "$work/file"
one_line "is not a folder" "a file as the folder"
run 1 "a malformed ray" "$solution" view "$scene" --ray "0 1 three 0 0 -1" -o "$work/m"
one_line "'three' is not a finite number" "a malformed ray"
run 1 "a zero direction" "$solution" view "$scene" --ray "0 1 3 0 0 0" -o "$work/m"
one_line "the direction is zero" "a zero direction"
run 1 "a pixel outside the image" "$solution" view "$scene" --pixel 400,10 -o "$work/p"
one_line "outside the 320x240 image" "a pixel outside the image"
run 1 "--index without --rays" "$solution" view "$scene" --index 1 -o "$work/i"
one_line "--index needs --rays" "--index without --rays"
run 1 "two kinds of ray" "$solution" view "$scene" --ray "$ray" --pixel 1,1 -o "$work/two"
one_line "give one of --ray" "two kinds of ray"
run 2 "a missing scene file" "$solution" view "$work/missing.gltf" --ray "$ray" -o "$work/x"
run 1 "no output folder" "$solution" view "$scene" --ray "$ray"
one_line "-o DIR is required" "no output folder"
for d in u r m p i two x; do [ -e "$work/$d" ] && fail "a folder $d was written for bad input"; done

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
