/* check/stream.h - inside mcbox only: the generator behind a
 * mcbox_stream, so that the catalog's samplers that draw from a PCG32
 * stream (rejection, the pdf objects) can be run through the public check
 * with the very uniforms the suite's own harness gives them. Not installed.
 */
#ifndef CHK_STREAM_H
#define CHK_STREAM_H

#include "check/check.h"
#include "mc/rng.h"

/* The PCG32 generator of s (valid while the check that passed s runs). */
mc_rng *chk_stream_rng(mcbox_stream *s);

#endif /* CHK_STREAM_H */
