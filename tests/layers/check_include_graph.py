#!/usr/bin/env python3
"""The layers of the house (docs/layout.md): nothing includes upward, and peers that should not
know each other do not.

Every #include "a/b/c.h" in a tracked .cpp or .h file is an edge from the including file's
layer to the included file's layer. Layers are framework/<part> (core, interface, scene, accel,
oracle, sampling, render, verification, external, pov, blender); the grader's engine, kit, wire and worker,
each assignment's folder and its worker/, and grader/ itself (the registry); viewer, cli, fast,
bench, fuzz, assignments, solutions and tests. ALLOWED lists, for each layer, the layers it may include
besides itself; any other edge is printed as FILE:LINE and fails the test, and so does a file
in a layer the table does not know (a new folder must say where it sits).

An assignment's folder in grader/ (grader/a3_grid) needs no line in the table: it may use the
kit, the wire format and the engine's session API, its own wire/ (its tasks' names, inputs and
structures on the wire, which both sides compile) and the folders of the assignments its
registry line says it builds on (grader/assignment_registry.cpp); its worker/ (the tasks the
worker runtime runs) only the framework, the wire formats and the worker runtime.

Usage: check_include_graph.py SOURCE_DIR
"""
import os
import re
import subprocess
import sys

FRAMEWORK = {"framework/" + p for p in ("core", "interface", "scene", "accel", "oracle", "sampling", "render", "verification",
                                        "external", "pov", "blender")}

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
    # Checking renders apart from making them: image and statistical comparison, replicated
    # renders, the pixels an edge crosses, the share of a render spent tracing.
    "framework/verification": {"framework/core", "framework/interface", "framework/scene", "framework/accel",
                               "framework/render"},
    # Running the reference renderers (a time limit, a scratch folder) and the manifest of their inputs.
    "framework/external": {"framework/core"},
    "framework/pov": {"framework/core", "framework/scene", "framework/oracle", "framework/render", "framework/external"},
    # Beside pov/: the Blender Cycles exporter and references of the radiometry scenes.
    "framework/blender": {"framework/core", "framework/scene", "framework/external"},
    # Student code and the reference solutions: only the contract.
    "assignments": {"framework/core", "framework/interface"},
    "solutions": {"framework/core", "framework/interface"},
    # The grader never includes assignment code, the fast paths or the command line. What
    # both the grader and a worker speak: the byte format, scenes and structures on the wire.
    "grader/wire": {"framework/core", "framework/interface", "framework/scene"},
    # The worker runtime: the sandbox entry, the task registry, the render task.
    "grader/worker": FRAMEWORK | {"grader/wire"},
    # The engine names no assignment: session, isolation, process runner, batch, reports,
    # rubric; it reaches the assignments through the registry's header alone.
    "grader/engine": FRAMEWORK | {"grader/wire"},
    # Generic checks: truth tables, the hit judge, ray sets, scenes, structure tests, images,
    # statistics. Never an assignment.
    "grader/kit": FRAMEWORK | {"grader/wire", "grader/engine"},
    # The registry: the one file that names every assignment.
    "grader": None,
    "fast": FRAMEWORK,
    # The viewer sits above the grader (it reads traces, structure views and the grader's
    # statistics) and below the command line; nothing below it includes it.
    "viewer": FRAMEWORK | {"grader/engine", "grader/kit", "grader/wire"},  # and every assignment folder (below)
    "cli": FRAMEWORK | {"grader/engine", "grader/wire", "viewer"},  # and every assignment's wire/ (below)
    "bench": FRAMEWORK | {"fast"},
    "fuzz": FRAMEWORK | {"grader/engine", "grader/wire", "grader/kit", "grader/worker", "grader/a1_bvh"},
    # The test suite and the hostile fixtures may reach anything.
    "tests": None,
    "grader/fixtures": None,
}


ASSIGNMENT = re.compile(r"a\d+_[a-z0-9_]+$")


def layer_of(path):
    parts = path.split("/")
    if parts[0] == "framework" and len(parts) > 2:
        return "framework/" + parts[1]
    if parts[0] == "grader" and len(parts) > 2:
        if ASSIGNMENT.match(parts[1]) and len(parts) > 3 and parts[2] in ("wire", "worker"):
            return "grader/" + parts[1] + "/" + parts[2]
        return "grader/" + parts[1]
    return parts[0] if len(parts) > 1 else None


def assignment_rules(source):
    """The layers of each assignment folder from the registry's lines: {"a2", "...", a2Groups,
    {"a0_intersect", "a1_bvh", "a2_sah"}} lets grader/a2_sah include grader/a1_bvh."""
    rules = {}
    with open(os.path.join(source, "grader/assignment_registry.cpp")) as f:
        for line in f:
            m = re.search(r'\{"a\d+",.*\{([^{}]*)\}\}', line)
            if not m:
                continue
            folders = re.findall(r'"([^"]+)"', m.group(1))
            own = folders[-1]
            built_on = {"grader/" + f + part for f in folders[:-1] if os.path.isdir(os.path.join(source, "grader", f))
                        for part in ("", "/wire")}
            mine = "grader/" + own
            rules[mine] = FRAMEWORK | {"grader/wire", "grader/engine", "grader/kit", mine + "/wire"} | built_on
            rules[mine + "/wire"] = {"framework/core", "framework/interface", "framework/scene", "grader/wire"}
            rules[mine + "/worker"] = FRAMEWORK | {"grader/wire", "grader/worker", mine + "/wire"}
    return rules


def main():
    source = sys.argv[1]
    files = subprocess.run(["git", "-C", source, "ls-files", "*.cpp", "*.h"], capture_output=True, text=True,
                           check=True).stdout.split()
    allowed_by_layer = dict(ALLOWED, **assignment_rules(source))
    # The viewer draws any assignment's data (a6's samplers, a3's cells): every grader layer.
    allowed_by_layer["viewer"] = ALLOWED["viewer"] | {layer for layer in allowed_by_layer if layer.startswith("grader/")}
    # rtlab view hands the viewer the linked assignment functions through their wire calls (a6's
    # sampleOnce and estimateSample), the ones the worker runs.
    allowed_by_layer["cli"] = ALLOWED["cli"] | {layer for layer in allowed_by_layer if layer.endswith("/wire")}
    problems = []
    include = re.compile(r'\s*#\s*include\s+"([^"]+)"')
    intrinsics = re.compile(r'\s*#\s*include\s+<(\w*intrin\.h|arm_neon\.h)>')
    for path in files:
        layer = layer_of(path)
        if layer is None:
            continue
        if layer not in allowed_by_layer:
            problems.append(f"{path}:1: layer {layer} is not in the include-graph table (an assignment folder needs its registry line)")
            continue
        allowed = allowed_by_layer[layer]
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
