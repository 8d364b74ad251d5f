/* render/names.h - enum values by name, for the options of the Cornell
 * box program (this book's #ch-cornell).
 *
 * The renderer's choices (strategy, sampler, gamma, scene) each have a
 * table of names in enum order, NULL-terminated so that the program's
 * option tables can list them. One lookup serves all of them, so that a
 * name and its value cannot drift apart in a hand-written parser.
 */
#ifndef RT_NAMES_H
#define RT_NAMES_H

/* The index of `name` in `names`, a NULL-terminated table of distinct
 * strings (compared exactly, case included), or -1 when it is not there
 * or `name` is NULL. The terminator is the table's length: every name
 * table of render/ has one, for the option tables. */
int rt_name_index(const char *const names[], const char *name);

#endif /* RT_NAMES_H */
