#!/bin/sh
# Gradescope runs this once when it builds the autograder image (Ubuntu base; docs/grading.md,
# "Gradescope"): install the packages rtlab needs, build it, fetch the bunny.
set -eu
cd /autograder/source
scripts/install-deps
cmake --preset release
cmake --build --preset release -j "$(nproc)"
scripts/fetch-models build/models || echo "setup.sh: no bunny (graded on a procedural mesh instead)"
# Student code runs as this unprivileged user, on top of the grader's own sandbox.
id student >/dev/null 2>&1 || adduser --disabled-password --gecos "" student
