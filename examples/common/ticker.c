/* examples/common/ticker.c - the progress line of ticker.h. */
/* clock_gettime, fileno, isatty and the pthread calls are POSIX, not C17. */
#define _POSIX_C_SOURCE 200809L
#include "examples/common/ticker.h"

#include <pthread.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

/* The thread and the exit handler that stops it share this state: one line
 * per process, so it lives here rather than with a caller that returns
 * long before the line ends. */
static struct {
    pthread_mutex_t lock;
    pthread_cond_t wake;
    pthread_t thread;
    bool running, stop;
    const char *prog;
    double estimate;
    struct timespec t0;
} ticker = {.lock = PTHREAD_MUTEX_INITIALIZER, .wake = PTHREAD_COND_INITIALIZER};

static double since(const struct timespec *t0)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - t0->tv_sec) + 1e-9 * (double)(now.tv_nsec - t0->tv_nsec);
}

/* Seconds below two minutes, minutes below two hours, then hours. */
static void duration(double s, char *buf, size_t n)
{
    if (s < 120.0)
        snprintf(buf, n, "%.0f s", s);
    else if (s < 7200.0)
        snprintf(buf, n, "%.1f min", s / 60.0);
    else
        snprintf(buf, n, "%.1f h", s / 3600.0);
}

static void *tick(void *arg)
{
    (void)arg;
    pthread_mutex_lock(&ticker.lock);
    while (!ticker.stop) {
        struct timespec until;
        clock_gettime(CLOCK_REALTIME, &until);
        until.tv_sec += 1;
        pthread_cond_timedwait(&ticker.wake, &ticker.lock, &until);
        if (ticker.stop)
            break;
        char done[32], total[32];
        duration(since(&ticker.t0), done, sizeof done);
        duration(ticker.estimate, total, sizeof total);
        /* Drawn from the start of the line, the rest of it erased, and the
         * cursor sent back to the start: a table row printed on stdout
         * meanwhile writes over the progress line instead of after it. */
        fprintf(stderr, "\r%s: %s of about %s\033[K\r", ticker.prog, done, total);
        fflush(stderr);
    }
    pthread_mutex_unlock(&ticker.lock);
    return NULL;
}

/* At exit: stop the thread and clear its line, so that what the program
 * printed last is not followed by a stale progress line. */
static void ticker_end(void)
{
    pthread_mutex_lock(&ticker.lock);
    ticker.stop = true;
    pthread_cond_signal(&ticker.wake);
    pthread_mutex_unlock(&ticker.lock);
    pthread_join(ticker.thread, NULL);
    fputs("\r\033[K", stderr);
    fflush(stderr);
}

void app_ticker_start(const char *prog, double seconds)
{
    if (ticker.running || !isatty(fileno(stderr)))
        return;
    ticker.prog = prog;
    ticker.estimate = seconds;
    clock_gettime(CLOCK_MONOTONIC, &ticker.t0);
    if (pthread_create(&ticker.thread, NULL, tick, NULL) != 0)
        return; /* no line, the run itself goes on */
    ticker.running = true;
    atexit(ticker_end);
}
