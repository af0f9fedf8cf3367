/* The Bagnold profile of a steady mu(I) layer on an incline; see gf_mui_oracles.h. */
#include <math.h>

#include "continuum/gf_mui_oracles.h"

double gf_bagnold_theta_start(const gf_mui_params *law)
{
    return atan(law->mu_s);
}

double gf_bagnold_theta_stop(const gf_mui_params *law)
{
    return atan(law->mu_2);
}

double gf_bagnold_inertial_number(const gf_bagnold *b)
{
    return gf_mui_inertial_number(&b->law, tan(b->theta_rad));
}

/* (2/3) I sqrt(phi g cos theta)/d: u = amplitude (h^{3/2} - (h - y)^{3/2}). */
static double amplitude(const gf_bagnold *b)
{
    double I = gf_bagnold_inertial_number(b);
    if (!(I > 0.0))
        return 0.0;
    return 2.0 / 3.0 * I * sqrt(b->phi * b->g_m_s2 * cos(b->theta_rad)) / b->d_m;
}

double gf_bagnold_velocity(const gf_bagnold *b, double y_m)
{
    double A = amplitude(b);
    if (A == 0.0 || isinf(A))
        return A;
    double depth = fmax(b->h_m - y_m, 0.0);
    return A * (b->h_m * sqrt(b->h_m) - depth * sqrt(depth));
}

double gf_bagnold_surface_velocity(const gf_bagnold *b)
{
    return gf_bagnold_velocity(b, b->h_m);
}

double gf_bagnold_flux(const gf_bagnold *b)
{
    return 0.6 * b->h_m * gf_bagnold_surface_velocity(b);
}
