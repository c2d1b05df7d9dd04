# Sourced by the tests that build from committed files only (student_release.sh,
# gradescope_autograder.sh, new_assignment.sh).
#
# scratch_repository SOURCE DEST: DEST becomes a git repository holding SOURCE as git sees it
# (tracked and new files, nothing ignored) in one commit, plus uncommitted work that must never
# ship: an edit to a tracked stub, a staged new file and an untracked one, each containing
# $UNCOMMITTED_MARKER.
#
# scratch_copy SOURCE DEST: the same repository without the uncommitted work.
#
# Also what these tests share: $work, a folder of their own removed when they exit, and fail.
UNCOMMITTED_MARKER="UNCOMMITTED-$$-MARKER"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

scratch_copy() {
    local source=$1 dest=$2 f
    mkdir -p "$dest"
    (cd "$source" && git ls-files -z --cached --others --exclude-standard) | while IFS= read -r -d '' f; do
        [ -f "$source/$f" ] || continue
        mkdir -p "$dest/$(dirname "$f")"
        cp -p "$source/$f" "$dest/$f"
    done
    git -C "$dest" init --quiet
    git -C "$dest" add --all
    git -C "$dest" -c user.name=test -c user.email=test@localhost commit --quiet -m "scratch"
}

scratch_repository() {
    local source=$1 dest=$2
    scratch_copy "$source" "$dest"
    echo "// $UNCOMMITTED_MARKER" >> "$dest/assignments/a0_intersect/ray_box.cpp"
    echo "$UNCOMMITTED_MARKER" > "$dest/assignments/staged-notes.txt"
    git -C "$dest" add assignments/staged-notes.txt
    echo "$UNCOMMITTED_MARKER" > "$dest/untracked-notes.txt"
}

# The files committed at HEAD of repository REPO that a student release keeps, sorted: everything but
# what rtlab release leaves out (cli/release_command.cpp).
released_files() {
    git -C "$1" ls-tree -r --name-only HEAD | grep -Ev '^(solutions|fast|grader/fixtures|bench|tests|\.ci)/' | sort
}
