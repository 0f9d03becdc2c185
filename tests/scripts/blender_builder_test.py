# Run by Blender (tests/scripts/blender_builder_test.sh): renders the Blender builder's
# (scene/blender_scene.py) mirrors, custom normals and absorbing glass with Cycles in scenes
# whose images are known in closed form, and compares them.
#
#   blender -b --factory-startup --python-exit-code 3 --python THIS.py -- SOURCE_DIR WORK_DIR
#
# Every scene is lit by a constant sky of radiance 1 alone, so a pixel's value is the fraction of
# it that reaches the camera:
# 1. a conductor mirror plane seen at 40°–75°: each pixel is the Fresnel reflectance at its
#    angle, computed here with complex numbers (independently of the builder's real form);
# 2. the same metal as a plane facing the camera with custom normals tilted by 40°: the
#    reflectance at the tilted normal's angle, which proves Cycles shades with the given normals;
#    and the normals Blender keeps, read back, against the ones given;
# 3. a slab of absorbing glass seen head-on: R + (1 − R)X with X = (1 − R)e/(1 − R·e),
#    e = exp(−a·d), R = ((η − 1)/(η + 1))² (the sum of the light crossing it after 0, 2, 4, …
#    internal reflections).
import cmath
import math
import os
import sys

import bpy

SOURCE_DIR, WORK_DIR = sys.argv[sys.argv.index("--") + 1:][:2]
BUILDER_PATH = os.path.join(SOURCE_DIR, "scene", "blender_scene.py")
builder = {"__name__": "gib_blender_builder"}
with open(BUILDER_PATH) as file:
    exec(compile(file.read(), BUILDER_PATH, "exec"), builder)

# Test values in the range of metals (not a particular one), different in every channel.
N = (0.2, 0.9, 1.4)
K = (3.4, 2.4, 1.6)
failures = []


def check(condition, message):
    print(("ok: " if condition else "FAIL: ") + message)
    if not condition:
        failures.append(message)


def fresnel_conductor(cos_i, n, k):
    # Unpolarised reflectance of a smooth interface from air onto index η = n + iκ (Born & Wolf,
    # §14.2), in complex arithmetic.
    eta = complex(n, k)
    root = cmath.sqrt(eta * eta - (1 - cos_i * cos_i))
    r_s = (cos_i - root) / (cos_i + root)
    r_p = (eta * eta * cos_i - root) / (eta * eta * cos_i + root)
    return 0.5 * (abs(r_s) ** 2 + abs(r_p) ** 2)


def material(name, mirror=None, glass=None):
    return {"name": name, "diffuse": None, "glossy": None, "mirror": mirror, "glass": glass,
            "emission": None}


def quad_mesh(corners, material_index, normals=None):
    return {"name": f"quad{material_index}", "material": material_index,
            "positions": [x for c in corners for x in c], "normals": normals,
            "triangles": [0, 1, 2, 0, 2, 3]}


def box_mesh(low, high, material_index):
    # A closed box, its twelve triangles facing outwards.
    (x0, y0, z0), (x1, y1, z1) = low, high
    positions = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0),
                 (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    quads = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (3, 7, 6, 2), (0, 4, 7, 3), (1, 2, 6, 5)]
    return {"name": "box", "material": material_index,
            "positions": [x for p in positions for x in p], "normals": None,
            "triangles": [i for a, b, c, d in quads for i in (a, b, c, a, c, d)]}


# The camera at the origin looking down +z (GI Bench's frame: right = forward × up).
CAMERA = {"position": (0.0, 0.0, 0.0), "forward": (0.0, 0.0, 1.0), "right": (-1.0, 0.0, 0.0),
          "up": (0.0, 1.0, 0.0), "clip_start": 1e-3, "clip_end": 1e3}
SIZE = 16


def render(name, materials, meshes, fov_deg, spp):
    scene = builder["empty_file"]()
    made = [builder["make_material"](spec, True) for spec in materials]
    for spec in meshes:
        builder["make_mesh"](scene, spec, made)
    builder["make_camera"](scene, dict(CAMERA, vertical_fov_deg=fov_deg))
    builder["make_world"](scene, (1.0, 1.0, 1.0))
    out = os.path.join(WORK_DIR, name + ".exr")
    builder["configure_render"](
        scene, {"width": SIZE, "height": SIZE, "spp": spp, "seed": 1, "max_bounces": 1024}, out)
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(out)
    pixels = list(image.pixels)  # RGBA rows from the bottom of the image up
    return [[pixels[4 * (row * SIZE + column) + c] for c in range(3)]
            for row in range(SIZE) for column in range(SIZE)]


def pixel_directions(index, fov_deg, grid=8):
    # Camera rays spread evenly over pixel `index` (rows from the bottom), in world space: the
    # box filter averages a pixel over its square.
    row, column = divmod(index, SIZE)
    t = math.tan(math.radians(fov_deg) / 2)
    for u in range(grid):
        for v in range(grid):
            x = (2 * (column + (u + 0.5) / grid) / SIZE - 1) * t  # along "right", (−1, 0, 0)
            y = (2 * (row + (v + 0.5) / grid) / SIZE - 1) * t
            length = math.sqrt(x * x + y * y + 1)
            yield (-x / length, y / length, 1 / length)


def dot(a, b):
    return sum(p * q for p, q in zip(a, b))


def worst_fresnel_error(image, fov_deg, normal):
    # The largest difference of a pixel from the exact reflectance averaged over the pixel.
    worst = 0.0
    for index, value in enumerate(image):
        cosines = [abs(dot(d, normal)) for d in pixel_directions(index, fov_deg)]
        for c in range(3):
            exact = sum(fresnel_conductor(x, N[c], K[c]) for x in cosines) / len(cosines)
            worst = max(worst, abs(value[c] - exact))
    return worst


# A wrong formula (Schlick's approximation with the same F(0) is 0.009–0.03 off at these angles)
# or a wrong normal is far beyond this; 256 stratified samples average the reflectance's nearly
# linear change across a pixel to well within it.
FRESNEL_TOLERANCE = 2e-4

# 1. A plane through (0, 0, 10) tilted so the camera sees it at 40°–75°.
tilt = math.radians(57.5)
normal = (0.0, math.sin(tilt), -math.cos(tilt))
along = (0.0, math.cos(tilt), math.sin(tilt))
corners = [tuple(10 * z + 100 * (sx * x + sy * a)
                 for z, x, a in zip((0, 0, 1), (1, 0, 0), along))
           for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
# Reversed, so that the front face, the side (b − a) × (c − a) points to, looks at the camera.
image = render("conductor", [material("metal", mirror={"n": N, "k": K})],
               [quad_mesh(corners[::-1], 0)], 30.0, 256)
angles = [math.degrees(math.acos(abs(dot(d, normal))))
          for i in range(SIZE * SIZE) for d in pixel_directions(i, 30.0, grid=1)]
error = worst_fresnel_error(image, 30.0, normal)
check(error < FRESNEL_TOLERANCE,
      f"conductor mirror at {min(angles):.1f}°–{max(angles):.1f}°: worst pixel "
      f"{error:.2e} from the exact Fresnel reflectance (tolerance {FRESNEL_TOLERANCE})")

# 2. A plane facing the camera, its custom normals tilted by 40° about x (up the image): the
#    reflected rays leave 10° above the plane, where Cycles takes them as they are.
tilted = (0.0, math.sin(math.radians(40)), -math.cos(math.radians(40)))
facing = [(100.0, -100.0, 10.0), (-100.0, -100.0, 10.0), (-100.0, 100.0, 10.0),
          (100.0, 100.0, 10.0)]
image = render("normals", [material("metal", mirror={"n": N, "k": K})],
               [quad_mesh(facing, 0, normals=list(tilted) * 4)], 10.0, 16)
error = worst_fresnel_error(image, 10.0, tilted)
flat = max(abs(fresnel_conductor(1.0, N[c], K[c]) - fresnel_conductor(-tilted[2], N[c], K[c]))
           for c in range(3))
check(error < FRESNEL_TOLERANCE,
      f"custom normals tilted 40°: worst pixel {error:.2e} from the reflectance at the tilted "
      f"normal (tolerance {FRESNEL_TOLERANCE}; shading with the plane's own normal would be "
      f"{flat:.3f} off in one channel)")

# The normals Blender keeps: a band of a UV sphere (no poles, whose triangles would have no area)
# with its exact normals, read back after Blender's encoding.
rings, segments = 16, 32
positions, normals, triangles = [], [], []
for i in range(rings + 1):
    theta = math.pi * (i + 1) / (rings + 2)
    for j in range(segments + 1):
        phi = 2 * math.pi * j / segments
        n = (math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi))
        positions += [50 * c for c in n]
        normals += n
for i in range(rings):
    for j in range(segments):
        a, b = i * (segments + 1) + j, (i + 1) * (segments + 1) + j
        triangles += [a, a + 1, b + 1, a, b + 1, b]
scene = builder["empty_file"]()
builder["make_mesh"](scene, {"name": "sphere", "material": 0, "positions": positions,
                             "normals": normals, "triangles": triangles},
                     [bpy.data.materials.new("matte")])
mesh = bpy.data.meshes["sphere"]
mesh.calc_normals_split()
worst = 0.0
for loop in mesh.loops:
    given = normals[3 * loop.vertex_index:3 * loop.vertex_index + 3]
    worst = max(worst, math.acos(min(1.0, dot(loop.normal, given))))
# Blender encodes a custom normal as two 16-bit angles relative to its own normal.
NORMAL_TOLERANCE_RAD = 1e-3
check(worst < NORMAL_TOLERANCE_RAD,
      f"custom normals read back within {worst:.2e} rad of those given (tolerance "
      f"{NORMAL_TOLERANCE_RAD})")

# 3. A glass slab 10 units thick, seen head-on through a 2° field of view (rays within 1° of
#    its normal: the reflectance and path length differ from normal incidence's by under 1e-4).
IOR, THICKNESS = 1.5, 10.0
absorption = (0.1, 0.05, 0.0)
density = max(absorption)
glass = {"ior": IOR, "absorption": {"color": tuple(1 - a / density for a in absorption),
                                    "density": density}}
image = render("glass", [material("glass", glass=glass)],
               [box_mesh((-100.0, -100.0, 20.0), (100.0, 100.0, 20.0 + THICKNESS), 0)], 2.0, 64)
r = ((IOR - 1) / (IOR + 1)) ** 2
for c, name in enumerate("RGB"):
    e = math.exp(-absorption[c] * THICKNESS)
    expected = r + (1 - r) * (1 - r) * e / (1 - r * e)
    values = [pixel[c] for pixel in image]
    mean = sum(values) / len(values)
    spread = math.sqrt(sum((v - mean) ** 2 for v in values) / (len(values) - 1))
    # The pixels are independent estimates: their mean is off by more than 4.5 standard errors
    # with probability below 1e-5 (normal tails; 256 pixels of 64 samples each).
    bound = 4.5 * spread / math.sqrt(len(values)) + 1e-5
    check(abs(mean - expected) <= bound,
          f"absorbing glass, {name}: mean {mean:.5f}, exact {expected:.5f} (bound {bound:.5f})")

if failures:
    print(f"FAIL: {len(failures)} check(s) failed")
    sys.exit(1)
print("PASS")
