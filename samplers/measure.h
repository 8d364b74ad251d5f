/* samplers/measure.h - changing the measure of a density.
 *
 * Shirley, "Ray Tracing: The Rest of Your Life" (v1.123), chapter 7
 * "Sampling Lights Directly", and the blog post on light pdfs that derives
 * pdf = distance^2 / (A cos) for a point drawn uniformly on an area light
 * (this book's #ch-lights): a point q drawn on a light with density p_A per
 * unit AREA, seen from p, gives the direction (q - p) / |q - p| with
 * density per unit SOLID ANGLE p_omega = p_A |q - p|^2 / |cos theta_light|,
 * because a patch dA at distance d tilted by theta_light subtends
 * d omega = |cos theta_light| dA / d^2. For a uniform light of area A that
 * is d^2 / (A |cos theta_light|).
 */
#ifndef SMP_MEASURE_H
#define SMP_MEASURE_H

/* pdf_area * dist_sq / |cos_light|: the density per unit solid angle of a
 * direction to a point sampled with density pdf_area per unit area at
 * squared distance dist_sq (> 0), where cos_light is the cosine between the
 * light's normal and the direction. 0 when cos_light == 0 (a light seen
 * edge-on subtends no solid angle) instead of the infinity or NaN of the
 * plain quotient. */
double smp_area_to_solid_angle(double pdf_area, double dist_sq, double cos_light);

#endif /* SMP_MEASURE_H */
