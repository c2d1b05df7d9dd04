#!/usr/bin/env python3
"""Writes the small glTF files tests/test_gltf_loader.cpp reads (run from anywhere; the
outputs are committed). Expected values in the test are worked out by hand from the numbers
here, not read back from the loader.

hierarchy.gltf / hierarchy.glb: a node tree (TRS root, a matrix child, a TRS child with a
non-uniform scale), interleaved POSITION+NORMAL with byteStride 24, u8 / u16 (accessor
byteOffset 4) / u32 indices, a non-indexed primitive whose accessor skips a NaN through its
byteOffset, a POINTS primitive (skipped), a camera, a 100 cd light and a sphere.
The other files are each broken in one way; huge-*, deep-* and cycle.gltf exceed the
loader's input limits (tests/test_gltf_limits.cpp).
"""

import base64
import json
import math
import os
import struct
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from gltf_builder import (ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER, FLOAT, UNSIGNED_BYTE,  # noqa: E402
                          UNSIGNED_INT, UNSIGNED_SHORT, GltfBuilder, axis_angle_quaternion)

HERE = os.path.dirname(os.path.abspath(__file__))
GENERATOR = "rtlab tests/data/make-test-data.py"
DEEP_HIERARCHY_LEVELS = 1001  # levels in all: one more than the loader's limit of 1000
DEEP_JSON_LEVELS = 10000      # far beyond the loader's JSON depth limit of 64


def hierarchy():
    g = GltfBuilder(GENERATOR)
    red = g.add_material("red", (0.8, 0.1, 0.1))
    glow = g.add_material("glow", (0.5, 0.5, 0.5), emission=(1.0, 0.5, 0.25), emissive_strength=4.0)

    # Interleaved: position then normal per vertex, 24 bytes apart.
    triangle = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]
    normal = (0.6, 0.8, 0.0)
    interleaved = b"".join(struct.pack("<6f", *p, *normal) for p in triangle)
    vertices = g.add_buffer_view(interleaved, ARRAY_BUFFER, stride=24)
    positions = g.add_accessor(vertices, FLOAT, "VEC3", 3, bounds=([0, 0, 0], [1, 1, 0]))
    normals = g.add_accessor(vertices, FLOAT, "VEC3", 3, byte_offset=12)

    u8 = g.add_accessor(g.add_buffer_view(struct.pack("<3B", 0, 1, 2), ELEMENT_ARRAY_BUFFER),
                        UNSIGNED_BYTE, "SCALAR", 3)
    u16 = g.add_accessor(g.add_buffer_view(struct.pack("<5H", 9, 9, 0, 1, 2), ELEMENT_ARRAY_BUFFER),
                         UNSIGNED_SHORT, "SCALAR", 3, byte_offset=4)
    u32 = g.add_accessor(g.add_buffer_view(struct.pack("<3I", 0, 2, 1), ELEMENT_ARRAY_BUFFER),
                         UNSIGNED_INT, "SCALAR", 3)
    # Non-indexed: the accessor starts 12 bytes in, past a NaN vertex it must not read.
    loose = struct.pack("<12f", math.nan, math.nan, math.nan, 0, 0, 0, 0, 0, 1, 1, 0, 0)
    loose_positions = g.add_accessor(g.add_buffer_view(loose, ARRAY_BUFFER), FLOAT, "VEC3", 3,
                                     byte_offset=12, bounds=([0, 0, 0], [1, 0, 1]))

    def mesh(name, primitives):
        g.doc.setdefault("meshes", []).append({"name": name, "primitives": primitives})
        return len(g.doc["meshes"]) - 1

    with_normals = {"POSITION": positions, "NORMAL": normals}
    mesh_u8 = mesh("u8", [{"attributes": with_normals, "indices": u8, "material": red}])
    mesh_u16 = mesh("u16", [{"attributes": with_normals, "indices": u16, "material": glow, "mode": 4}])
    mesh_u32 = mesh("u32", [{"attributes": {"POSITION": positions}, "indices": u32}])
    mesh_loose = mesh("unindexed", [{"attributes": {"POSITION": loose_positions}, "material": red},
                                    {"attributes": {"POSITION": positions}, "mode": 0}])

    root = g.add_node("root", translation=[10, 0, 0], rotation=axis_angle_quaternion((0, 0, 1), 90),
                      scale=[2, 2, 2])
    g.add_node("matrixChild", root, mesh=mesh_u8,
               matrix=[1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1])
    g.add_node("trsChild", root, mesh=mesh_u16, translation=[0, 0, -1], scale=[3, 1, 1])
    g.add_point_light("lamp", 100.0, (1.0, 0.5, 0.25), parent=root, translation=[0, 0, 1])
    g.add_sphere("ball", 0.5, glow, parent=root, translation=[1, 0, 0], scale=[1.5, 1.5, 1.5])
    g.add_node("u32Node", mesh=mesh_u32)
    g.add_node("unindexedNode", mesh=mesh_loose, translation=[0, 3, 0])
    g.add_camera("cam", 0.5, 1.5, translation=[1, 2, 3], rotation=axis_angle_quaternion((0, 1, 0), 90))
    return g


def finite_bounds(positions):
    """POSITION min and max, as glTF requires them, over the finite coordinates."""
    finite = [[c for c in axis if math.isfinite(c)] for axis in zip(*positions)]
    return [min(axis) for axis in finite], [max(axis) for axis in finite]


def one_triangle(positions=((0, 0, 0), (1, 0, 0), (0, 1, 0)), indices=(0, 1, 2)):
    """A minimal valid file; the broken ones below change one thing in it."""
    g = GltfBuilder(GENERATOR)
    payload = b"".join(struct.pack("<3f", *p) for p in positions)
    view = g.add_buffer_view(payload, ARRAY_BUFFER)
    accessor = g.add_accessor(view, FLOAT, "VEC3", len(positions), bounds=finite_bounds(positions))
    g.doc["meshes"] = [{"name": "tri", "primitives": [
        {"attributes": {"POSITION": accessor}, "indices": g.add_index_accessor([indices])}]}]
    g.add_node("triangle", mesh=0)
    return g


def write_text(name, text):
    with open(os.path.join(HERE, name), "w") as f:
        f.write(text)


def main():
    h = hierarchy()
    h.write(os.path.join(HERE, "hierarchy.gltf"))
    h.write(os.path.join(HERE, "hierarchy.glb"))
    with open(os.path.join(HERE, "truncated.glb"), "wb") as f:
        f.write(h.glb_bytes()[:100])

    write_text("bad-json.gltf", '{"asset": {"version": "2.0"}, "nodes": [{"name": "a"\n')
    one_triangle(indices=(0, 1, 3)).write(os.path.join(HERE, "index-out-of-range.gltf"))
    one_triangle(positions=((0, 0, 0), (1, math.nan, 0), (0, 1, 0))).write(
        os.path.join(HERE, "nan-vertex.gltf"))

    missing = one_triangle()
    doc = missing._finished_doc("missing.bin")
    write_text("missing-buffer.gltf", json.dumps(doc, indent=1) + "\n")

    overrun = one_triangle()
    overrun.doc["accessors"][0]["count"] = 4  # the view holds 3 vertices
    overrun.write(os.path.join(HERE, "accessor-overrun.gltf"))

    spot = one_triangle()
    spot.add_point_light("spot", 10.0)
    spot.doc["extensions"]["KHR_lights_punctual"]["lights"][0]["type"] = "spot"
    spot.doc["extensions"]["KHR_lights_punctual"]["lights"][0]["spot"] = {"outerConeAngle": 0.5}
    spot.write(os.path.join(HERE, "spot-light.gltf"))

    squashed = one_triangle()
    squashed.add_material("white", (0.8, 0.8, 0.8))
    squashed.add_sphere("egg", 1.0, 0, scale=[1, 2, 1])
    squashed.write(os.path.join(HERE, "nonuniform-sphere.gltf"))

    # Two nodes that are each other's child, which no scene lists: only a check of the whole
    # node graph finds them.
    cycle = one_triangle()
    cycle.doc["nodes"] += [{"name": "a", "mesh": 0, "children": [2]}, {"name": "b", "children": [1]}]
    cycle.write(os.path.join(HERE, "cycle.gltf"))

    # The input limits (docs/scenes.md): each file asks for far more than it holds.
    huge = one_triangle()
    finished_doc = huge._finished_doc

    def claiming_a_terabyte(uri):
        doc = finished_doc(uri)
        doc["buffers"][0]["byteLength"] = 1 << 40
        return doc

    huge._finished_doc = claiming_a_terabyte
    huge.write(os.path.join(HERE, "huge-buffer.gltf"))
    huge.write(os.path.join(HERE, "huge-buffer.glb"))

    many = one_triangle()
    many.doc["accessors"][0]["count"] = (1 << 32) - 3  # a multiple of 3 just under 2^32
    many.write(os.path.join(HERE, "huge-accessor-count.gltf"))

    deep = one_triangle()
    for level in range(2, DEEP_HIERARCHY_LEVELS + 1):  # the triangle is level 1
        deep.add_node("level%d" % level, parent=len(deep.doc["nodes"]) - 1)
    deep.write(os.path.join(HERE, "deep-hierarchy.gltf"))

    nested = one_triangle()
    nested.doc["nodes"][0]["extras"] = {"nested": "NESTED"}  # Python's json module recurses
    write_text("deep-json.gltf", nested.gltf_text().replace(
        '"NESTED"', "[" * DEEP_JSON_LEVELS + "]" * DEEP_JSON_LEVELS))


if __name__ == "__main__":
    main()
