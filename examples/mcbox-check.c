/* examples/mcbox-check.c - the command-line door of mcbox/check.h: test a
 * sampler written in any language against its density (chapter 5,
 * Generating Random Directions, and every sampler after it).
 *
 *   mcbox-check --exec CMD --domain D [...]   the sampler and its density
 *       are a program that speaks docs/check-protocol.md on stdin/stdout
 *   mcbox-check --samples FILE --pdf NAME     points from a file, the density
 *       of a catalog row (warp list)
 *   mcbox-check --samples FILE --pdf-exec CMD --domain D   the density from
 *       a program
 *
 * The uniforms are those mcbox_check_run would give an in-process sampler
 * (mcbox_check_uniforms), so a program and a C callback of the same warp
 * get the same statistic. Exit 0 pass, 1 fail, 2 no verdict: bad input, a
 * program that broke the protocol (then it is killed and reaped: never a
 * verdict from half the data), or a check that could not decide
 * (undetermined). The parts are in examples/check_cli/.
 *
 * Build and run:  make all
 *   build/bin/mcbox-check --exec 'build/bin/warp serve cosine' --domain hemisphere
 *   build/bin/warp sample cosine --n 1e5 | build/bin/mcbox-check --samples - --pdf cosine
 */
#define _POSIX_C_SOURCE 200809L /* fcntl, access */

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "examples/check_cli/check_cli.h"
#include "examples/common/cli.h"

static const char USAGE[] =
    "usage: mcbox-check --exec CMD --domain D [options]\n"
    "       mcbox-check --samples FILE|- --pdf NAME [--param k=v]... [options]\n"
    "       mcbox-check --samples FILE|- --pdf-exec CMD --domain D [options]\n"
    "Tests a sampler's points against its density: Pearson's chi-square test on the\n"
    "domain's chart, with normalization, domain, pdf-consistency and inverse checks.\n"
    "Exit status 0 pass, 1 fail, 2 no verdict: bad input, a program that broke the\n"
    "protocol, or a check that could not decide (undetermined). Protocol:\n"
    "docs/check-protocol.md; manual: man mcbox-check.\n"
    "The sampler and its density:\n"
    "  --exec CMD         a program run with /bin/sh -c CMD: samples from mcbox's uniforms\n"
    "                     (or its own generator) and its density, over pipes\n"
    "  --samples FILE     the points of FILE (- for stdin), one sample per line\n"
    "  --format F         csv (default; numbers separated by spaces, tabs or commas), f32 or\n"
    "                     f64 (raw little-endian records)\n"
    "  --pdf NAME         the density of a catalog row (see warp list) for --samples\n"
    "  --pdf-exec CMD     the density from a program (the protocol's pdf command)\n"
    "  --domain D         interval, square, disc, triangle, sphere, hemisphere, cap,\n"
    "                     spherical-triangle, spherical-quad, or a catalog row (warp list)\n"
    "  --param 'k=v ...'  parameters of the --pdf row, of a catalog --domain, or of\n"
    "                     cap (axis=x,y,z cos_max=C), spherical-triangle (a=x,y,z b=x,y,z\n"
    "                     c=x,y,z), spherical-quad (corner=x,y,z u=x,y,z v=x,y,z);\n"
    "                     repeatable, several assignments per option separated by blanks\n"
    "  --interval A,B     the interval's ends (default 0,1)\n"
    "  --uniforms K       uniforms per sample, 0 to 16 (default 2, 1 for an interval, the\n"
    "                     row's own for a catalog row); 0: the program draws from its own\n"
    "                     generator\n"
    "  --invert           also check the program's inverse: invert(sample(u)) = u\n"
    "  --atom 'x,y,z:m'   a discrete atom at that point with probability m (repeatable)\n"
    "  --timeout SEC      the longest wait for the program (default 60)\n"
    "The check:\n"
    "  --n N              samples (default 1e6 for --exec; for --samples the file's, or\n"
    "                     its first N)\n"
    "  --seed S           seed of the uniforms (default 1)\n"
    "  --alpha A          family-wise significance level, in (0, 1) (default 0.01)\n"
    "  --tests M          tests the level is shared over (Sidak; default 1)\n"
    "  --cells NXxNY      histogram cells (NX for an interval; default the chart's)\n"
    "  --lobe-width W     sphere, hemisphere, cap: histogram theta / (theta + W) about the\n"
    "                     lobe axis, spreading a peaked lobe over many cells\n"
    "  --lobe-axis X,Y,Z  the lobe chart's axis (default +z, or the cap's axis)\n"
    "  --norm-tol T       |integral of the density - 1| allowed (default 1e-6)\n"
    "  --pdf-tol T        relative |reported pdf - density| allowed (default 1e-6)\n"
    "  --weight-tol T     relative |weight - f / pdf| allowed (default 1e-6)\n"
    "  --invert-tol T     |invert(sample(u)) - u| allowed (default 1e-6)\n"
    "  --quad-order Q     Gauss-Legendre points per axis of a cell (1 to 64, default 8)\n"
    "  --quad-depth D     halvings of a cell where two rules disagree (0 to 30, default 12)\n"
    "  --quad-error-max E the largest quadrature error a verdict may rest on (default 1e-3)\n"
    "Reports:\n"
    "  --name NAME        the sampler's name in reports (letters, digits, . _ -)\n"
    "  --json             print the whole result as one JSON object instead of the summary\n"
    "                     (with exit 2 too: the verdict \"error\" or \"undetermined\")\n"
    "  --junit FILE       write a JUnit XML test suite of one test case (a failure on\n"
    "                     fail, an error on exit 2)\n"
    "  --plot DIR         write DIR/NAME.png (gnuplot) and DIR/NAME.dat: observed and\n"
    "                     expected counts, and (observed - expected) / sqrt(expected)\n"
    "  --help, --version\n" APP_NUMBER_GRAMMAR "\n";

static const char USAGE_IMAGES[] =
    "\nusage: mcbox-check --image FILE --image FILE... --scene NAME|--truth FILE [options]\n"
    "Tests a renderer's images against the truth, block by block and per channel, at a\n"
    "stated family-wise false-alarm rate (mcbox/image.h; man mcbox-check, IMAGES):\n"
    "  --image FILE       one render (PFM, EXR, PNG, PPM); 2 or more, from different seeds:\n"
    "                     the noise is measured from them\n"
    "  --image-mean FILE --image-second FILE --spp N\n"
    "                     instead: one render's per-pixel mean and mean of squares over N\n"
    "                     samples (pixels taken as independent)\n"
    "  --scene NAME       the truth: a conformance scene's closed form (mcbox-scene list)\n"
    "  --truth FILE       the truth: an exact float image; --truth-error E its error bound\n"
    "  --reference FILE --reference-noise FILE\n"
    "                     the truth: a noisy float image and its standard error per pixel;\n"
    "                     or --reference 2 or more times: independent renders whose mean is\n"
    "                     the truth and whose spread its noise\n"
    "  --transfer T       how 8- and 16-bit files were encoded: linear, gamma2 (round(255\n"
    "                     sqrt x)), gamma2.2, srgb, book (the write_color of Shirley's books)\n"
    "  --alpha A          family-wise false-alarm rate (default 0.01)\n"
    "  --block B          block side in pixels (default the larger side / 8)\n"
    "  --picture FILE     .png or .ppm: each block coloured by its z (red brighter than the\n"
    "                     truth, blue darker; black frames: rejected)\n"
    "  --json, --junit FILE, --name NAME   as above\n";

static void open_reports(cli_app *c)
{
    if (c->a.plot) {
        struct stat st;
        if (stat(c->a.plot, &st) != 0 || !S_ISDIR(st.st_mode) || access(c->a.plot, W_OK) != 0)
            cli_fail("--plot: '%s' is not a writable directory", c->a.plot);
    }
    if (c->a.junit) {
        if (!app_outfile_open(&c->junit, c->a.junit))
            cli_fail("--junit: cannot write '%s': %s", c->a.junit, strerror(errno));
        fcntl(fileno(c->junit.f), F_SETFD, FD_CLOEXEC); /* not the programs' to hold */
        c->junit_open = true;
    }
}

int main(int argc, char **argv)
{
    static cli_app c; /* large (the invert cache): not on the stack */
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
            fputs(USAGE, stdout);
            fputs(USAGE_IMAGES, stdout);
            return 0;
        }
        if (strcmp(argv[i], "--version") == 0) {
            printf("mcbox-check (mcbox) %s, library %s\n", APP_VERSION, mcbox_version());
            return 0;
        }
    }
    cli_report_prescan(argc, argv);
    for (int i = 1; i < argc; i++)
        if (strcmp(argv[i], "--image") == 0 || strcmp(argv[i], "--image-mean") == 0)
            return cli_image_main(argc, argv);
    c.a = cli_parse(argc, argv);
    cli_report_errors_to(&c);
    signal(SIGPIPE, SIG_IGN); /* a program that dies is an EPIPE, reported */
    open_reports(&c);
    cli_setup(&c);
    if (c.a.samples)
        cli_load_samples(&c);
    c.t0 = cli_now();
    mcbox_check_result r;
    mcbox_check_table t;
    int rc = c.a.exec ? cli_run_exec(&c, &r, &t) : cli_run_samples(&c, &r, &t);
    if (rc != 0)
        cli_fail("the check could not run: %s", r.message);
    if (c.a.json)
        cli_print_json(stdout, &c, &r, &t);
    else
        cli_print_summary(stdout, &c, &r);
    fflush(stdout);
    if (r.warning[0])
        fprintf(stderr, "%s: warning: %s\n", CLI_PROG, r.warning);
    if (r.undetermined) /* the message says "undetermined" itself, or is given the word */
        fprintf(stderr, "%s: %s%s\n", CLI_PROG,
                strncmp(r.message, "undetermined", 12) == 0 ? "" : "undetermined: ", r.message);
    if (c.junit_open && !cli_write_junit(&c, &r, cli_now() - c.t0))
        fprintf(stderr, "%s: warning: cannot write %s: %s\n", CLI_PROG, c.a.junit, strerror(errno));
    if (c.a.plot)
        cli_plot(&c, &t, &r);
    mcbox_check_table_free(&t);
    free(c.text);
    return r.pass ? 0 : r.undetermined ? 2 : 1;
}
