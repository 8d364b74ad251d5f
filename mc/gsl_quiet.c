/* mc/gsl_quiet.c - one thread-safe switch-off of GSL's error handler. */
#include "mc/gsl_quiet.h"

#include <threads.h>

#include <gsl/gsl_errno.h>

static void switch_off(void)
{
    gsl_set_error_handler_off();
}

void mc_gsl_quiet(void)
{
    /* call_once returns in every thread only after switch_off has finished
     * in one of them, so no thread can read the handler while it changes. */
    static once_flag once = ONCE_FLAG_INIT;
    call_once(&once, switch_off);
}
