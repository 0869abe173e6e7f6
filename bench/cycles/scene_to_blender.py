# Builds one camera of a CENG795 path-tracing scene in Blender Cycles and renders it to a
# linear float EXR, for bench/cycles_anchor.sh. Run inside Blender:
#   blender -b --factory-startup --python-exit-code 1 --python scene_to_blender.py -- \
#     SCENE.xml --camera K --scale F --spp N --seed S --threads T --out FILE.exr
#
# The mapping, chosen so that both renderers estimate the same image:
#   Mesh, LightMesh (inline faces or PLY, with transforms) -> triangle meshes, the XML's
#     winding kept, so Cycles' front faces are the renderer's;
#   opaque Sphere -> a one-point point cloud of the sphere's radius, which Cycles
#     intersects as an exact sphere; a dielectric Sphere -> a smooth icosphere (a ray
#     refracted into a point sphere never leaves it);
#   normalized modified Phong with ks = 0 -> Diffuse BSDF of colour kd;
#   a Phong part (ks > 0) -> Beckmann Glossy of colour ks (N . V), roughness from the
#     exponent;
#   dielectric -> Glass BSDF (IOR) + the Glossy part on the outer side + Volume Absorption;
#   LightMesh -> Emission of strength = Radiance on its front faces;
#   PointLight of intensity I -> point lamp of power 4 pi I, radius 0;
#   MaxRecursionDepth -> every bounce limit, no Russian roulette (min bounces = max),
#     no clamping, no denoising, no adaptive sampling, no light threshold, box filter 1 px.
import math
import os
import sys

import bmesh
import bpy
from mathutils import Matrix, Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from xml_scene import Scene, fail, floats, read_ply  # noqa: E402


def parse_args(argv):
    argv = argv[argv.index("--") + 1:] if "--" in argv else []
    if not argv:
        fail("usage: ... -- SCENE.xml --camera K --scale F --spp N --seed S --threads T --out F")
    a = {"scene": argv[0], "camera": 0, "scale": 1.0, "spp": 16, "seed": 0, "threads": 2,
         "out": "out.exr", "subdiv": 6}
    i = 1
    while i + 1 < len(argv):
        key = argv[i].lstrip("-")
        if key not in a:
            fail("unknown option " + argv[i])
        a[key] = type(a[key])(argv[i + 1])
        i += 2
    return a


def material_node_tree(sc, mat_id, radiance=None):
    """A Cycles material for XML material mat_id (an Emission of `radiance` for lights)."""
    mat = bpy.data.materials.new("m%s%s" % (mat_id, "_light" if radiance else ""))
    mat.use_nodes = True
    nt = mat.node_tree
    nt.nodes.clear()
    out = nt.nodes.new("ShaderNodeOutputMaterial")
    geom = nt.nodes.new("ShaderNodeNewGeometry")
    if radiance is not None:
        em = nt.nodes.new("ShaderNodeEmission")
        em.inputs["Color"].default_value = (radiance[0], radiance[1], radiance[2], 1.0)
        em.inputs["Strength"].default_value = 1.0
        black = nt.nodes.new("ShaderNodeBsdfDiffuse")
        black.inputs["Color"].default_value = (0, 0, 0, 1)
        mix = nt.nodes.new("ShaderNodeMixShader")  # Emission on the front faces only.
        nt.links.new(geom.outputs["Backfacing"], mix.inputs[0])
        nt.links.new(em.outputs[0], mix.inputs[1])
        nt.links.new(black.outputs[0], mix.inputs[2])
        nt.links.new(mix.outputs[0], out.inputs["Surface"])
        return mat
    m = sc.materials.get(mat_id)
    if m is None:
        fail("%s: Material %s is not defined" % (sc.path, mat_id))
    kd = floats(m.findtext("DiffuseReflectance") or "0 0 0")
    ks = floats(m.findtext("SpecularReflectance") or "0 0 0")
    brdf = sc.brdfs.get(m.get("BRDF"))
    kind = m.get("type", "")
    if brdf is None and max(ks) > 0:
        fail("%s: Material %s: a specular part needs a BRDF" % (sc.path, mat_id))
    if brdf is not None and brdf[0] not in ("ModifiedPhong",) and max(ks) > 0:
        fail("%s: Material %s: BRDF %s has no Cycles counterpart here" % (sc.path, mat_id, brdf[0]))
    if kind not in ("", "dielectric"):
        fail("%s: Material %s: type %s has no Cycles counterpart here" % (sc.path, mat_id, kind))
    if brdf is not None and not brdf[1] and max(ks) > 0:
        fail("%s: Material %s: only the normalized modified Phong maps" % (sc.path, mat_id))
    parts = []
    if max(kd) > 0:
        d = nt.nodes.new("ShaderNodeBsdfDiffuse")
        d.inputs["Color"].default_value = (kd[0], kd[1], kd[2], 1.0)
        d.inputs["Roughness"].default_value = 0.0
        parts.append(d.outputs[0])
    if max(ks) > 0:
        # cos^n of the angle to the mirror direction is about cos^(4n) of the half-vector's
        # angle (that angle is about half), Blinn-Phong m = 4n; Beckmann alpha =
        # sqrt(2 / (m + 2)), and Cycles' Roughness input is sqrt(alpha).
        alpha = math.sqrt(2.0 / (4.0 * brdf[2] + 2.0))
        g = nt.nodes.new("ShaderNodeBsdfGlossy")
        g.distribution = "BECKMANN"
        g.inputs["Roughness"].default_value = math.sqrt(alpha)
        # The modified Phong lobe is f cos(theta_i) and narrow, so it reflects ks cos(theta_o)
        # of what it sees; the microfacet lobe has no such cosine: colour = ks (N . V).
        dot = nt.nodes.new("ShaderNodeVectorMath")
        dot.operation = "DOT_PRODUCT"
        nt.links.new(geom.outputs["Normal"], dot.inputs[0])
        nt.links.new(geom.outputs["Incoming"], dot.inputs[1])
        cos = nt.nodes.new("ShaderNodeMath")
        cos.operation = "MAXIMUM"
        nt.links.new(dot.outputs["Value"], cos.inputs[0])
        cos.inputs[1].default_value = 0.0
        tint = nt.nodes.new("ShaderNodeMixRGB")
        tint.blend_type = "MULTIPLY"
        tint.inputs["Fac"].default_value = 1.0
        tint.inputs["Color1"].default_value = (ks[0], ks[1], ks[2], 1.0)
        nt.links.new(cos.outputs[0], tint.inputs["Color2"])
        nt.links.new(tint.outputs[0], g.inputs["Color"])
        parts.append(g.outputs[0])
    surface = None
    for p in parts:
        if surface is None:
            surface = p
        else:
            add = nt.nodes.new("ShaderNodeAddShader")
            nt.links.new(surface, add.inputs[0])
            nt.links.new(p, add.inputs[1])
            surface = add.outputs[0]
    if kind == "dielectric":
        ior = float((m.findtext("RefractionIndex") or "1.5").strip())
        glass = nt.nodes.new("ShaderNodeBsdfGlass")
        glass.distribution = "SHARP"
        glass.inputs["IOR"].default_value = ior
        glass.inputs["Color"].default_value = (1, 1, 1, 1)
        outer = glass.outputs[0]
        if surface is not None:  # The reflection model lights only the outer side.
            add = nt.nodes.new("ShaderNodeAddShader")
            nt.links.new(glass.outputs[0], add.inputs[0])
            nt.links.new(surface, add.inputs[1])
            mix = nt.nodes.new("ShaderNodeMixShader")
            nt.links.new(geom.outputs["Backfacing"], mix.inputs[0])
            nt.links.new(add.outputs[0], mix.inputs[1])
            nt.links.new(glass.outputs[0], mix.inputs[2])
            outer = mix.outputs[0]
        surface = outer
        sigma = floats(m.findtext("AbsorptionCoefficient") or "0 0 0")
        if max(sigma) > 0:
            # Cycles' coefficient is density * (1 - colour); colour 0 per channel keeps
            # density as the coefficient, so one density with a colour for the ratios.
            dens = max(sigma)
            va = nt.nodes.new("ShaderNodeVolumeAbsorption")
            va.inputs["Color"].default_value = tuple(1.0 - s / dens for s in sigma) + (1.0,)
            va.inputs["Density"].default_value = dens
            nt.links.new(va.outputs[0], out.inputs["Volume"])
            mat.cycles.homogeneous_volume = True
    if surface is None:  # Black.
        d = nt.nodes.new("ShaderNodeBsdfDiffuse")
        d.inputs["Color"].default_value = (0, 0, 0, 1)
        surface = d.outputs[0]
    nt.links.new(surface, out.inputs["Surface"])
    return mat


def add_mesh(sc, e, mat, name):
    faces = e.find("Faces")
    if faces is None:
        fail("%s: %s %s has no Faces" % (sc.path, e.tag, e.get("id")))
    if faces.get("plyFile"):
        verts, tris = read_ply(os.path.join(sc.dir, faces.get("plyFile")))
    else:
        off = int(faces.get("vertexOffset", "0"))
        idx = [int(v) for v in (faces.text or "").split()]
        used = sorted(set(i + off - 1 for i in idx))
        remap = {v: k for k, v in enumerate(used)}
        for v in used:
            if not 0 <= v < len(sc.vertices):
                fail("%s: %s %s: vertex %d out of range" % (sc.path, e.tag, e.get("id"), v + 1))
        verts = [sc.vertices[v] for v in used]
        tris = [tuple(remap[i + off - 1] for i in idx[k:k + 3]) for k in range(0, len(idx) - 2, 3)]
    me = bpy.data.meshes.new(name)
    me.from_pydata(verts, [], tris)
    me.materials.append(mat)
    if e.get("shadingMode") == "smooth":
        for poly in me.polygons:
            poly.use_smooth = True
    ob = bpy.data.objects.new(name, me)
    ob.matrix_world = sc.matrix(e)
    bpy.context.scene.collection.objects.link(ob)


def add_sphere(sc, e, mat, dielectric, subdiv):
    c = Vector(sc.vertices[int(e.findtext("Center").strip()) - 1])
    r = float(e.findtext("Radius").strip())
    name = "sphere%s" % e.get("id")
    if dielectric:
        me = bpy.data.meshes.new(name)
        bm = bmesh.new()
        bmesh.ops.create_icosphere(bm, subdivisions=subdiv, radius=r)
        bm.to_mesh(me)
        bm.free()
        for poly in me.polygons:
            poly.use_smooth = True
        data = me
        local = Matrix.Translation(c)
    else:
        # One vertex made a point of radius r by geometry nodes (Mesh to Points): Cycles
        # renders the point cloud's points as exact spheres.
        me = bpy.data.meshes.new(name)
        me.from_pydata([tuple(c)], [], [])
        data = me
        local = Matrix.Identity(4)
        ng = bpy.data.node_groups.new(name + "_points", "GeometryNodeTree")
        ng.inputs.new("NodeSocketGeometry", "Geometry")
        ng.outputs.new("NodeSocketGeometry", "Geometry")
        gi = ng.nodes.new("NodeGroupInput")
        go = ng.nodes.new("NodeGroupOutput")
        pts = ng.nodes.new("GeometryNodeMeshToPoints")
        pts.inputs["Radius"].default_value = r
        setm = ng.nodes.new("GeometryNodeSetMaterial")
        setm.inputs["Material"].default_value = mat
        ng.links.new(gi.outputs[0], pts.inputs["Mesh"])
        ng.links.new(pts.outputs[0], setm.inputs["Geometry"])
        ng.links.new(setm.outputs[0], go.inputs[0])
    data.materials.append(mat)
    ob = bpy.data.objects.new(name, data)
    ob.matrix_world = sc.matrix(e) @ local
    bpy.context.scene.collection.objects.link(ob)
    if not dielectric:
        ob.modifiers.new("points", "NODES").node_group = ng


def add_camera(sc, cam_el, scale):
    pos = Vector(floats(cam_el.findtext("Position")))
    gaze = Vector(floats(cam_el.findtext("Gaze"))).normalized()
    up = Vector(floats(cam_el.findtext("Up")))
    if cam_el.get("type") != "lookAt" and cam_el.findtext("FovY") is None:
        fail("%s: Camera %s: only lookAt cameras with FovY map" % (sc.path, cam_el.get("id")))
    right = gaze.cross(up).normalized()
    up = right.cross(gaze).normalized()
    rot = Matrix(((right.x, up.x, -gaze.x), (right.y, up.y, -gaze.y), (right.z, up.z, -gaze.z)))
    cd = bpy.data.cameras.new("camera")
    cd.sensor_fit = "VERTICAL"
    cd.lens_unit = "FOV"
    cd.angle_y = math.radians(float(cam_el.findtext("FovY")))
    cd.clip_start = float((cam_el.findtext("NearDistance") or "0.001").strip())
    cd.clip_end = 1e6
    ob = bpy.data.objects.new("camera", cd)
    ob.matrix_world = Matrix.Translation(pos) @ rot.to_4x4()
    bpy.context.scene.collection.objects.link(ob)
    bpy.context.scene.camera = ob
    w, h = (int(v) for v in cam_el.findtext("ImageResolution").split())
    return max(1, round(w * scale)), max(1, round(h * scale))


def settings(s, depth, a, size):
    s.render.engine = "CYCLES"
    cy = s.cycles
    cy.device = "CPU"
    cy.samples = a["spp"]
    cy.seed = a["seed"]
    cy.use_adaptive_sampling = False
    cy.use_denoising = False
    for k in ("max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces",
              "transparent_max_bounces", "min_light_bounces", "min_transparent_bounces"):
        setattr(cy, k, depth)
    cy.volume_bounces = 0
    cy.sample_clamp_direct = 0.0
    cy.sample_clamp_indirect = 0.0
    cy.blur_glossy = 0.0
    cy.caustics_reflective = True
    cy.caustics_refractive = True
    cy.light_sampling_threshold = 0.0
    cy.pixel_filter_type = "BOX"
    cy.filter_width = 1.0
    for k, v in (("use_light_tree", False), ("use_guiding", False),
                 ("direct_light_sampling_type", "MULTIPLE_IMPORTANCE_SAMPLING")):
        if hasattr(cy, k):
            setattr(cy, k, v)
    s.render.threads_mode = "FIXED"
    s.render.threads = a["threads"]
    s.render.resolution_x, s.render.resolution_y = size
    s.render.resolution_percentage = 100
    s.render.film_transparent = False
    s.render.use_persistent_data = False
    s.view_settings.view_transform = "Standard"
    s.view_settings.look = "None"
    s.view_settings.exposure = 0.0
    s.view_settings.gamma = 1.0
    im = s.render.image_settings
    im.file_format = "OPEN_EXR"
    im.color_mode = "RGB"
    im.color_depth = "32"
    im.exr_codec = "ZIP"
    s.render.filepath = os.path.abspath(a["out"])
    w = bpy.data.worlds.new("black")
    w.use_nodes = False
    w.color = (0.0, 0.0, 0.0)
    if hasattr(w.cycles, "sampling_method"):
        w.cycles.sampling_method = "NONE"
    s.world = w


def build(a):
    sc = Scene(a["scene"])
    r = sc.root
    if r.findtext("BackgroundColor") and max(floats(r.findtext("BackgroundColor"))) > 0:
        fail("%s: BackgroundColor: only black maps (the paths that escape see it)" % sc.path)
    cams = r.find("Cameras")
    cam_list = list(cams) if cams is not None else []
    if not 0 <= a["camera"] < len(cam_list):
        fail("%s: --camera %d: the scene has %d cameras" % (sc.path, a["camera"], len(cam_list)))
    size = add_camera(sc, cam_list[a["camera"]], a["scale"])
    lights = r.find("Lights")
    for e in (list(lights) if lights is not None else []):
        if e.tag == "AmbientLight":
            if max(floats(e.text)) > 0:
                fail("%s: AmbientLight: only black maps" % sc.path)
        elif e.tag == "PointLight":
            i = floats(e.findtext("Intensity"))
            peak = max(i)
            ld = bpy.data.lights.new("point%s" % e.get("id"), "POINT")
            ld.energy = 4.0 * math.pi * peak
            ld.color = tuple(v / peak for v in i) if peak > 0 else (0, 0, 0)
            ld.shadow_soft_size = 0.0
            ob = bpy.data.objects.new(ld.name, ld)
            ob.location = Vector(floats(e.findtext("Position")))
            bpy.context.scene.collection.objects.link(ob)
        else:
            fail("%s: Lights: %s has no Cycles counterpart here" % (sc.path, e.tag))
    mats = {}
    for e in r.find("Objects"):
        mid = (e.findtext("Material") or "").strip()
        if e.tag in ("Mesh", "LightMesh"):
            rad = floats(e.findtext("Radiance")) if e.tag == "LightMesh" else None
            key = (mid, tuple(rad) if rad else None)
            if key not in mats:
                mats[key] = material_node_tree(sc, mid, rad)
            add_mesh(sc, e, mats[key], "%s%s" % (e.tag, e.get("id")))
        elif e.tag == "Sphere":
            if (mid, None) not in mats:
                mats[(mid, None)] = material_node_tree(sc, mid)
            dielectric = sc.materials[mid].get("type") == "dielectric"
            add_sphere(sc, e, mats[(mid, None)], dielectric, a["subdiv"])
        else:
            fail("%s: Objects: %s has no Cycles counterpart here" % (sc.path, e.tag))
    settings(bpy.context.scene, sc.depth, a, size)


def main():
    a = parse_args(sys.argv)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    build(a)
    bpy.ops.render.render(write_still=True)
    if not os.path.isfile(os.path.abspath(a["out"])):
        fail("no image written to " + a["out"])


main()
