/* render/names.c - enum values by name. */
#include "render/names.h"

#include <stddef.h>
#include <string.h>

int rt_name_index(const char *const names[], const char *name)
{
    if (!name)
        return -1;
    for (int i = 0; names[i]; i++)
        if (strcmp(name, names[i]) == 0)
            return i;
    return -1;
}
