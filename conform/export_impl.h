/* conform/export_impl.h - what the exporters of conform/export.h share:
 * numbers that read back exactly, the opening comment every file carries,
 * and the bits of geometry more than one format needs. Internal to conform/.
 */
#ifndef CF_EXPORT_IMPL_H
#define CF_EXPORT_IMPL_H

#include <stdbool.h>
#include <stdio.h>

#include "conform/conform.h"
#include "mc/vec3.h"

/* A number as text: the shortest %.Ng form (N = 1 .. 17) that strtod reads
 * back as the same double. Returned by value so that several can appear
 * in one printf call (the arrays live to the end of the full expression). */
typedef struct cf_numtext {
    char s[32];
} cf_numtext;

cf_numtext cf_num(double x);

/* The seven conventions of conform/conform.h, in the order of every
 * file's opening comment; each exporter gives one line per convention
 * saying how it pins it. */
enum { CF_PIN_HANDEDNESS, CF_PIN_FOV, CF_PIN_FILTER, CF_PIN_UNITS, CF_PIN_EMITTERS,
       CF_PIN_MATERIALS, CF_PIN_DEPTH, CF_N_PINS };

/* Writes the opening comment: the scene, the conventions with this
 * scene's numbers, then "How this file pins them:" and pins[0 ..
 * CF_N_PINS). Each line starts with `lead` ("# ", or "   " inside an XML
 * comment); with `xml`, "--" never appears (an XML comment may not hold
 * it). */
void cf_write_header(FILE *f, const cf_scene *s, const char *format, int size, int spp,
                     const char *lead, bool xml, const char *const pins[CF_N_PINS]);

/* The unit normal of a quad's front face, u x v normalized. */
vec3 cf_quad_normal(const cf_shape *sh);

/* Whether the quad's edges u and v are perpendicular (within rounding of
 * the table's decimal numbers: |u.v| <= 1e-12 |u| |v|). */
bool cf_quad_is_rectangle(const cf_shape *sh);

/* True when shape i's material emits. */
bool cf_shape_emits(const cf_scene *s, int i);

/* Clip distances for cameras that have them (Mitsuba, Blender): near is
 * half the smallest distance from lookfrom to any shape (never below
 * 1e-6 of the scene's extent), far twice the largest, so that no surface
 * is clipped away and none is hidden behind the far plane. */
void cf_clip_range(const cf_scene *s, double *near_clip, double *far_clip);

/* The exporters proper. Each writes the whole file and leaves error
 * detection to cf_export (ferror and fflush at the end). */
void cf_export_pbrt(FILE *f, const cf_scene *s, int size, int spp);
void cf_export_mitsuba(FILE *f, const cf_scene *s, int size, int spp);
void cf_export_blender(FILE *f, const cf_scene *s, int size, int spp);
void cf_export_table(FILE *f, const cf_scene *s, int size, int spp);

#endif /* CF_EXPORT_IMPL_H */
