/* render/engine.h - the one door to render/fast/: which code traces the
 * scene's rays and the book integrator's rows.
 *
 * The reference renderer (render/) needs nothing from render/fast/; the
 * fast path computes the same bits sooner, with the processor's vector
 * instructions (render/fast/isa.h chooses them once per process). This is
 * the only part of the renderer that knows the fast path exists: the
 * driver (render/drive.c) takes its row kernel from here, and the named
 * scenes (render/scenes.c) their leaf tests. With MCBOX_ISA=portable in
 * the environment the engine is the portable one and no instruction-set
 * code runs; tests/test_render_cli.c renders every strategy both ways and
 * compares the files byte for byte.
 */
#ifndef RT_ENGINE_H
#define RT_ENGINE_H

#include "render/leaf4.h"

struct rt_row;
struct rt_row_counts;

typedef struct rt_engine {
    const char *isa;    /* "avx2" or "portable" */
    rt_leaf_tests leaf; /* the four-wide tests of a root leaf (render/leaf4.h) */
    /* The row kernel of the book's integrator, four paths at a time
     * (render/row.h): rt_row_reference's pixels, bit for bit. */
    struct rt_row_counts (*row4)(const struct rt_row *r);
} rt_engine;

/* The engine of this process, the same on every call. */
const rt_engine *rt_engine_get(void);

#endif /* RT_ENGINE_H */
