/* conform/export_table.c - a conformance scene as a plain table of
 * numbers, for a renderer written along Shirley's "Ray Tracing in One
 * Weekend" series: no parser to write, each line one sscanf.
 *
 * The table is the cf_scene itself, field by field, so it carries the
 * truth's conventions as they are: a renderer in the style of the series
 * already has a right-handed camera(lookfrom, lookat, vup, vfov), quads as
 * q + a u + b v, spheres, Lambertian and dielectric materials and a
 * background colour; the comment says what it must add (one-sided
 * emitters, a box filter, no gamma).
 */
#include "conform/export_impl.h"

static const char *const PINS[CF_N_PINS] = {
    "lookfrom, lookat, vup, vfov as the series' camera takes them; its u = vup x w,\n"
    "w = unit(lookfrom - lookat), is the image's right.",
    "vfov is vertical, as in the series.",
    "nothing to pin in a table: average SPP samples drawn uniformly over each pixel's\n"
    "square, as the series' camera draws them, with no wider filter.",
    "radiance as given; write the linear mean. Do not apply the series' gamma 2 or clamp\n"
    "to [0, 1) before comparing; a .pfm or .exr keeps floats.",
    "the renderer must make emitters one-sided: a quad's emitted() returns the radiance\n"
    "only for rays hitting its front (dot(ray direction, u x v) < 0), a sphere's for rays\n"
    "hitting its outside (its inside when inward is 1). The series' diffuse_light is\n"
    "two-sided as written.",
    "diffuse: Lambertian, scattering on both faces; glass: the series' dielectric with\n"
    "the exact Fresnel reflectance instead of Schlick's approximation, index 1 on the\n"
    "front side; emitter: emits, reflects nothing; diffuse_emitter: both.",
    "max_depth is given in segments: a ray_color(ray, depth) that starts at depth =\n"
    "max_depth and returns 0 at depth 0 follows exactly that many."};

static const char *const KEYS =
    "#\n"
    "# Format: one item per line, a key then its values separated by blanks; lines that\n"
    "# start with '#' are comments. Numbers read back as the exact doubles of the scene.\n"
    "#   scene NAME                  the scene's name (one word)\n"
    "#   image WIDTH HEIGHT SPP      pixels across and down, samples per pixel\n"
    "#   lookfrom X Y Z              the camera's position\n"
    "#   lookat X Y Z                the point it looks at\n"
    "#   vup X Y Z                   the image's up direction\n"
    "#   vfov DEGREES                vertical field of view\n"
    "#   background L                radiance of every ray that leaves the scene\n"
    "#   max_depth N                 path segments that reach the truth (camera ray = 1)\n"
    "#   t_min T                     a self-intersection offset suited to the scene's scale\n"
    "#   materials N                 N material lines follow, indices 0 .. N-1 in order\n"
    "#   material I KIND ALBEDO RADIANCE IOR\n"
    "#                               KIND: diffuse, emitter, diffuse_emitter or glass;\n"
    "#                               fields a kind does not use are 0\n"
    "#   shapes N                    N shape lines follow, each a quad or a sphere\n"
    "#   quad QX QY QZ UX UY UZ VX VY VZ M\n"
    "#                               the parallelogram q + a u + b v, (a, b) in [0, 1]^2,\n"
    "#                               front face toward u x v, material M\n"
    "#   sphere CX CY CZ R INWARD M  centre, radius, INWARD 1 when the front face is the\n"
    "#                               inside (else 0), material M\n"
    "#   end                         the last line\n"
    "# Reading it in C: fgets each line, then e.g.\n"
    "#   sscanf(line, \"lookfrom %lf %lf %lf\", &x, &y, &z) == 3\n"
    "#   sscanf(line, \"material %d %31s %lf %lf %lf\", &i, kind, &albedo, &radiance, &ior) == 5\n"
    "#\n";

static const char *kind_word(cf_material_kind k)
{
    return k == CF_DIFFUSE ? "diffuse" : k == CF_EMITTER ? "emitter"
                                      : k == CF_DIFFUSE_EMITTER ? "diffuse_emitter" : "glass";
}

static void put_vec(FILE *f, const char *key, vec3 v)
{
    fprintf(f, "%s %s %s %s", key, cf_num(v.x).s, cf_num(v.y).s, cf_num(v.z).s);
}

void cf_export_table(FILE *f, const cf_scene *s, int size, int spp)
{
    cf_write_header(f, s, "Plain table", size, spp, "# ", false, PINS);
    fputs(KEYS, f);
    fprintf(f, "scene %s\nimage %d %d %d\n", s->name, size, size, spp);
    put_vec(f, "lookfrom", s->lookfrom);
    put_vec(f, "\nlookat", s->lookat);
    put_vec(f, "\nvup", s->vup);
    fprintf(f, "\nvfov %s\nbackground %s\nmax_depth %d\nt_min %s\n", cf_num(s->vfov_deg).s,
            cf_num(s->background).s, s->min_depth, cf_num(s->t_min).s);
    fprintf(f, "materials %d\n", s->n_materials);
    for (int i = 0; i < s->n_materials; i++) {
        const cf_material *m = &s->materials[i];
        /* Only the fields of the kind, so that a reader may not pick up
         * a stray value a table left in an unused field. */
        bool reflects = m->kind == CF_DIFFUSE || m->kind == CF_DIFFUSE_EMITTER;
        bool emits = m->kind == CF_EMITTER || m->kind == CF_DIFFUSE_EMITTER;
        fprintf(f, "material %d %s %s %s %s\n", i, kind_word(m->kind),
                cf_num(reflects ? m->albedo : 0.0).s, cf_num(emits ? m->radiance : 0.0).s,
                cf_num(m->kind == CF_GLASS ? m->ior : 0.0).s);
    }
    fprintf(f, "shapes %d\n", s->n_shapes);
    for (int i = 0; i < s->n_shapes; i++) {
        const cf_shape *sh = &s->shapes[i];
        if (sh->kind == CF_QUAD) {
            put_vec(f, "quad", sh->q);
            fprintf(f, " %s %s %s %s %s %s %d\n", cf_num(sh->u.x).s, cf_num(sh->u.y).s,
                    cf_num(sh->u.z).s, cf_num(sh->v.x).s, cf_num(sh->v.y).s, cf_num(sh->v.z).s,
                    sh->material);
        } else {
            put_vec(f, "sphere", sh->center);
            fprintf(f, " %s %d %d\n", cf_num(sh->radius).s, sh->inward ? 1 : 0, sh->material);
        }
    }
    fputs("end\n", f);
}
