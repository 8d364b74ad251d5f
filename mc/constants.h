/* mc/constants.h - mathematical constants used across mcbox.
 *
 * ISO C has no M_PI, so the project names its own constants with the MC_
 * prefix. Values are the correctly rounded doubles of the exact numbers.
 * Serves every chapter of this book; first used in its #ch-pi, where pi is
 * the quantity being estimated.
 */
#ifndef MC_CONSTANTS_H
#define MC_CONSTANTS_H

#define MC_PI        3.14159265358979323846264338327950288 /* pi */
#define MC_2PI       6.28318530717958647692528676655900577 /* 2 pi: azimuth range */
#define MC_4PI       12.5663706143591729538505735331180115 /* 4 pi: solid angle of the sphere */
#define MC_PI_2      1.57079632679489661923132169163975144 /* pi / 2 */
#define MC_PI_4      0.78539816339744830961566084581987572 /* pi / 4: area of the quarter disc */
#define MC_INV_PI    0.31830988618379067153776752674502872 /* 1 / pi: Lambertian BRDF rho / pi */
#define MC_INV_2PI   0.15915494309189533576888376337251436 /* 1 / (2 pi): uniform hemisphere pdf */
#define MC_INV_4PI   0.07957747154594766788444188168625718 /* 1 / (4 pi): uniform sphere pdf */
#define MC_LN2       0.69314718055994530941723212145817657 /* ln 2 */
#define MC_SQRT2     1.41421356237309504880168872420969808 /* sqrt 2 */

#endif /* MC_CONSTANTS_H */
