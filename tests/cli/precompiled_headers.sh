#!/bin/bash
# The grader compiles each submission file after the student headers, precompiled once
# (grader/engine/precompiled_header.h), and that changes no verdict:
#   - the precompiled header is kept in the build tree, and the toolchain's compiler takes it
#     (GCC's -H marks a precompiled header it uses with "!"; one it rejects, it reads as text);
#   - a file is compiled after it: a helper that names rtlab::Ray without including its header
#     compiles in grading;
#   - a file that compiles alone but clashes with the interfaces (a struct rtlab::Ray of its own) is
#     compiled again without the header, and the submission keeps full marks;
#   - where no header can be made (an interface header that does not compile), every file
#     compiles without it, with full marks, and the build test says why it was slower.
# Usage: precompiled_headers.sh BUILD_DIR SOURCE_DIR
set -u
build=$1
source=$2
. "$(dirname "$0")/grading_checks.sh"

# submission NAME HELPER_TEXT: the reference a0 with one more file, marked so that no other
# test has its bytes (the object cache would otherwise skip its compile).
submission() {
    reference_a0 "$1"
    printf '// precompiled_headers.sh %s\n%s\n' "$$" "$2" > "$scratch/$1/assignments/a0_intersect/helper.cpp"
}

if ! "$build/rtlab-grader" grade --help > /dev/null 2>&1; then fail "rtlab-grader does not run"; fi

submission uses 'namespace rtlab { float helperOrigin(const Ray& ray) { return ray.origin.x; } }'
grade uses || fail "the grading did not run: $(cat "$scratch/uses.log")"
[ "$(field uses "b['status']")" = passed ] ||
    fail "a helper naming rtlab::Ray without its include did not compile, so the student headers were not compiled first: $(field uses "b.get('reason')")"
[ "$(field uses "r['score'] == r['max_score']")" = True ] || fail "the reference a0 with a helper lost marks"

submission clashes 'namespace rtlab { struct Ray { int count; }; } int helperCount() { return rtlab::Ray{3}.count; }'
grade clashes || fail "the grading did not run: $(cat "$scratch/clashes.log")"
[ "$(field clashes "b['status']")" = passed ] ||
    fail "a file that compiles alone failed after the student headers: $(field clashes "b.get('reason')") $(field clashes "b['details'][-5:]")"
[ "$(field clashes "r['score'] == r['max_score']")" = True ] || fail "a file that compiles alone cost marks"

# A source root whose interfaces include one that does not compile alone, so that no header
# can be precompiled; an a0 submission never includes it. Its framework/ is a copy, the rest
# the source's (without .git, the stubs are its assignments/ as they are).
mkdir -p "$scratch/root"
for entry in "$source"/*; do [ "$(basename "$entry")" = framework ] || ln -s "$(realpath "$entry")" "$scratch/root/"; done
cp -r "$source/framework" "$scratch/root/"
printf '#pragma once\n#error "precompiled_headers.sh: this header does not compile"\n' > "$scratch/root/framework/interface/a99_unused.h"
reference_a0 without
"$build/rtlab-grader" grade --submission "$scratch/without" --assignment a0 --quiet --root "$scratch/root" --models "$build/models" \
    --work "$scratch/work-without" --json "$scratch/without.json" > "$scratch/without.log" 2>&1 ||
    fail "the grading without a precompiled header did not run: $(cat "$scratch/without.log")"
[ "$(field without "r['score'] == r['max_score']")" = True ] || fail "the reference a0 lost marks without a precompiled header"
[ "$(field without "any(d.startswith('slower: every file compiled without the precompiled') and 'a99_unused.h' in d for d in b['details'])")" = True ] ||
    fail "the build test does not say why it compiled without a precompiled header: $(field without "b['details']")"
[ "$(field uses "any(d.startswith('slower:') for d in b['details'])")" = False ] ||
    fail "a build with the precompiled header says it was slower: $(field uses "b['details']")"

# The kept header, and whether the compiler takes it with the submissions' flags.
header=$(find "$build/grader/precompiled-headers" -name rtlab_student_headers.h -newer "$scratch/uses" | head -1)
[ -n "$header" ] || header=$(find "$build/grader/precompiled-headers" -name rtlab_student_headers.h | head -1)
if [ -z "$header" ] || [ ! -f "$header.gch" ]; then
    fail "no precompiled header under $build/grader/precompiled-headers"
else
    mapfile -t flags < <(python3 -c "import json,sys; print('\n'.join(json.load(open(sys.argv[1]))['compile_flags']))" "$build/grader/submission-toolchain.json")
    compiler=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['compiler'])" "$build/grader/submission-toolchain.json")
    used=$("$compiler" "${flags[@]}" -Winvalid-pch -H -include "$header" -I "$scratch/work-uses/build/include" \
        -fsyntax-only "$source/solutions/a0_intersect/ray_box.cpp" 2>&1)
    grep -q "^! .*rtlab_student_headers.h.gch" <<< "$used" ||
        fail "the compiler does not use the precompiled header: $(head -3 <<< "$used")"
fi

[ $failures -eq 0 ] && echo "precompiled_headers: used by the compiler, no verdict changed"
exit $((failures > 0))
