/* render/lights4.h - the light list's densities at four hit points at once.
 *
 * At every diffuse hit the book's integrator (chapters 8-10 of "Ray
 * Tracing: The Rest of Your Life") prepares the density toward each light
 * from the hit point and evaluates it at the direction it drew. When the
 * renderer advances four paths together (render/render.c), these do that
 * for the four hit points in the lanes of one vector: on processors with
 * AVX2, one vector instruction per operation of render/lights.h, in the
 * same order and without fused multiply-adds, so that every lane holds
 * bit for bit what render/lights.h (and so the pdf objects of pdf/pdf.h)
 * computes for it (with AVX-512VL, its mask registers for the comparisons
 * and selections); elsewhere, render/lights.h lane by lane.
 * tests/test_render_pdf.c checks the equality.
 */
#ifndef RT_LIGHTS4_H
#define RT_LIGHTS4_H

#include <stdbool.h>

#include "mc/vec3.h"
#include "render/lights.h"

#define RT_LIGHTS4_LANES 4

/* rt_lights_at for four origins, structure of arrays: field[i][k] is
 * light i seen from origin k. */
typedef struct rt_lights4 {
    const rt_light *lights;
    int n;
    double ox[RT_LIGHTS4_LANES], oy[RT_LIGHTS4_LANES], oz[RT_LIGHTS4_LANES];
    double num[RT_LIGHTS_AT_MAX][RT_LIGHTS4_LANES];
    double ax[RT_LIGHTS_AT_MAX][RT_LIGHTS4_LANES], ay[RT_LIGHTS_AT_MAX][RT_LIGHTS4_LANES],
        az[RT_LIGHTS_AT_MAX][RT_LIGHTS4_LANES];
    double cos_max[RT_LIGHTS_AT_MAX][RT_LIGHTS4_LANES];
    double one_minus_cos[RT_LIGHTS_AT_MAX][RT_LIGHTS4_LANES];
    double cone[RT_LIGHTS_AT_MAX][RT_LIGHTS4_LANES];
} rt_lights4;

/* rt_lights_prepare of lights[0..n) (1 <= n <= RT_LIGHTS_AT_MAX) from
 * each of the four origins. */
void rt_lights4_prepare(rt_lights4 *at, const rt_light *lights, int n,
                        const vec3 origin[RT_LIGHTS4_LANES]);

/* Lane k (0 <= k < 4) as the one-origin form, for rt_lights_at_generate. */
void rt_lights4_lane(const rt_lights4 *at, int k, rt_lights_at *out);

/* The instruction sets the vector forms may use: every one computes the
 * same bits (tests/test_render_pdf.c runs each one the processor has). */
typedef enum rt_lights4_isa {
    RT_LIGHTS4_PORTABLE, /* render/lights.h lane by lane */
    RT_LIGHTS4_AVX2,     /* 4 lanes in a ymm register */
    RT_LIGHTS4_AVX512    /* the same with AVX-512VL mask registers */
} rt_lights4_isa;

/* Whether this build and this processor can run isa. */
bool rt_lights4_isa_available(rt_lights4_isa isa);

/* The isa rt_lights4_prepare and rt_lights4_value use: the last available
 * one of the list above. */
rt_lights4_isa rt_lights4_isa_best(void);

/* rt_lights4_prepare and rt_lights4_value with the instruction set given
 * (available, see above). */
void rt_lights4_prepare_isa(rt_lights4_isa isa, rt_lights4 *at, const rt_light *lights, int n,
                            const vec3 origin[RT_LIGHTS4_LANES]);
void rt_lights4_value_isa(rt_lights4_isa isa, const rt_lights4 *at, const vec3 d[RT_LIGHTS4_LANES],
                          double out[RT_LIGHTS4_LANES]);

/* rt_lights_at_generate of lane k: the same draws, the same direction. */
vec3 rt_lights4_generate(const rt_lights4 *at, int k, mc_rng *rng);

/* rt_lights_at_value of lane k at the unit direction d[k], into out[k],
 * for the four lanes. */
void rt_lights4_value(const rt_lights4 *at, const vec3 d[RT_LIGHTS4_LANES],
                      double out[RT_LIGHTS4_LANES]);

#endif /* RT_LIGHTS4_H */
