/* conform/export_pbrt.c - a conformance scene as a pbrt-v4 scene file.
 *
 * What pbrt-v4 does by default that the truth does not assume, and what
 * this file writes instead (facts from pbrt-v4's file-format reference and
 * its sources: cameras, film, lights, shapes):
 * - Its camera space is left-handed: LookAt builds the camera's x axis as
 *   up x direction, which a right-handed scene sees as the image's left.
 *   "Scale -1 1 1" before LookAt turns it back; the shapes, declared after
 *   WorldBegin, do not see it.
 * - The film's sensor scale is exposure time x ISO / 100, the exposure time
 *   the camera's shutterclose - shutteropen: 1 x 100 / 100 with the values
 *   pinned here. An "rgb L" is divided by the luminance of the colour
 *   space's illuminant, so rgb (1, 1, 1) comes out as pixel (1, 1, 1) with
 *   the CIE 1931 sensor and no white balance. A grey "rgb reflectance"
 *   becomes an exactly flat spectrum (pbrt special-cases r = g = b).
 * - The EXR is written in half floats unless "savefp16" is false.
 * - A shape without a Material gets a diffuse one of reflectance 0.5: every
 *   shape here names its own.
 */
#include "conform/export_impl.h"

static const char *const PINS[CF_N_PINS] = {
    "\"Scale -1 1 1\" before LookAt: pbrt's camera space is left-handed and\n"
    "LookAt alone would mirror the image left to right. The shapes are not mirrored.",
    "Camera \"perspective\" \"float fov\": pbrt's fov spans the shorter image axis.",
    "PixelFilter \"box\", xradius = yradius = 0.5: pbrt draws film positions from the\n"
    "filter, here uniformly over the pixel, each with weight 1.",
    "Film \"rgb\", sensor \"cie1931\", iso 100, whitebalance 0, shutter open 0 to 1:\n"
    "imaging ratio = exposure time x iso / 100 = 1. pbrt scales \"rgb L\" so that rgb 1\n"
    "has luminance 1, so a grey L is pixel L. savefp16 false: 32-bit floats.",
    "AreaLightSource \"diffuse\", twosided false, emits toward the surface normal: a\n"
    "bilinearmesh patch with P = q, q + u, q + v, q + u + v has normal u x v; a sphere's\n"
    "normal points out, and ReverseOrientation turns an inward sphere's in.",
    "Material \"diffuse\" reflects on both sides; \"dielectric\" with a float eta (no\n"
    "dispersion) and roughness 0 is smooth with exact Fresnel, eta = inside / outside,\n"
    "outside where the normal points. Emitters get a black diffuse material.",
    "Integrator \"path\" \"integer maxdepth\" counts bounces, one fewer than segments:\n"
    "the value written, the scene's segment count, allows one segment more."};

static void put_grey(FILE *f, double x)
{
    cf_numtext t = cf_num(x);
    fprintf(f, "[ %s %s %s ]", t.s, t.s, t.s);
}

static void put_point(FILE *f, vec3 p)
{
    fprintf(f, " %s %s %s", cf_num(p.x).s, cf_num(p.y).s, cf_num(p.z).s);
}

static const char *kind_name(cf_material_kind k)
{
    return k == CF_DIFFUSE ? "diffuse" : k == CF_EMITTER ? "emitter"
                                      : k == CF_DIFFUSE_EMITTER ? "diffuse emitter" : "glass";
}

static void put_material(FILE *f, const cf_material *m)
{
    fputs("    Material ", f);
    if (m->kind == CF_GLASS) {
        fprintf(f, "\"dielectric\" \"float eta\" [ %s ] \"float roughness\" [ 0 ]\n",
                cf_num(m->ior).s);
        return;
    }
    /* An emitter alone reflects nothing. */
    fputs("\"diffuse\" \"rgb reflectance\" ", f);
    put_grey(f, m->kind == CF_EMITTER ? 0.0 : m->albedo);
    fputc('\n', f);
    if (cf_material_emits(m)) {
        fputs("    AreaLightSource \"diffuse\" \"rgb L\" ", f);
        put_grey(f, m->radiance);
        fputs(" \"bool twosided\" [ false ]\n", f);
    }
}

static void put_shape(FILE *f, const cf_scene *s, int i)
{
    const cf_shape *sh = &s->shapes[i];
    const cf_material *m = &s->materials[sh->material];
    fprintf(f, "# shape %d: %s%s, material %d (%s)\nAttributeBegin\n", i,
            sh->kind == CF_QUAD ? "quad" : "sphere", sh->inward ? " (inward)" : "", sh->material,
            kind_name(m->kind));
    if (sh->kind == CF_SPHERE) {
        fputs("    Translate", f);
        put_point(f, sh->center);
        fputc('\n', f);
        if (sh->inward)
            fputs("    ReverseOrientation\n", f);
    }
    put_material(f, m);
    if (sh->kind == CF_SPHERE) {
        fprintf(f, "    Shape \"sphere\" \"float radius\" [ %s ]\n", cf_num(sh->radius).s);
    } else {
        /* Vertex order p00, p10, p01, p11: pbrt's patch normal is
         * dp/du x dp/dv = u x v, the quad's front. */
        fputs("    Shape \"bilinearmesh\" \"point3 P\" [", f);
        put_point(f, sh->q);
        put_point(f, vec3_add(sh->q, sh->u));
        put_point(f, vec3_add(sh->q, sh->v));
        put_point(f, vec3_add(vec3_add(sh->q, sh->u), sh->v));
        fputs(" ] \"integer indices\" [ 0 1 2 3 ]\n", f);
    }
    fputs("AttributeEnd\n", f);
}

void cf_export_pbrt(FILE *f, const cf_scene *s, int size, int spp)
{
    cf_write_header(f, s, "pbrt-v4 scene", size, spp, "# ", false, PINS);
    fprintf(f, "# Render: pbrt %s.pbrt (writes %s.exr)\n\n", s->name, s->name);
    fputs("ColorSpace \"srgb\"\nScale -1 1 1\nLookAt", f);
    put_point(f, s->lookfrom);
    fputs("  ", f);
    put_point(f, s->lookat);
    fputs("  ", f);
    put_point(f, s->vup);
    fprintf(f,
            "\nCamera \"perspective\" \"float fov\" [ %s ] \"float lensradius\" [ 0 ]\n"
            "    \"float shutteropen\" [ 0 ] \"float shutterclose\" [ 1 ]\n",
            cf_num(s->vfov_deg).s);
    fprintf(f, "Sampler \"independent\" \"integer pixelsamples\" [ %d ]\n", spp);
    fputs("PixelFilter \"box\" \"float xradius\" [ 0.5 ] \"float yradius\" [ 0.5 ]\n", f);
    fprintf(f,
            "Film \"rgb\" \"integer xresolution\" [ %d ] \"integer yresolution\" [ %d ]\n"
            "    \"string filename\" [ \"%s.exr\" ] \"string sensor\" [ \"cie1931\" ]\n"
            "    \"float iso\" [ 100 ] \"float whitebalance\" [ 0 ] \"bool savefp16\" [ false ]\n",
            size, size, s->name);
    fprintf(f, "Integrator \"path\" \"integer maxdepth\" [ %d ] \"bool regularize\" [ false ]\n",
            s->min_depth);
    fputs("\nWorldBegin\n\n", f);
    if (s->background > 0.0) {
        fputs("# the background: radiance of every ray that leaves the scene\n"
              "LightSource \"infinite\" \"rgb L\" ",
              f);
        put_grey(f, s->background);
        fputs("\n\n", f);
    }
    for (int i = 0; i < s->n_shapes; i++) {
        put_shape(f, s, i);
        fputc('\n', f);
    }
}
