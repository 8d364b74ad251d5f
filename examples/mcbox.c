/* examples/mcbox.c - one name for mcbox's programs, as git is for its own:
 * `mcbox CMD ARGS...` runs the program mcbox-CMD with ARGS.
 *
 * The program is looked for in the directory of mcbox's own executable
 * (from /proc/self/exe), never on PATH: an installed mcbox runs the
 * mcbox-CMD installed with it, a build tree's mcbox that of the same
 * build. A build tree names the catalog's program plain `warp` (installed
 * as mcbox-warp), so for the commands of the table below whose build-tree
 * name differs, that name is tried second.
 *
 * Build and run:  make all && build/bin/mcbox warp list
 *                 build/bin/mcbox check --exec 'build/bin/warp serve cosine' \
 *                     --domain hemisphere
 */
#define _POSIX_C_SOURCE 200809L /* readlink */

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "examples/common/cli.h"

#define PROG "mcbox"
#define PATH_SIZE 4096

typedef struct command {
    const char *name, *build_name, *summary;
} command;

/* The commands mcbox ships; any other mcbox-CMD beside mcbox runs too. */
static const command COMMANDS[] = {
    {"check", "mcbox-check", "test a sampler (a program, a file of points) against its density"},
    {"warp", "warp", "the sampler catalog: list, sample, pdf, chi2, serve"},
    {"scene", "mcbox-scene", "the conformance scenes as pbrt, Mitsuba, Blender or table files"},
};
#define N_COMMANDS (sizeof COMMANDS / sizeof COMMANDS[0])

static void usage(void)
{
    /* The commands are listed as "COMMAND is one of": each is a program of
     * its own, with its own --help and its own name in its messages. */
    fputs("usage: mcbox COMMAND [ARGS...]\n"
          "Runs the program mcbox-COMMAND installed beside mcbox with ARGS;\n"
          "`mcbox COMMAND --help` shows its options, `man mcbox-COMMAND` its manual.\n"
          "COMMAND is one of:\n",
          stdout);
    for (size_t i = 0; i < N_COMMANDS; i++)
        printf("  %-7s %s\n", COMMANDS[i].name, COMMANDS[i].summary);
    fputs("Options: --help, --version. Bad input: one line on stderr, exit status 2.\n", stdout);
}

/* Whether name can be part of a file name beside mcbox: lowercase
 * letters, digits and '-' (no '/', no "..": nothing outside the directory). */
static int valid_name(const char *name)
{
    if (!*name || *name == '-' || strlen(name) > 64)
        return 0;
    for (const char *p = name; *p; p++)
        if (!((*p >= 'a' && *p <= 'z') || (*p >= '0' && *p <= '9') || *p == '-'))
            return 0;
    return 1;
}

/* The directory of the running executable, with its trailing '/', into dir. */
static void self_dir(char *dir, size_t size)
{
    ssize_t n = readlink("/proc/self/exe", dir, size - 1);
    if (n <= 0 || (size_t)n >= size - 1)
        app_fail(PROG, "cannot find its own executable (/proc/self/exe): %s",
                 n < 0 ? strerror(errno) : "path too long");
    dir[n] = '\0';
    char *slash = strrchr(dir, '/');
    if (!slash)
        app_fail(PROG, "its own executable '%s' has no directory", dir);
    slash[1] = '\0';
}

/* The program for cmd beside mcbox (into path), or false when there is none. */
static int find_program(const char *dir, const char *cmd, char *path, size_t size)
{
    const char *names[2] = {NULL, NULL};
    char prefixed[80];
    snprintf(prefixed, sizeof prefixed, "mcbox-%s", cmd);
    names[0] = prefixed;
    for (size_t i = 0; i < N_COMMANDS; i++)
        if (strcmp(cmd, COMMANDS[i].name) == 0)
            names[1] = COMMANDS[i].build_name;
    for (int k = 0; k < 2; k++) {
        if (!names[k] || (size_t)snprintf(path, size, "%s%s", dir, names[k]) >= size)
            continue;
        if (access(path, X_OK) == 0)
            return 1;
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2)
        app_fail(PROG, "no command (mcbox --help lists them)");
    const char *cmd = argv[1];
    if (strcmp(cmd, "--help") == 0 || strcmp(cmd, "-h") == 0) {
        usage();
        return 0;
    }
    if (strcmp(cmd, "--version") == 0) {
        printf("mcbox (mcbox) %s\n", APP_VERSION);
        return 0;
    }
    if (cmd[0] == '-')
        app_fail(PROG, "unknown option '%s' (a command comes first; see mcbox --help)", cmd);
    if (!valid_name(cmd))
        app_fail(PROG, "unknown command '%.80s' (mcbox --help lists them)", cmd);
    static char dir[PATH_SIZE], path[PATH_SIZE];
    self_dir(dir, sizeof dir);
    if (!find_program(dir, cmd, path, sizeof path))
        app_fail(PROG, "unknown command '%s': no program mcbox-%s in %s (mcbox --help lists them)",
                 cmd, cmd, dir);
    /* The program sees its own name as argv[0], so its messages name it. */
    argv[1] = path;
    fflush(stdout);
    execv(path, argv + 1);
    app_fail(PROG, "cannot run %s: %s", path, strerror(errno));
}
