/* conform/export.c - the format table, the checks every export starts
 * with, and the pieces the exporters share (conform/export_impl.h).
 */
#include "conform/export.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "conform/export_impl.h"

const char *const cf_export_format_names[] = {"pbrt", "mitsuba", "blender", "table", NULL};

static const char *const EXTENSIONS[CF_EXPORT_N_FORMATS] = {".pbrt", ".xml", ".py", ".txt"};

bool cf_export_format_parse(const char *name, cf_export_format *fmt)
{
    if (!name)
        return false;
    for (int i = 0; i < CF_EXPORT_N_FORMATS; i++)
        if (strcmp(name, cf_export_format_names[i]) == 0) {
            *fmt = (cf_export_format)i;
            return true;
        }
    return false;
}

/* Through int: an enum without negative values may be unsigned, and the
 * test must also reject values cast in from outside the enum. */
static bool is_format(cf_export_format fmt) { return (int)fmt >= 0 && (int)fmt < CF_EXPORT_N_FORMATS; }

const char *cf_export_format_name(cf_export_format fmt)
{
    return is_format(fmt) ? cf_export_format_names[fmt] : NULL;
}

const char *cf_export_extension(cf_export_format fmt)
{
    return is_format(fmt) ? EXTENSIONS[fmt] : NULL;
}

cf_numtext cf_num(double x)
{
    cf_numtext t;
    /* 17 significant digits always read back as the same double; fewer
     * often do, and read better ("0.1", not "0.10000000000000001"). */
    int digits = 1;
    for (; digits <= 17; digits++) {
        snprintf(t.s, sizeof t.s, "%.*g", digits, x);
        if (strtod(t.s, NULL) == x || !isfinite(x))
            break;
    }
    /* %g turns to an exponent once the integer part has more digits than
     * the precision (90 at one digit is "9e+01"): give it those digits. */
    if (isfinite(x) && x != 0.0) {
        int e10 = (int)floor(log10(fabs(x)));
        if (e10 >= digits && e10 < 17)
            snprintf(t.s, sizeof t.s, "%.*g", e10 + 1, x);
    }
    return t;
}

vec3 cf_quad_normal(const cf_shape *sh) { return vec3_normalize(vec3_cross(sh->u, sh->v)); }

bool cf_quad_is_rectangle(const cf_shape *sh)
{
    /* The tables give edges in decimal, so a right angle may carry
     * rounding of a few ulps, far below 1e-12 of |u| |v|. */
    return fabs(vec3_dot(sh->u, sh->v)) <= 1e-12 * vec3_length(sh->u) * vec3_length(sh->v);
}

bool cf_shape_emits(const cf_scene *s, int i)
{
    return cf_material_emits(&s->materials[s->shapes[i].material]);
}

void cf_clip_range(const cf_scene *s, double *near_clip, double *far_clip)
{
    double nearest = HUGE_VAL, farthest = 0.0;
    vec3 e = s->lookfrom;
    for (int i = 0; i < s->n_shapes; i++) {
        const cf_shape *sh = &s->shapes[i];
        if (sh->kind == CF_SPHERE) {
            double dc = vec3_length(vec3_sub(sh->center, e));
            nearest = fmin(nearest, fabs(dc - sh->radius));
            farthest = fmax(farthest, dc + sh->radius);
        } else {
            /* The distance to the quad's plane is a lower bound of the
             * distance to the quad; its farthest point is a corner. */
            nearest = fmin(nearest, fabs(vec3_dot(cf_quad_normal(sh), vec3_sub(e, sh->q))));
            vec3 corners[4] = {sh->q, vec3_add(sh->q, sh->u), vec3_add(sh->q, sh->v),
                               vec3_add(vec3_add(sh->q, sh->u), sh->v)};
            for (int k = 0; k < 4; k++)
                farthest = fmax(farthest, vec3_length(vec3_sub(corners[k], e)));
        }
    }
    if (farthest == 0.0) { /* no shapes: any range will do */
        *near_clip = 0.01;
        *far_clip = 1e4;
        return;
    }
    /* A camera on a surface's plane gives a bound of 0, which no camera
     * takes; 1e-6 of the extent stays far above float rounding. */
    *near_clip = fmax(0.5 * nearest, 1e-6 * farthest);
    *far_clip = 2.0 * farthest;
}

/* Writes t; with xml, a '-' after a '-' is written " -" so that "--"
 * never appears inside an XML comment. */
static void put_text(FILE *f, const char *t, bool xml)
{
    for (const char *p = t; *p; p++) {
        if (xml && *p == '-' && p > t && p[-1] == '-')
            fputc(' ', f);
        fputc(*p, f);
    }
}

/* Writes text line by line, each line after `lead`; with `hang`, the
 * lines after the first (after a '\n' in text) are indented three more
 * spaces, under the text of a numbered item. */
static void put_lines(FILE *f, const char *lead, const char *text, bool hang, bool xml)
{
    char line[256];
    const char *p = text;
    bool first = true;
    while (*p) {
        size_t n = strcspn(p, "\n");
        if (n >= sizeof line)
            n = sizeof line - 1;
        memcpy(line, p, n);
        line[n] = '\0';
        fputs(lead, f);
        if (hang && !first)
            fputs("   ", f);
        put_text(f, line, xml);
        fputc('\n', f);
        first = false;
        p += n;
        if (*p == '\n')
            p++;
    }
}

/* The conventions of conform/conform.h that need no number of the scene. */
static const char *const FIXED[] = {
    "3. Pixel filter: a pixel is the mean radiance over its own square (a box filter\n"
    "one pixel wide, radius 0.5), rows from the top.",
    "4. Units of light: radiance in W/(m^2 sr), linear; radiance 1 is pixel value 1\n"
    "(no exposure, white balance, tone curve, clamping or denoising).",
    "5. Emitters are one-sided and Lambertian: a quad q + a u + b v emits toward\n"
    "u x v only, a sphere from its outside, or from its inside where marked inward.",
    "6. Materials: diffuse is Lambertian on both faces (BRDF albedo / pi); glass is a\n"
    "smooth dielectric with the exact unpolarized Fresnel reflectance, no absorption,\n"
    "and index 1 on the side its faces' fronts look to."};

void cf_write_header(FILE *f, const cf_scene *s, const char *format, int size, int spp,
                     const char *lead, bool xml, const char *const pins[CF_N_PINS])
{
    char text[1024];
    snprintf(text, sizeof text, "mcbox conformance scene \"%s\":\n%s", s->name, s->summary);
    put_lines(f, lead, text, false, xml);
    snprintf(text, sizeof text,
             "%s file for a %d x %d image at %d samples per pixel,\nwritten by mcbox-scene.",
             format, size, size, spp);
    put_lines(f, lead, text, false, xml);
    put_lines(f, lead,
              "Every pixel of this scene is known exactly (mcbox, conform/truth.h) under the\n"
              "conventions below; this file pins each of them instead of trusting a default.",
              false, xml);
    snprintf(text, sizeof text,
             "1. Handedness: a right-handed world. The camera at (%s, %s, %s) looks at\n"
             "(%s, %s, %s) with (%s, %s, %s) up in the image, so that right in the\n"
             "image is (view direction) x (up).",
             cf_num(s->lookfrom.x).s, cf_num(s->lookfrom.y).s, cf_num(s->lookfrom.z).s,
             cf_num(s->lookat.x).s, cf_num(s->lookat.y).s, cf_num(s->lookat.z).s,
             cf_num(s->vup.x).s, cf_num(s->vup.y).s, cf_num(s->vup.z).s);
    put_lines(f, lead, text, true, xml);
    snprintf(text, sizeof text,
             "2. Field of view: %s degrees vertically; the image is square, so\n"
             "horizontally too.",
             cf_num(s->vfov_deg).s);
    put_lines(f, lead, text, true, xml);
    for (size_t i = 0; i < sizeof FIXED / sizeof FIXED[0]; i++)
        put_lines(f, lead, FIXED[i], true, xml);
    snprintf(text, sizeof text,
             "7. Path length: paths of up to %d segments (the camera ray is the first) come\n"
             "within 1e-12 of the truth; a higher limit only comes closer.",
             s->min_depth);
    put_lines(f, lead, text, true, xml);
    put_lines(f, lead, "How this file pins them:", false, xml);
    for (int i = 0; i < CF_N_PINS; i++) {
        snprintf(text, sizeof text, "%d. %s", i + 1, pins[i]);
        put_lines(f, lead, text, true, xml);
    }
}

/* Scene names go into file names, pbrt and Python strings, XML comments
 * and the table's first line: letters, digits, '.', '_' and '-' keep all
 * of them free of quoting, a letter or digit first keeps the name from
 * looking like an option, and no "--" keeps an XML comment whole. */
static bool valid_name(const char *name)
{
    if (!name || strlen(name) > 64 || !((*name >= 'a' && *name <= 'z') ||
                                        (*name >= 'A' && *name <= 'Z') ||
                                        (*name >= '0' && *name <= '9')) ||
        strstr(name, "--"))
        return false;
    for (const char *p = name; *p; p++)
        if (!((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') || (*p >= '0' && *p <= '9') ||
              *p == '.' || *p == '_' || *p == '-'))
            return false;
    return true;
}

static bool finite3(vec3 v) { return vec3_is_finite(v); }

/* Whether s is a scene the exporters can write at all: counts within the
 * arrays, material indices in range, finite numbers, a proper camera. */
static bool valid_scene(const cf_scene *s)
{
    if (!valid_name(s->name) || !s->summary || strchr(s->summary, '\n'))
        return false;
    if (s->n_materials < 1 || s->n_materials > CF_MAX_MATERIALS || s->n_shapes < 0 ||
        s->n_shapes > CF_MAX_SHAPES || s->min_depth < 1)
        return false;
    if (!finite3(s->lookfrom) || !finite3(s->lookat) || !finite3(s->vup) ||
        !(s->vfov_deg > 0.0 && s->vfov_deg < 180.0) || !(s->background >= 0.0) ||
        !isfinite(s->background) || !(s->t_min >= 0.0) || !isfinite(s->t_min))
        return false;
    vec3 dir = vec3_sub(s->lookat, s->lookfrom);
    if (vec3_length(dir) == 0.0 || vec3_length(vec3_cross(dir, s->vup)) == 0.0)
        return false;
    for (int i = 0; i < s->n_materials; i++) {
        const cf_material *m = &s->materials[i];
        if (!(m->albedo >= 0.0 && m->albedo <= 1.0) || !(m->radiance >= 0.0) ||
            !isfinite(m->radiance) || (m->kind == CF_GLASS && !(m->ior > 1.0 && isfinite(m->ior))))
            return false;
    }
    for (int i = 0; i < s->n_shapes; i++) {
        const cf_shape *sh = &s->shapes[i];
        if (sh->material < 0 || sh->material >= s->n_materials)
            return false;
        if (sh->kind == CF_QUAD ? !finite3(sh->q) || !finite3(sh->u) || !finite3(sh->v) ||
                                      vec3_length(vec3_cross(sh->u, sh->v)) == 0.0
                                : !finite3(sh->center) || !(sh->radius > 0.0) ||
                                      !isfinite(sh->radius))
            return false;
    }
    return true;
}

bool cf_export_supports(const cf_scene *s, cf_export_format fmt)
{
    if (!s || !is_format(fmt) || !valid_scene(s))
        return false;
    if (fmt == CF_EXPORT_MITSUBA)
        for (int i = 0; i < s->n_shapes; i++)
            if (s->shapes[i].kind == CF_QUAD && !cf_quad_is_rectangle(&s->shapes[i]))
                return false;
    return true;
}

int cf_export(FILE *f, const cf_scene *s, cf_export_format fmt, int size, int spp)
{
    if (!f || size < 1 || size > CF_EXPORT_MAX_SIZE || spp < 1 || spp > CF_EXPORT_MAX_SPP ||
        !cf_export_supports(s, fmt))
        return CF_EXPORT_EINVALID;
    switch (fmt) {
    case CF_EXPORT_PBRT:
        cf_export_pbrt(f, s, size, spp);
        break;
    case CF_EXPORT_MITSUBA:
        cf_export_mitsuba(f, s, size, spp);
        break;
    case CF_EXPORT_BLENDER:
        cf_export_blender(f, s, size, spp);
        break;
    case CF_EXPORT_TABLE:
    default:
        cf_export_table(f, s, size, spp);
        break;
    }
    /* A failed write sets the stream's error flag and later ones fail
     * too, so one test at the end catches any; the flush catches a full
     * disk that buffering hid until now. */
    if (fflush(f) != 0 || ferror(f))
        return CF_EXPORT_EWRITE;
    return CF_EXPORT_OK;
}

const char *cf_export_strerror(int status)
{
    switch (status) {
    case CF_EXPORT_OK:
        return "written";
    case CF_EXPORT_EWRITE:
        return "write error";
    case CF_EXPORT_EINVALID:
        return "size, sample count or scene out of range for the format";
    default:
        return "unknown status";
    }
}
