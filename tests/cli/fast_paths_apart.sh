#!/bin/bash
# The tuned paths stay apart (fast/CMakeLists.txt): nothing below fast/ in the layers includes
# it, the student's rtlab holds none of its code (the wide BVHs, their own builder, the tuned
# grid), and rtlab-solution does.
# Usage: fast_paths_apart.sh BUILD_DIR SOURCE_DIR
set -u
build=$1
source=$2
failures=0
includes=$(cd "$source" && grep -rlE '^#include "fast/' framework grader assignments solutions)
[ -z "$includes" ] || { echo "FAIL: these include fast/: $includes"; failures=$((failures + 1)); }
# Code of fast/ that a linker cannot leave out: the accelerator's vtable.
wide=$(nm -C "$build/rtlab" | grep -c "vtable for rtlab::WideBvhAccelerator")
[ "$wide" -eq 0 ] || { echo "FAIL: rtlab links the wide BVH"; failures=$((failures + 1)); }
wide=$(nm -C "$build/rtlab-solution" | grep -c "vtable for rtlab::WideBvhAccelerator")
[ "$wide" -eq 2 ] || { echo "FAIL: rtlab-solution lacks the wide BVHs (found $wide of 2 vtables)"; failures=$((failures + 1)); }
builder=$(nm -C "$build/rtlab" | grep -c " rtlab::WideBvh<[48]> rtlab::buildWideBvh<[48]>(")
[ "$builder" -eq 0 ] || { echo "FAIL: rtlab links fast/'s BVH builder"; failures=$((failures + 1)); }
builder=$(nm -C "$build/rtlab-solution" | grep -c " rtlab::WideBvh<[48]> rtlab::buildWideBvh<[48]>(")
[ "$builder" -eq 2 ] || { echo "FAIL: rtlab-solution lacks fast/'s BVH builder (found $builder of 2)"; failures=$((failures + 1)); }
grid=$(nm -C "$build/rtlab" | grep -c "vtable for rtlab::FastGridAccelerator")
[ "$grid" -eq 0 ] || { echo "FAIL: rtlab links the tuned grid"; failures=$((failures + 1)); }
grid=$(nm -C "$build/rtlab-solution" | grep -c "vtable for rtlab::FastGridAccelerator")
[ "$grid" -eq 1 ] || { echo "FAIL: rtlab-solution lacks the tuned grid"; failures=$((failures + 1)); }
echo "$((7 - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
