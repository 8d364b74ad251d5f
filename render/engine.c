/* render/engine.c - the engine of this process, from render/fast/. */
#include "render/engine.h"

#include <threads.h>

#include "render/fast/hit4.h"
#include "render/fast/isa.h"
#include "render/fast/rows.h"

/* Written once, by call_once, before any read. */
static rt_engine engine;
static once_flag engine_once = ONCE_FLAG_INIT;

static void choose(void)
{
    rt_isa isa = rt_isa_best();
    engine = (rt_engine){rt_isa_name(isa), rt_fast_leaf_tests(isa), rt_fast_render_row};
}

const rt_engine *rt_engine_get(void)
{
    call_once(&engine_once, choose);
    return &engine;
}
