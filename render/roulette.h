/* render/roulette.h - Russian roulette for the path tracer's strategies
 * (this book's #ch-cornell, "Ending a path: Russian roulette"): a path
 * ends early with probability 1 - q and a survivor's throughput is divided
 * by q, which keeps every estimate unbiased and saves the rays of the
 * bounces that add little. The bidirectional walks play their own
 * (render/bdpt.h, RT_BDPT_RR_START).
 */
#ifndef RT_ROULETTE_H
#define RT_ROULETTE_H

#include <stdbool.h>

#include "mc/vec3.h"
#include "render/sampler.h"

/* Russian roulette's survival probability at a vertex reached with
 * throughput beta (channels >= 0) on a surface of albedo `albedo` (the
 * scatter's attenuation): min(0.95, largest channel of beta * albedo),
 * the throughput expected past the vertex, whatever direction is drawn
 * there. 0 when that is 0. */
double rt_roulette_survival(vec3 beta, vec3 albedo);

/* Roulette at the vertex after depth + 1 segments, from rr_start segments
 * on (the caller plays only when roulette is asked for): beta_albedo is
 * the throughput that reached the vertex times its albedo, *beta the
 * throughput with the new direction's s/p in; a survivor's *beta is divided by the survival
 * probability. Returns false when the path stops here. Draws one uniform
 * from sampler when it plays. */
bool rt_roulette(int rr_start, int depth, vec3 beta_albedo, vec3 *beta, rt_sampler *sampler);

#endif /* RT_ROULETTE_H */
