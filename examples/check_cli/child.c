/* examples/check_cli/child.c - the program behind --exec or --pdf-exec:
 * started in its own process group, fed and read over pipes with every wait
 * bounded by --timeout, killed and reaped when it breaks the protocol. */
#define _POSIX_C_SOURCE 200809L /* fork, poll, kill, waitpid, strsignal */

#include "examples/check_cli/check_cli.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <poll.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

double cli_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Keeps the end of the child's stderr; false at its EOF. */
static bool read_stderr(cli_child *ch)
{
    char buf[4096];
    ssize_t k = read(ch->err, buf, sizeof buf);
    if (k < 0 && (errno == EINTR || errno == EAGAIN))
        return true;
    if (k <= 0)
        return false;
    size_t m = (size_t)k;
    if (m >= CLI_TAIL) {
        memcpy(ch->tail, buf + m - CLI_TAIL, CLI_TAIL);
        ch->tail_len = CLI_TAIL;
    } else {
        size_t keep = ch->tail_len + m > CLI_TAIL ? CLI_TAIL - m : ch->tail_len;
        memmove(ch->tail, ch->tail + ch->tail_len - keep, keep);
        memcpy(ch->tail + keep, buf, m);
        ch->tail_len = keep + m;
    }
    return true;
}

/* The last non-empty line of the child's stderr, printable, into buf. */
static void stderr_line(const cli_child *ch, char *buf, size_t size)
{
    size_t end = ch->tail_len;
    while (end > 0 && strchr("\n\r ", ch->tail[end - 1]))
        end--;
    size_t start = end;
    while (start > 0 && ch->tail[start - 1] != '\n')
        start--;
    size_t k = 0;
    for (size_t i = start; i < end && k + 1 < size && k < 200; i++) {
        unsigned char b = (unsigned char)ch->tail[i];
        buf[k++] = b >= 0x20 && b < 0x7f ? (char)b : '?';
    }
    buf[k] = '\0';
}

/* Waits up to `seconds` for the child to end; true when it did. */
static bool reap_within(cli_child *ch, double seconds)
{
    double end = cli_now() + seconds;
    while (!ch->reaped) {
        pid_t r = waitpid(ch->pid, &ch->status, WNOHANG);
        if (r == ch->pid || (r < 0 && errno != EINTR)) {
            ch->reaped = true;
            break;
        }
        if (cli_now() >= end)
            return false;
        struct timespec ts = {0, 5000000};
        nanosleep(&ts, NULL);
    }
    return true;
}

/* Kills the child's process group (a shell's children too) and reaps it. */
static void kill_and_reap(cli_child *ch)
{
    kill(-ch->pid, SIGKILL);
    kill(ch->pid, SIGKILL);
    while (!ch->reaped && waitpid(ch->pid, &ch->status, 0) < 0 && errno == EINTR) {
    }
    ch->reaped = true;
}

static void describe_status(const cli_child *ch, char *buf, size_t size)
{
    int st = ch->status;
    if (WIFSIGNALED(st))
        snprintf(buf, size, "; it was killed by signal %d (%s)", WTERMSIG(st), strsignal(WTERMSIG(st)));
    else if (WIFEXITED(st) && WEXITSTATUS(st) > 128 && WEXITSTATUS(st) < 160)
        snprintf(buf, size, "; it exited with status %d (a shell's: its command was killed by "
                 "signal %d, %s)", WEXITSTATUS(st), WEXITSTATUS(st) - 128,
                 strsignal(WEXITSTATUS(st) - 128));
    else if (WIFEXITED(st) && WEXITSTATUS(st) != 0)
        snprintf(buf, size, "; it exited with status %d", WEXITSTATUS(st));
    else
        buf[0] = '\0';
}

_Noreturn void cli_child_fail(cli_app *c, double grace, const char *fmt, ...)
{
    cli_child *ch = &c->ch;
    char what[400], status[128] = "", err_line[220] = "";
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    bool ended = reap_within(ch, grace);
    if (ended)
        describe_status(ch, status, sizeof status);
    kill_and_reap(ch); /* and what it left running in its group */
    if (ch->err >= 0) {
        fcntl(ch->err, F_SETFL, O_NONBLOCK);
        for (int k = 0; k < 64 && read_stderr(ch); k++) {
        }
    }
    stderr_line(ch, err_line, sizeof err_line);
    c->have_child = false;
    cli_fail("'%s': %s: %s%s%s%s%s", ch->cmd, c->where, what, status,
             ended ? "" : "; it was killed", err_line[0] ? "; its stderr: " : "", err_line);
}

static void set_cloexec_nonblock(int fd)
{
    fcntl(fd, F_SETFD, FD_CLOEXEC);
    fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
}

void cli_child_start(cli_app *c, const char *cmd)
{
    cli_child *ch = &c->ch;
    memset(ch, 0, sizeof *ch);
    ch->cmd = cmd;
    int pin[2], pout[2], perr[2];
    if (pipe(pin) || pipe(pout) || pipe(perr))
        cli_fail("cannot make pipes for '%s': %s", cmd, strerror(errno));
    fflush(NULL);
    pid_t pid = fork();
    if (pid < 0)
        cli_fail("cannot start '%s': %s", cmd, strerror(errno));
    if (pid == 0) {
        /* Async-signal-safe calls only until exec: the parent may hold
         * OpenMP threads. SIGPIPE back to its default, which exec would
         * otherwise keep ignored. */
        setpgid(0, 0);
        signal(SIGPIPE, SIG_DFL);
        dup2(pin[0], 0);
        dup2(pout[1], 1);
        dup2(perr[1], 2);
        int fds[6] = {pin[0], pin[1], pout[0], pout[1], perr[0], perr[1]};
        for (int k = 0; k < 6; k++)
            if (fds[k] > 2)
                close(fds[k]);
        execl("/bin/sh", "sh", "-c", cmd, (char *)NULL);
        _exit(127);
    }
    setpgid(pid, pid); /* also here: no race with the kill of a failure */
    close(pin[0]);
    close(pout[1]);
    close(perr[1]);
    ch->pid = pid, ch->in = pin[1], ch->out = pout[0], ch->err = perr[0];
    set_cloexec_nonblock(ch->in);
    set_cloexec_nonblock(ch->out);
    set_cloexec_nonblock(ch->err);
    c->have_child = true;
}

/* What a program that never answers its first sample batch was sent: the
 * usual cause is a count of uniforms it does not expect, which leaves it
 * waiting for lines that never come. */
static void first_batch_hint(const cli_app *c, char *buf, size_t size)
{
    int nu = c->s.uniforms;
    const char *from = c->uniforms_from_row ? ", the catalog row's own count" : "";
    if (nu == 0)
        snprintf(buf, size, "; it was sent 'draw K' (UNIFORMS 0 in hello%s): a program that maps "
                 "uniforms needs --uniforms K", from);
    else
        snprintf(buf, size, "; it was sent 'sample K' with %d uniform%s per line (UNIFORMS %d in "
                 "hello%s): a program that takes another count needs --uniforms K, one that draws "
                 "its own --uniforms 0", nu, nu > 1 ? "s" : "", nu, from);
}

/* Moves the bytes read so far into answer lines; returns the count of
 * lines complete. */
static size_t take_lines(cli_app *c, size_t got, size_t k, cli_answer_fn fn)
{
    cli_child *ch = &c->ch;
    char err[300];
    while (got < k && ch->rpos < ch->rlen) {
        char b = ch->rbuf[ch->rpos++];
        if (b != '\n') {
            if (ch->line_len == APP_PROTO_MAX_LINE)
                cli_child_fail(c, 0.0, "answer %zu is longer than %d bytes (garbage, not numbers)",
                               got + 1, APP_PROTO_MAX_LINE);
            ch->line[ch->line_len++] = b;
            continue;
        }
        if (!fn(c, got, ch->line, ch->line_len, err, sizeof err))
            cli_child_fail(c, 0.0, "answer %zu of %zu: %s", got + 1, k, err);
        got++;
        ch->line_len = 0;
    }
    if (got == k && ch->rpos < ch->rlen)
        cli_child_fail(c, 0.0, "more output than the %zu answer line%s asked for", k, k > 1 ? "s" : "");
    return got;
}

/* A program that closed a pipe is ending: up to this many seconds for its
 * own exit status (a busy machine reaps a shell's exit slowly), which the
 * message then names; it costs nothing when the program ends at once. */
#define ENDING_GRACE 2.0

/* Writes and reads at once: a program may answer line by line while the
 * batch is still being written, and polling both directions keeps either
 * pipe from filling up and blocking the two processes. */
void cli_exchange(cli_app *c, const char *text, size_t n, size_t k, cli_answer_fn fn)
{
    cli_child *ch = &c->ch;
    size_t written = 0, got = 0;
    double deadline = cli_now() + c->a.timeout;
    /* Output before the command is sent is more than the previous command
     * asked for (what comes later is caught by the answers' own format, or
     * at the end of the run). */
    struct pollfd early = {ch->out, POLLIN, 0};
    if (c->batch > 0 && poll(&early, 1, 0) > 0 && (early.revents & POLLIN)) {
        ssize_t m = read(ch->out, ch->rbuf, sizeof ch->rbuf);
        if (m > 0)
            cli_child_fail(c, 0.0, "before it, more output than the previous command asked for");
        if (m == 0)
            cli_child_fail(c, ENDING_GRACE, "it closed its stdout");
    }
    for (;;) {
        got = take_lines(c, got, k, fn);
        if (written == n && got == k)
            break;
        struct pollfd p[3] = {{written < n ? ch->in : -1, POLLOUT, 0},
                              {ch->out, POLLIN, 0},
                              {ch->err, POLLIN, 0}};
        double left = deadline - cli_now();
        if (left <= 0.0) {
            char hint[300] = "";
            bool sampling = strstr(c->where, "(sample ") || strstr(c->where, "(draw ");
            if (sampling && c->sample_batches == 1 && got == 0)
                first_batch_hint(c, hint, sizeof hint);
            cli_child_fail(c, 0.0, "no %s within the %g s of --timeout (%zu of %zu answer%s read)%s",
                           written < n ? "progress reading our input" : "answer", c->a.timeout, got,
                           k, k > 1 ? "s" : "", hint);
        }
        int r = poll(p, 3, (int)fmin(left * 1000.0 + 1.0, 1e9));
        if (r < 0 && errno != EINTR)
            cli_child_fail(c, 0.0, "poll: %s", strerror(errno));
        if (r <= 0)
            continue;
        if (p[0].revents & (POLLOUT | POLLERR | POLLHUP)) {
            ssize_t w = write(ch->in, text + written, n - written);
            if (w > 0)
                written += (size_t)w, deadline = cli_now() + c->a.timeout;
            else if (w < 0 && errno != EAGAIN && errno != EINTR)
                cli_child_fail(c, ENDING_GRACE, "it closed its stdin after %zu of %zu answers (%s)", got, k,
                               strerror(errno));
        }
        if ((p[2].revents & (POLLIN | POLLHUP | POLLERR)) && !read_stderr(ch))
            close(ch->err), ch->err = -1;
        if (p[1].revents & (POLLIN | POLLHUP | POLLERR)) {
            ssize_t m = read(ch->out, ch->rbuf, sizeof ch->rbuf);
            if (m == 0)
                cli_child_fail(c, ENDING_GRACE, "it closed its stdout after %zu of %zu answer%s", got, k,
                               k > 1 ? "s" : "");
            if (m > 0)
                ch->rpos = 0, ch->rlen = (size_t)m, deadline = cli_now() + c->a.timeout;
        }
    }
}

/* Room for a command and k lines of m numbers. */
static char *text_room(cli_app *c, size_t k, int m)
{
    size_t need = 64 + k * ((size_t)m * 26 + 1);
    if (need > c->text_cap) {
        free(c->text);
        c->text = malloc(need);
        c->text_cap = c->text ? need : 0;
        if (!c->text)
            cli_child_fail(c, 0.0, "out of memory");
    }
    return c->text;
}

size_t cli_format_batch(cli_app *c, app_proto_cmd cmd, const double *v, size_t k, int m,
                        size_t stride)
{
    char *t = text_room(c, k, m);
    size_t cap = c->text_cap, used = app_proto_format_command(t, cap, cmd, k);
    for (size_t i = 0; m > 0 && i < k; i++)
        used += app_proto_format_numbers(t + used, cap - used, v + i * stride, m);
    c->batch++;
    c->sample_batches += cmd == APP_PROTO_SAMPLE || cmd == APP_PROTO_DRAW;
    snprintf(c->where, sizeof c->where, "command %llu (%s %zu)", (unsigned long long)c->batch,
             app_proto_cmd_name(cmd), k);
    return used;
}

/* Reads to EOF after the last command: the program must exit 0 without
 * another line. A verdict already reached is not lost to a program that
 * is slow to exit (a server that ignores EOF, a long teardown): past
 * --timeout it is killed and the verdict stands, with a note. */
void cli_child_end(cli_app *c, bool verdict_reached)
{
    cli_child *ch = &c->ch;
    snprintf(c->where, sizeof c->where, "after the last command (end of its input)");
    close(ch->in);
    ch->in = -1;
    double deadline = cli_now() + c->a.timeout;
    bool late = false;
    while (!late && (ch->out >= 0 || ch->err >= 0)) {
        struct pollfd p[2] = {{ch->out, POLLIN, 0}, {ch->err, POLLIN, 0}};
        double left = deadline - cli_now();
        if (left <= 0.0 && !verdict_reached)
            cli_child_fail(c, 0.0, "it did not exit within the %g s of --timeout", c->a.timeout);
        late = left <= 0.0;
        if (late || poll(p, 2, (int)(left * 1000.0 + 1.0)) <= 0)
            continue;
        if (p[1].revents && !read_stderr(ch))
            close(ch->err), ch->err = -1;
        if (p[0].revents) {
            ssize_t m = read(ch->out, ch->rbuf, sizeof ch->rbuf);
            if (m > 0)
                cli_child_fail(c, 0.0, "it wrote %zd byte%s more than the answers asked for", m,
                               m > 1 ? "s" : "");
            if (m == 0)
                close(ch->out), ch->out = -1;
        }
    }
    if (!late && !reap_within(ch, fmax(0.0, deadline - cli_now()))) {
        if (!verdict_reached)
            cli_child_fail(c, 0.0, "it did not exit within the %g s of --timeout", c->a.timeout);
        late = true;
    }
    if (late) {
        kill_and_reap(ch);
        snprintf(c->note, sizeof c->note, "'%s' had not exited %g s (--timeout) after the end of "
                 "its input: it was killed; the verdict, reached before, stands", ch->cmd,
                 c->a.timeout);
        fprintf(stderr, "%s: note: %s\n", CLI_PROG, c->note);
    } else if (!WIFEXITED(ch->status) || WEXITSTATUS(ch->status) != 0) {
        cli_child_fail(c, 0.0, "it did not exit with status 0");
    }
    if (ch->out >= 0)
        close(ch->out), ch->out = -1;
    if (ch->err >= 0)
        close(ch->err), ch->err = -1;
    c->have_child = false;
}
