#!/bin/bash
# The command-line contract: --help everywhere, exit 2 for usage errors, exit 1 with one line
# naming the file for bad input, exit 3 when a stub is reached, and nothing overwritten.
# Usage: cli_errors.sh BUILD_DIR SOURCE_DIR
set -u
build=$1
source=$2
solution=$build/rtlab-solution
student=$build/rtlab
scene=$source/scenes/cornell-box.gltf
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$source/tests/cli/exit_checks.sh"

for command in "" info render hits scene grade release export-blender compare refs; do
    run 0 "rtlab $command --help" "$solution" $command --help
done
run 2 "no subcommand" "$solution"
run 2 "unknown subcommand" "$solution" frobnicate
run 2 "unknown flag" "$solution" render "$scene" -o "$work/x.png" --no-such-flag
run 2 "missing output" "$solution" render "$scene"

run 1 "missing scene file" "$solution" info "$work/missing.gltf"
one_line "missing.gltf" "missing scene file"

printf '{"asset": {"version": "2.0"}, "nodes": [' > "$work/broken.gltf"
run 1 "malformed glTF" "$solution" render "$work/broken.gltf" -o "$work/out.png"
one_line "broken.gltf" "malformed glTF"
[ -e "$work/out.png" ] && fail "an output was written for a broken scene"
run 1 "malformed glTF to Blender" "$solution" export-blender "$work/broken.gltf" -o "$work/out.py"
one_line "broken.gltf" "malformed glTF to Blender"
[ -e "$work/out.py" ] && fail "a Blender script was written for a broken scene"
run 2 "compare --blender without the scene" "$solution" compare --blender "$work/broken.gltf"
run 2 "compare with one image" "$solution" compare "$work/broken.gltf"
run 2 "refs --hits with --blender" "$solution" refs --blender --hits

run 1 "unknown accelerator" "$solution" render "$scene" -o "$work/x.png" --accel bvh-magic
one_line "bvh-magic" "unknown accelerator"
run 1 "bucket count out of range" "$solution" render "$scene" -o "$work/x.png" --accel bvh-buckets:99
one_line "bvh-buckets:99" "bucket count out of range"
run 1 "recursive traversal of the wide BVH" "$solution" render "$scene" -o "$work/x.png" --accel bvh4-sah --traversal recursive
one_line "bvh4-sah" "recursive traversal of the wide BVH"

# The student binary does not link the fast paths (fast/): their names say where they are.
run 1 "a wide BVH in the student binary" "$student" render "$scene" -o "$work/x.png" --accel bvh4-sah
one_line "only into rtlab-solution" "a wide BVH in the student binary"
run 1 "the tuned grid in the student binary" "$student" render "$scene" -o "$work/x.png" --accel fastgrid
one_line "fastgrid is a fast path of fast/" "the tuned grid in the student binary"
run 1 "the fast BVH in the student binary" "$student" render "$scene" -o "$work/x.png" --accel fastbvh:width=4
one_line "fastbvh is a fast path of fast/" "the fast BVH in the student binary"
run 1 "an option value out of its range" "$solution" render "$scene" -o "$work/x.png" --accel grid:C=0
one_line "C must be a number in 1..1000" "an option value out of its range"
run 1 "an option the structure does not have" "$solution" render "$scene" -o "$work/x.png" --accel grid:B=12
one_line "'B=12' is not an option of grid" "an option the structure does not have"
run 0 "rtlab render --help" "$student" render --help
grep -q "bvh4" "$work/stdout" && fail "rtlab render --help offers bvh4"
run 0 "rtlab-solution render --help" "$solution" render --help
grep -q "bvh4:" "$work/stdout" || fail "rtlab-solution render --help lacks bvh4"
grep -q "fastgrid:" "$work/stdout" || fail "rtlab-solution render --help lacks fastgrid"
grep -q "fastbvh:" "$work/stdout" || fail "rtlab-solution render --help lacks fastbvh"

release_dir=$work/release-into
mkdir "$release_dir"
echo keep > "$release_dir/mine.txt"
run 1 "a release into a folder that is not empty" "$solution" release "$release_dir"
one_line "is not empty" "a release into a folder that is not empty"
[ "$(ls -A "$release_dir")" = "mine.txt" ] && [ "$(cat "$release_dir/mine.txt")" = keep ] ||
    fail "a refused release changed the folder"
run 1 "a release from a folder that is not a git repository" "$solution" release --from "$work" "$work/release-new"
one_line "not a git repository" "a release from a folder that is not a git repository"
[ ! -e "$work/release-new" ] || fail "a failed release left its folder"

run 1 "output into a missing folder" "$solution" render "$scene" -o "$work/no/such/dir/x.png"
one_line "no/such/dir" "output into a missing folder"

cp "$scene" "$work/scene.gltf"
cp "$source"/scenes/*.bin "$work/" 2>/dev/null
before=$(sha256sum "$work/scene.gltf")
run 1 "render onto the input scene" "$solution" render "$work/scene.gltf" -o "$work/scene.gltf"
[ "$(sha256sum "$work/scene.gltf")" = "$before" ] || fail "the input scene was changed"

printf '0 0 0 1 0\n' > "$work/bad-rays.txt"
run 1 "malformed ray file" "$solution" hits "$scene" --rays "$work/bad-rays.txt" -o "$work/h.csv"
one_line "bad-rays.txt:1" "malformed ray file"

run 3 "a stub reached by the student binary" "$student" render "$scene" -o "$work/s.png" --accel brute
one_line "not implemented" "a stub reached by the student binary"

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
