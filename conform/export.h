/* conform/export.h - the conformance scenes as files other renderers read:
 * pbrt-v4, Mitsuba 3, Blender (Cycles) and a plain table for a renderer
 * written along Shirley's "Ray Tracing in One Weekend" series.
 *
 * A scene of conform/conform.h is judged against its exact pixels
 * (conform/truth.h) only if the other renderer computes what the truth
 * assumes. Each format has its own defaults that would change the answer
 * without an error: a left-handed camera (pbrt mirrors the image), two-sided
 * emitters (Cycles), one-sided diffuse surfaces (Mitsuba), a wide pixel
 * filter, tone curves, half-float output, denoising, clamping, a path length
 * cut short. Every exported file opens with a comment naming the scene, the
 * conventions of conform/conform.h and how that file pins each of them, and
 * then pins them explicitly rather than leaning on a default.
 *
 * Numbers are written in the shortest decimal form that reads back as the
 * same double, so a file parsed back gives the table's values exactly.
 */
#ifndef CF_EXPORT_H
#define CF_EXPORT_H

#include <stdbool.h>
#include <stdio.h>

#include "conform/conform.h"

typedef enum cf_export_format {
    CF_EXPORT_PBRT,    /* pbrt-v4 scene file */
    CF_EXPORT_MITSUBA, /* Mitsuba 3 XML scene */
    CF_EXPORT_BLENDER, /* Python script for Blender that builds the scene and renders it with Cycles */
    CF_EXPORT_TABLE,   /* one item per line, a key then numbers (scanf-friendly) */
    CF_EXPORT_N_FORMATS
} cf_export_format;

/* What cf_export returns. */
enum {
    CF_EXPORT_OK = 0,
    CF_EXPORT_EWRITE = -1,  /* the stream reported an error (errno as stdio left it) */
    CF_EXPORT_EINVALID = -2 /* a size or sample count out of range, or a scene the
                             * format cannot express; nothing was written */
};

/* Largest image side and sample count a file may ask for: Cycles takes at
 * most 2^24 samples per pixel; 16384 pixels a side is far beyond what a
 * conformance run needs and keeps size * size within an int. */
#define CF_EXPORT_MAX_SIZE 16384
#define CF_EXPORT_MAX_SPP (1 << 24)

/* The format names ("pbrt", "mitsuba", "blender", "table"), in the order of
 * cf_export_format, NULL-terminated. */
extern const char *const cf_export_format_names[];

/* The format of that name into *fmt; false (and *fmt untouched) for any
 * other name. */
bool cf_export_format_parse(const char *name, cf_export_format *fmt);

/* The name of fmt, or NULL when fmt is not a format. */
const char *cf_export_format_name(cf_export_format fmt);

/* The file extension of fmt with its dot (".pbrt", ".xml", ".py", ".txt"),
 * or NULL when fmt is not a format. */
const char *cf_export_extension(cf_export_format fmt);

/* Whether the format can express the scene exactly. Mitsuba's rectangle is
 * the image of [-1, 1]^2 under an affine map whose shading frame must be
 * orthonormal, so it takes quads whose edges are perpendicular only; the
 * other formats take any parallelogram. */
bool cf_export_supports(const cf_scene *s, cf_export_format fmt);

/* Writes scene s to f in format fmt for a size x size image (1 ..
 * CF_EXPORT_MAX_SIZE) of spp samples per pixel (1 .. CF_EXPORT_MAX_SPP).
 * Where the format names an output image (pbrt, Blender), it is
 * "<scene name>.exr". Returns CF_EXPORT_OK, CF_EXPORT_EWRITE when a write
 * or the final fflush fails (a full disk, a stream not open for writing),
 * or CF_EXPORT_EINVALID (nothing written) for a null argument, a size or
 * sample count out of range, an unknown format or a scene it does not
 * support. */
int cf_export(FILE *f, const cf_scene *s, cf_export_format fmt, int size, int spp);

/* One line saying what a status of cf_export means. */
const char *cf_export_strerror(int status);

#endif /* CF_EXPORT_H */
