/* render/fast/isa.c - the one decision of the instruction set. */
#include "render/fast/isa.h"

#include <stdlib.h>
#include <string.h>
#include <threads.h>

bool rt_isa_available(rt_isa isa)
{
    switch (isa) {
    case RT_ISA_PORTABLE:
        return true;
    case RT_ISA_AVX2:
#if RT_ISA_X86
        return __builtin_cpu_supports("avx2");
#else
        return false;
#endif
    }
    return false;
}

/* Written once, by call_once, before any read: every later call, from
 * any thread, sees the same choice. */
static rt_isa chosen;
static once_flag choose_once = ONCE_FLAG_INIT;

static void choose(void)
{
    const char *want = getenv("MCBOX_ISA");
    bool portable = want && strcmp(want, "portable") == 0;
    chosen = !portable && rt_isa_available(RT_ISA_AVX2) ? RT_ISA_AVX2 : RT_ISA_PORTABLE;
}

rt_isa rt_isa_best(void)
{
    call_once(&choose_once, choose);
    return chosen;
}

const char *rt_isa_name(rt_isa isa)
{
    return isa == RT_ISA_AVX2 ? "avx2" : "portable";
}
