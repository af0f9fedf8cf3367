/* The early-force extrapolation of gf_early_force.h, by GSL's linear least squares. */
#include "stages/gf_early_force.h"

#include <math.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit.h>

double gf_early_force_fit(const double *t, const double *F, int n, double t0, double t1)
{
    int m = 0;
    for (int i = 0; i < n; ++i)
        m += t[i] >= t0 && t[i] <= t1;
    if (m < 4)
        return NAN;
    gsl_matrix *X = gsl_matrix_alloc((size_t)m, 3), *cov = gsl_matrix_alloc(3, 3);
    gsl_vector *y = gsl_vector_alloc((size_t)m), *c = gsl_vector_alloc(3);
    gsl_multifit_linear_workspace *w = gsl_multifit_linear_alloc((size_t)m, 3);
    gsl_set_error_handler_off(); /* GSL's default handler aborts; a failed fit gives NaN */
    double c0 = NAN, chi2;
    if (X && cov && y && c && w) {
        size_t row = 0;
        for (int i = 0; i < n; ++i) {
            if (t[i] < t0 || t[i] > t1)
                continue;
            gsl_matrix_set(X, row, 0, 1.0);
            gsl_matrix_set(X, row, 1, sqrt(t[i]));
            gsl_matrix_set(X, row, 2, t[i]);
            gsl_vector_set(y, row++, F[i]);
        }
        if (gsl_multifit_linear(X, y, c, cov, &chi2, w) == 0)
            c0 = gsl_vector_get(c, 0);
    }
    gsl_multifit_linear_free(w);
    gsl_vector_free(c), gsl_vector_free(y);
    gsl_matrix_free(cov), gsl_matrix_free(X);
    return c0;
}
