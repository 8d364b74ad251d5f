/* tests/test_conform_export.c - the exporters of conform/export.h and the
 * program mcbox-scene of $MC_BUILD/bin.
 *
 * Every scene of cf_scene_names and a probe scene of this file (every
 * material kind and shape, odd numbers, a tilted rectangle, an inward and
 * an outward sphere, a background) exports in every format. By value: the
 * pbrt file's LookAt and fov read back as the scene's camera, its patches'
 * corners as the quads' with u x v as their normal, each emitter's
 * radiance, the shapes, inward spheres and background; the Mitsuba file is
 * well-formed XML (a small checker below) whose rectangles' to_world takes
 * [-1, 1]^2 onto the quad and +z to u x v (through the inverse transpose,
 * as normals go), with the box filter and the emitters where the scene has
 * them; the table reads back with sscanf as the exact doubles of the
 * scene; the Blender script carries the settings that pin the conventions
 * and parses as Python (when python3 is there). Write errors (a stream
 * opened read-only, /dev/full) give CF_EXPORT_EWRITE; bad arguments and a
 * parallelogram for Mitsuba give CF_EXPORT_EINVALID and write nothing.
 * The program: bad input exits 2 with one line "mcbox-scene: ..." and
 * nothing on stdout; its files are byte for byte what cf_export writes.
 */
#define _XOPEN_SOURCE 700 /* mkdtemp, WEXITSTATUS */

#include "tests/support/mc_test.h"

#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "conform/conform.h"
#include "conform/export.h"
#include "conform/export_impl.h"

/* Every material kind and shape the format must carry, with numbers that
 * no default or dropped factor could match. The first quad is tilted and
 * its edges perpendicular: (1.2, 0, 0.5) . (-0.25, 0.8, 0.6) = 0. */
static const cf_scene PROBE = {
    .name = "probe",
    .summary = "every kind of material and shape, for the exporters' tests",
    .lookfrom = {0.37, 1.91, -2.385},
    .lookat = {0.12, 0.2, 0.3},
    .vup = {0.1, 1.0, 0.05},
    .vfov_deg = 41.3,
    .size = 24,
    .background = 0.237,
    .t_min = 2.5e-5,
    .min_depth = 17,
    .n_materials = 4,
    .materials = {{.kind = CF_DIFFUSE, .albedo = 0.615},
                  {.kind = CF_EMITTER, .radiance = 3.71},
                  {.kind = CF_DIFFUSE_EMITTER, .albedo = 0.33, .radiance = 0.71},
                  {.kind = CF_GLASS, .ior = 1.333}},
    .n_shapes = 5,
    .shapes = {{.kind = CF_QUAD, .q = {-0.6, -0.1, 0.2}, .u = {1.2, 0.0, 0.5},
                .v = {-0.25, 0.8, 0.6}, .material = 0},
               {.kind = CF_QUAD, .q = {0.9, 0.3, -0.4}, .u = {0.0, 0.7, 0.0},
                .v = {0.9, 0.0, 0.2}, .material = 1},
               {.kind = CF_SPHERE, .center = {0.2, 0.45, 0.1}, .radius = 0.3125, .material = 1},
               {.kind = CF_SPHERE, .center = {0.0, 0.0, 0.0}, .radius = 7.5, .inward = true,
                .material = 2},
               {.kind = CF_SPHERE, .center = {-0.3, 0.2, -0.1}, .radius = 0.17, .material = 3}},
};

/* The scenes under test: the library's and the probe. */
static const cf_scene *scene_at(int i)
{
    int n = 0;
    while (cf_scene_names[n])
        n++;
    return i < n ? cf_scene_find(cf_scene_names[i]) : i == n ? &PROBE : NULL;
}

/* cf_export through a temporary file into a string (malloc'd); *rc gets
 * its status. */
static char *export_text(const cf_scene *s, cf_export_format fmt, int size, int spp, int *rc)
{
    FILE *f = tmpfile();
    assert_non_null(f);
    *rc = cf_export(f, s, fmt, size, spp);
    long n = ftell(f);
    assert_true(n >= 0);
    char *buf = malloc((size_t)n + 1);
    assert_non_null(buf);
    rewind(f);
    buf[fread(buf, 1, (size_t)n, f)] = '\0';
    assert_int_equal(fclose(f), 0);
    return buf;
}

static char *export_ok(const cf_scene *s, cf_export_format fmt)
{
    int rc;
    char *t = export_text(s, fmt, 37, 53, &rc);
    if (rc != CF_EXPORT_OK)
        fail_msg("%s as %s: status %d", s->name, cf_export_format_name(fmt), rc);
    return t;
}

static int count(const char *text, const char *needle)
{
    int n = 0;
    for (const char *p = text; (p = strstr(p, needle)); p += strlen(needle))
        n++;
    return n;
}

static bool emits(const cf_scene *s, int i)
{
    return cf_material_emits(&s->materials[s->shapes[i].material]);
}

static void assert_vec_equal(vec3 a, vec3 b, double tol, const char *what, const char *scene)
{
    if (!(fabs(a.x - b.x) <= tol && fabs(a.y - b.y) <= tol && fabs(a.z - b.z) <= tol))
        fail_msg("%s: %s (%.17g, %.17g, %.17g) != (%.17g, %.17g, %.17g)", scene, what, a.x, a.y,
                 a.z, b.x, b.y, b.z);
}

/* Reads n numbers from p (blanks, commas and '[' between them). */
static const char *numbers(const char *p, double *out, int n)
{
    for (int i = 0; i < n; i++) {
        while (*p == ' ' || *p == ',' || *p == '[' || *p == '\n')
            p++;
        char *end;
        out[i] = strtod(p, &end);
        if (end == p)
            fail_msg("no number %d at '%.40s'", i, p);
        p = end;
    }
    return p;
}

static void test_format_table(void **state)
{
    (void)state;
    static const char *const ext[] = {".pbrt", ".xml", ".py", ".txt"};
    int n = 0;
    for (; cf_export_format_names[n]; n++) {
        cf_export_format fmt;
        assert_true(cf_export_format_parse(cf_export_format_names[n], &fmt));
        assert_int_equal(fmt, n);
        assert_string_equal(cf_export_format_name(fmt), cf_export_format_names[n]);
        assert_string_equal(cf_export_extension(fmt), ext[n]);
    }
    assert_int_equal(n, CF_EXPORT_N_FORMATS);
    cf_export_format fmt = CF_EXPORT_TABLE;
    assert_false(cf_export_format_parse("PBRT", &fmt));
    assert_false(cf_export_format_parse("", &fmt));
    assert_false(cf_export_format_parse(NULL, &fmt));
    assert_int_equal(fmt, CF_EXPORT_TABLE);
    assert_null(cf_export_format_name((cf_export_format)CF_EXPORT_N_FORMATS));
    assert_null(cf_export_extension((cf_export_format)-1));
}

static void test_numbers_read_back(void **state)
{
    (void)state;
    assert_string_equal(cf_num(90.0).s, "90");
    assert_string_equal(cf_num(0.1).s, "0.1");
    assert_string_equal(cf_num(-2.385).s, "-2.385");
    assert_string_equal(cf_num(1e-6).s, "1e-06");
    assert_string_equal(cf_num(12345678.0).s, "12345678");
    const double xs[] = {53.13010235415598, 1.0 / 3.0, 2.5e-5, -0.0, 6.02214076e23, 4.9e-324};
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; i++)
        if (strtod(cf_num(xs[i]).s, NULL) != xs[i])
            fail_msg("%.17g written as %s", xs[i], cf_num(xs[i]).s);
}

static void test_every_scene_every_format(void **state)
{
    (void)state;
    static const char *const lead[] = {"# ", "<?xml", "# ", "# "};
    for (int i = 0; scene_at(i); i++) {
        const cf_scene *s = scene_at(i);
        for (int k = 0; k < CF_EXPORT_N_FORMATS; k++) {
            char *t = export_ok(s, (cf_export_format)k), title[128];
            snprintf(title, sizeof title, "mcbox conformance scene \"%s\"", s->name);
            if (strncmp(t, lead[k], strlen(lead[k])) != 0 || !strstr(t, title) ||
                !strstr(t, "How this file pins them:") || strstr(t, title) > t + 200)
                fail_msg("%s as %s: no opening comment naming the scene", s->name,
                         cf_export_format_names[k]);
            char depth[64];
            snprintf(depth, sizeof depth, "paths of up to %d segments", s->min_depth);
            assert_non_null(strstr(t, depth));
            for (int c = 1; c <= 7; c++) { /* every convention and every pin */
                char item[16];
                snprintf(item, sizeof item, "%d. ", c);
                if (count(t, item) < 2)
                    fail_msg("%s as %s: convention %d not stated and pinned", s->name,
                             cf_export_format_names[k], c);
            }
            free(t);
        }
    }
}

/* The text between the i-th "AttributeBegin" and its "AttributeEnd", in a
 * static buffer. */
static const char *pbrt_block(const char *t, int i)
{
    static char block[4096];
    const char *p = t;
    for (int k = 0; k <= i; k++) {
        p = strstr(p, "AttributeBegin");
        if (!p)
            fail_msg("no block %d", i);
        p += 14;
    }
    const char *end = strstr(p, "AttributeEnd");
    assert_non_null(end);
    assert_true((size_t)(end - p) < sizeof block);
    memcpy(block, p, (size_t)(end - p));
    block[end - p] = '\0';
    return block;
}

/* One shape's AttributeBegin block b against shape i: its emitter, its
 * orientation and its geometry. Returns whether it holds an area light. */
static bool check_pbrt_shape(const cf_scene *s, int i, const char *b)
{
    double v[12];
    const cf_shape *sh = &s->shapes[i];
    const char *light = strstr(b, "AreaLightSource \"diffuse\" \"rgb L\"");
    if (emits(s, i) != (light != NULL))
        fail_msg("%s: shape %d: AreaLightSource where the scene has %s", s->name, i,
                 emits(s, i) ? "an emitter" : "none");
    if (light) {
        numbers(light + 33, v, 3);
        double L = s->materials[sh->material].radiance;
        assert_true(v[0] == L && v[1] == L && v[2] == L);
        assert_non_null(strstr(light, "\"bool twosided\" [ false ]"));
    }
    assert_int_equal(strstr(b, "ReverseOrientation") != NULL, sh->kind == CF_SPHERE && sh->inward);
    if (sh->kind == CF_SPHERE) {
        numbers(strstr(b, "Translate") + 9, v, 3);
        assert_vec_equal(vec3_make(v[0], v[1], v[2]), sh->center, 0.0, "centre", s->name);
        numbers(strstr(b, "\"float radius\"") + 14, v, 1);
        assert_true(v[0] == sh->radius);
        return light != NULL;
    }
    /* pbrt's patch: p00, p10, p01, p11, normal (p10 - p00) x (p01 - p00). */
    const char *P = strstr(b, "Shape \"bilinearmesh\" \"point3 P\" [");
    assert_non_null(P);
    numbers(P + 32, v, 12);
    vec3 p00 = vec3_make(v[0], v[1], v[2]), p10 = vec3_make(v[3], v[4], v[5]),
         p01 = vec3_make(v[6], v[7], v[8]), p11 = vec3_make(v[9], v[10], v[11]);
    assert_vec_equal(p00, sh->q, 0.0, "p00", s->name);
    assert_vec_equal(p10, vec3_add(sh->q, sh->u), 1e-12, "p10", s->name);
    assert_vec_equal(p01, vec3_add(sh->q, sh->v), 1e-12, "p01", s->name);
    assert_vec_equal(p11, vec3_add(vec3_add(sh->q, sh->u), sh->v), 1e-12, "p11", s->name);
    vec3 n = vec3_cross(vec3_sub(p10, p00), vec3_sub(p01, p00));
    assert_vec_equal(n, vec3_cross(sh->u, sh->v), 1e-9, "normal", s->name);
    return light != NULL;
}

static void check_pbrt(const cf_scene *s)
{
    char *text = export_ok(s, CF_EXPORT_PBRT);
    /* The opening comment names the directives too: search what follows. */
    const char *t = strstr(text, "\nColorSpace \"srgb\"\n");
    assert_non_null(t);
    double v[12];
    const char *look = strstr(t, "\nLookAt ");
    assert_non_null(look);
    numbers(look + 8, v, 9);
    assert_vec_equal(vec3_make(v[0], v[1], v[2]), s->lookfrom, 0.0, "LookAt from", s->name);
    assert_vec_equal(vec3_make(v[3], v[4], v[5]), s->lookat, 0.0, "LookAt at", s->name);
    assert_vec_equal(vec3_make(v[6], v[7], v[8]), s->vup, 0.0, "LookAt up", s->name);
    /* The mirror that makes pbrt's camera right-handed comes just before. */
    const char *scale = strstr(t, "\nScale -1 1 1\nLookAt ");
    assert_true(scale && scale + 13 == look);
    numbers(strstr(t, "\"float fov\"") + 11, v, 1);
    assert_true(v[0] == s->vfov_deg);
    assert_non_null(strstr(t, "PixelFilter \"box\" \"float xradius\" [ 0.5 ] \"float yradius\" [ 0.5 ]"));
    assert_non_null(strstr(t, "\"integer pixelsamples\" [ 53 ]"));
    assert_non_null(strstr(t, "\"integer xresolution\" [ 37 ] \"integer yresolution\" [ 37 ]"));
    assert_non_null(strstr(t, "\"float iso\" [ 100 ] \"float whitebalance\" [ 0 ] \"bool savefp16\" [ false ]"));
    numbers(strstr(t, "\"integer maxdepth\"") + 18, v, 1);
    assert_true(v[0] >= s->min_depth);
    assert_int_equal(count(t, "Shape \""), s->n_shapes);
    assert_int_equal(count(t, "AttributeBegin"), s->n_shapes);
    int n_lights = 0;
    for (int i = 0; i < s->n_shapes; i++)
        n_lights += check_pbrt_shape(s, i, pbrt_block(t, i));
    assert_int_equal(count(t, "AreaLightSource"), n_lights);
    const char *sky = strstr(t, "LightSource \"infinite\" \"rgb L\"");
    assert_int_equal(sky != NULL, s->background > 0.0);
    if (sky) {
        numbers(sky + 30, v, 3);
        assert_true(v[0] == s->background && v[2] == s->background);
        assert_true(sky > strstr(t, "WorldBegin"));
    }
    free(text);
}

static void test_pbrt_by_value(void **state)
{
    (void)state;
    for (int i = 0; scene_at(i); i++)
        check_pbrt(scene_at(i));
}

/* A small XML checker: one root element, every tag closed in order,
 * attribute values quoted, no text outside tags but blanks, no "--"
 * inside a comment. Returns NULL or what is wrong. */
static const char *xml_problem(const char *x)
{
    static char why[160];
    char stack[32][32];
    int depth = 0, roots = 0;
    for (const char *p = x; *p;) {
        if (*p != '<') {
            if (!isspace((unsigned char)*p)) {
                snprintf(why, sizeof why, "text outside a tag: '%.30s'", p);
                return why;
            }
            p++;
            continue;
        }
        const char *q;
        if (strncmp(p, "<?", 2) == 0) {
            if (p != x || !(q = strstr(p, "?>")))
                return "a misplaced or open <?...?>";
            p = q + 2;
        } else if (strncmp(p, "<!--", 4) == 0) {
            q = strstr(p + 4, "--");
            if (!q || q[2] != '>')
                return "\"--\" inside a comment, or a comment not closed";
            p = q + 3;
        } else {
            bool closing = p[1] == '/';
            const char *name = p + 1 + closing;
            size_t len = strspn(name, "abcdefghijklmnopqrstuvwxyz_");
            if (len == 0 || len >= 32)
                return "a tag without a name";
            bool quoted = false;
            for (q = name + len; *q && (quoted || *q != '>'); q++) {
                if (*q == '"')
                    quoted = !quoted;
                else if (!quoted && *q == '=' && q[1] != '"')
                    return "an unquoted attribute";
                else if (!quoted && *q == '<')
                    return "a '<' inside a tag";
            }
            if (!*q)
                return "a tag not closed";
            if (closing) {
                if (depth == 0 || strncmp(stack[depth - 1], name, len) != 0 ||
                    stack[depth - 1][len]) {
                    snprintf(why, sizeof why, "</%.*s> closes %s", (int)len, name,
                             depth ? stack[depth - 1] : "nothing");
                    return why;
                }
                depth--;
            } else if (q[-1] != '/') {
                if (depth == 32)
                    return "too deep";
                roots += depth == 0;
                memcpy(stack[depth], name, len);
                stack[depth++][len] = '\0';
            } else {
                roots += depth == 0;
            }
            p = q + 1;
        }
    }
    if (depth)
        return "an element not closed";
    return roots == 1 ? NULL : "not exactly one root element";
}

static void test_xml_checker_catches(void **state)
{
    (void)state;
    assert_null(xml_problem("<?xml version=\"1.0\"?>\n<!-- a - b -->\n<a x=\"1\"><b/><c></c></a>\n"));
    const char *bad[] = {"<a><b></a></b>", "<a>", "<a/><b/>", "<a>text</a>", "<!-- a -- b --><a/>",
                         "<a x=1/>", "<a"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        if (!xml_problem(bad[i]))
            fail_msg("the checker passed '%s'", bad[i]);
}

/* The to_world matrix of the i-th rectangle, row-major. */
static void mitsuba_matrix(const char *t, int i, double m[16])
{
    const char *p = t;
    for (int k = 0; k <= i; k++) {
        p = strstr(p, "<shape type=\"rectangle\">");
        assert_non_null(p);
        p += 10;
    }
    p = strstr(p, "<matrix value=\"");
    assert_non_null(p);
    numbers(p + 15, m, 16);
}

static vec3 affine(const double m[16], double x, double y, double z, double w)
{
    return vec3_make(m[0] * x + m[1] * y + m[2] * z + m[3] * w,
                     m[4] * x + m[5] * y + m[6] * z + m[7] * w,
                     m[8] * x + m[9] * y + m[10] * z + m[11] * w);
}

/* A rectangle's to_world m (row-major) against quad sh: Mitsuba's
 * [-1, 1]^2 lands on the quad, (-1, -1) on q, (1, -1) on q + u, (-1, 1) on
 * q + v, and its normal +z, which goes through the inverse transpose of
 * the linear part (third column (column 0 x column 1) / det), on u x v. */
static void check_rectangle(const char *scene, const cf_shape *sh, const double m[16])
{
    assert_vec_equal(affine(m, -1, -1, 0, 1), sh->q, 1e-12, "(-1, -1)", scene);
    assert_vec_equal(affine(m, 1, -1, 0, 1), vec3_add(sh->q, sh->u), 1e-12, "(1, -1)", scene);
    assert_vec_equal(affine(m, -1, 1, 0, 1), vec3_add(sh->q, sh->v), 1e-12, "(-1, 1)", scene);
    vec3 c0 = affine(m, 1, 0, 0, 0), c1 = affine(m, 0, 1, 0, 0), c2 = affine(m, 0, 0, 1, 0);
    double det = vec3_dot(vec3_cross(c0, c1), c2);
    if (!(det > 0.0))
        fail_msg("%s: a rectangle's to_world turns its normal away from u x v", scene);
    vec3 n = vec3_normalize(vec3_scale(vec3_cross(c0, c1), 1.0 / det));
    assert_vec_equal(n, cf_quad_normal(sh), 1e-12, "normal", scene);
    assert_vec_equal(vec3_normalize(c2), cf_quad_normal(sh), 1e-12, "z axis", scene);
}

static void check_mitsuba(const cf_scene *s)
{
    char *text = export_ok(s, CF_EXPORT_MITSUBA);
    const char *why = xml_problem(text);
    if (why)
        fail_msg("%s: the XML is not well-formed: %s", s->name, why);
    /* The opening comment names the elements too: search what follows. */
    const char *t = strstr(text, "-->");
    assert_non_null(t);
    assert_non_null(strstr(t, "<scene version=\"3.0.0\">"));
    assert_int_equal(count(t, "<rfilter type=\"box\"/>"), 1);
    assert_non_null(strstr(t, "<string name=\"fov_axis\" value=\"y\"/>"));
    assert_non_null(strstr(t, "<string name=\"component_format\" value=\"float32\"/>"));
    assert_non_null(strstr(t, "<integer name=\"sample_count\" value=\"53\"/>"));
    assert_non_null(strstr(t, "<integer name=\"width\" value=\"37\"/>"));
    double v[16];
    numbers(strstr(t, "<float name=\"fov\" value=\"") + 25, v, 1);
    assert_true(v[0] == s->vfov_deg);
    numbers(strstr(t, "<integer name=\"max_depth\" value=\"") + 33, v, 1);
    assert_true(v[0] == s->min_depth);
    numbers(strstr(t, "origin=\"") + 8, v, 3);
    assert_vec_equal(vec3_make(v[0], v[1], v[2]), s->lookfrom, 0.0, "origin", s->name);
    numbers(strstr(t, "target=\"") + 8, v, 3);
    assert_vec_equal(vec3_make(v[0], v[1], v[2]), s->lookat, 0.0, "target", s->name);
    numbers(strstr(t, " up=\"") + 5, v, 3);
    assert_vec_equal(vec3_make(v[0], v[1], v[2]), s->vup, 0.0, "up", s->name);
    int n_emit = 0, n_inward = 0, n_rect = 0, n_diffuse = 0;
    for (int i = 0; i < s->n_shapes; i++) {
        const cf_shape *sh = &s->shapes[i];
        n_emit += emits(s, i);
        n_inward += sh->kind == CF_SPHERE && sh->inward;
        if (sh->kind != CF_QUAD)
            continue;
        double m[16];
        mitsuba_matrix(t, n_rect++, m);
        check_rectangle(s->name, sh, m);
    }
    for (int i = 0; i < s->n_materials; i++)
        n_diffuse += s->materials[i].kind == CF_DIFFUSE || s->materials[i].kind == CF_DIFFUSE_EMITTER;
    assert_int_equal(count(t, "<shape type="), s->n_shapes);
    assert_int_equal(count(t, "<shape type=\"rectangle\">"), n_rect);
    assert_int_equal(count(t, "<emitter type=\"area\">"), n_emit);
    assert_int_equal(count(t, "<boolean name=\"flip_normals\" value=\"true\"/>"), n_inward);
    assert_int_equal(count(t, "<bsdf type=\"twosided\""), n_diffuse);
    assert_int_equal(count(t, "<emitter type=\"constant\">"), s->background > 0.0);
    free(text);
}

static void test_mitsuba_by_value(void **state)
{
    (void)state;
    for (int i = 0; scene_at(i); i++)
        check_mitsuba(scene_at(i));
}

static int kind_of(const char *word)
{
    static const char *const words[] = {"diffuse", "emitter", "diffuse_emitter", "glass"};
    for (int k = 0; k < 4; k++)
        if (strcmp(word, words[k]) == 0)
            return k;
    return -1;
}

static void check_table(const cf_scene *s)
{
    char *t = export_ok(s, CF_EXPORT_TABLE), name[64], kind[32];
    double x[10];
    int w, h, spp, n, idx, mat, inward, materials = 0, shapes = 0, items = 0;
    bool ended = false;
    for (char *line = strtok(t, "\n"); line; line = strtok(NULL, "\n")) {
        if (line[0] == '#')
            continue;
        assert_false(ended);
        items++;
        if (sscanf(line, "scene %63s", name) == 1) {
            assert_string_equal(name, s->name);
        } else if (sscanf(line, "image %d %d %d", &w, &h, &spp) == 3) {
            assert_true(w == 37 && h == 37 && spp == 53);
        } else if (sscanf(line, "lookfrom %lf %lf %lf", &x[0], &x[1], &x[2]) == 3) {
            assert_vec_equal(vec3_make(x[0], x[1], x[2]), s->lookfrom, 0.0, "lookfrom", s->name);
        } else if (sscanf(line, "lookat %lf %lf %lf", &x[0], &x[1], &x[2]) == 3) {
            assert_vec_equal(vec3_make(x[0], x[1], x[2]), s->lookat, 0.0, "lookat", s->name);
        } else if (sscanf(line, "vup %lf %lf %lf", &x[0], &x[1], &x[2]) == 3) {
            assert_vec_equal(vec3_make(x[0], x[1], x[2]), s->vup, 0.0, "vup", s->name);
        } else if (sscanf(line, "vfov %lf", &x[0]) == 1) {
            assert_true(x[0] == s->vfov_deg);
        } else if (sscanf(line, "background %lf", &x[0]) == 1) {
            assert_true(x[0] == s->background);
        } else if (sscanf(line, "max_depth %d", &n) == 1) {
            assert_int_equal(n, s->min_depth);
        } else if (sscanf(line, "t_min %lf", &x[0]) == 1) {
            assert_true(x[0] == s->t_min);
        } else if (sscanf(line, "materials %d", &n) == 1) {
            assert_int_equal(n, s->n_materials);
        } else if (sscanf(line, "material %d %31s %lf %lf %lf", &idx, kind, &x[0], &x[1], &x[2]) == 5) {
            assert_int_equal(idx, materials);
            const cf_material *m = &s->materials[materials++];
            assert_int_equal(kind_of(kind), m->kind);
            assert_true(x[0] == (m->kind == CF_DIFFUSE || m->kind == CF_DIFFUSE_EMITTER ? m->albedo : 0.0));
            assert_true(x[1] == (m->kind == CF_EMITTER || m->kind == CF_DIFFUSE_EMITTER ? m->radiance : 0.0));
            assert_true(x[2] == (m->kind == CF_GLASS ? m->ior : 0.0));
        } else if (sscanf(line, "shapes %d", &n) == 1) {
            assert_int_equal(n, s->n_shapes);
        } else if (sscanf(line, "quad %lf %lf %lf %lf %lf %lf %lf %lf %lf %d", &x[0], &x[1], &x[2],
                          &x[3], &x[4], &x[5], &x[6], &x[7], &x[8], &mat) == 10) {
            const cf_shape *sh = &s->shapes[shapes++];
            assert_int_equal(sh->kind, CF_QUAD);
            assert_vec_equal(vec3_make(x[0], x[1], x[2]), sh->q, 0.0, "q", s->name);
            assert_vec_equal(vec3_make(x[3], x[4], x[5]), sh->u, 0.0, "u", s->name);
            assert_vec_equal(vec3_make(x[6], x[7], x[8]), sh->v, 0.0, "v", s->name);
            assert_int_equal(mat, sh->material);
        } else if (sscanf(line, "sphere %lf %lf %lf %lf %d %d", &x[0], &x[1], &x[2], &x[3], &inward,
                          &mat) == 6) {
            const cf_shape *sh = &s->shapes[shapes++];
            assert_int_equal(sh->kind, CF_SPHERE);
            assert_vec_equal(vec3_make(x[0], x[1], x[2]), sh->center, 0.0, "centre", s->name);
            assert_true(x[3] == sh->radius && inward == (int)sh->inward && mat == sh->material);
        } else if (strcmp(line, "end") == 0) {
            ended = true;
        } else {
            fail_msg("%s: a line no key matches: '%s'", s->name, line);
        }
    }
    assert_true(ended);
    assert_int_equal(materials, s->n_materials);
    assert_int_equal(shapes, s->n_shapes);
    assert_int_equal(items, 12 + s->n_materials + s->n_shapes);
    free(t);
}

static void test_table_reads_back(void **state)
{
    (void)state;
    for (int i = 0; scene_at(i); i++)
        check_table(scene_at(i));
}

static void test_blender_script(void **state)
{
    (void)state;
    const char *b = mc_test_build_dir();
    bool python = system("command -v python3 >/dev/null 2>&1") == 0;
    for (int i = 0; scene_at(i); i++) {
        const cf_scene *s = scene_at(i);
        char *t = export_ok(s, CF_EXPORT_BLENDER), path[1024], cmd[2048];
        static const char *const pins[] = {
            "cycles.pixel_filter_type = 'BOX'", "cycles.filter_width = 1.0",
            "view_transform = 'Standard'", "view_settings.exposure = 0.0",
            "cycles.use_denoising = False", "cycles.use_adaptive_sampling = False",
            "cycles.sample_clamp_indirect = 0.0", "image.color_depth = '32'",
            "data.sensor_fit = 'VERTICAL'", "geometry.outputs['Backfacing']",
            "SPP = 53\n", "SIZE = 37\n", "cycles.diffuse_bounces = MAX_DEPTH"};
        for (size_t k = 0; k < sizeof pins / sizeof pins[0]; k++)
            if (!strstr(t, pins[k]))
                fail_msg("%s: the script lacks \"%s\"", s->name, pins[k]);
        char depth[32];
        snprintf(depth, sizeof depth, "MAX_DEPTH = %d\n", s->min_depth);
        assert_non_null(strstr(t, depth));
        if (python) {
            snprintf(path, sizeof path, "%s/test_conform_export.py", b);
            FILE *f = fopen(path, "w");
            assert_non_null(f);
            fputs(t, f);
            assert_int_equal(fclose(f), 0);
            snprintf(cmd, sizeof cmd,
                     "python3 -c \"import ast, sys; ast.parse(open(sys.argv[1]).read())\" %s", path);
            if (system(cmd) != 0)
                fail_msg("%s: the Blender script is not valid Python", s->name);
            remove(path);
        }
        free(t);
    }
}

static void test_write_errors(void **state)
{
    (void)state;
    char path[1024];
    snprintf(path, sizeof path, "%s/test_conform_export.ro", mc_test_build_dir());
    FILE *w = fopen(path, "w");
    assert_non_null(w);
    fputs("x\n", w);
    assert_int_equal(fclose(w), 0);
    for (int k = 0; k < CF_EXPORT_N_FORMATS; k++) {
        FILE *f = fopen(path, "r");
        assert_non_null(f);
        assert_int_equal(cf_export(f, &PROBE, (cf_export_format)k, 8, 4), CF_EXPORT_EWRITE);
        fclose(f);
        f = fopen("/dev/full", "w");
        if (f) { /* Linux: every write fails with ENOSPC */
            assert_int_equal(cf_export(f, &PROBE, (cf_export_format)k, 8, 4), CF_EXPORT_EWRITE);
            fclose(f);
        }
    }
    remove(path);
    assert_non_null(cf_export_strerror(CF_EXPORT_EWRITE));
}

static void test_invalid_arguments_write_nothing(void **state)
{
    (void)state;
    cf_scene skew = PROBE; /* a parallelogram: Mitsuba's rectangle cannot take it */
    skew.shapes[0].v = vec3_make(0.3, 0.8, 0.6);
    cf_scene unnamed = PROBE;
    unnamed.name = "two words";
    cf_scene bad_index = PROBE;
    bad_index.shapes[1].material = 4;
    struct {
        const cf_scene *s;
        int fmt, size, spp;
    } bad[] = {{&PROBE, CF_EXPORT_PBRT, 0, 4},  {&PROBE, CF_EXPORT_TABLE, CF_EXPORT_MAX_SIZE + 1, 4},
               {&PROBE, CF_EXPORT_BLENDER, 8, 0}, {&PROBE, CF_EXPORT_MITSUBA, 8, CF_EXPORT_MAX_SPP + 1},
               {NULL, CF_EXPORT_PBRT, 8, 4},     {&PROBE, CF_EXPORT_N_FORMATS, 8, 4},
               {&skew, CF_EXPORT_MITSUBA, 8, 4}, {&unnamed, CF_EXPORT_TABLE, 8, 4},
               {&bad_index, CF_EXPORT_PBRT, 8, 4}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        int rc;
        char *t = export_text(bad[i].s, (cf_export_format)bad[i].fmt, bad[i].size, bad[i].spp, &rc);
        if (rc != CF_EXPORT_EINVALID || (t && t[0]))
            fail_msg("case %zu: status %d, %zu bytes written", i, rc, t ? strlen(t) : 0);
        free(t);
    }
    assert_false(cf_export_supports(&skew, CF_EXPORT_MITSUBA));
    for (int k = 0; k < CF_EXPORT_N_FORMATS; k++)
        if (k != CF_EXPORT_MITSUBA) {
            assert_true(cf_export_supports(&skew, (cf_export_format)k));
            free(export_ok(&skew, (cf_export_format)k));
        }
}

/* Runs mcbox-scene with args (shell words); its stdout and stderr go to
 * out and err (at most 64 KiB each). Returns the exit status. */
static char out[1 << 16], err[1 << 16];
static int run(const char *args)
{
    const char *b = mc_test_build_dir();
    char cmd[4096], path[1024];
    snprintf(cmd, sizeof cmd, "%s/bin/mcbox-scene %s >%s/scene_cli.out 2>%s/scene_cli.err", b, args,
             b, b);
    int rc = system(cmd);
    snprintf(path, sizeof path, "%s/scene_cli.out", b);
    mc_test_read_text(path, out, sizeof out);
    snprintf(path, sizeof path, "%s/scene_cli.err", b);
    mc_test_read_text(path, err, sizeof err);
    return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

static void test_cli_bad_input(void **state)
{
    (void)state;
    static const char *const bad[] = {
        "", "frobnicate", "--frobnicate", "export nope --format pbrt",
        "export quad-wall --format nope", "export quad-wall --format pbrt --size 0",
        "export quad-wall --format pbrt --size abc", "export quad-wall --format pbrt --size 16385",
        "export quad-wall --format pbrt --spp 0", "export quad-wall --format pbrt --spp -3",
        "export quad-wall", "export --format pbrt", "export quad-wall --format pbrt --format table",
        "export quad-wall --format pbrt --dir /tmp", "export quad-wall glass-slab --format pbrt",
        "list --size 8", "list quad-wall", "export-all", "export-all --dir /nonexistent-dir/a/b",
        "export-all --dir /tmp -o x", "export quad-wall --format pbrt -o /nonexistent-dir/x.pbrt",
        "export quad-wall --format pbrt --size"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        int rc = run(bad[i]);
        char *nl = strchr(err, '\n');
        if (rc != 2 || out[0] || !nl || nl[1] || strncmp(err, "mcbox-scene: ", 13) != 0)
            fail_msg("'%s': exit %d, stdout '%s', stderr '%s'", bad[i], rc, out, err);
    }
}

static void test_cli_writes_what_the_library_writes(void **state)
{
    (void)state;
    assert_int_equal(run("--help"), 0);
    assert_non_null(strstr(out, "usage: mcbox-scene"));
    assert_int_equal(run("--version"), 0);
    assert_int_equal(run("list"), 0);
    for (int i = 0; cf_scene_names[i]; i++)
        assert_non_null(strstr(out, cf_scene_find(cf_scene_names[i])->summary));
    assert_int_equal(run("export quad-wall --format=table --size 17 --spp 3"), 0);
    int rc;
    char *t = export_text(cf_scene_find("quad-wall"), CF_EXPORT_TABLE, 17, 3, &rc);
    assert_string_equal(out, t);
    free(t);

    char dir[] = "/tmp/mcbox-scene-test-XXXXXX", args[2048], path[1024], file[1 << 16];
    assert_non_null(mkdtemp(dir));
    snprintf(args, sizeof args, "export-all --dir %s/all --size 9 --spp 2", dir);
    assert_int_equal(run(args), 0);
    int files = 0;
    for (int i = 0; cf_scene_names[i]; i++)
        for (int k = 0; k < CF_EXPORT_N_FORMATS; k++, files++) {
            const cf_scene *s = cf_scene_find(cf_scene_names[i]);
            snprintf(path, sizeof path, "%s/all/%s%s", dir, s->name,
                     cf_export_extension((cf_export_format)k));
            mc_test_read_text(path, file, sizeof file);
            t = export_text(s, (cf_export_format)k, 9, 2, &rc);
            if (strcmp(file, t) != 0)
                fail_msg("%s differs from cf_export's", path);
            free(t);
            remove(path);
        }
    char summary[128];
    snprintf(summary, sizeof summary, "%d files in %s/all", files, dir);
    assert_non_null(strstr(out, summary));
    snprintf(path, sizeof path, "%s/all", dir);
    assert_int_equal(rmdir(path), 0);

    snprintf(path, sizeof path, "%s/one.xml", dir);
    snprintf(args, sizeof args, "export glass-slab --format mitsuba -o %s", path);
    assert_int_equal(run(args), 0);
    assert_string_equal(out, "");
    mc_test_read_text(path, file, sizeof file);
    t = export_text(cf_scene_find("glass-slab"), CF_EXPORT_MITSUBA, cf_scene_find("glass-slab")->size,
                    1024, &rc);
    assert_string_equal(file, t);
    free(t);
    remove(path);
    assert_int_equal(rmdir(dir), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_format_table),
        cmocka_unit_test(test_numbers_read_back),
        cmocka_unit_test(test_every_scene_every_format),
        cmocka_unit_test(test_pbrt_by_value),
        cmocka_unit_test(test_xml_checker_catches),
        cmocka_unit_test(test_mitsuba_by_value),
        cmocka_unit_test(test_table_reads_back),
        cmocka_unit_test(test_blender_script),
        cmocka_unit_test(test_write_errors),
        cmocka_unit_test(test_invalid_arguments_write_nothing),
        cmocka_unit_test(test_cli_bad_input),
        cmocka_unit_test(test_cli_writes_what_the_library_writes),
    };
    mc_test_select();
    return cmocka_run_group_tests(tests, NULL, NULL);
}
