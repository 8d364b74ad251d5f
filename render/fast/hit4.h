/* render/fast/hit4.h - the four-wide tests of a root leaf's lanes
 * (render/leaf4.h) in vector instructions.
 *
 * Each test computes, lane by lane, exactly what the reference's quad and
 * sphere tests compute (hit4.c says why the bits are the same), so a scene
 * that uses them renders the same image as one that does not.
 */
#ifndef RT_FAST_HIT4_H
#define RT_FAST_HIT4_H

#include "render/fast/isa.h"
#include "render/leaf4.h"

/* The tests in instruction set isa, which the processor must have: with
 * RT_ISA_AVX2, both vector tests; with RT_ISA_PORTABLE, none (the BVH
 * alone). */
rt_leaf_tests rt_fast_leaf_tests(rt_isa isa);

#endif /* RT_FAST_HIT4_H */
