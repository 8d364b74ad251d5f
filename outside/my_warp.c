/* my_warp.c - a sampler of your own, tested with an installed mcbox.
 *
 * The cosine-weighted hemisphere by Malley's method: a uniform point of
 * the unit disc (Shirley and Chiu's concentric map of the square, which
 * keeps areas and neighbourhoods), lifted straight up to the hemisphere.
 * Its density is cos(theta) / pi per unit solid angle. mcbox draws a
 * million points from it, histograms them, integrates the density over
 * every cell and runs Pearson's test; it also checks that the density
 * integrates to 1, that the pdf the sampler reports agrees with it, and
 * that the inverse maps every point back to its uniforms.
 *
 * Two deliberately wrong variants must be REJECTED (negative controls: a
 * check that passes everything proves nothing): the density without its
 * 1/pi, and a polar disc whose radius lacks its sqrt.
 *
 * Build and run:  cc my_warp.c $(pkg-config --cflags --libs mcbox) -lm -o my_warp
 *                 ./my_warp         (exit 0: the warp passed, both controls were rejected)
 */
#include <math.h>
#include <stdio.h>

#include <mcbox/check.h>

#define PI 3.14159265358979323846

/* Shirley and Chiu's concentric map of [0,1)^2 onto the unit disc: each
 * square ring about the centre goes to a circle of the same radius. */
static void concentric_disc(double u1, double u2, double *x, double *y)
{
    double sx = 2.0 * u1 - 1.0, sy = 2.0 * u2 - 1.0, r, phi;
    if (sx == 0.0 && sy == 0.0) {
        *x = *y = 0.0;
        return;
    }
    if (fabs(sx) > fabs(sy))
        r = sx, phi = (PI / 4.0) * (sy / sx);
    else
        r = sy, phi = PI / 2.0 - (PI / 4.0) * (sx / sy);
    *x = r * cos(phi), *y = r * sin(phi);
}

/* BEGIN SNIPPET own_c_sampler */
/* Malley: a uniform disc point has density 1/pi per unit area; lifting
 * it to z = sqrt(1 - r^2) divides areas by cos(theta) = z, so the
 * direction's density is z / pi per unit solid angle. */
static void sample(const double *u, mcbox_sample *out, void *ctx)
{
    (void)ctx;
    double x, y;
    concentric_disc(u[0], u[1], &x, &y);
    double z = sqrt(fmax(0.0, 1.0 - x * x - y * y));
    out->x[0] = x, out->x[1] = y, out->x[2] = z;
    out->pdf = z / PI; /* optional: mcbox compares it with pdf() */
}

/* cos(theta) / pi per unit solid angle on the upper hemisphere, 0 below. */
static double pdf(const double *x, void *ctx)
{
    (void)ctx;
    return x[2] >= 0.0 ? x[2] / PI : 0.0;
}
/* END SNIPPET own_c_sampler */

/* The inverse: drop the direction to the disc (x, y), then undo the
 * concentric map wedge by wedge (right/left: |sx| > |sy|, top/bottom). */
static void invert(const double *x, double *u, void *ctx)
{
    (void)ctx;
    double r = hypot(x[0], x[1]), psi = atan2(x[1], x[0]), sx, sy;
    if (fabs(psi) <= PI / 4.0 || fabs(psi) >= 3.0 * PI / 4.0) {
        double phi = x[0] >= 0.0 ? psi : (psi > 0.0 ? psi - PI : psi + PI);
        sx = x[0] >= 0.0 ? r : -r;
        sy = sx * phi * (4.0 / PI);
    } else {
        double phi = x[1] >= 0.0 ? psi : psi + PI;
        sy = x[1] >= 0.0 ? r : -r;
        sx = sy * (PI / 2.0 - phi) * (4.0 / PI);
    }
    u[0] = 0.5 * (sx + 1.0), u[1] = 0.5 * (sy + 1.0);
}

/* Wrong 1: the density without its 1/pi (it integrates to pi). */
static double pdf_no_inv_pi(const double *x, void *ctx)
{
    (void)ctx;
    return x[2] >= 0.0 ? x[2] : 0.0;
}

/* Wrong 2: a polar disc with r = u1 instead of sqrt(u1), which crowds the
 * points toward the pole, claiming the correct density. */
static void sample_no_sqrt(const double *u, mcbox_sample *out, void *ctx)
{
    (void)ctx;
    double r = u[0], phi = 2.0 * PI * u[1];
    out->x[0] = r * cos(phi), out->x[1] = r * sin(phi);
    out->x[2] = sqrt(fmax(0.0, 1.0 - r * r));
}

/* Runs the check; returns 1 when it passed, 0 when it rejected, -1 when
 * it could not run. */
/* BEGIN SNIPPET own_c_check */
static int check(const char *name, mcbox_sampler *s)
{
    mcbox_check_options o = mcbox_check_defaults();
    mcbox_check_result r;
    if (mcbox_check_run(s, &o, &r, NULL) != 0) {
        printf("%-22s could not run: %s\n", name, r.message);
        return -1;
    }
    printf("%-22s %s  chi2 %.1f, %d dof, p = %.3g; integral %.6f; inverse error %.2g%s%s\n", name,
           r.pass ? "PASS    " : "REJECTED", r.statistic, r.dof, r.pvalue, r.pdf_integral,
           r.invert_error, r.pass ? "" : "\n                       why: ", r.message);
    return r.pass ? 1 : 0;
}
/* END SNIPPET own_c_check */

int main(void)
{
    printf("mcbox %s\n", mcbox_version());
    /* BEGIN SNIPPET own_c_main */
    mcbox_sampler s = mcbox_sampler_init(MCBOX_HEMISPHERE);
    s.sample = sample, s.pdf = pdf, s.invert = invert;
    int good = check("cosine (Malley)", &s);
    /* END SNIPPET own_c_main */

    mcbox_sampler w1 = s;
    w1.pdf = pdf_no_inv_pi;
    int bad1 = check("control: pdf, no 1/pi", &w1);

    mcbox_sampler w2 = mcbox_sampler_init(MCBOX_HEMISPHERE);
    w2.sample = sample_no_sqrt, w2.pdf = pdf;
    int bad2 = check("control: r, no sqrt", &w2);

    int ok = good == 1 && bad1 == 0 && bad2 == 0;
    printf("my_warp: %s\n", ok ? "ok (the warp passes, both wrong variants are rejected)"
                               : "FAILED (see above)");
    return ok ? 0 : 1;
}
