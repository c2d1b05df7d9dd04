#!/usr/bin/env python3
"""The docs' shell commands run as written (docs/README.md, "Commands in these pages").

Reads every Markdown file tracked by git and its fenced blocks:

* every fenced block names its language (```sh, ```text, ```cpp, ...), so no command hides in
  an anonymous block;
* ```sh, ```bash and ```shell blocks are commands, one a line (a trailing backslash continues
  it; `# ...` comments are the shell's); in ```console blocks the lines starting with `$ `;
* a block right after the comment `<!-- example: REASON -->` is not run: REASON says what it
  needs that the test does not have (a submission, Slurm, a full build, minutes).

Every other command runs with bash, in the repository's top folder, in a scratch copy of the
tracked files of SOURCE_DIR (a git repository of one commit) whose build/ is a link to
BINARY_DIR, the tree ctest built; one command after the other, in the order of the files, each
with a hard timeout. A command fails when it exits non-zero, except that a command of your
implementation (`build/rtlab ...`) may exit 3 with "... is not implemented yet": the stubs of
assignments/ throw NotImplemented until you fill them in. After the last command,
`git status --porcelain --ignored` of the scratch copy must show nothing new but ignored files
under out/ (the docs' output folder) or build*/ folders.

Usage: run_doc_commands.py SOURCE_DIR BINARY_DIR [--timeout SECONDS] [--keep] [--list]
Prints FILE:LINE: problem for each failure and exits 1 if any. Python 3 standard library only.
"""
import argparse
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

COMMAND_LANGUAGES = {"sh", "bash", "shell", "console"}
FENCE = re.compile(r"^(\s{0,3})(`{3,}|~{3,})\s*([^`\s]*)")
EXAMPLE = re.compile(r"^\s*<!--\s*example:\s*(.*?)\s*-->\s*$")
NOT_IMPLEMENTED = re.compile(r"is not implemented yet")
# What the commands may leave behind in the scratch copy: ignored files in these folders.
ALLOWED_OUTPUT = re.compile(r"^(out|build[^/]*)/")


class Command:
    def __init__(self, path, line, text, example):
        self.path, self.line, self.text, self.example = path, line, text, example

    def where(self):
        return f"{self.path}:{self.line}"


def tracked(root, *patterns):
    out = subprocess.run(["git", "-C", root, "ls-files", "-z", "--", *patterns], check=True,
                         capture_output=True).stdout.decode()
    return sorted(p for p in out.split("\0") if p and os.path.exists(os.path.join(root, p)))


def extract(root, rel, problems):
    """The commands of one Markdown file."""
    with open(os.path.join(root, rel), encoding="utf-8") as f:
        lines = f.read().splitlines()
    commands = []
    i = 0
    previous = ""  # the last non-blank line before the current one
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            if lines[i].strip():
                previous = lines[i]
            i += 1
            continue
        indent, fence, language = m.group(1), m.group(2), m.group(3).lower()
        start = i + 1
        i += 1
        body = []
        while i < len(lines) and not re.match(r"^\s{0,3}" + re.escape(fence[0]) + "{" + str(len(fence)) + r",}\s*$", lines[i]):
            body.append((i + 1, lines[i][len(indent):] if lines[i].startswith(indent) else lines[i].lstrip()))
            i += 1
        i += 1  # the closing fence
        marker = EXAMPLE.match(previous)
        previous = ""
        if not language:
            problems.append(f"{rel}:{start}: a fenced block without a language: name it (sh for commands, text for output, cpp, ...)")
            continue
        if language not in COMMAND_LANGUAGES:
            continue
        example = None
        if marker:
            example = marker.group(1)
            if not example:
                problems.append(f"{rel}:{start - 1}: an example marker without a reason: <!-- example: needs WHAT -->")
                example = "(no reason)"
        pending, pending_line = "", None
        for number, text in body:
            if language == "console":
                if not text.startswith("$ "):
                    continue
                text = text[2:]
            if not pending and (not text.strip() or text.lstrip().startswith("#")):
                continue
            if pending_line is None:
                pending_line = number
            if text.rstrip().endswith("\\"):
                pending += text.rstrip()[:-1] + " "
                continue
            commands.append(Command(rel, pending_line, pending + text, example))
            pending, pending_line = "", None
        if pending:
            problems.append(f"{rel}:{pending_line}: the command's last line ends with a backslash")
    return commands


def scratch_copy(source, binary, parent):
    tree = os.path.join(parent, "tree")
    os.mkdir(tree)
    for rel in tracked(source):
        target = os.path.join(tree, rel)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copy2(os.path.join(source, rel), target, follow_symlinks=False)
    env = dict(os.environ, GIT_AUTHOR_NAME="docs", GIT_AUTHOR_EMAIL="docs@localhost",
               GIT_COMMITTER_NAME="docs", GIT_COMMITTER_EMAIL="docs@localhost")
    for git in (["init", "-q"], ["add", "-A"], ["commit", "-q", "--no-verify", "-m", "scratch copy"]):
        subprocess.run(["git", "-c", "init.defaultBranch=main", "-c", "commit.gpgsign=false", *git], cwd=tree, check=True,
                       env=env, stdout=subprocess.DEVNULL)
    # build/ is the tree ctest built; a link, which git would list as untracked.
    os.symlink(os.path.realpath(binary), os.path.join(tree, "build"))
    with open(os.path.join(tree, ".git", "info", "exclude"), "a") as f:
        f.write("/build\n")
    return tree


def status(tree):
    out = subprocess.run(["git", "status", "--porcelain", "--ignored", "--untracked-files=all"], cwd=tree,
                         check=True, capture_output=True).stdout.decode()
    return set(line for line in out.splitlines() if line)


def run(command, tree, timeout):
    """Exit status (None on timeout), output, seconds. On timeout the command's whole process
    group is killed (it runs in a session of its own), so nothing it started lingers."""
    started = time.monotonic()
    process = subprocess.Popen(["bash", "-c", "set -o pipefail\n" + command.text], cwd=tree, stdin=subprocess.DEVNULL,
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, start_new_session=True)
    try:
        output, _ = process.communicate(timeout=timeout)
        code = process.returncode
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        output, _ = process.communicate()
        code = None
    return code, output.decode(errors="replace"), time.monotonic() - started


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("source")
    parser.add_argument("binary")
    parser.add_argument("--timeout", type=float, default=90, help="seconds per command (default 90)")
    parser.add_argument("--keep", action="store_true", help="keep the scratch copy and print where it is")
    parser.add_argument("--list", action="store_true", help="only list the commands and the examples")
    args = parser.parse_args()
    source = os.path.realpath(args.source)

    problems = []
    commands = []
    for rel in tracked(source, "*.md"):
        commands += extract(source, rel, problems)
    to_run = [c for c in commands if c.example is None]
    examples = [c for c in commands if c.example is not None]
    if args.list:
        for c in commands:
            print(f"{c.where()}: {'example (' + c.example + ')' if c.example else 'run'}: {c.text}")
        return 0

    parent = tempfile.mkdtemp(prefix="rtlab-doc-commands-")
    try:
        tree = scratch_copy(source, args.binary, parent)
        before = status(tree)
        for c in to_run:
            code, output, seconds = run(c, tree, args.timeout)
            stub = code == 3 and c.text.split()[0] == "build/rtlab" and NOT_IMPLEMENTED.search(output)
            verdict = "ok" if code == 0 else "ok (not implemented yet)" if stub else \
                f"timed out after {args.timeout:g} s" if code is None else f"exit {code}"
            print(f"{c.where()}: {verdict} in {seconds:.1f} s: {c.text}", flush=True)
            if code != 0 and not stub:
                tail = "".join("\n    " + l for l in output.rstrip().splitlines()[-15:])
                problems.append(f"{c.where()}: {verdict}: {c.text}{tail}")
        for line in sorted(status(tree) - before):
            path = line[3:]
            if not (line.startswith("!! ") and ALLOWED_OUTPUT.match(path)):
                what = "left an untracked file" if line.startswith("??") else \
                    "wrote an ignored file outside out/ and build*/" if line.startswith("!!") else "changed a tracked file"
                problems.append(f"the docs' commands {what}: {line}")
    finally:
        if args.keep:
            print(f"scratch copy kept in {parent}")
        else:
            shutil.rmtree(parent, ignore_errors=True)

    for p in problems:
        print(p)
    print(f"{len(to_run)} commands run, {len(examples)} examples not run; {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
