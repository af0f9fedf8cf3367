/*
 * Plane Couette flow of a mu(I) layer under gravity, semi-analytic
 * (Djouwe Meffeja 2012, §5.3 and Annex B); see gf_mui_oracles.h.
 *
 * The thesis finds k1 by Newton's method from k1 = mu_2 - 1e-6 and Lambda_c by
 * bisection on gdot*(0) with a 1e-5 tolerance. Here both are roots of one
 * monotone function each, found by Brent's method on a bracket the physics
 * gives:
 *   k1:       int_0^1 gdot*(y; k1) dy = 1 for k1 in [mu_s (1 + eps Lambda), mu_2):
 *             zero flux at the lower end (gdot*(0) = 0 there), divergent as
 *             k1 -> mu_2 (the top of the layer reaches mu_2, I -> inf);
 *   Lambda_c: the same with k1 = mu_s (1 + eps Lambda), for Lambda in
 *             (0, (mu_2 - mu_s)/(mu_s eps)): zero flux as Lambda -> 0,
 *             divergent at the upper end where again k1 -> mu_2.
 * The integrals use GSL's CQUAD to 1e-13 relative.
 */
#include "continuum/gf_mui_oracles.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_roots.h>
#include <math.h>

typedef struct couette_args {
    const gf_mui_params *law;
    double eps, alpha, Lambda, k1;
} couette_args;

static double shear_rate(const couette_args *a, double y)
{
    double P = 1.0 + a->eps * a->Lambda * (1.0 - y);
    double num = a->k1 - a->law->mu_s * P;
    if (num <= 0.0)
        return 0.0;  /* mu(I) P* = k1 below mu_s P*: static */
    return a->Lambda * a->law->I0 / a->alpha * sqrt(P) * num / (a->law->mu_2 * P - a->k1);
}

static double shear_rate_gsl(double y, void *p)
{
    return shear_rate(p, y);
}

static gf_status integrate_shear(gf_ctx *ctx, const couette_args *a, double y0, double y1, double *out)
{
    gsl_integration_cquad_workspace *ws = gsl_integration_cquad_workspace_alloc(200);
    if (!ws)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "couette: quadrature workspace");
    gsl_function f = {.function = shear_rate_gsl, .params = (void *)a};
    double abserr = 0.0;
    size_t nevals = 0;
    int rc = gsl_integration_cquad(&f, y0, y1, 0.0, 1e-13, ws, out, &abserr, &nevals);
    gsl_integration_cquad_workspace_free(ws);
    if (rc != GSL_SUCCESS || !isfinite(*out))
        return GF_FAIL(ctx, GF_ERR_NOT_CONVERGED, "couette: quadrature failed (%s)", gsl_strerror(rc));
    return GF_OK;
}

/* Brent's method on f over [lo, hi] (f(lo) < 0 < f(hi)), to 1e-14 relative in x. */
static gf_status brent(gf_ctx *ctx, const char *what, gsl_function *f, double lo, double hi, double *root)
{
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "couette: root solver");
    int rc = gsl_root_fsolver_set(s, f, lo, hi);
    for (int it = 0; rc == GSL_SUCCESS && it < 200; ++it) {
        rc = gsl_root_fsolver_iterate(s);
        if (rc != GSL_SUCCESS)
            break;
        rc = gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 0.0, 1e-14);
        if (rc == GSL_SUCCESS)
            break;
        rc = GSL_SUCCESS;
        if (it == 199)
            rc = GSL_EMAXITER;
    }
    *root = gsl_root_fsolver_root(s);
    gsl_root_fsolver_free(s);
    if (rc != GSL_SUCCESS)
        return GF_FAIL(ctx, GF_ERR_NOT_CONVERGED, "couette: %s: Brent's method failed (%s)", what, gsl_strerror(rc));
    return GF_OK;
}

typedef struct root_args {
    gf_ctx *ctx;
    couette_args a;
    int critical;  /* 1: the unknown is Lambda with k1 = mu_s (1 + eps Lambda) */
    gf_status st;
} root_args;

static double flux_residual(double x, void *p)
{
    root_args *r = p;
    couette_args a = r->a;
    if (r->critical) {
        a.Lambda = x;
        a.k1 = a.law->mu_s * (1.0 + a.eps * x);
    } else {
        a.k1 = x;
    }
    double integral = 0.0;
    gf_status st = integrate_shear(r->ctx, &a, 0.0, 1.0, &integral);
    if (st != GF_OK) {
        r->st = st;
        return NAN;
    }
    return integral - 1.0;
}

/* Moves hi towards the divergent end (hi_limit) until the residual is positive. */
static gf_status bracket_upper(root_args *r, double lo, double hi_limit, double *hi)
{
    for (double gap = 1e-2; gap > 1e-15; gap *= 0.1) {
        *hi = hi_limit - gap * (hi_limit - lo);
        double f = flux_residual(*hi, r);
        if (r->st != GF_OK)
            return r->st;
        if (f > 0.0)
            return GF_OK;
    }
    return GF_FAIL(r->ctx, GF_ERR_NOT_CONVERGED, "couette: no bracket for the %s", r->critical ? "critical height" : "stress k1");
}

static gf_status check_args(gf_ctx *ctx, const gf_mui_params *law, double eps, double alpha)
{
    GF_TRY(gf_mui_check(ctx, law, "couette"));
    if (!(eps >= 0.0 && isfinite(eps)))
        return GF_FAIL(ctx, GF_ERR_ARG, "couette: eps = rho g d/P0 must be >= 0 (got %g)", eps);
    if (!(alpha > 0.0 && isfinite(alpha)))
        return GF_FAIL(ctx, GF_ERR_ARG, "couette: alpha = U0/sqrt(P0/rho_s) must be > 0 (got %g)", alpha);
    return GF_OK;
}

gf_status gf_couette_critical_height(gf_ctx *ctx, const gf_mui_params *law, double eps, double alpha, double *Lambda_c)
{
    GF_TRY(check_args(ctx, law, eps, alpha));
    if (eps == 0.0) {
        *Lambda_c = INFINITY;
        return GF_OK;
    }
    gsl_set_error_handler_off();  /* GSL's default handler aborts; errors come back as codes here */
    root_args r = {.ctx = ctx, .a = {.law = law, .eps = eps, .alpha = alpha}, .critical = 1, .st = GF_OK};
    double top = (law->mu_2 - law->mu_s) / (law->mu_s * eps), hi = 0.0;
    GF_TRY(bracket_upper(&r, 0.0, top, &hi));
    gsl_function f = {.function = flux_residual, .params = &r};
    gf_status st = brent(ctx, "critical height", &f, 1e-300, hi, Lambda_c);
    return r.st != GF_OK ? r.st : st;
}

gf_status gf_couette_solve(gf_ctx *ctx, const gf_mui_params *law, double eps, double alpha, double Lambda,
                           gf_couette *out)
{
    GF_TRY(check_args(ctx, law, eps, alpha));
    if (!(Lambda > 0.0 && isfinite(Lambda)))
        return GF_FAIL(ctx, GF_ERR_ARG, "couette: Lambda = H/d must be > 0 (got %g)", Lambda);
    *out = (gf_couette){.law = *law, .eps = eps, .alpha = alpha, .Lambda = Lambda};
    GF_TRY(gf_couette_critical_height(ctx, law, eps, alpha, &out->Lambda_c));
    if (eps == 0.0) {
        out->k1 = gf_couette_k1_no_gravity(law, alpha, Lambda);
        return GF_OK;
    }
    if (Lambda >= out->Lambda_c) {
        /* Annex B: a static bottom layer under the critical profile of height Lambda_c. */
        out->k1 = law->mu_s * (1.0 + eps * out->Lambda_c);
        out->y_static = 1.0 - out->Lambda_c / Lambda;
        return GF_OK;
    }
    gsl_set_error_handler_off();
    root_args r = {.ctx = ctx, .a = {.law = law, .eps = eps, .alpha = alpha, .Lambda = Lambda}, .st = GF_OK};
    double lo = law->mu_s * (1.0 + eps * Lambda), hi = 0.0;
    GF_TRY(bracket_upper(&r, lo, law->mu_2, &hi));
    gsl_function f = {.function = flux_residual, .params = &r};
    gf_status st = brent(ctx, "stress k1", &f, lo, hi, &out->k1);
    return r.st != GF_OK ? r.st : st;
}

/* The flowing layer as its own problem: height Lambda_c above y_static, same eps, alpha. */
static couette_args flowing_layer(const gf_couette *c, double y, double *y_layer)
{
    double height = c->y_static > 0.0 ? c->Lambda_c : c->Lambda;
    *y_layer = c->y_static > 0.0 ? (y - c->y_static) / (1.0 - c->y_static) : y;
    return (couette_args){.law = &c->law, .eps = c->eps, .alpha = c->alpha, .Lambda = height, .k1 = c->k1};
}

double gf_couette_shear_rate(const gf_couette *c, double y)
{
    double yl = 0.0;
    couette_args a = flowing_layer(c, y, &yl);
    if (yl <= 0.0 && c->y_static > 0.0)
        return 0.0;
    /* the layer coordinate stretches y by 1/(1 - y_static) */
    return shear_rate(&a, yl) / (1.0 - c->y_static);
}

double gf_couette_velocity(const gf_couette *c, double y)
{
    double yl = 0.0;
    couette_args a = flowing_layer(c, y, &yl);
    if (yl <= 0.0)
        return 0.0;
    if (c->eps == 0.0)
        return yl;  /* uniform shear */
    double u = NAN;
    if (integrate_shear(NULL, &a, 0.0, yl, &u) != GF_OK)
        return NAN;
    return u;
}

double gf_couette_velocity_closed_form(const gf_mui_params *law, double eps, double alpha, double Lambda, double k1,
                                       double y)
{
    /* eq. (5.6), written with s = sqrt(P*); F(y) - F(0). */
    double mu_s = law->mu_s, mu_2 = law->mu_2, I0 = law->I0;
    double a = 2.0 * I0 / (3.0 * alpha * eps * mu_2 * mu_2);
    double b = pow(k1, 1.5) * I0 * (mu_s - mu_2) / (alpha * eps * pow(mu_2, 2.5));
    double sq2 = sqrt(mu_2), sqk = sqrt(k1);
    double s0 = sqrt(1.0 + eps * Lambda), s1 = sqrt(1.0 + eps * Lambda * (1.0 - y));
    double F0 = a * (mu_2 * mu_s * s0 * s0 * s0 + 3.0 * k1 * (mu_s - mu_2) * s0) +
                b * log((sq2 * s0 - sqk) / (sq2 * s0 + sqk));
    double F1 = a * (mu_2 * mu_s * s1 * s1 * s1 + 3.0 * k1 * (mu_s - mu_2) * s1) +
                b * log((sq2 * s1 - sqk) / (sq2 * s1 + sqk));
    return F1 - F0;
}

double gf_couette_k1_no_gravity(const gf_mui_params *law, double alpha, double Lambda)
{
    return gf_mui_friction(law, alpha / Lambda);
}

double gf_couette_critical_height_linear(const gf_mui_params *law, double eps, double alpha)
{
    /* (5.14): Lambda^2 + (alpha/I0) Lambda - (dmu/(I0 mu_s)) (alpha/eps) = 0, positive root. */
    double dmu = law->mu_2 - law->mu_s, b = alpha / law->I0;
    return -0.5 * b + sqrt(0.25 * b * b + dmu * alpha / (law->mu_s * law->I0 * eps));
}
