/* bench/bench_pdf.c - nanoseconds per generate() and per value() of every
 * kind of pdf object in pdf/pdf.h (chapters 7, 8 and 10: what a renderer
 * calls at every diffuse bounce: one generate and, for a mixture, the
 * value of every component).
 *
 * generate: N directions from one PCG32 stream (the uniforms' cost
 * included, as in a renderer). value: N evaluations cycling over 4096
 * directions the same pdf generated (so the light pdfs take their hit
 * path). Each figure is the median thread CPU time of five repetitions.
 *
 * Build and run: make bench   (or: make all && build/bench/bench_pdf
 *                [--samples N] [--seed S])
 */
/* clock_gettime and its clocks are POSIX, not ISO C17. */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "examples/common/cli.h"
#include "pdf/pdf.h"

/* CPU time of this thread: other jobs on the machine do not count. */
static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Keeps the optimizer from dropping work whose result is otherwise unused. */
static volatile double sink;

enum { REPS = 5, POOL = 4096 };

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *t)
{
    qsort(t, REPS, sizeof t[0], cmp_double);
    return t[REPS / 2];
}

static double ns_generate(const pdf *p, uint64_t n, uint64_t seed)
{
    double t[REPS];
    for (int k = 0; k < REPS; k++) {
        mc_rng rng = mc_rng_derive(seed, (uint64_t)k);
        double acc = 0.0, t0 = now();
        for (uint64_t i = 0; i < n; i++) {
            vec3 d = pdf_generate(p, &rng);
            acc += d.x + d.y + d.z;
        }
        t[k] = (now() - t0) * 1e9 / (double)n;
        sink = acc;
    }
    return median(t);
}

static double ns_value(const pdf *p, uint64_t n, uint64_t seed)
{
    static vec3 pool[POOL];
    mc_rng rng = mc_rng_derive(seed, 99u);
    for (int i = 0; i < POOL; i++)
        pool[i] = pdf_generate(p, &rng);
    double t[REPS];
    for (int k = 0; k < REPS; k++) {
        double acc = 0.0, t0 = now();
        for (uint64_t i = 0; i < n; i++)
            acc += pdf_value(p, pool[i & (POOL - 1)]);
        t[k] = (now() - t0) * 1e9 / (double)n;
        sink = acc;
    }
    return median(t);
}

int main(int argc, char **argv)
{
    uint64_t n = 500000u, seed = 2385u;
    const app_opt opts[] = {
        {"--samples", APP_COUNT, &n, "calls per repetition (default 5e5)", NULL, 0, 0},
        {"--seed", APP_SEED, &seed, "seed of the uniform streams (default 2385)", NULL, 0, 0},
    };
    app_parse("bench_pdf",
              "usage: bench_pdf [--samples N] [--seed S]\n"
              "  nanoseconds per generate() and value() of every pdf object (median of 5 runs)",
              argc, argv, opts, sizeof opts / sizeof opts[0], NULL, 0);

    vec3 o = vec3_make(0.3, -0.2, 0.1);
    pdf uniform = pdf_uniform_sphere();
    pdf cosine = pdf_cosine(vec3_make(0.36, -0.48, 0.8));
    pdf quad = pdf_toward_quad(o, vec3_make(-0.4, -0.6, 1.3), vec3_make(1.0, 0.1, 0.35),
                               vec3_make(-0.15, 0.8, 0.45));
    pdf far = pdf_toward_sphere(o, vec3_make(3.3, 3.8, 12.1), 1.0);
    pdf inside = pdf_toward_sphere(o, vec3_make(0.5, 0.1, -0.2), 2.0);
    const pdf *parts[2] = {&cosine, &quad}, *items[2] = {&quad, &far};
    const double weights[2] = {0.5, 0.5};
    pdf mixture = pdf_mixture(parts, weights, 2), list = pdf_list(items, 2);
    const struct {
        const char *name;
        const pdf *p;
    } rows[] = {{"uniform-sphere", &uniform},
                {"cosine", &cosine},
                {"toward-quad", &quad},
                {"toward-sphere", &far},
                {"toward-sphere-inside", &inside},
                {"mixture-cosine-quad", &mixture},
                {"list-quad-sphere", &list}};

    printf("%-22s %12s %9s\n", "pdf", "ns_generate", "ns_value");
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++)
        printf("%-22s %12.2f %9.2f\n", rows[i].name, ns_generate(rows[i].p, n, seed),
               ns_value(rows[i].p, n, seed));
    return 0;
}
