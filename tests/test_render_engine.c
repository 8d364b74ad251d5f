/* tests/test_render_engine.c - the one door to the fast path
 * (render/engine.h): with MCBOX_ISA=portable in the environment before
 * the first render, the engine is the portable one, the instruction set
 * is the portable one and the named scenes carry no four-wide leaf tests,
 * so no instruction-set code can run; tests/test_render_cli.c shows that
 * this mode writes the default engine's bytes. Each test binary is its own
 * process, so the variable is set in main, before anything asks. */
#define _POSIX_C_SOURCE 200809L

#include "tests/support/mc_test.h"

#include <stdlib.h>
#include <string.h>

#include "render/engine.h"
#include "render/fast/isa.h"
#include "render/render.h"
#include "render/scenes.h"

static void test_portable_mode_runs_no_isa_code(void **state)
{
    (void)state;
    const rt_engine *e = rt_engine_get();
    assert_string_equal(e->isa, "portable");
    assert_true(rt_isa_best() == RT_ISA_PORTABLE);
    assert_null(e->leaf.hit4);
    assert_null(e->leaf.hit1);
    assert_non_null(e->row4);
    /* The same engine on every call. */
    assert_ptr_equal(rt_engine_get(), e);
    /* A render through the door in this mode, for good measure: the book
     * scene, every pixel sampled. */
    rt_camera_params cp;
    rt_scene *s = rt_scene_named("book", &cp);
    assert_non_null(s);
    rt_image *img = rt_image_create(8, 8);
    assert_non_null(img);
    rt_render_job job = rt_render_job_default(s, rt_camera_make(cp, 8, 8));
    job.spp = 2;
    assert_int_equal(rt_render(&job, img, NULL), 0);
    for (int i = 0; i < 64; i++)
        assert_true(img->px[i].n + img->px[i].dropped == 2);
    rt_image_destroy(img);
    rt_scene_destroy(s);
}

int main(void)
{
    if (setenv("MCBOX_ISA", "portable", 1) != 0)
        return 1;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_portable_mode_runs_no_isa_code),
    };
    mc_test_select();
    return cmocka_run_group_tests_name("test_render_engine", tests, NULL, NULL);
}
