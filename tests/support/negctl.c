/* tests/support/negctl.c - negative-control tally and its report line. */
#include "tests/support/negctl.h"

#include <stdio.h>
#include <stdlib.h>

/* BEGIN SNIPPET negctl_record */
bool negctl_record(negctl *t, const char *name, const char *check, bool caught)
{
    t->ran++;
    if (caught)
        t->caught++;
    printf("negative control %s: %s by %s\n", name, caught ? "caught" : "NOT caught", check);
    return caught;
}

int negctl_report(const negctl *t)
{
    printf("negative controls: caught %d/%d\n", t->caught, t->ran);
    fflush(stdout);
    return t->caught == t->ran ? 0 : -1;
}
/* END SNIPPET negctl_record */

int negctl_group_setup(void **state)
{
    negctl *t = calloc(1, sizeof *t);
    *state = t;
    return t ? 0 : -1;
}

int negctl_group_teardown(void **state)
{
    negctl *t = *state;
    int rc = t ? negctl_report(t) : -1;
    free(t);
    return rc;
}
