# Sourced by the tests that grade submissions of their own on a0 (unit_object_cache.sh,
# precompiled_headers.sh): a scratch folder removed on exit, the grading, and checks over its
# JSON report. The sourcing script sets $build and $source; `failures` counts the failed checks.
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
failures=0

fail() {
    echo "FAIL: $*"
    failures=$((failures + 1))
}

# reference_a0 NAME: $scratch/NAME, a submission of the reference a0.
reference_a0() {
    mkdir -p "$scratch/$1/assignments"
    cp -r "$source/solutions/a0_intersect" "$scratch/$1/assignments/"
}

# grade NAME [GRADER]: grades $scratch/NAME on a0 with GRADER (rtlab-grader of the build by
# default), working in $scratch/work-NAME, into $scratch/NAME.json and $scratch/NAME.log.
grade() {
    "${2:-$build/rtlab-grader}" grade --submission "$scratch/$1" --assignment a0 --quiet --root "$source" \
        --models "$build/models" --work "$scratch/work-$1" --json "$scratch/$1.json" > "$scratch/$1.log" 2>&1
}

# field NAME EXPR: a Python expression over the report r of grading NAME and its build test b.
field() {
    python3 -c "import json,sys; r=json.load(open(sys.argv[1])); b=r['tests'][0]; print($2)" "$scratch/$1.json"
}
