/* Boyer, Guazzelli & Pouliquen (2011) μ(I_v) and its inclined layer: see gf_boyer.h. */
#include "core/gf_boyer.h"

#include <math.h>

const gf_boyer_law GF_BOYER_2011 = {0.32, 0.7, 0.005, 0.585};

double gf_boyer_mu(const gf_boyer_law *law, double Iv, int contact_only)
{
    double mu = law->mu1 + (law->mu2 - law->mu1) / (1.0 + law->I0 / Iv);
    return contact_only ? mu : mu + Iv + 2.5 * law->phi_m * sqrt(Iv);
}

double gf_boyer_Iv(const gf_boyer_law *law, double mu, int contact_only)
{
    if (!(mu > law->mu1))
        return 0.0;
    if (contact_only) /* mu1 + (mu2 - mu1)/(1 + I0/I_v) = mu, solved for I_v */
        return mu < law->mu2 ? law->I0 * (mu - law->mu1) / (law->mu2 - mu) : INFINITY;
    /* full law: bisection on log I_v, mu(I_v) increasing monotonically */
    double lo = 1e-14, hi = 1e6;
    for (int it = 0; it < 200; ++it) {
        double m = sqrt(lo * hi);
        if (gf_boyer_mu(law, m, contact_only) < mu)
            lo = m;
        else
            hi = m;
    }
    return sqrt(lo * hi);
}

double gf_boyer_phi(const gf_boyer_law *law, double Iv) { return law->phi_m / (1.0 + sqrt(Iv)); }

double gf_boyer_layer_T_over_Tv(const gf_boyer_law *law, double mu_drive, double tan_theta, double h_over_D,
                                double L_over_D, int contact_only)
{
    double Iv = gf_boyer_Iv(law, mu_drive, contact_only);
    if (!(Iv > 0.0))
        return INFINITY;
    return L_over_D * tan_theta / (6.0 * Iv * gf_boyer_phi(law, Iv) * h_over_D * h_over_D);
}
