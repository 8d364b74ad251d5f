/* tests/mpi/rowcost.c - the cost of each image row of the book's Cornell
 * box, for docs/scaling.md: how evenly the row interleaving of an MPI run
 * (rank r of K takes rows r, r + K, ...) shares the work.
 *
 * Build: make MPI=1 build/mpi/tests-mpi/rowcost; run:
 *   build/mpi/tests-mpi/rowcost [width] [spp]     (default 600 4)
 * Renders each row alone (rt_render_rows with step = height) and prints
 * "row,segments" lines: the ray segments traced, which the render time
 * follows. Not a test: a measurement.
 */
#include <stdio.h>
#include <stdlib.h>

#include "render/render.h"
#include "render/scenes.h"

int main(int argc, char **argv)
{
    int width = argc > 1 ? atoi(argv[1]) : 600;
    uint64_t spp = argc > 2 ? (uint64_t)atoll(argv[2]) : 4;
    if (width < 1 || width > 65536 || spp < 1) {
        fprintf(stderr, "rowcost: usage: rowcost [width] [spp]\n");
        return 2;
    }
    rt_camera_params cp;
    rt_scene *scene = rt_scene_named("book", &cp);
    rt_image *img = rt_image_create(width, width);
    if (!scene || !img) {
        fprintf(stderr, "rowcost: out of memory\n");
        return 1;
    }
    rt_render_job job = rt_render_job_default(scene, rt_camera_make(cp, width, width));
    job.spp = spp;
    printf("row,segments\n");
    for (int y = 0; y < width; y++) {
        rt_render_stats st;
        if (rt_render_rows(&job, img, y, width, &st) != 0) {
            fprintf(stderr, "rowcost: render failed\n");
            return 1;
        }
        printf("%d,%llu\n", y, (unsigned long long)st.segments);
    }
    rt_image_destroy(img);
    rt_scene_destroy(scene);
    return 0;
}
