/* check/run.c - the public check in one call: a sampler's samples drawn
 * and added in batches (mcbox_check_run), points given as they are
 * (mcbox_check_points), and a table of counts made elsewhere
 * (mcbox_check_counts). */
#include "check/check.h"
#include "check/internal.h"
#include "check/stream.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mc/chi2.h"

/* --- the whole check in one call ----------------------------------------- */

int mcbox_check_run(const mcbox_sampler *s, const mcbox_check_options *o,
                    mcbox_check_result *r, mcbox_check_table *t)
{
    if (t)
        memset(t, 0, sizeof *t);
    mcbox_check *c = mcbox_check_begin(s, o, r);
    if (!c)
        return -1;
    if (!s->sample && !(s->uniforms == 0 && s->sample_stream)) {
        free(c->obs);
        free(c->hint_x);
        free(c);
        chk_set_message(r, s->uniforms == 0 ? "uniforms = 0 needs sample_stream"
                                        : "the sampler has no sample function");
        return -1;
    }
    enum { CHUNK = 1024 };
    mcbox_sample batch[CHUNK];
    double u[CHUNK * MCBOX_MAX_UNIFORMS];
    int nu = s->uniforms;
    struct mcbox_stream stream;
    for (uint64_t done = 0; done < o->samples;) {
        size_t m = (size_t)(o->samples - done < CHUNK ? o->samples - done : CHUNK);
        for (size_t i = 0; i < m; i++) {
            mcbox_sample *q = &batch[i];
            q->x[0] = q->x[1] = q->x[2] = 0.0;
            q->pdf = q->weight = (double)NAN;
            q->atom = -1;
            if (nu == 0) {
                stream.rng = c->rng;
                s->sample_stream(&stream, q, s->ctx);
                c->rng = stream.rng;
            } else {
                mcbox_check_uniforms(c, u + i * (size_t)nu);
                s->sample(u + i * (size_t)nu, q, s->ctx);
            }
        }
        mcbox_check_add(c, batch, nu ? u : NULL, m);
        done += m;
    }
    return mcbox_check_finish(c, r, t);
}

int mcbox_check_points(const mcbox_sampler *s, const mcbox_sample *samples, uint64_t n,
                       const mcbox_check_options *o, mcbox_check_result *r,
                       mcbox_check_table *t)
{
    if (t)
        memset(t, 0, sizeof *t);
    if (o && n == 0) {
        chk_fresh_result(r);
        chk_set_message(r, "no samples to check");
        return -1;
    }
    mcbox_check_options oo;
    if (o) {
        oo = *o;
        oo.samples = n; /* the resolution follows the points there are */
    }
    mcbox_check *c = mcbox_check_begin(s, o ? &oo : NULL, r);
    if (!c)
        return -1;
    for (uint64_t done = 0; done < n;) {
        size_t m = (size_t)(n - done < 65536 ? n - done : 65536);
        mcbox_check_add(c, samples + done, NULL, m);
        done += m;
    }
    return mcbox_check_finish(c, r, t);
}

/* --- tables made elsewhere ------------------------------------------------- */

int mcbox_check_counts(const double *observed, const double *expected, size_t cells,
                       const mcbox_check_options *o, mcbox_check_result *r)
{
    chk_fresh_result(r);
    char err[200];
    if (!observed || !expected || cells == 0 || !o) {
        chk_set_message(r, "no tables (observed, expected, cells >= 1) or no options");
        return -1;
    }
    if (!chk_options_valid(o, err, sizeof err)) {
        chk_set_message(r, "invalid option: %s", err);
        return -1;
    }
    double n = 0.0;
    for (size_t k = 0; k < cells; k++) {
        if (!(observed[k] >= 0.0 && isfinite(observed[k]))) {
            chk_set_message(r, "observed[%zu] = %g is not a finite count >= 0", k, observed[k]);
            return -1;
        }
        if (!(expected[k] >= 0.0 && isfinite(expected[k]))) {
            chk_set_message(r, "expected[%zu] = %g is not a finite count >= 0", k, expected[k]);
            return -1;
        }
        n += observed[k];
    }
    mc_chi2_result pr = mc_chi2_pearson(observed, expected, cells, MC_GOF_MIN_EXPECTED);
    r->samples = (uint64_t)n;
    r->cells = cells;
    r->statistic = pr.stat;
    r->dof = pr.dof;
    r->pvalue = pr.pvalue;
    r->cells_pooled = pr.cells_pooled;
    r->in_zero_cells = (uint64_t)pr.obs_in_zero_cells;
    r->level = mc_sidak_alpha(o->alpha, o->tests);
    r->pdf_mismatch = 0.0;
    if (r->in_zero_cells > MC_GOF_ZERO_CELL_FRAC * n) {
        chk_set_message(r, "%llu observation(s) in cells whose expected count is 0",
                    (unsigned long long)r->in_zero_cells);
    } else if (pr.dof < 1) {
        chk_set_message(r, "no degrees of freedom: fewer than 2 cells after pooling");
    } else if (!(r->pvalue >= r->level)) {
        chk_set_message(r, "chi-square %.6g with %d degrees of freedom: p = %.3g, below the level %.3g",
                    r->statistic, r->dof, r->pvalue, r->level);
    } else {
        r->pass = true;
    }
    return 0;
}
