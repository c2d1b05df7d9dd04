#!/usr/bin/env python3
"""Writes the committed glTF scenes of scenes/ (README.md there describes them).

Standard library only, deterministic: running it again reproduces the committed files byte for
byte. Geometry is written in world space (float32), spheres and cameras sit on nodes.

Light intensities are in candela (glTF); rtlab renders I = cd / 683 W/sr with a Lambert BRDF,
radiance = albedo/pi * I * cos / d^2. The references are 16-bit PNGs, which clip above 1, so
the script bounds each scene's direct radiance from above (every light, no shadows) and refuses
to write a scene that could exceed kMaxRadiance.

The scenes of radiometry/ (a6) have area and sphere lights, which POV-Ray cannot render the
way rtlab does: they have no POV-Ray reference and no such bound; their lights are emissive
triangles and spheres (radiance = emissiveFactor * emissiveStrength) and point lights given in
watts (extras.rtlab.power, I = W / 4 pi).

Usage: scripts/make-scenes.py [OUTPUT_DIR]   (default: scenes/ next to this script)
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gltf_builder import GltfBuilder, box, f32v, look_at_quaternion, quad, uv_sphere  # noqa: E402

GENERATOR = "rtlab scripts/make-scenes.py"
LUMENS_PER_WATT = 683.0
MAX_RADIANCE = 1.0  # 16-bit PNG references clip above this (linear units)
ASPECT = 4 / 3      # the scenes are meant for 320x240


class SceneWriter:
    """GltfBuilder plus the world-space bookkeeping the radiance bound needs."""

    def __init__(self):
        self.g = GltfBuilder(GENERATOR)
        self.albedo = []    # per material
        self.emission = []
        self.triangles = []  # (p0, p1, p2, material)
        self.spheres = []    # (centre, radius, material)
        self.lights = []     # (position, rgb W/sr)

    def material(self, name, albedo, emission=None, strength=None, double_sided=False):
        """A Lambert material; emission is emissiveFactor, times `strength` when given."""
        self.albedo.append(albedo)
        radiance = [c * (strength or 1.0) for c in (emission or (0.0, 0.0, 0.0))]
        self.emission.append(radiance)
        return self.g.add_material(name, albedo, emission, strength, double_sided)

    def mesh(self, name, positions, triangles, material, normals=None):
        positions = [f32v(p) for p in positions]
        self.g.add_node(name, mesh=self.g.add_mesh(name, positions, triangles, material, normals))
        self.triangles += [(positions[a], positions[b], positions[c], material) for a, b, c in triangles]

    def sphere(self, name, centre, radius, material):
        self.g.add_sphere(name, radius, material, translation=f32v(centre))
        self.spheres.append((f32v(centre), radius, material))

    def light(self, name, position, candela, colour=(1.0, 1.0, 1.0), watts=None):
        """A point light of `candela`, or of radiant flux `watts` (then candela is ignored)."""
        self.g.add_point_light(name, candela, colour, translation=f32v(position), watts=watts)
        wattsPerSr = watts / (4 * math.pi) if watts is not None else candela / LUMENS_PER_WATT
        self.lights.append((f32v(position), [c * wattsPerSr for c in colour]))

    def camera(self, position, target, yfov_degrees):
        """A camera at `position` looking at `target`, +Y up."""
        self.g.add_camera("camera", math.radians(yfov_degrees), ASPECT, translation=f32v(position),
                          rotation=look_at_quaternion(position, target))

    def max_radiance(self):
        """Upper bound of the rendered radiance: every light unshadowed, plus emission."""
        best = 0.0
        for p0, p1, p2, m in self.triangles:
            n = cross(sub(p1, p0), sub(p2, p0))
            if dot(n, n) == 0.0:
                continue
            points = [lerp3(p0, p1, p2, i / 16, j / 16) for i in range(17) for j in range(17 - i)]
            for light_position, _ in self.lights:  # the foot of the perpendicular, if inside
                points += perpendicular_foot_inside(light_position, p0, p1, p2)
            for p in points:
                best = max(best, self._radiance_at(p, normalize(n), m))
        for centre, radius, m in self.spheres:
            for light_position, intensity in self.lights:
                d = math.dist(light_position, centre) - radius
                best = max(best, max(self.albedo[m][c] / math.pi * intensity[c] / d ** 2 + self.emission[m][c]
                                     for c in range(3)))
        return best

    def _radiance_at(self, p, n, m):
        total = [self.emission[m][c] for c in range(3)]
        for light_position, intensity in self.lights:
            to_light = sub(light_position, p)
            d2 = dot(to_light, to_light)
            cos = abs(dot(n, to_light)) / math.sqrt(d2)  # lit from the side it is seen from
            for c in range(3):
                total[c] += self.albedo[m][c] / math.pi * intensity[c] * cos / d2
        return max(total)

    def write(self, path):
        bound = self.max_radiance()
        if bound > MAX_RADIANCE:
            sys.exit("make-scenes: %s could reach radiance %.3f > %g; lower its lights" % (path, bound, MAX_RADIANCE))
        self.g.write(path)
        print("%-22s %6d triangles %2d spheres %d lights  max radiance <= %.3f" % (
            os.path.basename(path), len(self.triangles), len(self.spheres), len(self.lights), bound))

    def write_unbounded(self, path):
        """For scenes with area lights, which have no 16-bit POV-Ray reference to clip."""
        self.g.write(path)
        emitters = sum(1 for *_, m in self.triangles + self.spheres if any(self.emission[m]))
        print("%-22s %6d triangles %2d spheres %d lights  %d emitting primitives" % (
            os.path.basename(path), len(self.triangles), len(self.spheres), len(self.lights), emitters))


def sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def dot(a, b):
    return sum(a[i] * b[i] for i in range(3))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def normalize(v):
    length = math.sqrt(dot(v, v))
    return [c / length for c in v]


def lerp3(p0, p1, p2, u, v):
    return [p0[i] + u * (p1[i] - p0[i]) + v * (p2[i] - p0[i]) for i in range(3)]


def perpendicular_foot_inside(q, p0, p1, p2):
    """[the projection of q onto the triangle's plane] when it falls inside, else []."""
    e1, e2 = sub(p1, p0), sub(p2, p0)
    n = cross(e1, e2)
    foot = sub(q, [dot(sub(q, p0), n) / dot(n, n) * c for c in n])
    w = sub(foot, p0)
    d11, d12, d22 = dot(e1, e1), dot(e1, e2), dot(e2, e2)
    det = d11 * d22 - d12 * d12
    u = (d22 * dot(w, e1) - d12 * dot(w, e2)) / det
    v = (d11 * dot(w, e2) - d12 * dot(w, e1)) / det
    return [foot] if u >= 0 and v >= 0 and u + v <= 1 else []


def rotate_y(points, degrees, pivot):
    a = math.radians(degrees)
    c, s = math.cos(a), math.sin(a)
    out = []
    for x, y, z in points:
        dx, dz = x - pivot[0], z - pivot[2]
        out.append([pivot[0] + c * dx + s * dz, y, pivot[2] - s * dx + c * dz])
    return out


def add_quad(scene, name, corner, u, v, material):
    positions, triangles = quad(corner, u, v)
    scene.mesh(name, positions, triangles, material)


def add_box(scene, name, centre, size, yaw_degrees, material):
    half = [s / 2 for s in size]
    positions, triangles = box([centre[0] - half[0], 0.0, centre[2] - half[2]],
                               [centre[0] + half[0], size[1], centre[2] + half[2]])
    scene.mesh(name, rotate_y(positions, yaw_degrees, centre), triangles, material)


def ground(scene, half_size, material):
    add_quad(scene, "ground", [-half_size, 0.0, half_size], [2 * half_size, 0.0, 0.0],
             [0.0, 0.0, -2 * half_size], material)


def cornell_box():
    s = SceneWriter()
    white = s.material("white", (0.73, 0.73, 0.73))
    red = s.material("red", (0.63, 0.065, 0.05))
    green = s.material("green", (0.14, 0.45, 0.091))
    add_quad(s, "floor", [-1, 0, 1], [2, 0, 0], [0, 0, -2], white)
    add_quad(s, "ceiling", [-1, 2, -1], [2, 0, 0], [0, 0, 2], white)
    add_quad(s, "back wall", [-1, 0, -1], [2, 0, 0], [0, 2, 0], white)
    add_quad(s, "left wall", [-1, 0, 1], [0, 0, -2], [0, 2, 0], red)
    add_quad(s, "right wall", [1, 0, -1], [0, 0, 2], [0, 2, 0], green)
    add_box(s, "short box", [0.4375, 0, 0.4375], [0.5, 0.5, 0.5], -18, white)
    add_box(s, "tall box", [-0.4375, 0, -0.4375], [0.5, 1.0, 0.5], 20, white)
    s.light("ceiling light", [0, 1.375, 0.25], 1000.0, (1.0, 0.9, 0.75))
    s.camera([0, 0.9375, 3.75], [0, 0.9375, 0], 40)  # off-centre: no pixel centre on a corner line
    return s


def spheres():
    s = SceneWriter()
    floor = s.material("floor", (0.7, 0.7, 0.7))
    white = s.material("white", (0.8, 0.8, 0.8))
    red = s.material("red", (0.8, 0.15, 0.1))
    blue = s.material("blue", (0.1, 0.25, 0.8))
    green = s.material("green", (0.15, 0.7, 0.2))
    yellow = s.material("yellow", (0.9, 0.75, 0.45))
    ground(s, 5, floor)
    s.sphere("big", [0, 1, 0], 1.0, white)
    s.sphere("red", [-1.75, 0.5, 0.75], 0.5, red)
    s.sphere("blue", [1.75, 0.75, 0.5], 0.75, blue)
    s.sphere("green", [0.5, 0.3125, 1.5], 0.3125, green)
    s.sphere("yellow", [-0.625, 0.25, 1.875], 0.25, yellow)
    s.light("key light", [3, 5, 4], 25000.0)
    s.camera([0, 2.5, 7], [0, 0.75, 0], 40)
    return s


def smooth_mesh():
    s = SceneWriter()
    floor = s.material("floor", (0.7, 0.7, 0.7))
    clay = s.material("clay", (0.8, 0.45, 0.3))
    ground(s, 4, floor)
    positions, normals, triangles = uv_sphere(1.0, 12, 24)
    s.mesh("smooth sphere", [[p[0] - 1.25, p[1] + 1, p[2]] for p in positions], triangles, clay, normals)
    s.mesh("faceted sphere", [[p[0] + 1.25, p[1] + 1, p[2]] for p in positions], triangles, clay)
    s.light("key light", [2, 4, 3], 20000.0)
    s.camera([0, 2, 6.5], [0, 0.875, 0], 40)
    return s


def light_behind():
    s = SceneWriter()
    floor = s.material("floor", (0.7, 0.7, 0.7))
    wall = s.material("wall", (0.75, 0.7, 0.6))
    crate = s.material("crate", (0.3, 0.5, 0.8))
    ground(s, 4, floor)
    add_quad(s, "wall", [-1.5, 0, 0], [3, 0, 0], [0, 1.25, 0], wall)  # faces the camera
    add_box(s, "box", [2.25, 0, 1.25], [0.75, 0.75, 0.75], 30, crate)
    s.light("hidden light", [0, 3, -1.5], 21000.0)  # behind the wall, above its top
    s.camera([2, 3, 7], [0, 0.5, 0], 45)
    return s


def multi_light():
    s = SceneWriter()
    floor = s.material("floor", (0.75, 0.75, 0.75))
    white = s.material("white", (0.8, 0.8, 0.8))
    ground(s, 5, floor)
    s.sphere("ball", [0, 1, 0], 1.0, white)
    add_box(s, "box", [-1.75, 0, 0.75], [0.75, 0.75, 0.75], 25, white)
    # Same illuminance scale at each light's foot: intensity grows with the height squared.
    s.light("near warm", [-1.5, 1.5, 1.75], 2500.0, (1.0, 0.55, 0.3))
    s.light("middle green", [3, 3, -1], 10000.0, (0.35, 1.0, 0.45))
    s.light("far blue", [-2, 7, -6], 55000.0, (0.35, 0.55, 1.0))
    s.camera([0, 3, 8], [0, 0.5, 0], 40)
    return s


# ---- radiometry (a6): area and sphere lights -------------------------------------------------


def penumbra():
    """A 1 m square light 2 m above the ground, facing down (L = 10), and a 0.5 m square occluder
    halfway: from the ground its shadow on the light's plane is 1 m wide, so the umbra shrinks to
    a point and the shadow is penumbra. The scene of the estimator comparison
    (docs/a6-radiometry.md#run-time-against-error)."""
    s = SceneWriter()
    floor = s.material("floor", (0.8, 0.8, 0.8))
    grey = s.material("occluder", (0.5, 0.5, 0.5))
    light = s.material("light", (0.0, 0.0, 0.0), (1.0, 1.0, 1.0), 10.0)
    ground(s, 4, floor)
    add_quad(s, "occluder", [-0.15, 1.0, -0.35], [0.5, 0.0, 0.0], [0.0, 0.0, 0.5], grey)  # facing down
    add_quad(s, "square light", [-0.5, 2.0, -0.5], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0], light)  # facing down
    s.camera([2.2, 1.7, 2.8], [0.2, 0.1, 0.0], 40)  # below the light: it is out of the picture
    return s


def sphere_light():
    """A sphere light (radius 0.4 m, L = 12) above a ball and a box: round soft shadows."""
    s = SceneWriter()
    floor = s.material("floor", (0.8, 0.8, 0.8))
    white = s.material("white", (0.8, 0.8, 0.8))
    blue = s.material("blue", (0.2, 0.35, 0.8))
    light = s.material("light", (0.0, 0.0, 0.0), (1.0, 0.95, 0.85), 12.0)
    ground(s, 4, floor)
    s.sphere("ball", [0.6, 0.35, 0.4], 0.35, white)
    add_box(s, "box", [-0.8, 0, -0.2], [0.5, 0.5, 0.5], 20, blue)
    s.sphere("sphere light", [0, 1.8, 0], 0.4, light)
    s.camera([0, 1.5, 4], [0, 0.5, 0], 45)
    return s


def mixed_lights():
    """Point lights in watts and in candela and a double-sided area light, side by side."""
    s = SceneWriter()
    floor = s.material("floor", (0.75, 0.75, 0.75))
    white = s.material("white", (0.8, 0.8, 0.8))
    panel = s.material("panel", (0.0, 0.0, 0.0), (0.6, 0.8, 1.0), 8.0, double_sided=True)
    ground(s, 4, floor)
    s.sphere("ball", [-1.0, 0.6, 0.0], 0.6, white)
    add_box(s, "box", [1.3, 0, -0.3], [0.6, 0.6, 0.6], -15, white)
    # A vertical panel between them, turned 30 degrees towards the camera, emitting towards both.
    add_quad(s, "panel light", [-0.1, 0.2, -0.55], [0.4, 0.0, 0.6928], [0.0, 0.6, 0.0], panel)
    s.light("warm bulb", [-1.8, 2.2, 1.5], 0.0, (1.0, 0.8, 0.6), watts=150.0)
    s.light("blue spot", [2.0, 3.0, 1.0], 2500.0, (0.6, 0.7, 1.0))
    s.camera([0, 2, 5.5], [0, 0.5, 0], 40)
    return s


def closed_form():
    """A 1 m square light 1 m above a large ground, facing down (L = 4): the irradiance on the
    ground is Lambert's contour integral of the square, 0.7523 L under its centre. The camera
    sees only ground and sky, never the light (tests/test_renderer.cpp checks the image)."""
    s = SceneWriter()
    floor = s.material("floor", (0.8, 0.8, 0.8))
    light = s.material("light", (0.0, 0.0, 0.0), (1.0, 1.0, 1.0), 4.0)
    ground(s, 10, floor)
    add_quad(s, "square light", [-0.5, 1.0, -0.5], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0], light)  # facing down
    s.camera([0, 0.45, 2.6], [0, 0, 0.1], 30)
    return s


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                             "..", "scenes")
    os.makedirs(os.path.join(out, "radiometry"), exist_ok=True)
    for name, make in [("cornell-box", cornell_box), ("spheres", spheres), ("smooth-mesh", smooth_mesh),
                       ("light-behind", light_behind), ("multi-light", multi_light)]:
        make().write(os.path.join(out, name + ".gltf"))
    for name, make in [("penumbra", penumbra), ("sphere-light", sphere_light), ("mixed-lights", mixed_lights),
                       ("closed-form", closed_form)]:
        make().write_unbounded(os.path.join(out, "radiometry", name + ".gltf"))


if __name__ == "__main__":
    main()
