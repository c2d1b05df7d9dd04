#!/bin/bash
# The process model of the grader (docs/grading.md, "Isolation and trust"), checked on the
# built executables: rtlab-grader contains no assignment function, and each worker is a
# static image whose first instruction is the framework's sandbox entry point.
# Usage: worker_image.sh BUILD_DIR
set -u
build=$1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# Every function of the assignment interfaces (framework/interface/*.h).
assignment_functions="intersectBox intersectTriangle intersectSphere buildBvh splitMedian splitMiddle splitEqualCounts
intersectBvhRecursive intersectBvh occludedBvh splitSahSweep splitSahBuckets"
symbols=$(nm -C "$build/rtlab-grader")
for f in $assignment_functions; do
    if grep -q "rtlab::$f(" <<< "$symbols"; then fail "rtlab-grader contains rtlab::$f"; fi
done

for worker in "$build/rtlab-worker" "$build/rtlab-worker-solution"; do
    [ -x "$worker" ] || { fail "$worker is missing"; continue; }
    headers=$(readelf -h -l "$worker")
    if grep -q "INTERP" <<< "$headers"; then fail "$worker asks for a dynamic loader"; fi
    if readelf -d "$worker" 2>/dev/null | grep -q NEEDED; then fail "$worker needs shared libraries"; fi
    entry=$(awk '/Entry point address/ {print $4}' <<< "$headers")
    sandbox=$(nm "$worker" | awk '$3 == "rtlab_worker_entry" {print "0x" $1}')
    if [ -z "$sandbox" ] || [ $((entry)) -ne $((sandbox)) ]; then
        fail "$worker starts at $entry, not at rtlab_worker_entry ($sandbox)"
    fi
    for f in intersectBox buildBvh splitSahSweep; do
        nm -C "$worker" | grep -q "rtlab::$f(" || fail "$worker lacks rtlab::$f: it is not the code to grade"
    done
    # Without the grader's filter on descriptor 4 the entry point refuses to start.
    "$worker" < /dev/null > /dev/null 2>&1
    status=$?
    [ "$status" -eq 121 ] || fail "$worker without a filter exited with $status, not 121 (kExitSandboxFailed)"
done

if [ "$failures" -ne 0 ]; then
    echo "$failures failed"
    exit 1
fi
echo "worker_image: all checks passed"
