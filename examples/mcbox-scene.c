/* examples/mcbox-scene.c - the conformance scenes (conform/conform.h) as
 * files for other renderers: pbrt-v4, Mitsuba 3, Blender's Cycles, and a
 * plain table for a renderer of one's own (conform/export.h says what each
 * file pins and why).
 *
 *   mcbox-scene list                       name and summary of every scene
 *   mcbox-scene export NAME --format F [--size N] [--spp N] [-o FILE]
 *                                          one file, to stdout without -o
 *   mcbox-scene export-all --dir DIR [--size N] [--spp N]
 *                                          DIR/NAME.pbrt, .xml, .py, .txt
 *   mcbox-scene truth NAME [--size N] -o FILE.pfm
 *                                          the exact image (conform/truth.h)
 *
 * A file written with -o or into DIR is either complete or absent: the
 * old file stays until the new one is whole (examples/common/outfile.h).
 * Any bad input: one line on stderr, exit status 2.
 *
 * Build and run:  make build/bin/mcbox-scene && build/bin/mcbox-scene list
 *                 build/bin/mcbox-scene export quad-wall --format pbrt -o quad-wall.pbrt
 *                 pbrt quad-wall.pbrt     # writes quad-wall.exr
 */
#define _POSIX_C_SOURCE 200809L /* mkdir */

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "imageio/image_io.h"
#include "conform/export.h"
#include "conform/truth.h"
#include "examples/common/cli.h"
#include "examples/common/outfile.h"

#define PROG "mcbox-scene"
#define DEFAULT_SPP 1024

static const char USAGE[] =
    "usage: mcbox-scene list\n"
    "       mcbox-scene export NAME --format F [--size N] [--spp N] [-o FILE]\n"
    "       mcbox-scene export-all --dir DIR [--size N] [--spp N]\n"
    "       mcbox-scene truth NAME [--size N] -o FILE.pfm\n"
    "Writes the conformance scenes, whose every pixel mcbox knows exactly, for other\n"
    "renderers. Each file opens with the conventions it pins. Manual: man mcbox-scene.\n"
    "  --format F   pbrt (pbrt-v4), mitsuba (Mitsuba 3 XML), blender (a Python script\n"
    "               for Blender's Cycles) or table (numbers, one item per line)\n"
    "  --size N     image width = height in pixels, 1 to 16384 (default: the scene's)\n"
    "  --spp N      samples per pixel, 1 to 16777216 (default 1024)\n"
    "  -o FILE      write FILE instead of standard output\n"
    "  --dir DIR    export-all: the directory (created if missing) for NAME.pbrt,\n"
    "               NAME.xml, NAME.py and NAME.txt of every scene\n"
    "  truth        the exact pixel values as a linear PFM (every pixel's mean over its\n"
    "               square, to the quadrature error it prints), for mcbox-check --truth\n"
    "  --help, --version\n" APP_NUMBER_GRAMMAR "\n";

typedef struct args {
    const char *command, *name, *format, *out, *dir;
    uint64_t size, spp; /* 0: not given */
} args;

static bool is_option(const char *a, const char *name)
{
    size_t len = strlen(name);
    return strncmp(a, name, len) == 0 && (a[len] == '\0' || a[len] == '=');
}

/* The value of a string option into *dest, refusing a second one. */
static void take(const char **dest, const char *name, int argc, char **argv, int *i)
{
    const char *v = app_option_value(PROG, argc, argv, i, strlen(name));
    if (*dest)
        app_fail(PROG, "%s given twice", name);
    if (!*v)
        app_fail(PROG, "%s needs a value", name);
    *dest = v;
}

static void take_count(uint64_t *dest, const char *name, uint64_t max, int argc, char **argv, int *i)
{
    const char *v = app_option_value(PROG, argc, argv, i, strlen(name));
    if (*dest)
        app_fail(PROG, "%s given twice", name);
    if (!app_parse_uint(v, 1, max, dest))
        app_fail(PROG, "%s: '%s' is not a whole number from 1 to %llu", name, v,
                 (unsigned long long)max);
}

static args parse(int argc, char **argv)
{
    args a = {0};
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        if (strcmp(s, "--help") == 0 || strcmp(s, "-h") == 0) {
            fputs(USAGE, stdout);
            exit(0);
        }
        if (strcmp(s, "--version") == 0) {
            printf("mcbox-scene (mcbox) %s\n", APP_VERSION);
            exit(0);
        }
        if (is_option(s, "--format"))
            take(&a.format, "--format", argc, argv, &i);
        else if (is_option(s, "-o"))
            take(&a.out, "-o", argc, argv, &i);
        else if (is_option(s, "--dir"))
            take(&a.dir, "--dir", argc, argv, &i);
        else if (is_option(s, "--size"))
            take_count(&a.size, "--size", CF_EXPORT_MAX_SIZE, argc, argv, &i);
        else if (is_option(s, "--spp"))
            take_count(&a.spp, "--spp", CF_EXPORT_MAX_SPP, argc, argv, &i);
        else if (s[0] == '-' && s[1] != '\0')
            app_fail(PROG, "unknown option '%s' (see --help)", s);
        else if (!a.command)
            a.command = s;
        else if (!a.name)
            a.name = s;
        else
            app_fail(PROG, "unexpected argument '%s' (see --help)", s);
    }
    if (!a.command)
        app_fail(PROG, "no command (list, export, export-all or truth; see --help)");
    bool list = strcmp(a.command, "list") == 0, one = strcmp(a.command, "export") == 0,
         all = strcmp(a.command, "export-all") == 0, truth = strcmp(a.command, "truth") == 0;
    if (!list && !one && !all && !truth)
        app_fail(PROG, "unknown command '%s' (list, export, export-all or truth; see --help)",
                 a.command);
    if (truth) {
        if (!a.name || !a.out || a.format || a.dir || a.spp)
            app_fail(PROG, "truth takes a scene name, -o FILE.pfm and --size only (see --help)");
        return a;
    }
    /* Each command refuses what it would ignore. */
    if ((list || all) && a.name)
        app_fail(PROG, "%s takes no scene name ('%s'; see --help)", a.command, a.name);
    const char *extra = (list || all) && a.format ? "--format"
                        : (list || all) && a.out    ? "-o"
                        : (list || one) && a.dir    ? "--dir"
                        : list && a.size            ? "--size"
                        : list && a.spp             ? "--spp"
                                                    : NULL;
    if (extra)
        app_fail(PROG, "%s does not take %s (see --help)", a.command, extra);
    if (one && !a.name)
        app_fail(PROG, "export needs a scene name (mcbox-scene list names them)");
    if (one && !a.format)
        app_fail(PROG, "export needs --format (pbrt, mitsuba, blender or table)");
    if (all && !a.dir)
        app_fail(PROG, "export-all needs --dir DIR");
    return a;
}

/* Writes one file through a temporary beside it, so that a failure leaves
 * the previous file as it was. */
static void write_file(const char *path, const cf_scene *s, cf_export_format fmt, int size, int spp)
{
    app_outfile o;
    if (!app_outfile_open(&o, path))
        app_fail(PROG, "cannot write '%s': %s", path, strerror(errno));
    int rc = cf_export(o.f, s, fmt, size, spp);
    int err = errno;
    if (rc != CF_EXPORT_OK) {
        app_outfile_abort(&o);
        app_fail(PROG, "cannot write '%s': %s", path,
                 rc == CF_EXPORT_EWRITE ? strerror(err) : cf_export_strerror(rc));
    }
    if (!app_outfile_commit(&o))
        app_fail(PROG, "cannot write '%s': %s", path, strerror(errno));
}

static void export_one(const args *a)
{
    cf_export_format fmt;
    if (!cf_export_format_parse(a->format, &fmt))
        app_fail(PROG, "--format: '%s' is not pbrt, mitsuba, blender or table", a->format);
    const cf_scene *s = cf_scene_find(a->name);
    if (!s)
        app_fail(PROG, "unknown scene '%s' (mcbox-scene list names them)", a->name);
    if (!cf_export_supports(s, fmt))
        app_fail(PROG, "scene '%s' cannot be written as %s", a->name, a->format);
    int size = a->size ? (int)a->size : s->size, spp = a->spp ? (int)a->spp : DEFAULT_SPP;
    if (a->out) {
        write_file(a->out, s, fmt, size, spp);
        return;
    }
    int rc = cf_export(stdout, s, fmt, size, spp);
    if (rc != CF_EXPORT_OK)
        app_fail(PROG, "cannot write standard output: %s",
                 rc == CF_EXPORT_EWRITE ? strerror(errno) : cf_export_strerror(rc));
}

static void export_all(const args *a)
{
    struct stat st;
    if (mkdir(a->dir, 0777) != 0 && errno != EEXIST)
        app_fail(PROG, "--dir: cannot create '%s': %s", a->dir, strerror(errno));
    if (stat(a->dir, &st) != 0 || !S_ISDIR(st.st_mode))
        app_fail(PROG, "--dir: '%s' is not a directory", a->dir);
    int files = 0, scenes = 0;
    for (const char *const *name = cf_scene_names; *name; name++, scenes++) {
        const cf_scene *s = cf_scene_find(*name);
        int size = a->size ? (int)a->size : s->size, spp = a->spp ? (int)a->spp : DEFAULT_SPP;
        for (int k = 0; k < CF_EXPORT_N_FORMATS; k++) {
            cf_export_format fmt = (cf_export_format)k;
            if (!cf_export_supports(s, fmt))
                app_fail(PROG, "scene '%s' cannot be written as %s", *name,
                         cf_export_format_name(fmt));
            char path[4096];
            if ((size_t)snprintf(path, sizeof path, "%s/%s%s", a->dir, *name,
                                 cf_export_extension(fmt)) >= sizeof path)
                app_fail(PROG, "--dir: '%s' is too long", a->dir);
            write_file(path, s, fmt, size, spp);
            files++;
        }
    }
    printf("%d files in %s (%d scenes x %d formats)\n", files, a->dir, scenes,
           (int)CF_EXPORT_N_FORMATS);
}

/* The scene's exact image as three equal channels. */
static void write_truth(const args *a)
{
    const cf_scene *s = cf_scene_find(a->name);
    if (!s)
        app_fail(PROG, "unknown scene '%s' (mcbox-scene list names them)", a->name);
    int size = a->size ? (int)a->size : s->size;
    size_t n = (size_t)size * (size_t)size;
    double *g = malloc(n * sizeof *g), *rgb = malloc(3 * n * sizeof *rgb), err;
    if (!g || !rgb || cf_truth_image(s, size, size, g, &err) != 0)
        app_fail(PROG, "out of memory");
    for (size_t i = 0; i < 3 * n; i++)
        rgb[i] = g[i / 3];
    char why[256];
    if (img_picture_write_pfm(a->out, size, size, rgb, why, sizeof why) != 0)
        app_fail(PROG, "-o %s: %s", a->out, why);
    /* The file's floats round each value by up to 2^-24 of it. */
    printf("%s %dx%d: quadrature error at most %.2g, then 32-bit floats; wrote %s\n", s->name,
           size, size, err, a->out);
    free(g);
    free(rgb);
}

int main(int argc, char **argv)
{
    args a = parse(argc, argv);
    if (strcmp(a.command, "list") == 0) {
        for (const char *const *name = cf_scene_names; *name; name++)
            printf("%-14s %s\n", *name, cf_scene_find(*name)->summary);
    } else if (strcmp(a.command, "export") == 0) {
        export_one(&a);
    } else if (strcmp(a.command, "truth") == 0) {
        write_truth(&a);
    } else {
        export_all(&a);
    }
    if (fflush(stdout) != 0 || ferror(stdout))
        app_fail(PROG, "cannot write standard output: %s", strerror(errno));
    return 0;
}
