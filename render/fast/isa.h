/* render/fast/isa.h - the instruction set of the fast path, chosen once.
 *
 * The fast path (render/fast/) traces four paths of a row together
 * (chapter 12 of the book, "Speed"): the four-ray hit of a root leaf
 * (hit4.h) and the light densities at four hit points (lights4.h); and
 * it tests a ray traced alone against four quads at once (hit4.h). Each
 * has a portable form, which is the reference renderer lane by lane, and
 * an AVX2 form that computes the same bits; this is the one place that
 * says which of them runs. docs/performance.md gives the measurements
 * that keep the AVX2 forms.
 */
#ifndef RT_FAST_ISA_H
#define RT_FAST_ISA_H

#include <stdbool.h>

#include "render/leaf4.h" /* RT_LANES */

/* Whether this build has the x86 vector code at all: gcc or clang on
 * x86-64. Every file of render/fast/ guards its intrinsics with this one
 * switch. */
#if defined(__x86_64__) && defined(__GNUC__)
#define RT_ISA_X86 1
#else
#define RT_ISA_X86 0
#endif

typedef enum rt_isa {
    RT_ISA_PORTABLE, /* the reference code, one lane after the other */
    RT_ISA_AVX2      /* four lanes in one 256-bit vector */
} rt_isa;

#define RT_ISA_COUNT 2

/* Whether this build and this processor can run isa. */
bool rt_isa_available(rt_isa isa);

/* The instruction set the fast path uses: the last available one of the
 * list above, decided on the first call and the same for the rest of the
 * process; RT_ISA_PORTABLE when the environment variable MCBOX_ISA is
 * "portable" (then no instruction-set code runs: the run mode that the
 * tests compare bit for bit with the default). */
rt_isa rt_isa_best(void);

/* "portable" or "avx2". */
const char *rt_isa_name(rt_isa isa);

#endif /* RT_FAST_ISA_H */
