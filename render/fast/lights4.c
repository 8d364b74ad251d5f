/* render/fast/lights4.c - render/lights.h's densities for four origins:
 * lane by lane, and in AVX2 vectors. */
#include "render/fast/lights4.h"

#include <math.h>

static void store_lane(rt_lights4 *at, int k, const rt_lights_at *one)
{
    at->ox[k] = one->origin.x;
    at->oy[k] = one->origin.y;
    at->oz[k] = one->origin.z;
    for (int i = 0; i < at->n; i++) {
        if (at->lights[i].kind == RT_PRIM_QUAD) {
            at->num[i][k] = one->num[i];
            continue;
        }
        at->ax[i][k] = one->axis[i].x;
        at->ay[i][k] = one->axis[i].y;
        at->az[i][k] = one->axis[i].z;
        at->cos_max[i][k] = one->cos_max[i];
        at->one_minus_cos[i][k] = one->one_minus_cos[i];
        at->cone[i][k] = one->cone[i];
    }
}

void rt_lights4_lane(const rt_lights4 *at, int k, rt_lights_at *out)
{
    out->lights = at->lights;
    out->n = at->n;
    out->origin = vec3_make(at->ox[k], at->oy[k], at->oz[k]);
    for (int i = 0; i < at->n; i++) {
        if (at->lights[i].kind == RT_PRIM_QUAD) {
            out->num[i] = at->num[i][k];
            continue;
        }
        out->axis[i] = vec3_make(at->ax[i][k], at->ay[i][k], at->az[i][k]);
        out->cos_max[i] = at->cos_max[i][k];
        out->one_minus_cos[i] = at->one_minus_cos[i][k];
        out->cone[i] = at->cone[i][k];
    }
}

vec3 rt_lights4_generate(const rt_lights4 *at, int k, rt_sampler *sampler)
{
    uint32_t i = rt_sampler_index(sampler, (uint32_t)at->n);
    double u1, u2;
    rt_sampler_2d(sampler, &u1, &u2);
    return rt_light_generate(&at->lights[i], vec3_make(at->ox[k], at->oy[k], at->oz[k]),
                             vec3_make(at->ax[i][k], at->ay[i][k], at->az[i][k]),
                             at->one_minus_cos[i][k], u1, u2);
}

/* The list's average sum / n. For n a power of two, 1 / n is exact and
 * sum * (1 / n) is the correctly rounded sum / n as the quotient is: the
 * same bits for a multiplication instead of a division. */
static bool power_of_two(int n) { return n > 0 && (n & (n - 1)) == 0; }

#if RT_ISA_X86
/* Hand-written AVX2: with render/lights.h lane by lane instead (the
 * portable path), make bench's book render took 35% longer
 * (docs/performance.md), far above the 5% that a vector copy of the
 * densities must pay for. */
#include <immintrin.h>

#define AVX2_INLINE __attribute__((target("avx2"), always_inline)) static inline

/* The x, y and z of four vectors, a lane each. */
AVX2_INLINE void lanes_of(const vec3 v[4], __m256d *x, __m256d *y, __m256d *z)
{
    *x = _mm256_setr_pd(v[0].x, v[1].x, v[2].x, v[3].x);
    *y = _mm256_setr_pd(v[0].y, v[1].y, v[2].y, v[3].y);
    *z = _mm256_setr_pd(v[0].z, v[1].z, v[2].z, v[3].z);
}

/* The list's average of the summed densities (power_of_two above). */
AVX2_INLINE __m256d list_average(__m256d sum, int n)
{
    return power_of_two(n) ? _mm256_mul_pd(sum, _mm256_set1_pd(1.0 / (double)n))
                           : _mm256_div_pd(sum, _mm256_set1_pd((double)n));
}

/* Each statement below is the vector form of the line of render/lights.h
 * (or of the sampler it calls) named in its comment; operands keep their
 * order where it matters for rounding (sums left to right). */
__attribute__((target("avx2"))) static void prepare_avx2(rt_lights4 *at, const vec3 origin[4])
{
    __m256d ox, oy, oz;
    lanes_of(origin, &ox, &oy, &oz);
    _mm256_storeu_pd(at->ox, ox);
    _mm256_storeu_pd(at->oy, oy);
    _mm256_storeu_pd(at->oz, oz);
    const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
    for (int i = 0; i < at->n; i++) {
        const rt_light *l = &at->lights[i];
        if (l->kind == RT_PRIM_QUAD) {
            /* num = normal . (q - origin) */
            __m256d bx = _mm256_sub_pd(_mm256_set1_pd(l->q.x), ox),
                    by = _mm256_sub_pd(_mm256_set1_pd(l->q.y), oy),
                    bz = _mm256_sub_pd(_mm256_set1_pd(l->q.z), oz);
            __m256d num = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(l->normal.x), bx),
                                                      _mm256_mul_pd(_mm256_set1_pd(l->normal.y), by)),
                                        _mm256_mul_pd(_mm256_set1_pd(l->normal.z), bz));
            _mm256_storeu_pd(at->num[i], num);
            continue;
        }
        /* pdf_sphere_cone: axis = center - origin, dist_sq = |axis|^2 */
        __m256d vx = _mm256_sub_pd(_mm256_set1_pd(l->center.x), ox),
                vy = _mm256_sub_pd(_mm256_set1_pd(l->center.y), oy),
                vz = _mm256_sub_pd(_mm256_set1_pd(l->center.z), oz);
        __m256d dist_sq = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(vx, vx), _mm256_mul_pd(vy, vy)),
                                        _mm256_mul_pd(vz, vz));
        /* smp_sphere_cone_cap: outside when dist_sq > r2; then
         * c = sqrt((dist_sq - r2) / dist_sq), 1 - cos = (r2 / dist_sq) / (1 + c);
         * inside, cos = -1 and 1 - cos = 2. */
        __m256d r2 = _mm256_set1_pd(l->radius * l->radius);
        __m256d outside = _mm256_cmp_pd(dist_sq, r2, _CMP_GT_OQ);
        __m256d c = _mm256_sqrt_pd(_mm256_div_pd(_mm256_sub_pd(dist_sq, r2), dist_sq));
        __m256d h = _mm256_div_pd(_mm256_div_pd(r2, dist_sq), _mm256_add_pd(one, c));
        c = _mm256_blendv_pd(_mm256_set1_pd(-1.0), c, outside);
        h = _mm256_blendv_pd(_mm256_set1_pd(2.0), h, outside);
        _mm256_storeu_pd(at->cos_max[i], c);
        _mm256_storeu_pd(at->one_minus_cos[i], h);
        /* the unit axis, or +z for an origin at the centre */
        __m256d s = _mm256_div_pd(one, _mm256_sqrt_pd(dist_sq));
        __m256d pos = _mm256_cmp_pd(dist_sq, zero, _CMP_GT_OQ);
        _mm256_storeu_pd(at->ax[i], _mm256_and_pd(pos, _mm256_mul_pd(s, vx)));
        _mm256_storeu_pd(at->ay[i], _mm256_and_pd(pos, _mm256_mul_pd(s, vy)));
        _mm256_storeu_pd(at->az[i], _mm256_blendv_pd(one, _mm256_mul_pd(s, vz), pos));
        /* smp_uniform_cap_pdf at the axis, where 1 - z is 0:
         * 1 / (2 pi h) for h > 0, else 0 */
        __m256d cone = _mm256_div_pd(one, _mm256_mul_pd(_mm256_set1_pd(MC_2PI), h));
        _mm256_storeu_pd(at->cone[i], _mm256_and_pd(_mm256_cmp_pd(h, zero, _CMP_GT_OQ), cone));
    }
}

/* pdf_quad_density's s = w . (q x v) and t = w . (u x q) at the point
 * q = (origin + r d) - corner of the quad's plane. */
__attribute__((target("avx2"))) static inline void quad_st(const rt_light *l, __m256d ox,
                                                           __m256d oy, __m256d oz, __m256d dx,
                                                           __m256d dy, __m256d dz, __m256d r,
                                                           __m256d *s, __m256d *t)
{
    __m256d qx = _mm256_sub_pd(_mm256_add_pd(ox, _mm256_mul_pd(r, dx)), _mm256_set1_pd(l->q.x)),
            qy = _mm256_sub_pd(_mm256_add_pd(oy, _mm256_mul_pd(r, dy)), _mm256_set1_pd(l->q.y)),
            qz = _mm256_sub_pd(_mm256_add_pd(oz, _mm256_mul_pd(r, dz)), _mm256_set1_pd(l->q.z));
    __m256d ux = _mm256_set1_pd(l->u.x), uy = _mm256_set1_pd(l->u.y), uz = _mm256_set1_pd(l->u.z);
    __m256d vx = _mm256_set1_pd(l->v.x), vy = _mm256_set1_pd(l->v.y), vz = _mm256_set1_pd(l->v.z);
    __m256d wx = _mm256_set1_pd(l->w.x), wy = _mm256_set1_pd(l->w.y), wz = _mm256_set1_pd(l->w.z);
    __m256d cx = _mm256_sub_pd(_mm256_mul_pd(qy, vz), _mm256_mul_pd(qz, vy)),
            cy = _mm256_sub_pd(_mm256_mul_pd(qz, vx), _mm256_mul_pd(qx, vz)),
            cz = _mm256_sub_pd(_mm256_mul_pd(qx, vy), _mm256_mul_pd(qy, vx));
    *s = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(wx, cx), _mm256_mul_pd(wy, cy)), _mm256_mul_pd(wz, cz));
    cx = _mm256_sub_pd(_mm256_mul_pd(uy, qz), _mm256_mul_pd(uz, qy));
    cy = _mm256_sub_pd(_mm256_mul_pd(uz, qx), _mm256_mul_pd(ux, qz));
    cz = _mm256_sub_pd(_mm256_mul_pd(ux, qy), _mm256_mul_pd(uy, qx));
    *t = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(wx, cx), _mm256_mul_pd(wy, cy)), _mm256_mul_pd(wz, cz));
}

/* vec3_dot of (ax, ay, az) and (bx, by, bz), summed left to right. */
__attribute__((target("avx2"))) static inline __m256d dot3(__m256d ax, __m256d ay, __m256d az,
                                                           __m256d bx, __m256d by, __m256d bz)
{
    return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(ax, bx), _mm256_mul_pd(ay, by)), _mm256_mul_pd(az, bz));
}

/* For cone i: d . axis, and *rim = cos_max - the rim slack. */
AVX2_INLINE __m256d cone_dot(const rt_lights4 *at, int i, __m256d dx, __m256d dy, __m256d dz,
                             __m256d *rim)
{
    *rim = _mm256_sub_pd(_mm256_loadu_pd(at->cos_max[i]), _mm256_set1_pd(PDF_CONE_RIM_TOL));
    return dot3(dx, dy, dz, _mm256_loadu_pd(at->ax[i]), _mm256_loadu_pd(at->ay[i]),
                _mm256_loadu_pd(at->az[i]));
}

/* pdf_quad_density's distance r = num / denom along d, denom = normal . d. */
AVX2_INLINE __m256d quad_r(const rt_lights4 *at, int i, __m256d dx, __m256d dy, __m256d dz,
                           __m256d *denom)
{
    const rt_light *l = &at->lights[i];
    *denom = dot3(_mm256_set1_pd(l->normal.x), _mm256_set1_pd(l->normal.y),
                  _mm256_set1_pd(l->normal.z), dx, dy, dz);
    return _mm256_div_pd(_mm256_loadu_pd(at->num[i]), *denom);
}

__attribute__((target("avx2"))) static void value_avx2(const rt_lights4 *at, const vec3 d[4],
                                                       double out[4])
{
    __m256d dx, dy, dz;
    lanes_of(d, &dx, &dy, &dz);
    __m256d ox = _mm256_loadu_pd(at->ox), oy = _mm256_loadu_pd(at->oy), oz = _mm256_loadu_pd(at->oz);
    const __m256d zero = _mm256_setzero_pd(), lo = _mm256_set1_pd(-PDF_QUAD_EDGE_TOL),
                  hi = _mm256_set1_pd(1.0 + PDF_QUAD_EDGE_TOL);
    const __m256d sign = _mm256_set1_pd(-0.0);
    __m256d sum = zero;
    for (int i = 0; i < at->n; i++) {
        const rt_light *l = &at->lights[i];
        if (l->kind != RT_PRIM_QUAD) {
            /* d . axis < cos_max - rim ? 0 : cone */
            __m256d rim, dd = cone_dot(at, i, dx, dy, dz, &rim);
            __m256d off = _mm256_cmp_pd(dd, rim, _CMP_LT_OQ);
            sum = _mm256_add_pd(sum, _mm256_andnot_pd(off, _mm256_loadu_pd(at->cone[i])));
            continue;
        }
        /* pdf_quad_density: denom = normal . d, r = num / denom */
        __m256d denom, r = quad_r(at, i, dx, dy, dz, &denom);
        __m256d s, t;
        quad_st(l, ox, oy, oz, dx, dy, dz, r, &s, &t);
        /* denom != 0, r > 0, s and t within the edges (ordered: NaN fails) */
        __m256d ok = _mm256_and_pd(_mm256_cmp_pd(denom, zero, _CMP_NEQ_OQ),
                                   _mm256_cmp_pd(r, zero, _CMP_GT_OQ));
        ok = _mm256_and_pd(ok, _mm256_and_pd(_mm256_cmp_pd(s, lo, _CMP_GE_OQ), _mm256_cmp_pd(s, hi, _CMP_LE_OQ)));
        ok = _mm256_and_pd(ok, _mm256_and_pd(_mm256_cmp_pd(t, lo, _CMP_GE_OQ), _mm256_cmp_pd(t, hi, _CMP_LE_OQ)));
        /* smp_area_to_solid_angle(inv_area, r r, denom):
         * c = |denom|, c > 0 ? inv_area r^2 / c : 0 */
        __m256d c = _mm256_andnot_pd(sign, denom);
        ok = _mm256_and_pd(ok, _mm256_cmp_pd(c, zero, _CMP_GT_OQ));
        __m256d v = _mm256_div_pd(_mm256_mul_pd(_mm256_set1_pd(l->inv_area), _mm256_mul_pd(r, r)), c);
        sum = _mm256_add_pd(sum, _mm256_and_pd(ok, v));
    }
    _mm256_storeu_pd(out, list_average(sum, at->n));
}

#endif

void rt_lights4_prepare(rt_isa isa, rt_lights4 *at, const rt_light *lights, int n,
                        const vec3 origin[RT_LANES])
{
    at->lights = lights;
    at->n = n;
#if RT_ISA_X86
    if (isa == RT_ISA_AVX2) {
        prepare_avx2(at, origin);
        return;
    }
#else
    (void)isa;
#endif
    for (int k = 0; k < RT_LANES; k++) {
        rt_lights_at one;
        rt_lights_prepare(&one, lights, n, origin[k]);
        store_lane(at, k, &one);
    }
}

/* BEGIN SNIPPET lights4_value */
void rt_lights4_value(rt_isa isa, const rt_lights4 *at, const vec3 d[RT_LANES],
                      double out[RT_LANES])
{
#if RT_ISA_X86
    if (isa == RT_ISA_AVX2) {
        value_avx2(at, d, out);
        return;
    }
#else
    (void)isa;
#endif
    for (int k = 0; k < RT_LANES; k++) {
        rt_lights_at one;
        rt_lights4_lane(at, k, &one);
        out[k] = rt_lights_at_value(&one, d[k]);
    }
}
/* END SNIPPET lights4_value */
