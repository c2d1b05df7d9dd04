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
failures=0
passes=0

# expect CODE DESCRIPTION -- COMMAND...: runs COMMAND, checks its exit code, keeps its stderr.
expect() {
    local code=$1 description=$2
    shift 3
    "$@" > "$work/stdout" 2> "$work/stderr"
    local actual=$?
    if [ "$actual" -ne "$code" ]; then
        echo "FAIL: $description: exit $actual, expected $code ($*)"
        sed 's/^/    /' "$work/stderr" | head -5
        failures=$((failures + 1))
    else
        passes=$((passes + 1))
    fi
}

# one_line_naming TEXT DESCRIPTION: stderr is a single line that contains TEXT.
one_line_naming() {
    local lines
    lines=$(wc -l < "$work/stderr")
    if [ "$lines" -ne 1 ] || ! grep -qF -- "$1" "$work/stderr"; then
        echo "FAIL: $2: expected one line naming '$1', got:"
        sed 's/^/    /' "$work/stderr" | head -5
        failures=$((failures + 1))
    else
        passes=$((passes + 1))
    fi
}

for command in "" info render hits scene grade release export-blender compare refs; do
    expect 0 "rtlab $command --help" -- "$solution" $command --help
done
expect 2 "no subcommand" -- "$solution"
expect 2 "unknown subcommand" -- "$solution" frobnicate
expect 2 "unknown flag" -- "$solution" render "$scene" -o "$work/x.png" --no-such-flag
expect 2 "missing output" -- "$solution" render "$scene"

expect 1 "missing scene file" -- "$solution" info "$work/missing.gltf"
one_line_naming "missing.gltf" "missing scene file"

printf '{"asset": {"version": "2.0"}, "nodes": [' > "$work/broken.gltf"
expect 1 "malformed glTF" -- "$solution" render "$work/broken.gltf" -o "$work/out.png"
one_line_naming "broken.gltf" "malformed glTF"
[ -e "$work/out.png" ] && { echo "FAIL: an output was written for a broken scene"; failures=$((failures + 1)); }
expect 1 "malformed glTF to Blender" -- "$solution" export-blender "$work/broken.gltf" -o "$work/out.py"
one_line_naming "broken.gltf" "malformed glTF to Blender"
[ -e "$work/out.py" ] && { echo "FAIL: a Blender script was written for a broken scene"; failures=$((failures + 1)); }
expect 2 "compare --blender without the scene" -- "$solution" compare --blender "$work/broken.gltf"
expect 2 "compare with one image" -- "$solution" compare "$work/broken.gltf"
expect 2 "refs --hits with --blender" -- "$solution" refs --blender --hits

expect 1 "unknown accelerator" -- "$solution" render "$scene" -o "$work/x.png" --accel bvh-magic
one_line_naming "bvh-magic" "unknown accelerator"
expect 1 "bucket count out of range" -- "$solution" render "$scene" -o "$work/x.png" --accel bvh-buckets:99
one_line_naming "bvh-buckets:99" "bucket count out of range"
expect 1 "recursive traversal of the wide BVH" -- "$solution" render "$scene" -o "$work/x.png" --accel bvh4-sah --traversal recursive
one_line_naming "bvh4-sah" "recursive traversal of the wide BVH"

# The student binary does not link the fast paths (fast/): their names say where they are.
expect 1 "a wide BVH in the student binary" -- "$student" render "$scene" -o "$work/x.png" --accel bvh4-sah
one_line_naming "only into rtlab-solution" "a wide BVH in the student binary"
expect 1 "an option value out of its range" -- "$solution" render "$scene" -o "$work/x.png" --accel grid:C=0
one_line_naming "C must be a number in 1..1000" "an option value out of its range"
expect 1 "an option the structure does not have" -- "$solution" render "$scene" -o "$work/x.png" --accel grid:B=12
one_line_naming "'B=12' is not an option of grid" "an option the structure does not have"
"$student" render --help | grep -q "bvh4" && { echo "FAIL: rtlab render --help offers bvh4"; failures=$((failures + 1)); }
"$solution" render --help | grep -q "bvh4:" || { echo "FAIL: rtlab-solution render --help lacks bvh4"; failures=$((failures + 1)); }

release_dir=$work/release-into
mkdir "$release_dir"
echo keep > "$release_dir/mine.txt"
expect 1 "a release into a folder that is not empty" -- "$solution" release "$release_dir"
one_line_naming "is not empty" "a release into a folder that is not empty"
[ "$(ls -A "$release_dir")" = "mine.txt" ] && [ "$(cat "$release_dir/mine.txt")" = keep ] ||
    { echo "FAIL: a refused release changed the folder"; failures=$((failures + 1)); }
expect 1 "a release from a folder that is not a git repository" -- "$solution" release --from "$work" "$work/release-new"
one_line_naming "not a git repository" "a release from a folder that is not a git repository"
[ ! -e "$work/release-new" ] || { echo "FAIL: a failed release left its folder"; failures=$((failures + 1)); }

expect 1 "output into a missing folder" -- "$solution" render "$scene" -o "$work/no/such/dir/x.png"
one_line_naming "no/such/dir" "output into a missing folder"

cp "$scene" "$work/scene.gltf"
cp "$source"/scenes/*.bin "$work/" 2>/dev/null
before=$(sha256sum "$work/scene.gltf")
expect 1 "render onto the input scene" -- "$solution" render "$work/scene.gltf" -o "$work/scene.gltf"
[ "$(sha256sum "$work/scene.gltf")" = "$before" ] || { echo "FAIL: the input scene was changed"; failures=$((failures + 1)); }

printf '0 0 0 1 0\n' > "$work/bad-rays.txt"
expect 1 "malformed ray file" -- "$solution" hits "$scene" --rays "$work/bad-rays.txt" -o "$work/h.csv"
one_line_naming "bad-rays.txt:1" "malformed ray file"

expect 3 "a stub reached by the student binary" -- "$student" render "$scene" -o "$work/s.png" --accel brute
one_line_naming "not implemented" "a stub reached by the student binary"

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
