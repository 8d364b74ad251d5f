/* render/roulette.c - Russian roulette of the path tracer's strategies. */
#include "render/roulette.h"

#include <math.h>

/* BEGIN SNIPPET roulette_rule */
/* The survival probability of Russian roulette at a vertex reached with
 * throughput beta on a surface of albedo rho, from beta_albedo = beta *
 * rho: the throughput the path is expected to carry past the vertex
 * (E[f cos / p] = rho for any density p of the direction, Lambertian or
 * specular), and q = min(0.95, its largest channel). It is decided before
 * the factor s/p of the direction drawn there enters: with the mixture that
 * factor is small exactly for the directions aimed at the lamp, and a q
 * that followed it would divide the lamp's radiance by a small q. */
static double survival(vec3 beta_albedo)
{
    double q = vec3_max_component(beta_albedo);
    return q < 0.95 ? q : 0.95;
}

double rt_roulette_survival(vec3 beta, vec3 albedo) { return survival(vec3_mul(beta, albedo)); }

/* The path goes on with probability q = survival(beta_albedo) and its
 * throughput, the s/p of the new direction already in, is divided by q,
 * so that the expected contribution of everything after this point is
 * unchanged (q (X / q) + (1 - q) 0 = X). */
bool rt_roulette(int rr_start, int depth, vec3 beta_albedo, vec3 *beta, rt_sampler *sampler)
{
    if (depth + 1 < rr_start)
        return true;
    double q = survival(beta_albedo);
    if (!(q > 0.0) || rt_sampler_1d(sampler) >= q)
        return false;
    *beta = vec3_scale(*beta, 1.0 / q);
    return true;
}
/* END SNIPPET roulette_rule */
