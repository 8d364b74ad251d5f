/* conform/export_mitsuba.c - a conformance scene as a Mitsuba 3 XML scene.
 *
 * Mitsuba 3's defaults that the truth does not assume, and what this file
 * writes instead (facts from Mitsuba 3's plugin reference):
 * - The film's reconstruction filter is a Gaussian; its "box" filter has a
 *   fixed radius of half a pixel, so each sample counts in its own pixel.
 * - hdrfilm writes half floats unless component_format is float32.
 * - The field of view is horizontal unless fov_axis says otherwise.
 * - Non-transmissive BSDFs are one-sided: a diffuse surface seen from
 *   behind is black. The truth's diffuse surfaces reflect on both sides, so
 *   they are wrapped in "twosided".
 * - The rectangle shape is [-1, 1]^2 in the plane z = 0 with normal +z,
 *   placed by an affine to_world whose shading frame is taken from the
 *   images of its x and y axes: only quads with perpendicular edges map
 *   onto it (cf_export_supports refuses others).
 * The image is not mirrored: Mitsuba's lookat names the camera's x axis
 * "left" and its perspective projection puts that axis at the image's
 * left, so right is (view direction) x (up), as in the truth.
 */
#include "conform/export_impl.h"

static const char *const PINS[CF_N_PINS] = {
    "<lookat origin target up> as the sensor's to_world: Mitsuba's world is right-handed\n"
    "and its perspective sensor puts (view direction) x (up) at the image's right.",
    "fov with fov_axis \"y\": the vertical angle (the default axis is x).",
    "<rfilter type=\"box\"/>: radius 0.5 pixel, each sample counts in its own pixel only\n"
    "(the default is a Gaussian); sampler \"independent\" with sample_count.",
    "<rgb> radiance, linear: hdrfilm applies no curve; component_format float32 (the\n"
    "default is float16). An rgb variant (scalar_rgb) reads the values as they are; a\n"
    "spectral one gives back the same grey.",
    "emitter \"area\" is one-sided, toward the shape's normal: a rectangle's to_world has\n"
    "the columns u / 2, v / 2, unit u x v and the quad's centre, so its [-1, 1]^2 with\n"
    "normal +z lands on the quad facing u x v; flip_normals turns an inward sphere's in.",
    "diffuse is one-sided in Mitsuba: wrapped in \"twosided\". dielectric with int_ior =\n"
    "the index and ext_ior 1: exact Fresnel, the interior behind the normal. Emitters get\n"
    "an explicit black diffuse.",
    "integrator \"path\" max_depth counts segments (1: emitters seen directly only): the\n"
    "scene's value. Russian roulette (rr_depth) is unbiased."};

static void put_rgb(FILE *f, const char *indent, const char *name, double x)
{
    cf_numtext t = cf_num(x);
    fprintf(f, "%s<rgb name=\"%s\" value=\"%s, %s, %s\"/>\n", indent, name, t.s, t.s, t.s);
}

static void put_material(FILE *f, const cf_material *m, int i)
{
    if (m->kind == CF_GLASS) {
        fprintf(f,
                "    <bsdf type=\"dielectric\" id=\"material%d\">\n"
                "        <float name=\"int_ior\" value=\"%s\"/>\n"
                "        <float name=\"ext_ior\" value=\"1\"/>\n"
                "    </bsdf>\n",
                i, cf_num(m->ior).s);
    } else if (m->kind == CF_EMITTER) {
        fprintf(f, "    <bsdf type=\"diffuse\" id=\"material%d\">\n", i);
        put_rgb(f, "        ", "reflectance", 0.0);
        fputs("    </bsdf>\n", f);
    } else {
        fprintf(f, "    <bsdf type=\"twosided\" id=\"material%d\">\n"
                   "        <bsdf type=\"diffuse\">\n", i);
        put_rgb(f, "            ", "reflectance", m->albedo);
        fputs("        </bsdf>\n    </bsdf>\n", f);
    }
}

/* The rectangle's to_world, row by row: it takes (x, y, 0) to
 * centre + x u / 2 + y v / 2, so (-1, -1) is q, and (0, 0, 1) to the unit
 * u x v. Normals go through the inverse transpose, which for these
 * columns sends +z along (u / 2) x (v / 2): the quad's front. */
static void put_rectangle_matrix(FILE *f, const cf_shape *sh)
{
    vec3 c = vec3_add(sh->q, vec3_scale(vec3_add(sh->u, sh->v), 0.5));
    vec3 a = vec3_scale(sh->u, 0.5), b = vec3_scale(sh->v, 0.5), n = cf_quad_normal(sh);
    double rows[3][4] = {{a.x, b.x, n.x, c.x}, {a.y, b.y, n.y, c.y}, {a.z, b.z, n.z, c.z}};
    fputs("            <matrix value=\"", f);
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 4; k++)
            fprintf(f, "%s ", cf_num(rows[r][k]).s);
    fputs("0 0 0 1\"/>\n", f);
}

static void put_shape(FILE *f, const cf_scene *s, int i)
{
    const cf_shape *sh = &s->shapes[i];
    if (sh->kind == CF_QUAD) {
        fputs("    <shape type=\"rectangle\">\n        <transform name=\"to_world\">\n", f);
        put_rectangle_matrix(f, sh);
        fputs("        </transform>\n", f);
    } else {
        fprintf(f,
                "    <shape type=\"sphere\">\n"
                "        <point name=\"center\" x=\"%s\" y=\"%s\" z=\"%s\"/>\n"
                "        <float name=\"radius\" value=\"%s\"/>\n"
                "        <boolean name=\"flip_normals\" value=\"%s\"/>\n",
                cf_num(sh->center.x).s, cf_num(sh->center.y).s, cf_num(sh->center.z).s,
                cf_num(sh->radius).s, sh->inward ? "true" : "false");
    }
    fprintf(f, "        <ref id=\"material%d\"/>\n", sh->material);
    if (cf_shape_emits(s, i)) {
        fputs("        <emitter type=\"area\">\n", f);
        put_rgb(f, "            ", "radiance", s->materials[sh->material].radiance);
        fputs("        </emitter>\n", f);
    }
    fputs("    </shape>\n", f);
}

static void put_sensor(FILE *f, const cf_scene *s, int size, int spp)
{
    double near_clip, far_clip;
    cf_clip_range(s, &near_clip, &far_clip);
    fprintf(f,
            "    <sensor type=\"perspective\">\n"
            "        <float name=\"fov\" value=\"%s\"/>\n"
            "        <string name=\"fov_axis\" value=\"y\"/>\n"
            "        <float name=\"near_clip\" value=\"%s\"/>\n"
            "        <float name=\"far_clip\" value=\"%s\"/>\n",
            cf_num(s->vfov_deg).s, cf_num(near_clip).s, cf_num(far_clip).s);
    fprintf(f,
            "        <transform name=\"to_world\">\n"
            "            <lookat origin=\"%s, %s, %s\" target=\"%s, %s, %s\" up=\"%s, %s, %s\"/>\n"
            "        </transform>\n",
            cf_num(s->lookfrom.x).s, cf_num(s->lookfrom.y).s, cf_num(s->lookfrom.z).s,
            cf_num(s->lookat.x).s, cf_num(s->lookat.y).s, cf_num(s->lookat.z).s,
            cf_num(s->vup.x).s, cf_num(s->vup.y).s, cf_num(s->vup.z).s);
    fprintf(f,
            "        <sampler type=\"independent\">\n"
            "            <integer name=\"sample_count\" value=\"%d\"/>\n"
            "        </sampler>\n"
            "        <film type=\"hdrfilm\">\n"
            "            <integer name=\"width\" value=\"%d\"/>\n"
            "            <integer name=\"height\" value=\"%d\"/>\n"
            "            <string name=\"file_format\" value=\"openexr\"/>\n"
            "            <string name=\"pixel_format\" value=\"rgb\"/>\n"
            "            <string name=\"component_format\" value=\"float32\"/>\n"
            "            <boolean name=\"sample_border\" value=\"false\"/>\n"
            "            <rfilter type=\"box\"/>\n"
            "        </film>\n"
            "    </sensor>\n",
            spp, size, size);
}

void cf_export_mitsuba(FILE *f, const cf_scene *s, int size, int spp)
{
    fputs("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<!--\n", f);
    cf_write_header(f, s, "Mitsuba 3 scene", size, spp, "   ", true, PINS);
    fprintf(f, "   Render: mitsuba -m scalar_rgb %s.xml -o %s.exr\n", s->name, s->name);
    fputs("-->\n<scene version=\"3.0.0\">\n", f);
    fprintf(f,
            "    <integrator type=\"path\">\n"
            "        <integer name=\"max_depth\" value=\"%d\"/>\n"
            "        <boolean name=\"hide_emitters\" value=\"false\"/>\n"
            "    </integrator>\n\n",
            s->min_depth);
    put_sensor(f, s, size, spp);
    fputc('\n', f);
    for (int i = 0; i < s->n_materials; i++)
        put_material(f, &s->materials[i], i);
    fputc('\n', f);
    for (int i = 0; i < s->n_shapes; i++)
        put_shape(f, s, i);
    if (s->background > 0.0) {
        fputs("\n    <emitter type=\"constant\">\n", f);
        put_rgb(f, "        ", "radiance", s->background);
        fputs("    </emitter>\n", f);
    }
    fputs("</scene>\n", f);
}
