#!/usr/bin/env python3
"""Writes the example assignment of docs/adding-an-assignment.md into a copy of the tree.

The fenced block right after `<!-- file: PATH -->` becomes the file PATH, which must not exist
yet. The block right after `<!-- registry: FILE -->` holds two lines: an `#include`, which goes
after the last `#include "grader/...` of FILE, and the registry's entry, which goes after the
last entry of its list (a line that starts with `{"`).

Usage: write_example_assignment.py PAGE TREE
Prints the files it wrote; on a problem, one line naming the page and the problem, exit 1.
Python 3 standard library only.
"""
import os
import re
import sys

MARKER = re.compile(r"^<!--\s*(file|registry):\s*(\S+)\s*-->\s*$")
FENCE = re.compile(r"^```")


def blocks(lines):
    """(kind, path, text) for every marked block, in the page's order."""
    i = 0
    while i < len(lines):
        marker = MARKER.match(lines[i])
        i += 1
        if not marker:
            continue
        if i >= len(lines) or not FENCE.match(lines[i]):
            raise ValueError(f"line {i}: the {marker.group(1)} marker is not followed by a fenced block")
        end = next((j for j in range(i + 1, len(lines)) if FENCE.match(lines[j])), None)
        if end is None:
            raise ValueError(f"line {i + 1}: the fenced block never ends")
        yield marker.group(1), marker.group(2), "\n".join(lines[i + 1:end]) + "\n"
        i = end + 1


def add_registry_entry(path, text):
    include = [line for line in text.splitlines() if line.startswith("#include ")]
    entry = [line for line in text.splitlines() if line.lstrip().startswith('{"')]
    if len(include) != 1 or len(entry) != 1 or len(text.splitlines()) != 2:
        raise ValueError("the registry block is not one #include and one entry")
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    last_include = max((k for k, line in enumerate(lines) if line.startswith('#include "grader/')), default=None)
    last_entry = max((k for k, line in enumerate(lines) if line.lstrip().startswith('{"')), default=None)
    if last_include is None or last_entry is None:
        raise ValueError(f"{path} has no include of grader/ or no registry entry to follow")
    lines.insert(last_entry + 1, entry[0])
    lines.insert(last_include + 1, include[0])
    with open(path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: write_example_assignment.py PAGE TREE")
    page, tree = sys.argv[1], sys.argv[2]
    try:
        with open(page, encoding="utf-8") as f:
            lines = f.read().splitlines()
        found = list(blocks(lines))
        if not any(kind == "file" for kind, _, _ in found) or sum(kind == "registry" for kind, _, _ in found) != 1:
            raise ValueError("it needs file blocks and one registry block")
        for kind, rel, text in found:
            path = os.path.join(tree, rel)
            if os.path.isabs(rel) or ".." in rel.split("/"):
                raise ValueError(f"{rel} is not a path inside the tree")
            if kind == "registry":
                add_registry_entry(path, text)
                continue
            if os.path.exists(path):
                raise ValueError(f"{rel} exists already: the example adds files, it never replaces one")
            os.makedirs(os.path.dirname(path), exist_ok=True)
            with open(path, "w", encoding="utf-8") as f:
                f.write(text)
            print(rel)
    except (OSError, ValueError) as e:
        sys.exit(f"{page}: {e}")


if __name__ == "__main__":
    main()
