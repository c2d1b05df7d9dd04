#!/bin/bash
# The JUnit XML of a real grading run validates against grader/schemas/junit-10.xsd, for a run
# with failures (the stubs: every test not started) and one without (the reference solution).
# Usage: junit_schema.sh BUILD_DIR SOURCE_DIR
set -u
build=$1
source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
for rtlab in rtlab rtlab-solution; do
    if ! timeout 300 "$build/$rtlab" grade --assignment a0 --quiet --junit "$work/$rtlab.xml" > "$work/$rtlab.log" 2>&1; then
        echo "FAIL: $rtlab grade --junit did not finish:"; tail -5 "$work/$rtlab.log"; failures=$((failures + 1)); continue
    fi
    if ! xmllint --noout --schema "$source/grader/schemas/junit-10.xsd" "$work/$rtlab.xml" 2> "$work/xmllint.log"; then
        echo "FAIL: $rtlab's JUnit XML is not valid junit-10:"; head -5 "$work/xmllint.log"; failures=$((failures + 1))
    fi
done
# The stubs fail every test; a schema check over a report without failures would prove less.
grep -q '<failure type="not started"' "$work/rtlab.xml" || { echo "FAIL: the stubs' report has no failure element"; failures=$((failures + 1)); }
grep -q '<failure' "$work/rtlab-solution.xml" && { echo "FAIL: the solution's report has a failure"; failures=$((failures + 1)); }
# And the schema rejects what it must: a testcase without a name.
sed 's/<testcase name="[^"]*"/<testcase/' "$work/rtlab.xml" > "$work/broken.xml"
if xmllint --noout --schema "$source/grader/schemas/junit-10.xsd" "$work/broken.xml" 2> /dev/null; then
    echo "FAIL: the schema accepts a testcase without a name"; failures=$((failures + 1))
fi
[ $failures -eq 0 ] && echo "junit_schema: passed"
exit $((failures > 0))
