/*
 * Plane Poiseuille flow of the mu(I) rate part, closed form (Djouwe Meffeja
 * 2012, §5.4, eqs. (5.16)-(5.22)); see gf_mui_oracles.h.
 *
 * On the lower half, (mu(I) - mu_s) = m(y*) = beta^2 (1/2 - y*) (stress zero on
 * the centreline), I = I0 m/(dmu - m) and gdot* = Lambda I / beta, so
 *   u*(y*) = (Lambda I0/beta^3) [ dmu ln(1 + beta^2 y* / (dmu - beta^2/2)) - beta^2 y* ].
 * It is evaluated as (Lambda I0 dmu/beta^3) [L(x0) - L(x0 - x)] with
 * L(x) = -ln(1 - x) - x, x0 = beta^2/(2 dmu), x = beta^2 y* / dmu, and L by its
 * series for small x: the direct form cancels to O(beta^2) of its terms, which
 * would cost eight digits at beta = 0.005.
 */
#include "continuum/gf_mui_oracles.h"

#include <math.h>

/* L(x) = -ln(1 - x) - x = x^2/2 + x^3/3 + ..., 0 <= x < 1. */
static double minus_log1m_minus_x(double x)
{
    if (x > 1e-2)
        return -log1p(-x) - x;
    double term = x * x, sum = 0.0;
    for (int k = 2; k < 60; ++k, term *= x) {
        sum += term / k;
        if (term / k < 1e-18 * sum)
            break;
    }
    return sum;
}

double gf_poiseuille_beta_max(const gf_mui_params *law)
{
    return sqrt(2.0 * (law->mu_2 - law->mu_s));
}

gf_status gf_poiseuille_check(gf_ctx *ctx, const gf_mui_params *law, double beta, double Lambda)
{
    GF_TRY(gf_mui_check(ctx, law, "poiseuille"));
    double bmax = gf_poiseuille_beta_max(law);
    if (!(beta > 0.0 && beta < bmax))
        return GF_FAIL(ctx, GF_ERR_ARG,
                       "poiseuille: beta = sqrt(G H/P0) = %g has no steady solution (need 0 < beta < %g: the wall "
                       "stress G H/2 cannot exceed (mu_2 - mu_s) P0)",
                       beta, bmax);
    if (!(Lambda > 0.0))
        return GF_FAIL(ctx, GF_ERR_ARG, "poiseuille: Lambda = H/d must be > 0 (got %g)", Lambda);
    return GF_OK;
}

double gf_poiseuille_velocity(const gf_mui_params *law, double beta, double Lambda, double y)
{
    double dmu = law->mu_2 - law->mu_s, b2 = beta * beta;
    if (y > 0.5)
        y = 1.0 - y;
    double x0 = b2 / (2.0 * dmu), xm = b2 * (0.5 - y) / dmu;  /* xm = x0 - beta^2 y/dmu */
    return Lambda * law->I0 * dmu / (b2 * beta) * (minus_log1m_minus_x(x0) - minus_log1m_minus_x(xm));
}

double gf_poiseuille_umax(const gf_mui_params *law, double beta, double Lambda)
{
    return gf_poiseuille_velocity(law, beta, Lambda, 0.5);
}

double gf_poiseuille_umax_newtonian(const gf_mui_params *law, double beta, double Lambda)
{
    return beta * Lambda * law->I0 / (8.0 * (law->mu_2 - law->mu_s));
}
