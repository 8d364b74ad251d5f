/* examples/check_cli/plot.c - --plot DIR: the observed and expected counts
 * of every chart cell and the standardized residuals, as DIR/NAME.dat and
 * a gnuplot picture DIR/NAME.png. Observed and expected share one colour
 * scale (or one y range in 1D), so that the eye compares them directly;
 * cells holding samples where none were expected are marked on every
 * panel. */
#define _POSIX_C_SOURCE 200809L /* fork, pipe, fdopen, waitpid */

#include "examples/check_cli/check_cli.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

/* A path in a gnuplot single-quoted string: '' is a quote there. */
static void gp_quoted(FILE *f, const char *dir, const char *name, const char *ext)
{
    fputc('\'', f);
    for (const char *p = dir; *p; p++)
        fputs(*p == '\'' ? "''" : (char[2]){*p, '\0'}, f);
    fprintf(f, "/%s.%s'", name, ext);
}

/* The largest count of the chart's cells, observed or expected. */
static double count_max(const mcbox_check_table *t)
{
    double m = 0.0;
    for (size_t k = 0; k < (size_t)t->nx * (size_t)t->ny; k++)
        m = fmax(m, fmax(t->observed[k], t->expected[k]));
    return m > 0.0 ? m : 1.0;
}

/* The points of cells observed but expected empty, over panel k. */
static void empty_marks(FILE *f, const cli_app *c, const mcbox_check_table *t)
{
    fputs(", ", f);
    gp_quoted(f, c->a.plot, c->a.name, "dat");
    if (t->dims == 2)
        fputs(" using 1:(($3 > 0 && $4 == 0) ? $2 : 1/0)", f);
    else
        fputs(" using 1:(($2 > 0 && $3 == 0) ? $2 : 1/0)", f);
    fputs(" with points pt 6 ps 1.5 lc rgb 'black' title 'observed where expected 0'", f);
}

static void plot_script(FILE *f, const cli_app *c, const mcbox_check_table *t,
                        const mcbox_check_result *r)
{
    double top = count_max(t);
    fputs("set terminal pngcairo noenhanced size 1500,480 font ',9'\nset output ", f);
    gp_quoted(f, c->a.plot, c->a.name, "png");
    fprintf(f, "\nset multiplot layout 1,3 title '%s: %s, chi-square %.6g, %d dof, p = %.3g'\n",
            c->a.name, cli_verdict(r), r->statistic, r->dof, r->pvalue);
    fprintf(f, "set xlabel '%s'\nset key bottom right\n", t->xlabel);
    static const char *const titles[] = {"observed counts", "expected counts",
                                         "(observed - expected) / sqrt(expected)"};
    for (int k = 0; k < 3; k++) {
        fprintf(f, "set title '%s'\n", titles[k]);
        if (t->dims == 2) {
            fprintf(f, "set ylabel '%s'\nset xrange [%.17g:%.17g]\nset yrange [%.17g:%.17g]\n",
                    t->ylabel, t->lo[0], t->hi[0], t->lo[1], t->hi[1]);
            if (k == 2)
                fputs("set palette defined (-4 'blue', 0 'white', 4 'red')\nset cbrange [-4:4]\n", f);
            else
                fprintf(f, "set palette defined (0 'white', 1 'dark-blue')\nset cbrange [0:%.17g]\n",
                        top);
            fputs("plot ", f);
            gp_quoted(f, c->a.plot, c->a.name, "dat");
            fprintf(f, " using 1:2:%d with image notitle", k + 3);
        } else {
            if (k < 2)
                fprintf(f, "set yrange [0:%.17g]\n", 1.05 * top);
            else
                fputs("set autoscale y\n", f);
            fputs("plot ", f);
            gp_quoted(f, c->a.plot, c->a.name, "dat");
            fprintf(f, " using 1:%d with steps notitle", k + 2);
        }
        empty_marks(f, c, t);
        fputc('\n', f);
    }
    fputs("unset multiplot\n", f);
}

/* Cell centres in the order of the table (x major), then observed,
 * expected and the residual; a blank line after each x in 2D (gnuplot's
 * grid rows). The residual of a cell expected empty is 0 when it is
 * empty and nan when it holds samples (marked on the picture). */
static bool write_data(const cli_app *c, const mcbox_check_table *t, const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return false;
    fprintf(f, "# %s: chart cells: %s%s%s, observed, expected, (observed - expected) / sqrt(expected)\n",
            c->a.name, t->xlabel, t->dims == 2 ? ", " : "", t->dims == 2 ? t->ylabel : "");
    double dx = (t->hi[0] - t->lo[0]) / t->nx, dy = t->dims == 2 ? (t->hi[1] - t->lo[1]) / t->ny : 0.0;
    for (int i = 0; i < t->nx; i++) {
        for (int j = 0; j < t->ny; j++) {
            size_t k = (size_t)i * (size_t)t->ny + (size_t)j;
            double o = t->observed[k], e = t->expected[k];
            double z = e > 0.0 ? (o - e) / sqrt(e) : (o > 0.0 ? (double)NAN : 0.0);
            fprintf(f, "%.9g ", t->lo[0] + (i + 0.5) * dx);
            if (t->dims == 2)
                fprintf(f, "%.9g ", t->lo[1] + (j + 0.5) * dy);
            fprintf(f, "%.17g %.17g %.9g\n", o, e, z);
        }
        if (t->dims == 2)
            fputc('\n', f);
    }
    for (size_t k = (size_t)t->nx * (size_t)t->ny; k < t->cells; k++)
        fprintf(f, "# atom %zu: observed %.17g expected %.17g\n",
                k - (size_t)t->nx * (size_t)t->ny, t->observed[k], t->expected[k]);
    return fclose(f) == 0;
}

/* gnuplot reads the script on its stdin; its failure is a warning, the
 * verdict stands. */
void cli_plot(const cli_app *c, const mcbox_check_table *t, const mcbox_check_result *r)
{
    char path[4200];
    snprintf(path, sizeof path, "%s/%s.dat", c->a.plot, c->a.name);
    if (!write_data(c, t, path)) {
        fprintf(stderr, "%s: warning: cannot write %s: %s\n", CLI_PROG, path, strerror(errno));
        return;
    }
    int p[2];
    if (pipe(p) != 0)
        return;
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        int null = open("/dev/null", O_WRONLY);
        dup2(p[0], 0);
        dup2(null, 1);
        dup2(null, 2);
        close(p[0]);
        close(p[1]);
        signal(SIGPIPE, SIG_DFL);
        execlp("gnuplot", "gnuplot", (char *)NULL);
        _exit(127);
    }
    close(p[0]);
    FILE *g = pid > 0 ? fdopen(p[1], "w") : NULL;
    if (g) {
        plot_script(g, c, t, r);
        fclose(g);
    } else {
        close(p[1]);
    }
    int ws = 0;
    while (pid > 0 && waitpid(pid, &ws, 0) < 0 && errno == EINTR) {
    }
    if (pid < 0 || !WIFEXITED(ws) || WEXITSTATUS(ws) != 0)
        fprintf(stderr, "%s: warning: gnuplot %s; %s is written, the verdict stands\n", CLI_PROG,
                pid > 0 && WIFEXITED(ws) && WEXITSTATUS(ws) == 127 ? "was not found"
                                                                   : "failed to draw the chart",
                path);
}
