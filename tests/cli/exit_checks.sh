# Sourced by the tests of the command-line contract (cli_errors.sh, student_cli.sh): checks of a
# command's exit status and of the one line it writes on stderr. The sourcing script sets $work,
# a scratch folder; `failures` counts the checks that failed, `passes` those of run and
# one_line that passed.
failures=0
passes=0

# fail MESSAGE: a failed check, shown with the first lines of the last command's stderr.
fail() {
    echo "FAIL: $1"
    sed 's/^/    /' "$work/stderr" | head -5
    failures=$((failures + 1))
}

# run CODE DESCRIPTION COMMAND...: runs COMMAND and checks its exit code; keeps its stdout and
# stderr in $work.
run() {
    local code=$1 description=$2
    shift 2
    "$@" > "$work/stdout" 2> "$work/stderr"
    local actual=$?
    if [ "$actual" -eq "$code" ]; then
        passes=$((passes + 1))
    else
        fail "$description: exit $actual, expected $code ($*)"
    fi
}

# one_line TEXT DESCRIPTION: the last command's stderr is one line containing TEXT.
one_line() {
    if [ "$(wc -l < "$work/stderr")" -eq 1 ] && grep -qF -- "$1" "$work/stderr"; then
        passes=$((passes + 1))
    else
        fail "$2: expected one line naming '$1'"
    fi
}
