"""A small glTF 2.0 writer on the Python standard library, for rtlab's hand-authored scenes.

Geometry goes into one binary buffer (embedded as a base64 data URI in .gltf, or the BIN chunk
of a .glb). Every coordinate is rounded to float32 before it is written, so the JSON and the
binary data say exactly what the loader reads.
"""

import base64
import json
import math
import struct

FLOAT, UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT = 5126, 5121, 5123, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
INDEX_FORMATS = {UNSIGNED_BYTE: "B", UNSIGNED_SHORT: "H", UNSIGNED_INT: "I"}


def f32(x):
    """x rounded to the nearest float32 (a Python float that float32 represents exactly)."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def f32v(v):
    return [f32(c) for c in v]


def normalize(v):
    length = math.sqrt(sum(c * c for c in v))
    return [c / length for c in v]


def axis_angle_quaternion(axis, degrees):
    """glTF rotation (x, y, z, w) of `degrees` about `axis`."""
    half = math.radians(degrees) / 2
    x, y, z = normalize(axis)
    return [x * math.sin(half), y * math.sin(half), z * math.sin(half), math.cos(half)]


def quaternion_product(a, b):
    """The rotation b followed by a, both glTF (x, y, z, w)."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return [aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz]


def look_at_quaternion(position, target):
    """The rotation that turns a glTF camera (looking down -Z, +Y up) towards target, no roll."""
    dx, dy, dz = (target[i] - position[i] for i in range(3))
    yaw = math.degrees(math.atan2(-dx, -dz))
    pitch = math.degrees(math.atan2(dy, math.hypot(dx, dz)))
    return quaternion_product(axis_angle_quaternion((0, 1, 0), yaw), axis_angle_quaternion((1, 0, 0), pitch))


def quad(corner, edge_u, edge_v):
    """Two triangles of the parallelogram corner, corner+u, corner+u+v, corner+v, facing u x v."""
    p = [corner,
         [corner[i] + edge_u[i] for i in range(3)],
         [corner[i] + edge_u[i] + edge_v[i] for i in range(3)],
         [corner[i] + edge_v[i] for i in range(3)]]
    return p, [(0, 1, 2), (0, 2, 3)]


def box(lower, upper):
    """The 12 outward-facing triangles of an axis-aligned box (8 shared vertices)."""
    (x0, y0, z0), (x1, y1, z1) = lower, upper
    positions = [[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0],
                 [x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]]
    faces = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (3, 7, 6, 2), (0, 4, 7, 3), (1, 2, 6, 5)]
    triangles = []
    for a, b, c, d in faces:
        triangles += [(a, b, c), (a, c, d)]
    return positions, triangles


def uv_sphere(radius, bands, segments):
    """A UV sphere about the origin, poles on +-Y, with unit vertex normals."""
    positions, normals = [], []
    for i in range(bands + 1):
        theta = math.pi * i / bands
        for j in range(segments + 1):
            phi = 2 * math.pi * j / segments
            n = [math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi)]
            normals.append(n)
            positions.append([radius * c for c in n])
    triangles = []
    row = segments + 1
    for i in range(bands):
        for j in range(segments):
            a, b = i * row + j, i * row + j + 1
            c, d = a + row, b + row
            if i > 0:
                triangles.append((a, b, c))  # the pole rows would give zero-area triangles
            if i < bands - 1:
                triangles.append((b, d, c))
    return positions, normals, triangles


class GltfBuilder:
    def __init__(self, generator):
        self.doc = {"asset": {"version": "2.0", "generator": generator},
                    "scene": 0, "scenes": [{"nodes": []}], "nodes": []}
        self.data = bytearray()

    def _list(self, key):
        return self.doc.setdefault(key, [])

    def _add(self, key, item):
        items = self._list(key)
        items.append(item)
        return len(items) - 1

    def _use_extension(self, name):
        used = self._list("extensionsUsed")
        if name not in used:
            used.append(name)

    # ---- binary data ----------------------------------------------------------------------

    def add_buffer_view(self, payload, target=None, stride=None):
        while len(self.data) % 4:
            self.data.append(0)
        view = {"buffer": 0, "byteOffset": len(self.data), "byteLength": len(payload)}
        if target is not None:
            view["target"] = target
        if stride is not None:
            view["byteStride"] = stride
        self.data += payload
        return self._add("bufferViews", view)

    def add_accessor(self, view, component_type, kind, count, byte_offset=0, bounds=None):
        accessor = {"bufferView": view, "componentType": component_type, "type": kind, "count": count}
        if byte_offset:
            accessor["byteOffset"] = byte_offset
        if bounds is not None:
            accessor["min"], accessor["max"] = bounds
        return self._add("accessors", accessor)

    def add_vec3_accessor(self, vectors):
        vectors = [f32v(v) for v in vectors]
        payload = b"".join(struct.pack("<3f", *v) for v in vectors)
        view = self.add_buffer_view(payload, ARRAY_BUFFER)
        bounds = ([min(v[i] for v in vectors) for i in range(3)],
                  [max(v[i] for v in vectors) for i in range(3)])
        return self.add_accessor(view, FLOAT, "VEC3", len(vectors), bounds=bounds)

    def add_index_accessor(self, triangles, component_type=UNSIGNED_INT):
        flat = [i for t in triangles for i in t]
        payload = struct.pack("<%d%s" % (len(flat), INDEX_FORMATS[component_type]), *flat)
        view = self.add_buffer_view(payload, ELEMENT_ARRAY_BUFFER)
        return self.add_accessor(view, component_type, "SCALAR", len(flat))

    # ---- scene objects --------------------------------------------------------------------

    def add_material(self, name, albedo, emission=None, emissive_strength=None, double_sided=False):
        material = {"name": name,
                    "pbrMetallicRoughness": {"baseColorFactor": list(albedo) + [1.0],
                                             "metallicFactor": 0.0, "roughnessFactor": 1.0}}
        if double_sided:
            material["doubleSided"] = True
        if emission is not None:
            material["emissiveFactor"] = list(emission)
        if emissive_strength is not None:
            material["extensions"] = {
                "KHR_materials_emissive_strength": {"emissiveStrength": emissive_strength}}
            self._use_extension("KHR_materials_emissive_strength")
        return self._add("materials", material)

    def add_mesh(self, name, positions, triangles, material, normals=None):
        attributes = {"POSITION": self.add_vec3_accessor(positions)}
        if normals is not None:
            attributes["NORMAL"] = self.add_vec3_accessor([normalize(n) for n in normals])
        primitive = {"attributes": attributes, "indices": self.add_index_accessor(triangles),
                     "material": material, "mode": 4}
        return self._add("meshes", {"name": name, "primitives": [primitive]})

    def add_node(self, name, parent=None, **fields):
        """A node under `parent` (or a scene root); fields are glTF node properties."""
        node = {"name": name}
        node.update({k: v for k, v in fields.items() if v is not None})
        index = self._add("nodes", node)
        if parent is None:
            self.doc["scenes"][0]["nodes"].append(index)
        else:
            self.doc["nodes"][parent].setdefault("children", []).append(index)
        return index

    def add_camera(self, name, yfov, aspect_ratio=4 / 3, parent=None, **fields):
        camera = self._add("cameras", {"name": name, "type": "perspective", "perspective": {
            "yfov": yfov, "aspectRatio": aspect_ratio, "znear": 0.01}})
        return self.add_node(name, parent, camera=camera, **fields)

    def add_point_light(self, name, candela, colour=(1.0, 1.0, 1.0), parent=None, watts=None, **fields):
        """A KHR_lights_punctual point light; intensity in candela (rtlab: W/sr = cd / 683). With
        `watts`, its radiant flux goes into extras.rtlab.power (rtlab: W/sr = W / 4 pi) and the
        intensity is set to the same W/sr in candela, so other tools agree."""
        self._use_extension("KHR_lights_punctual")
        lights = self.doc.setdefault("extensions", {}).setdefault(
            "KHR_lights_punctual", {"lights": []})["lights"]
        light = {"name": name, "type": "point", "color": list(colour), "intensity": candela}
        if watts is not None:
            light["intensity"] = watts / (4 * math.pi) * 683.0
            light["extras"] = {"rtlab": {"power": watts}}
        lights.append(light)
        return self.add_node(name, parent,
                             extensions={"KHR_lights_punctual": {"light": len(lights) - 1}}, **fields)

    def add_sphere(self, name, radius, material, parent=None, **fields):
        """An analytic sphere: extras.rtlab.sphere, centred on the node's origin."""
        return self.add_node(name, parent,
                             extras={"rtlab": {"sphere": {"radius": radius, "material": material}}},
                             **fields)

    # ---- output -----------------------------------------------------------------------------

    def _finished_doc(self, uri):
        doc = json.loads(json.dumps(self.doc))
        if self.data:
            buffer = {"byteLength": len(self.data)}
            if uri is not None:
                buffer["uri"] = uri
            doc["buffers"] = [buffer]
        return doc

    def gltf_text(self):
        uri = "data:application/octet-stream;base64," + base64.b64encode(bytes(self.data)).decode()
        return json.dumps(self._finished_doc(uri), indent=1) + "\n"

    def glb_bytes(self):
        text = json.dumps(self._finished_doc(None), separators=(",", ":")).encode()
        text += b" " * (-len(text) % 4)
        binary = bytes(self.data) + b"\0" * (-len(self.data) % 4)
        chunks = struct.pack("<I4s", len(text), b"JSON") + text
        if binary:
            chunks += struct.pack("<I4s", len(binary), b"BIN\0") + binary
        return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks

    def write(self, path):
        if str(path).endswith(".glb"):
            with open(path, "wb") as f:
                f.write(self.glb_bytes())
        else:
            with open(path, "w") as f:
                f.write(self.gltf_text())
