/* conform/export_blender.c - a conformance scene as a Python script for
 * Blender that builds the scene, renders it with Cycles and writes an
 * OpenEXR image of 32-bit floats.
 *
 * Cycles' defaults that the truth does not assume, and what the script
 * sets instead (facts from Blender's manual and the Cycles add-on's
 * property definitions):
 * - A mesh with an Emission shader emits from both faces: the emission is
 *   masked by the Geometry node's Backfacing output.
 * - The pixel filter is Blackman-Harris, 1.5 pixels wide: set to a box of
 *   width 1.
 * - Denoising and adaptive sampling are on, indirect light is clamped at
 *   10, glossy paths are blurred, lights below a threshold are dropped at
 *   random, and the diffuse bounce limit is 4: each is set off or raised.
 * - Blender has no true sphere primitive that Cycles shades as a surface
 *   with an emission shader: spheres become polyhedra (see SPHERE_SEGMENTS
 *   in the script for what that costs).
 * Units: seen directly, an Emission shader of colour c and strength S is
 * the pixel c S, and a world Background of colour c and strength S gives
 * c S to every ray that leaves the scene ("a value of 1.0 will ensure that
 * the object in the image has the exact same color as the Color input",
 * Blender's manual on the Emission node). Cycles labels mesh emission in
 * W/m^2, but in the image's units the strength acts as radiance, so the
 * script writes the table's radiance as the strength of a white emission.
 */
#include "conform/export_impl.h"

static const char *const PINS[CF_N_PINS] = {
    "the camera object's matrix_world is built from LOOKFROM, LOOKAT and VUP: its -Z\n"
    "looks at LOOKAT, its +Y is up and its +X, (view direction) x (up), is the image's\n"
    "right. Blender's world is right-handed; no flip is needed.",
    "camera sensor_fit 'VERTICAL' and angle_y = the field of view.",
    "scene.cycles.pixel_filter_type = 'BOX' and filter_width = 1.0 pixel (the default\n"
    "is Blackman-Harris, 1.5 pixels).",
    "emission strength = the radiance, colour white; the world Background has strength\n"
    "1 and the background as colour. View transform 'Standard', look 'None', exposure 0,\n"
    "gamma 1, film_exposure 1; no denoising, no adaptive sampling, no clamping, light\n"
    "threshold 0, filter glossy 0; OpenEXR with 32-bit floats.",
    "Cycles emits from both faces of a mesh: the emission is masked by Geometry >\n"
    "Backfacing (and emission_sampling is 'FRONT' where Blender has it). A quad is the\n"
    "face (q, q + u, q + u + v, q + v), whose normal by Blender's counter-clockwise rule\n"
    "is u x v; a sphere is a polyhedron facing out, reversed where inward.",
    "Diffuse BSDF with roughness 0 is Lambertian and shades both faces; Glass BSDF,\n"
    "white, roughness 0, IOR = the index, is entered through the front face. Emitters\n"
    "have no BSDF, so they reflect nothing.",
    "max_bounces and every per-type limit (diffuse, glossy, transmission, transparent) =\n"
    "the scene's segment count: Cycles counts bounces, one fewer than segments, so one\n"
    "segment more is allowed."};

/* The script after its data: functions that build and render the scene.
 * Python, written as lines so that the indentation reads as in the file. */
static const char *const BODY[] = {
    "",
    "def output_path():",
    "    \"\"\"The EXR to write: the argument after '--', else NAME.exr beside the script.\"\"\"",
    "    if '--' in sys.argv and sys.argv.index('--') + 1 < len(sys.argv):",
    "        return os.path.abspath(sys.argv[sys.argv.index('--') + 1])",
    "    script = globals().get('__file__')",
    "    folder = os.path.dirname(os.path.abspath(script)) if script else os.getcwd()",
    "    return os.path.join(folder, SCENE + '.exr')",
    "",
    "",
    "def set_if_present(owner, name, value):",
    "    \"\"\"Sets a property that only some Blender versions have.\"\"\"",
    "    if hasattr(owner, name):",
    "        setattr(owner, name, value)",
    "",
    "",
    "def setup_render(scene):",
    "    scene.render.engine = 'CYCLES'",
    "    cycles = scene.cycles",
    "    cycles.device = 'CPU'",
    "    cycles.samples = SPP",
    "    cycles.seed = 0",
    "    cycles.use_adaptive_sampling = False",
    "    cycles.use_denoising = False",
    "    cycles.pixel_filter_type = 'BOX'",
    "    cycles.filter_width = 1.0",
    "    cycles.max_bounces = MAX_DEPTH",
    "    cycles.diffuse_bounces = MAX_DEPTH",
    "    cycles.glossy_bounces = MAX_DEPTH",
    "    cycles.transmission_bounces = MAX_DEPTH",
    "    cycles.transparent_max_bounces = MAX_DEPTH",
    "    cycles.volume_bounces = 0",
    "    cycles.sample_clamp_direct = 0.0",
    "    cycles.sample_clamp_indirect = 0.0",
    "    cycles.blur_glossy = 0.0",
    "    cycles.caustics_reflective = True",
    "    cycles.caustics_refractive = True",
    "    cycles.light_sampling_threshold = 0.0",
    "    cycles.film_exposure = 1.0",
    "    set_if_present(cycles, 'use_guiding', False)",
    "    set_if_present(cycles, 'time_limit', 0.0)",
    "    render = scene.render",
    "    render.resolution_x = SIZE",
    "    render.resolution_y = SIZE",
    "    render.resolution_percentage = 100",
    "    render.pixel_aspect_x = 1.0",
    "    render.pixel_aspect_y = 1.0",
    "    render.use_border = False",
    "    render.film_transparent = False",
    "    render.use_compositing = False",
    "    render.use_sequencer = False",
    "    render.dither_intensity = 0.0",
    "    scene.display_settings.display_device = 'sRGB'",
    "    scene.view_settings.view_transform = 'Standard'",
    "    scene.view_settings.look = 'None'",
    "    scene.view_settings.exposure = 0.0",
    "    scene.view_settings.gamma = 1.0",
    "    image = render.image_settings",
    "    image.file_format = 'OPEN_EXR'",
    "    image.color_mode = 'RGB'",
    "    image.color_depth = '32'",
    "    image.exr_codec = 'ZIP'",
    "",
    "",
    "def setup_camera(scene):",
    "    data = bpy.data.cameras.new('camera')",
    "    data.type = 'PERSP'",
    "    data.sensor_fit = 'VERTICAL'",
    "    data.angle_y = math.radians(VFOV_DEG)",
    "    data.shift_x = 0.0",
    "    data.shift_y = 0.0",
    "    data.clip_start, data.clip_end = CLIP",
    "    data.dof.use_dof = False",
    "    camera = bpy.data.objects.new('camera', data)",
    "    scene.collection.objects.link(camera)",
    "    scene.camera = camera",
    "    # Blender's camera looks down its -Z with +Y up: w points back at the eye.",
    "    eye = Vector(LOOKFROM)",
    "    w = (eye - Vector(LOOKAT)).normalized()",
    "    u = Vector(VUP).cross(w).normalized()",
    "    v = w.cross(u)",
    "    camera.matrix_world = Matrix(((u.x, v.x, w.x, eye.x), (u.y, v.y, w.y, eye.y),",
    "                                  (u.z, v.z, w.z, eye.z), (0.0, 0.0, 0.0, 1.0)))",
    "",
    "",
    "def setup_world(scene):",
    "    world = bpy.data.worlds.new('background')",
    "    world.use_nodes = True",
    "    nodes = world.node_tree.nodes",
    "    nodes.clear()",
    "    background = nodes.new('ShaderNodeBackground')",
    "    background.inputs['Color'].default_value = (BACKGROUND, BACKGROUND, BACKGROUND, 1.0)",
    "    background.inputs['Strength'].default_value = 1.0",
    "    output = nodes.new('ShaderNodeOutputWorld')",
    "    world.node_tree.links.new(background.outputs[0], output.inputs['Surface'])",
    "    scene.world = world",
    "",
    "",
    "def make_material(index, kind, albedo, radiance, ior):",
    "    material = bpy.data.materials.new('material%d' % index)",
    "    material.use_nodes = True",
    "    tree = material.node_tree",
    "    tree.nodes.clear()",
    "    output = tree.nodes.new('ShaderNodeOutputMaterial')",
    "    surface = None",
    "    if kind == 'glass':",
    "        surface = tree.nodes.new('ShaderNodeBsdfGlass')",
    "        try:",
    "            surface.distribution = 'SHARP'  # Blender 4 dropped it: roughness 0 is sharp",
    "        except TypeError:",
    "            pass",
    "        surface.inputs['Color'].default_value = (1.0, 1.0, 1.0, 1.0)",
    "        surface.inputs['Roughness'].default_value = 0.0",
    "        surface.inputs['IOR'].default_value = ior",
    "    if kind in ('diffuse', 'diffuse_emitter'):",
    "        surface = tree.nodes.new('ShaderNodeBsdfDiffuse')",
    "        surface.inputs['Color'].default_value = (albedo, albedo, albedo, 1.0)",
    "        surface.inputs['Roughness'].default_value = 0.0",
    "    if kind in ('emitter', 'diffuse_emitter') and radiance > 0.0:",
    "        emission = tree.nodes.new('ShaderNodeEmission')",
    "        emission.inputs['Color'].default_value = (1.0, 1.0, 1.0, 1.0)",
    "        emission.inputs['Strength'].default_value = radiance",
    "        # One-sided: the back face gets the mix's second input, left empty (black).",
    "        geometry = tree.nodes.new('ShaderNodeNewGeometry')",
    "        front = tree.nodes.new('ShaderNodeMixShader')",
    "        tree.links.new(geometry.outputs['Backfacing'], front.inputs[0])",
    "        tree.links.new(emission.outputs[0], front.inputs[1])",
    "        if surface is None:",
    "            surface = front",
    "        else:",
    "            both = tree.nodes.new('ShaderNodeAddShader')",
    "            tree.links.new(surface.outputs[0], both.inputs[0])",
    "            tree.links.new(front.outputs[0], both.inputs[1])",
    "            surface = both",
    "        # Blender 3.5 replaced sample_as_light with emission_sampling.",
    "        set_if_present(material.cycles, 'sample_as_light', LIGHT_SAMPLING)",
    "        set_if_present(material.cycles, 'emission_sampling',",
    "                       'FRONT' if LIGHT_SAMPLING else 'NONE')",
    "    else:",
    "        set_if_present(material.cycles, 'sample_as_light', False)",
    "        set_if_present(material.cycles, 'emission_sampling', 'NONE')",
    "    if surface is not None:",
    "        tree.links.new(surface.outputs[0], output.inputs['Surface'])",
    "    return material",
    "",
    "",
    "def quad_mesh(q, u, v):",
    "    q, u, v = Vector(q), Vector(u), Vector(v)",
    "    return [q, q + u, q + u + v, q + v], [(0, 1, 2, 3)]",
    "",
    "",
    "def sphere_mesh(center, radius, inward):",
    "    \"\"\"A latitude-longitude polyhedron with its vertices on the sphere, facing out.\"\"\"",
    "    cx, cy, cz = center",
    "    nu, nv = SPHERE_SEGMENTS, SPHERE_SEGMENTS // 2",
    "    verts = [(cx, cy, cz + radius)]",
    "    for j in range(1, nv):",
    "        s, c = math.sin(math.pi * j / nv), math.cos(math.pi * j / nv)",
    "        for i in range(nu):",
    "            phi = 2.0 * math.pi * i / nu",
    "            verts.append((cx + radius * s * math.cos(phi), cy + radius * s * math.sin(phi),",
    "                          cz + radius * c))",
    "    south = len(verts)",
    "    verts.append((cx, cy, cz - radius))",
    "",
    "    def ring(j, i):",
    "        return 1 + (j - 1) * nu + i % nu",
    "",
    "    # Counter-clockwise seen from outside: (north pole, ring 1) caps, quads going",
    "    # down then east, (last ring, south pole) caps.",
    "    faces = []",
    "    for i in range(nu):",
    "        faces.append((0, ring(1, i), ring(1, i + 1)))",
    "        for j in range(1, nv - 1):",
    "            faces.append((ring(j, i), ring(j + 1, i), ring(j + 1, i + 1), ring(j, i + 1)))",
    "        faces.append((ring(nv - 1, i), south, ring(nv - 1, i + 1)))",
    "    if inward:",
    "        faces = [tuple(reversed(face)) for face in faces]",
    "    return verts, faces",
    "",
    "",
    "def add_object(scene, name, verts, faces, material):",
    "    mesh = bpy.data.meshes.new(name)",
    "    mesh.from_pydata([tuple(p) for p in verts], [], faces)",
    "    mesh.validate()",
    "    mesh.update()",
    "    for polygon in mesh.polygons:",
    "        polygon.use_smooth = False",
    "    mesh.materials.append(material)",
    "    obj = bpy.data.objects.new(name, mesh)",
    "    scene.collection.objects.link(obj)",
    "",
    "",
    "def main():",
    "    bpy.ops.wm.read_factory_settings(use_empty=True)",
    "    scene = bpy.context.scene",
    "    setup_render(scene)",
    "    setup_camera(scene)",
    "    setup_world(scene)",
    "    materials = [make_material(i, *m) for i, m in enumerate(MATERIALS)]",
    "    for i, shape in enumerate(SHAPES):",
    "        if shape[0] == 'quad':",
    "            verts, faces = quad_mesh(*shape[2:])",
    "        else:",
    "            verts, faces = sphere_mesh(*shape[2:])",
    "        add_object(scene, 'shape%d' % i, verts, faces, materials[shape[1]])",
    "    scene.render.filepath = output_path()",
    "    bpy.ops.render.render(write_still=True)",
    "",
    "",
    "main()",
    NULL};

static void put_tuple(FILE *f, vec3 p)
{
    fprintf(f, "(%s, %s, %s)", cf_num(p.x).s, cf_num(p.y).s, cf_num(p.z).s);
}

static const char *kind_word(cf_material_kind k)
{
    return k == CF_DIFFUSE ? "diffuse" : k == CF_EMITTER ? "emitter"
                                      : k == CF_DIFFUSE_EMITTER ? "diffuse_emitter" : "glass";
}

static void put_data(FILE *f, const cf_scene *s, int size, int spp)
{
    double near_clip, far_clip;
    cf_clip_range(s, &near_clip, &far_clip);
    fprintf(f, "SCENE = '%s'\nSIZE = %d\nSPP = %d\nMAX_DEPTH = %d\nVFOV_DEG = %s\n", s->name,
            size, spp, s->min_depth, cf_num(s->vfov_deg).s);
    fputs("LOOKFROM = ", f);
    put_tuple(f, s->lookfrom);
    fputs("\nLOOKAT = ", f);
    put_tuple(f, s->lookat);
    fputs("\nVUP = ", f);
    put_tuple(f, s->vup);
    fprintf(f, "\nCLIP = (%s, %s)\nBACKGROUND = %s\n", cf_num(near_clip).s, cf_num(far_clip).s,
            cf_num(s->background).s);
    fputs("# (kind, albedo, radiance, ior), by index\nMATERIALS = [\n", f);
    for (int i = 0; i < s->n_materials; i++) {
        const cf_material *m = &s->materials[i];
        fprintf(f, "    ('%s', %s, %s, %s),\n", kind_word(m->kind), cf_num(m->albedo).s,
                cf_num(m->radiance).s, cf_num(m->ior).s);
    }
    fputs("]\n# ('quad', material, q, u, v) or ('sphere', material, center, radius, inward)\n"
          "SHAPES = [\n",
          f);
    for (int i = 0; i < s->n_shapes; i++) {
        const cf_shape *sh = &s->shapes[i];
        fprintf(f, "    ('%s', %d, ", sh->kind == CF_QUAD ? "quad" : "sphere", sh->material);
        if (sh->kind == CF_QUAD) {
            put_tuple(f, sh->q);
            fputs(", ", f);
            put_tuple(f, sh->u);
            fputs(", ", f);
            put_tuple(f, sh->v);
        } else {
            put_tuple(f, sh->center);
            fprintf(f, ", %s, %s", cf_num(sh->radius).s, sh->inward ? "True" : "False");
        }
        fputs("),\n", f);
    }
    fputs("]\n", f);
}

void cf_export_blender(FILE *f, const cf_scene *s, int size, int spp)
{
    cf_write_header(f, s, "Blender (Cycles) Python", size, spp, "# ", false, PINS);
    fprintf(f,
            "# Render: blender --background --factory-startup --python %s.py [-- OUT.exr]\n"
            "# (writes %s.exr beside this script unless OUT.exr is given).\n"
            "#\n"
            "# Cycles' units: seen directly, an Emission shader of colour c and strength S is the\n"
            "# pixel c S, and a world Background of colour c and strength S gives c S to every\n"
            "# ray that leaves the scene (Blender's manual: strength 1.0 shows an object in\n"
            "# exactly its colour). Cycles labels mesh emission W/m^2, but in the image's units\n"
            "# the strength acts as radiance in W/(m^2 sr): strength = the radiance, colour white.\n"
            "# (Blender 3.4 renders furnace-white 0.5 in every pixel this way.)\n\n",
            s->name, s->name);
    fputs("import math\nimport os\nimport sys\n\nimport bpy\nfrom mathutils import Matrix, "
          "Vector\n\n",
          f);
    put_data(f, s, size, spp);
    fputs("# Spheres are polyhedra of SPHERE_SEGMENTS around by SPHERE_SEGMENTS / 2 down with\n"
          "# their vertices on the sphere: within r (1 - cos(pi / 768)), 8.4e-6 r, of it. Closed\n"
          "# polyhedra keep the furnaces exact; a sphere lighting a floor loses about 1e-5 of\n"
          "# its irradiance, far below the noise of any practical sample count.\n"
          "SPHERE_SEGMENTS = 768\n\n"
          "# Whether Cycles also samples the emitters directly (next-event estimation), as\n"
          "# it does by default. Measured with Blender 3.4 against the exact images: with it,\n"
          "# quad-wall came out 0.2% dark next to its emitter, sphere-wall 1% dark (its sphere\n"
          "# is some 300,000 small emitting triangles) and furnace-grey 0.2% dark; with False,\n"
          "# paths find emitters by BSDF sampling alone and every scene matched the truth\n"
          "# within the noise, which is larger. True tests Cycles as it renders by default.\n"
          "LIGHT_SAMPLING = True\n\n",
          f);
    for (int i = 0; BODY[i]; i++) {
        fputs(BODY[i], f);
        fputc('\n', f);
    }
}
