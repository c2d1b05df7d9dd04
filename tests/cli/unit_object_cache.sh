#!/bin/bash
# The grader's object cache (grader/engine/unit_object_cache.h) serves an object only for the
# same bytes seen the same way, and changes no verdict and no message:
#   - a second grading of the same submission compiles nothing and reports what the first did,
#     the compiler's warnings included;
#   - a header of the submission changed under an unchanged .cpp recompiles that .cpp, and the
#     verdict follows the header;
#   - a .cpp cannot include another .cpp (each compiles in a view of its own), and says so;
#   - the committed stubs of the assignments not graded compile once per assignment folder
#     (grader/engine/stub_object_cache.h), whichever others a grading leaves out.
# Other tests grade at the same time and share the cache, so counts are checked as "all"/"none"
# only where the bytes are this test's own.
# Usage: unit_object_cache.sh BUILD_DIR SOURCE_DIR
set -u
build=$1
source=$2
. "$(dirname "$0")/grading_checks.sh"

# A submission whose ray_box.cpp depends on a header of its own and prints a warning, with a marker in a comment so that no other test ever has these bytes.
make_submission() {
    local dir=$scratch/$1 value=$2
    reference_a0 "$1"
    printf '#pragma once\n// unit_object_cache.sh %s\nnamespace cached_test { constexpr float kScale = %s; }\n' "$$" "$value" \
        > "$dir/assignments/a0_intersect/scale.h"
    python3 - "$dir/assignments/a0_intersect/ray_box.cpp" <<'PY'
import re, sys
path = sys.argv[1]
text = open(path).read()
text = text.replace('#include', '#include "scale.h"\n#include', 1)
# A hit only while the header's constant is 1 (the reference); with 2 every box is missed.
text, n = re.subn(r'return (true|false);', r'return (\1) && cached_test::kScale == 1.0f;', text)
assert n > 0, "ray_box.cpp has no return to scale"
text += '\nnamespace { int unusedHere() { int unusedWarning = 3; return 0; } }\n'
open(path, 'w').write(text)
PY
}

make_submission first 1.0f
grade first || fail "the first grading did not run: $(cat "$scratch/first.log")"
cp -r "$scratch/first" "$scratch/again"
grade again || fail "the second grading did not run: $(cat "$scratch/again.log")"
[ "$(field again "'compiled 0 of' in ' '.join(b['details'])")" = True ] ||
    fail "the same bytes compiled again: $(field again "b['details']")"
[ "$(field first "[t['status'] for t in r['tests']]")" = "$(field again "[t['status'] for t in r['tests']]")" ] ||
    fail "a cached object changed a verdict"
[ "$(field first "[d for d in b['details'] if 'warning' in d]")" = "$(field again "[d for d in b['details'] if 'warning' in d]")" ] ||
    fail "a cached object lost the compiler's messages"
[ "$(field again "any('unusedWarning' in d for d in b['details'])")" = True ] ||
    fail "the compiler's warning is not in the build test: $(field again "b['details']")"
[ "$(field first "r['score'] == r['max_score']")" = True ] || fail "the reference with scale 1 does not earn full marks"

# The header changes, ray_box.cpp does not: its object must not come from the cache.
make_submission changed 2.0f
grade changed || fail "the grading with a changed header did not run: $(cat "$scratch/changed.log")"
[ "$(field changed "r['score'] < r['max_score']")" = True ] ||
    fail "a changed header under an unchanged .cpp kept the old object (full marks with scale 2)"
# The build test's count says "compiled before" exactly when some files were.
for name in first again changed; do
    [ "$(field $name "[('compiled before' in l) == (l.split()[1] != l.split()[3]) for l in b['details'] if l.startswith('compiled ')]")" = "[True]" ] ||
        fail "the $name grading's count of compiled files reads wrong: $(field $name "b['details'][:3]")"
done

# One .cpp including another finds nothing.
make_submission includes 1.0f
printf '#include "ray_sphere.cpp"\n' >> "$scratch/includes/assignments/a0_intersect/ray_triangle.cpp"
grade includes
[ "$(field includes "b['status']")" = failed ] || fail "a .cpp included another .cpp"
[ "$(field includes "'ray_sphere.cpp' in b['reason']")" = True ] || fail "the build test does not name the missing file: $(field includes "b['reason']")"

# Grading a0 left out a1..a6, so each of their folders has its stubs' object; grading a1 leaves
# out a2..a6, another set of the same folders, and compiles none of them (a folder compiled in a
# grading has its own place under the work folder's build/stubs/).
"$build/rtlab-grader" grade --submission "$scratch/first" --assignment a1 --quiet --root "$source" --models "$build/models" \
    --work "$scratch/work-a1" --json "$scratch/a1.json" > "$scratch/a1.log" 2>&1 || fail "the a1 grading did not run: $(cat "$scratch/a1.log")"
[ -d "$scratch/work-a1/build/objects" ] && [ ! -e "$scratch/work-a1/build/stubs" ] ||
    fail "grading a1 after a0 compiled committed stubs again: $(ls "$scratch/work-a1/build/stubs" 2>&1 | tr '\n' ' ')"
[ "$(ls "$scratch/work-a1/build/objects" | grep -c '^stubs-a[2-6]_')" = 5 ] ||
    fail "grading a1 did not link a stubs' object per folder left out: $(ls "$scratch/work-a1/build/objects" | tr '\n' ' ')"

[ $failures -eq 0 ] && echo "unit_object_cache: repeated bytes served from the cache, changed headers recompiled, stubs compiled once per folder"
exit $((failures > 0))
