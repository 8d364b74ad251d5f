/* mc/gsl_quiet.h - GSL's aborting error handler, switched off once.
 *
 * GSL's default handler aborts the process on an error such as a
 * quadrature that misses its tolerance; a library must return a status
 * instead. The handler is one process-wide variable, so switching it off
 * from every OpenMP thread would be a data race. Every mc/ entry point that
 * reaches GSL (mc_quad_create, mc_chi2_pvalue) calls mc_gsl_quiet first; a
 * C11 call_once makes the single write happen before any of those callers
 * continues. Serves this book's #ch-integration and the chi-square tests
 * of its #ch-tests, through mc/quad.h and mc/chi2.h.
 */
#ifndef MC_GSL_QUIET_H
#define MC_GSL_QUIET_H

/* Calls gsl_set_error_handler_off() exactly once per process. Safe from
 * any thread, any number of times. */
void mc_gsl_quiet(void);

#endif /* MC_GSL_QUIET_H */
