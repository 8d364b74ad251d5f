/* tests/support/negctl.h - the tally of negative controls of one test
 * program.
 *
 * A negative control is a deliberately wrong sampler or pdf that a check of
 * the suite must reject; a check that cannot fail proves nothing. Each
 * program keeps one tally (in its cmocka group state), records every
 * control with the check that was meant to catch it, and at the end prints
 * exactly "negative controls: caught K/M", the line the test runner sums.
 */
#ifndef NEGCTL_H
#define NEGCTL_H

#include <stdbool.h>

typedef struct negctl {
    int ran;    /* controls run */
    int caught; /* of which the intended check rejected */
} negctl;

/* Counts one control and prints "negative control NAME: caught by CHECK"
 * or "... NOT caught by CHECK" on stdout. Returns caught. */
bool negctl_record(negctl *t, const char *name, const char *check, bool caught);

/* Prints "negative controls: caught K/M"; returns 0 when K == M, -1 else
 * (the value a cmocka group teardown returns to fail the group). */
int negctl_report(const negctl *t);

/* cmocka group setup and teardown that keep a negctl as the group state:
 * every test of the group gets it as *state. */
int negctl_group_setup(void **state);
int negctl_group_teardown(void **state);

#endif /* NEGCTL_H */
