#!/usr/bin/env python3
"""The layers of the house (docs/layout.md): nothing includes upward, and peers that should not
know each other do not.

Every #include "a/b/c.h" in a tracked .cpp or .h file is an edge from the including file's
layer to the included file's layer. Layers are framework/<part> (core, interface, scene, accel,
oracle, sampling, render, external, pov, blender), grader (with grader/worker), viewer, cli, fast, bench, fuzz,
assignments, solutions and tests. ALLOWED lists, for each layer, the layers it may include besides itself;
any other edge is printed as FILE:LINE and fails the test, and so does a file in a layer the
table does not know (a new folder must say where it sits).

Usage: check_include_graph.py SOURCE_DIR
"""
import os
import re
import subprocess
import sys

FRAMEWORK = {"framework/" + p for p in ("core", "interface", "scene", "accel", "oracle", "sampling", "render", "external",
                                        "pov", "blender")}

ALLOWED = {
    "framework/core": set(),
    # The student contract: what assignments and solutions see.
    "framework/interface": {"framework/core"},
    "framework/scene": {"framework/core"},
    "framework/accel": {"framework/core", "framework/interface", "framework/scene"},
    "framework/oracle": {"framework/core", "framework/scene"},
    # Random numbers and stratification for the renderer, the bench and the grader.
    "framework/sampling": {"framework/core"},
    "framework/render": {"framework/core", "framework/interface", "framework/scene", "framework/accel", "framework/oracle",
                         "framework/sampling"},
    # Running the reference renderers (a time limit, a scratch folder) and the manifest of their inputs.
    "framework/external": {"framework/core"},
    "framework/pov": {"framework/core", "framework/scene", "framework/oracle", "framework/render", "framework/external"},
    # Beside pov/: the Blender Cycles exporter and references of the radiometry scenes.
    "framework/blender": {"framework/core", "framework/scene", "framework/external"},
    # Student code and the reference solutions: only the contract.
    "assignments": {"framework/core", "framework/interface"},
    "solutions": {"framework/core", "framework/interface"},
    # Never any assignment code, the fast paths or the command line.
    "grader": FRAMEWORK | {"grader/worker"},
    "grader/worker": FRAMEWORK | {"grader"},
    "fast": FRAMEWORK,
    # The viewer sits above the grader (it reads traces, structure views and the grader's
    # statistics) and below the command line; nothing below it includes it.
    "viewer": FRAMEWORK | {"grader", "grader/worker"},
    "cli": FRAMEWORK | {"grader", "grader/worker", "viewer"},
    "bench": FRAMEWORK | {"fast"},
    "fuzz": FRAMEWORK | {"grader", "grader/worker"},
    # The test suite and the hostile fixtures may reach anything.
    "tests": None,
    "grader/fixtures": None,
}


def layer_of(path):
    parts = path.split("/")
    if parts[0] == "framework" and len(parts) > 2:
        return "framework/" + parts[1]
    if parts[0] == "grader" and len(parts) > 2 and parts[1] in ("worker", "fixtures"):
        return "grader/" + parts[1]
    return parts[0] if len(parts) > 1 else None


def main():
    source = sys.argv[1]
    files = subprocess.run(["git", "-C", source, "ls-files", "*.cpp", "*.h"], capture_output=True, text=True,
                           check=True).stdout.split()
    problems = []
    include = re.compile(r'\s*#\s*include\s+"([^"]+)"')
    intrinsics = re.compile(r'\s*#\s*include\s+<(\w*intrin\.h|arm_neon\.h)>')
    for path in files:
        layer = layer_of(path)
        if layer is None:
            continue
        if layer not in ALLOWED:
            problems.append(f"{path}:1: layer {layer} is not in the include-graph table")
            continue
        allowed = ALLOWED[layer]
        with open(os.path.join(source, path), errors="replace") as f:
            for number, line in enumerate(f, 1):
                simd = intrinsics.match(line)
                if simd and layer not in ("fast", "tests", "bench"):
                    problems.append(f"{path}:{number}: <{simd.group(1)}> outside fast/: tuned SIMD code lives there")
                m = include.match(line)
                if not m or "/" not in m.group(1):
                    continue  # a file of the same folder
                target = layer_of(m.group(1))
                if allowed is None or target == layer or target in allowed:
                    continue
                problems.append(f"{path}:{number}: {layer} includes {m.group(1)} ({target}), against the layers")
    for p in problems:
        print(p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
