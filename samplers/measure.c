/* samplers/measure.c - area density to solid-angle density. */
#include "samplers/measure.h"

#include <math.h>

/* BEGIN SNIPPET area_to_solid_angle */
double smp_area_to_solid_angle(double pdf_area, double dist_sq, double cos_light)
{
    /* d omega = |cos theta_light| dA / d^2, so p_omega = p_A dA / d omega. */
    double c = fabs(cos_light);
    return c > 0.0 ? pdf_area * dist_sq / c : 0.0;
}
/* END SNIPPET area_to_solid_angle */
