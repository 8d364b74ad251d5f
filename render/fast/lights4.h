/* render/fast/lights4.h - the light list's densities at four hit points at
 * once.
 *
 * At every diffuse hit the book's integrator (chapters 8-10 of "Ray
 * Tracing: The Rest of Your Life") prepares the density toward each light
 * from the hit point and evaluates it at the direction it drew. When the
 * renderer advances four paths together (render/fast/rows.c), these do
 * that for the four hit points in the lanes of one vector: with AVX2, one
 * vector instruction per operation of render/lights.h, in the same order
 * and without fused multiply-adds, so that every lane holds bit for bit
 * what render/lights.h (and so pdf/) computes for it; portably,
 * render/lights.h lane by lane. tests/test_render_pdf.c checks the
 * equality.
 */
#ifndef RT_FAST_LIGHTS4_H
#define RT_FAST_LIGHTS4_H

#include <stdbool.h>

#include "mc/vec3.h"
#include "render/fast/isa.h"
#include "render/lights.h"

/* rt_lights_at for four origins, structure of arrays: field[i][k] is
 * light i seen from origin k. */
typedef struct rt_lights4 {
    const rt_light *lights;
    int n;
    double ox[RT_LANES], oy[RT_LANES], oz[RT_LANES];
    double num[RT_LIGHTS_AT_MAX][RT_LANES];
    double ax[RT_LIGHTS_AT_MAX][RT_LANES], ay[RT_LIGHTS_AT_MAX][RT_LANES],
        az[RT_LIGHTS_AT_MAX][RT_LANES];
    double cos_max[RT_LIGHTS_AT_MAX][RT_LANES];
    double one_minus_cos[RT_LIGHTS_AT_MAX][RT_LANES];
    double cone[RT_LIGHTS_AT_MAX][RT_LANES];
} rt_lights4;

/* rt_lights_prepare of lights[0..n) (1 <= n <= RT_LIGHTS_AT_MAX) from
 * each of the four origins, with the instruction set isa (available). */
void rt_lights4_prepare(rt_isa isa, rt_lights4 *at, const rt_light *lights, int n,
                        const vec3 origin[RT_LANES]);

/* rt_lights_at_value of lane k at the unit direction d[k], into out[k],
 * for the four lanes, with the instruction set isa (available). */
void rt_lights4_value(rt_isa isa, const rt_lights4 *at, const vec3 d[RT_LANES],
                      double out[RT_LANES]);

/* Lane k (0 <= k < 4) as the one-origin form. */
void rt_lights4_lane(const rt_lights4 *at, int k, rt_lights_at *out);

/* rt_lights_at_generate of lane k: the same draws, the same direction. */
vec3 rt_lights4_generate(const rt_lights4 *at, int k, rt_sampler *sampler);

#endif /* RT_FAST_LIGHTS4_H */
