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
#include <stdio.h>

#include "examples/common/cli.h"
#include "examples/common/timing.h"
#include "pdf/pdf.h"

enum { REPS = 5, POOL = 4096 };

/* n directions from the pdf (ctx); returns their coordinate sum. */
static double generate_loop(void *ctx, uint64_t n, mc_rng *rng)
{
    const pdf *p = ctx;
    double acc = 0.0;
    for (uint64_t i = 0; i < n; i++) {
        vec3 d = pdf_generate(p, rng);
        acc += d.x + d.y + d.z;
    }
    return acc;
}

typedef struct value_job {
    const pdf *p;
    const vec3 *pool; /* POOL directions the pdf generated */
} value_job;

/* n values of the pdf, cycling over the pool; returns their sum. */
static double value_loop(void *ctx, uint64_t n, mc_rng *rng)
{
    const value_job *j = ctx;
    (void)rng;
    double acc = 0.0;
    for (uint64_t i = 0; i < n; i++)
        acc += pdf_value(j->p, j->pool[i & (POOL - 1)]);
    return acc;
}

static double ns_value(const pdf *p, uint64_t n, uint64_t seed)
{
    static vec3 pool[POOL];
    mc_rng rng = mc_rng_derive(seed, 99u);
    for (int i = 0; i < POOL; i++)
        pool[i] = pdf_generate(p, &rng);
    value_job j = {p, pool};
    return app_bench_ns(value_loop, &j, n, seed, REPS);
}

int main(int argc, char **argv)
{
    uint64_t n = 500000u, seed = 2385u;
    const app_opt opts[] = {
        {"--samples", APP_COUNT, &n, "calls per repetition (default 5e5)", NULL, 0, 0},
        {"--seed", APP_SEED, &seed, "seed of the uniform streams (default 2385)", NULL, 0, 0},
    };
    app_parse("bench_pdf",
              "bench_pdf [--samples N] [--seed S]\n"
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
    for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
        double gen = app_bench_ns(generate_loop, (void *)rows[i].p, n, seed, REPS);
        printf("%-22s %12.2f %9.2f\n", rows[i].name, gen, ns_value(rows[i].p, n, seed));
    }
    return 0;
}
