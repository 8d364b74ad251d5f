/* mc/sobol_table.h - the generator matrices of the Sobol sequence.
 *
 * Serves this book's #ch-qmc through mc/qmc.h, which is the interface to
 * use; this table is its data.
 *
 * Provenance: Joe and Kuo's direction numbers new-joe-kuo-6.21201 (S. Joe
 * and F. Y. Kuo, "Constructing Sobol sequences with better two-dimensional
 * projections", SIAM J. Sci. Comput. 30, 2008 [@joe-kuo2008]; the file is published at
 * https://web.maths.unsw.edu.au/~fkuo/sobol/), first MC_SOBOL_TABLE_DIMS
 * dimensions, read from the public copy Debian's python3-scipy ships
 * (scipy/stats/_sobol_direction_numbers.npz) and expanded by the
 * Bratley-Fox recurrence into 32 direction numbers per dimension. The
 * table is generated, never edited:
 *     /usr/bin/python3 tools/gen_sobol_table.py > mc/sobol_table.c
 */
#ifndef MC_SOBOL_TABLE_H
#define MC_SOBOL_TABLE_H

#include <stdint.h>

#define MC_SOBOL_TABLE_DIMS 1024

/* mc_sobol_matrix[d][k]: direction number v_{k+1} of dimension d as a
 * 32-bit fraction (column k of the generator matrix, bit 31 = 1/2): point i
 * of dimension d is the XOR of the columns k whose bit k of i is set.
 * Dimension 0 is the identity (van der Corput's sequence). */
extern const uint32_t mc_sobol_matrix[MC_SOBOL_TABLE_DIMS][32];

#endif /* MC_SOBOL_TABLE_H */
