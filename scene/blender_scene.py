# The fixed part of a script written by `gibench export-blender` (scene/blender_export.cpp writes
# the scene's data, SCENE, above it): builds the scene in an empty Blender file and renders it
# with Cycles on the CPU into a 32-bit float linear RGBA EXR. The exporter has already converted
# every unit and convention, so this part only copies numbers into Blender; what it adds are the
# render settings, each chosen so that Cycles estimates the same integral as GI Bench's reference
# without bias or post-processing (the comments say which default would change the image).
#
# Usage: blender -b --factory-startup --python-exit-code 3 --python SCRIPT -- OUT.exr
#                [--spp N] [--seed S] [--no-light-sampling]
# --spp and --seed replace the exported ones (a second, independent render of the same scene).
# --no-light-sampling leaves emissive meshes to BSDF sampling alone: far noisier, but without the
# darkening of Blender 3.4's light sampling where an emitter is seen at a grazing angle (measured
# in docs/cycles-cross-check.md).

import math
import os
import sys

import bpy
from mathutils import Matrix, Vector

USAGE = ("blender -b --factory-startup --python SCRIPT -- OUT.exr [--spp N] [--seed S] "
         "[--no-light-sampling]")


def fail(message):
    # One line and exit code 2, as gibench does for bad input.
    print(f"gibench blender script: {message}; usage: {USAGE}", file=sys.stderr)
    sys.exit(2)


def parse_arguments(render):
    args = sys.argv[sys.argv.index("--") + 1 :] if "--" in sys.argv else []
    out = None
    while args:
        arg = args.pop(0)
        if arg == "--no-light-sampling":
            render["light_sampling"] = False
        elif arg in ("--spp", "--seed"):
            if not args or not args[0].isdigit():
                fail(f"{arg} needs a non-negative integer")
            render[arg[2:]] = int(args.pop(0))
        elif arg.startswith("-") or out is not None:
            fail(f"unexpected argument '{arg}'")
        else:
            out = arg
    if out is None:
        fail("no output EXR given after '--'")
    if render["spp"] < 1:
        fail("--spp must be at least 1")
    if render["seed"] > 2**31 - 1:
        fail("--seed must be below 2^31 (Cycles' range)")
    return os.path.abspath(out)


def empty_file():
    # --factory-startup opens the default scene (cube, lamp, camera): remove all of it.
    for blocks in (bpy.data.objects, bpy.data.meshes, bpy.data.materials, bpy.data.lights,
                   bpy.data.cameras, bpy.data.worlds):
        for block in list(blocks):
            blocks.remove(block)
    return bpy.context.scene


def rgba(rgb):
    return (rgb[0], rgb[1], rgb[2], 1.0)


class Value:
    """A float of a material's node graph: a constant, or a socket that math nodes compute. The
    arithmetic operators add Math nodes (constants are folded in Python), so a formula reads as
    the C++ it copies."""

    def __init__(self, tree, value):
        self.tree, self.value = tree, value

    def apply(self, operation, *operands):
        values = [o.value if isinstance(o, Value) else float(o) for o in (self,) + operands]
        if all(isinstance(v, float) for v in values):
            return Value(self.tree, CONSTANT_FOLDS[operation](*values))
        node = self.tree.nodes.new("ShaderNodeMath")
        node.operation = operation
        for socket, v in zip(node.inputs, values):
            if isinstance(v, float):
                socket.default_value = v
            else:
                self.tree.links.new(v, socket)
        return Value(self.tree, node.outputs["Value"])

    def constant(self, value):
        return Value(self.tree, float(value))

    def __add__(self, other): return self.apply("ADD", other)
    def __radd__(self, other): return self.constant(other).apply("ADD", self)
    def __sub__(self, other): return self.apply("SUBTRACT", other)
    def __rsub__(self, other): return self.constant(other).apply("SUBTRACT", self)
    def __mul__(self, other): return self.apply("MULTIPLY", other)
    def __rmul__(self, other): return self.constant(other).apply("MULTIPLY", self)
    def __truediv__(self, other): return self.apply("DIVIDE", other)
    def sqrt(self): return self.apply("SQRT")
    def maximum(self, other): return self.apply("MAXIMUM", other)


CONSTANT_FOLDS = {"ADD": lambda a, b: a + b, "SUBTRACT": lambda a, b: a - b,
                  "MULTIPLY": lambda a, b: a * b, "DIVIDE": lambda a, b: a / b,
                  "SQRT": math.sqrt, "MAXIMUM": max, "ABSOLUTE": abs}


def conductor_fresnel(tree, n, k):
    """The colour of a mirror: the reflectance of eq. 1.5 for a conductor of complex index n + iκ
    per channel, in the closed real form of fresnelConductor (scene/fresnel_shared.h), step for
    step, at the angle between the incoming direction and the shading normal (the normal the
    Sharp Glossy BSDF reflects about)."""
    geometry = tree.nodes.new("ShaderNodeNewGeometry")
    dot = tree.nodes.new("ShaderNodeVectorMath")
    dot.operation = "DOT_PRODUCT"
    tree.links.new(geometry.outputs["Normal"], dot.inputs[0])
    tree.links.new(geometry.outputs["Incoming"], dot.inputs[1])
    cos_i = Value(tree, dot.outputs["Value"]).apply("ABSOLUTE")
    c2 = cos_i * cos_i
    s2 = 1.0 - c2
    combine = tree.nodes.new("ShaderNodeCombineRGB")
    for channel, socket in enumerate(combine.inputs):
        nc, kc = n[channel], k[channel]
        t0 = (nc * nc - kc * kc) - s2
        s = (t0 * t0 + 4.0 * nc * nc * kc * kc).sqrt()
        a = (0.5 * (s + t0)).maximum(0.0).sqrt()
        t1 = s + c2
        t2 = 2.0 * cos_i * a
        r_s = (t1 - t2) / (t1 + t2)
        t3 = c2 * s + s2 * s2
        t4 = t2 * s2
        r_p = r_s * (t3 - t4) / (t3 + t4)
        tree.links.new((0.5 * (r_s + r_p)).value, socket)
    return combine.outputs["Image"]


def make_surface(material, spec):
    # The surface's BSDF: a mirror, glass, or Lambert with an optional glossy lobe (Phong).
    tree = material.node_tree
    nodes, links = tree.nodes, tree.links
    if spec["mirror"] is not None:
        mirror = nodes.new("ShaderNodeBsdfGlossy")
        mirror.distribution = "SHARP"  # reflects all of its colour into the mirror direction
        if spec["mirror"] == "perfect":
            mirror.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        else:
            links.new(conductor_fresnel(tree, spec["mirror"]["n"], spec["mirror"]["k"]),
                      mirror.inputs["Color"])
        return mirror.outputs["BSDF"]
    if spec["glass"] is not None:
        # Cycles' Sharp Glass weighs reflection and refraction by the exact dielectric Fresnel
        # with the index ior from the front face (the outside) and 1/ior from the back.
        glass = nodes.new("ShaderNodeBsdfGlass")
        glass.distribution = "SHARP"
        glass.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        glass.inputs["IOR"].default_value = spec["glass"]["ior"]
        return glass.outputs["BSDF"]
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = rgba(spec["diffuse"])
    diffuse.inputs["Roughness"].default_value = 0.0  # Oren–Nayar with σ = 0 is Lambert
    surface = diffuse.outputs["BSDF"]
    if spec["glossy"] is not None:
        glossy = nodes.new("ShaderNodeBsdfGlossy")
        glossy.distribution = "BECKMANN"
        glossy.inputs["Color"].default_value = rgba(spec["glossy"]["color"])
        glossy.inputs["Roughness"].default_value = spec["glossy"]["roughness"]
        both = nodes.new("ShaderNodeAddShader")
        links.new(surface, both.inputs[0])
        links.new(glossy.outputs["BSDF"], both.inputs[1])
        surface = both.outputs["Shader"]
    return surface


def make_absorption(material, absorption):
    # Beer–Lambert inside a glass: σ = density·(1 − colour) per channel (the exporter's mapping,
    # cyclesAbsorption). A constant density is homogeneous, so Cycles attenuates by exp(−σd)
    # along each segment in closed form instead of marching through it.
    material.cycles.homogeneous_volume = True
    volume = material.node_tree.nodes.new("ShaderNodeVolumeAbsorption")
    volume.inputs["Color"].default_value = rgba(absorption["color"])
    volume.inputs["Density"].default_value = absorption["density"]
    return volume.outputs["Volume"]


def make_material(spec, light_sampling):
    material = bpy.data.materials.new(spec["name"])
    material.cycles.sample_as_light = light_sampling
    material.use_nodes = True
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    output = nodes.new("ShaderNodeOutputMaterial")
    surface = make_surface(material, spec)
    if spec["emission"] is not None:
        # Cycles' mesh emitters shine from both sides; GI Bench's from the front face only, the
        # side (b − a) × (c − a) points to, which is also the side Cycles calls front. The back
        # face keeps the reflection and loses the emission.
        emission = nodes.new("ShaderNodeEmission")
        emission.inputs["Color"].default_value = rgba(spec["emission"])
        emission.inputs["Strength"].default_value = 1.0  # radiance = colour · strength
        front = nodes.new("ShaderNodeAddShader")
        links.new(emission.outputs["Emission"], front.inputs[0])
        links.new(surface, front.inputs[1])
        geometry = nodes.new("ShaderNodeNewGeometry")
        sides = nodes.new("ShaderNodeMixShader")
        links.new(geometry.outputs["Backfacing"], sides.inputs["Fac"])
        links.new(front.outputs["Shader"], sides.inputs[1])  # Fac 0: the front face
        links.new(surface, sides.inputs[2])  # Fac 1: the back face
        surface = sides.outputs["Shader"]
    links.new(surface, output.inputs["Surface"])
    if spec["glass"] is not None and spec["glass"]["absorption"] is not None:
        links.new(make_absorption(material, spec["glass"]["absorption"]), output.inputs["Volume"])
    return material


def make_mesh(scene, spec, materials):
    # Exactly the exported triangles, in their winding (no validation, which could drop or
    # reorder them), shaded flat, or smooth with the exported normals.
    positions, indices, normals = spec["positions"], spec["triangles"], spec["normals"]
    count = len(indices) // 3
    mesh = bpy.data.meshes.new(spec["name"])
    mesh.vertices.add(len(positions) // 3)
    mesh.vertices.foreach_set("co", positions)
    mesh.loops.add(len(indices))
    mesh.loops.foreach_set("vertex_index", indices)
    mesh.polygons.add(count)
    mesh.polygons.foreach_set("loop_start", list(range(0, 3 * count, 3)))
    mesh.polygons.foreach_set("loop_total", [3] * count)
    mesh.polygons.foreach_set("use_smooth", [normals is not None] * count)
    mesh.update(calc_edges=True)
    if normals is not None:
        # Custom split normals: Blender 3.4 keeps them only with auto smooth on, and an angle of
        # 180° splits no edge, so every vertex has the one normal given. Blender stores them as
        # 16-bit offsets from its own vertex normal (docs/cycles-cross-check.md gives the error).
        mesh.use_auto_smooth = True
        mesh.auto_smooth_angle = math.pi
        mesh.normals_split_custom_set_from_vertices(
            [normals[i:i + 3] for i in range(0, len(normals), 3)])
    mesh.materials.append(materials[spec["material"]])
    scene.collection.objects.link(bpy.data.objects.new(spec["name"], mesh))


def make_camera(scene, spec):
    camera = bpy.data.cameras.new("camera")
    camera.type = "PERSP"
    # GI Bench's field of view is vertical whatever the aspect ratio.
    camera.sensor_fit = "VERTICAL"
    camera.angle_y = math.radians(spec["vertical_fov_deg"])
    camera.shift_x = camera.shift_y = 0.0
    camera.clip_start = spec["clip_start"]
    camera.clip_end = spec["clip_end"]
    if spec.get("lens_radius", 0.0) > 0.0:
        # GI Bench's thin lens: Cycles samples a disc of radius lens·10⁻³ / (2·f-stop) scene units
        # (lens: the focal length in mm, set above by angle_y), focused on the plane at
        # focus_distance along the view, as GI Bench's is.
        camera.dof.use_dof = True
        camera.dof.focus_distance = spec["focus_distance"]
        camera.dof.aperture_fstop = camera.lens * 1e-3 / (2.0 * spec["lens_radius"])
        camera.dof.aperture_blades = 0  # a disc, not a polygon
    obj = bpy.data.objects.new("camera", camera)
    # A Blender camera looks down its −Z axis with +Y up the image and +X to the right.
    p, r, u, f = spec["position"], spec["right"], spec["up"], spec["forward"]
    obj.matrix_world = Matrix(((r[0], u[0], -f[0], p[0]),
                               (r[1], u[1], -f[1], p[1]),
                               (r[2], u[2], -f[2], p[2]),
                               (0.0, 0.0, 0.0, 1.0)))
    scene.collection.objects.link(obj)
    scene.camera = obj


def aim_down_minus_z(direction):
    # Lamps shine along their −Z axis.
    return Vector(direction).to_track_quat("-Z", "Y").to_matrix().to_4x4()


def make_lamps(scene, spec):
    for index, spot in enumerate(spec["spot_lamps"]):
        lamp = bpy.data.lights.new(f"spot{index}", "SPOT")
        lamp.energy = spot["watts"]
        lamp.color = spot["color"]
        lamp.spot_size = spot["spot_size"]
        lamp.spot_blend = spot["spot_blend"]
        lamp.shadow_soft_size = 0.0  # a point, as GI Bench's spot light
        obj = bpy.data.objects.new(lamp.name, lamp)
        obj.matrix_world = Matrix.Translation(spot["position"]) @ aim_down_minus_z(spot["direction"])
        scene.collection.objects.link(obj)
    for index, sun in enumerate(spec["sun_lamps"]):
        lamp = bpy.data.lights.new(f"sun{index}", "SUN")
        lamp.energy = sun["strength"]  # irradiance in W/m² on a perpendicular plane
        lamp.color = sun["color"]
        lamp.angle = 0.0  # a direction, not a disc
        obj = bpy.data.objects.new(lamp.name, lamp)
        obj.matrix_world = aim_down_minus_z(sun["direction"])
        scene.collection.objects.link(obj)


def make_world(scene, sky, environment=None):
    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    background = world.node_tree.nodes["Background"]
    background.inputs["Color"].default_value = rgba(sky)
    background.inputs["Strength"].default_value = 1.0
    if environment is not None:
        # The map as a float image, looked up at the nearest texel through the rotation the
        # exporter computed (blender_export.cpp, environmentEntry), scaled by its intensity.
        image = bpy.data.images.new("environment", environment["width"], environment["height"],
                                    float_buffer=True, alpha=True)
        image.colorspace_settings.name = "Non-Color"  # linear Rec.709 as written
        image.pixels.foreach_set(environment["pixels"])
        nodes, links = world.node_tree.nodes, world.node_tree.links
        coordinates = nodes.new("ShaderNodeTexCoord")
        mapping = nodes.new("ShaderNodeMapping")
        mapping.vector_type = "VECTOR"
        mapping.inputs["Rotation"].default_value = Matrix(environment["matrix"]).to_euler("XYZ")
        texture = nodes.new("ShaderNodeTexEnvironment")
        texture.image = image
        texture.interpolation = "Closest"
        texture.projection = "EQUIRECTANGULAR"
        links.new(coordinates.outputs["Generated"], mapping.inputs["Vector"])
        links.new(mapping.outputs["Vector"], texture.inputs["Vector"])
        links.new(texture.outputs["Color"], background.inputs["Color"])
        background.inputs["Strength"].default_value = environment["strength"]
    scene.world = world


def configure_render(scene, render, out):
    scene.render.engine = "CYCLES"
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.feature_set = "SUPPORTED"
    cycles.samples = render["spp"]
    cycles.use_adaptive_sampling = False  # would stop converged pixels early: noise differs
    cycles.time_limit = 0.0
    cycles.use_denoising = False
    cycles.use_preview_denoising = False
    for layer in scene.view_layers:
        layer.cycles.use_denoising = False
        layer.samples = 0  # the scene's sample count
    cycles.seed = render["seed"]
    cycles.use_animated_seed = False
    # Cycles puts sample 0 at the pixel's centre instead of a random place in it: at N samples
    # per pixel that biases every pixel by 1/N of (centre − pixel mean), visible in the image
    # mean at a light's edges. Starting at sample 1 keeps every sample uniform over the pixel.
    cycles.sample_offset = 1
    cycles.sampling_pattern = "PROGRESSIVE_MULTI_JITTER"
    cycles.scrambling_distance = 1.0  # below 1 correlates pixels
    cycles.auto_scrambling_distance = False
    # GI Bench's pixel filter: uniform samples over the pixel's square, each weighted equally.
    cycles.pixel_filter_type = "BOX"
    cycles.filter_width = 1.0
    # No clamping (it cuts energy), no glossy blur, caustics kept, every light kept, no guiding,
    # no fast GI: each changes the expected value or the estimator.
    cycles.sample_clamp_direct = 0.0
    cycles.sample_clamp_indirect = 0.0
    cycles.blur_glossy = 0.0
    cycles.caustics_reflective = True
    cycles.caustics_refractive = True
    cycles.light_sampling_threshold = 0.0
    cycles.use_guiding = False
    cycles.use_fast_gi = False
    cycles.direct_light_sampling_type = "MULTIPLE_IMPORTANCE_SAMPLING"
    cycles.min_light_bounces = 0
    cycles.min_transparent_bounces = 0
    # GI Bench's paths end only by Russian roulette; Cycles' bounce limits are made too high to
    # matter (it also ends paths by Russian roulette, which keeps them unbiased).
    bounces = render["max_bounces"]
    cycles.max_bounces = bounces
    cycles.diffuse_bounces = bounces
    cycles.glossy_bounces = bounces
    cycles.transmission_bounces = bounces
    cycles.transparent_max_bounces = bounces
    cycles.volume_bounces = 0
    cycles.film_exposure = 1.0
    scene.render.film_transparent = False
    scene.render.use_motion_blur = False
    scene.render.use_compositing = False
    scene.render.use_sequencer = False
    scene.render.resolution_x = render["width"]
    scene.render.resolution_y = render["height"]
    scene.render.resolution_percentage = 100
    scene.render.pixel_aspect_x = scene.render.pixel_aspect_y = 1.0
    scene.render.use_border = False
    # The EXR holds scene-linear radiance; the view transform is left neutral all the same.
    scene.view_settings.view_transform = "Standard"
    scene.view_settings.look = "None"
    scene.view_settings.exposure = 0.0
    scene.view_settings.gamma = 1.0
    settings = scene.render.image_settings
    settings.file_format = "OPEN_EXR"
    settings.color_mode = "RGBA"
    settings.color_depth = "32"
    settings.exr_codec = "ZIP"
    scene.render.filepath = out
    scene.render.use_file_extension = False


def main():
    render = dict(SCENE["render"], light_sampling=True)  # noqa: F821 (written above this part)
    out = parse_arguments(render)
    scene = empty_file()
    materials = [make_material(spec, render["light_sampling"])
                 for spec in SCENE["materials"]]  # noqa: F821
    for spec in SCENE["meshes"]:  # noqa: F821
        make_mesh(scene, spec, materials)
    make_camera(scene, SCENE["camera"])  # noqa: F821
    make_lamps(scene, SCENE)  # noqa: F821
    make_world(scene, SCENE["sky"], SCENE["environment"])  # noqa: F821
    configure_render(scene, render, out)
    bpy.ops.render.render(write_still=True)
    if not os.path.isfile(out):
        print(f"gibench blender script: Cycles wrote no '{out}'", file=sys.stderr)
        sys.exit(3)


if __name__ == "__main__":  # not when a test loads the builder to call its parts
    main()
