# Sourced by the tests of what is built from committed files only (student_release.sh,
# gradescope_autograder.sh).
#
# scratch_repository SOURCE DEST: DEST becomes a git repository holding SOURCE as git sees it
# (tracked and new files, nothing ignored) in one commit, plus uncommitted work that must never
# ship: an edit to a tracked stub, a staged new file and an untracked one, each containing
# $UNCOMMITTED_MARKER.
UNCOMMITTED_MARKER="UNCOMMITTED-$$-MARKER"
scratch_repository() {
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
