/* lab/gsl_quiet.c - mc_gsl_quiet (mc/gsl_quiet.h) for the lab's module.
 * The native one guards the switch with C11's call_once, which wasi-libc
 * does not have; the module runs on one thread, where a flag is enough. */
#include "mc/gsl_quiet.h"

#include <stdbool.h>

#include <gsl/gsl_errno.h>

void mc_gsl_quiet(void)
{
    static bool done;
    if (!done) {
        gsl_set_error_handler_off();
        done = true;
    }
}
