/* mc/vec2.h - the 2-vector value type: points of the unit square, the disc
 * and the triangle, and the (u1, u2) pairs that warps consume and their
 * inverses return. Passed by value; static inline. */
#ifndef MC_VEC2_H
#define MC_VEC2_H

typedef struct vec2 {
    double x, y;
} vec2;

/* The vector (x, y). */
static inline vec2 vec2_make(double x, double y) { vec2 v = {x, y}; return v; }

#endif /* MC_VEC2_H */
