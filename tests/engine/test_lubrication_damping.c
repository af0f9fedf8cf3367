/*
 * Implicit lubrication damping (engine/contact/gf_lubrication.h).
 * A pair under lubrication alone obeys m* dv/dt = -c v, v = v0 exp(-c t/m*).
 * One step with the constant force -c_eff v must reproduce that decay exactly
 * below the cap, tend to c for c dt/m* << 1, and never reverse the approach
 * where an explicit force would (c dt/m* > 2: v -> (1 - c dt/m*) v < 0).
 */
#include <math.h>
#include <stdio.h>

#include "contact/gf_lubrication.h"
#include "gf_test.h"

/* n steps of v <- v - dt c_eff v / m (the force held over the step). */
static double decay(double c, double m, double dt, int n, double *v_min)
{
    double v = 1.0;
    *v_min = v;
    for (int k = 0; k < n; ++k) {
        v -= dt * gf_lubrication_damping(dt, c, m) * v / m;
        *v_min = fmin(*v_min, v);
    }
    return v;
}

int main(void)
{
    const double m = 1e-4, dt = 1e-5, t = 2e-3;
    const int n = (int)lround(t / dt);

    /* weak damping, x = c dt/m = 1e-3: c_eff = c to O(x) */
    double c_weak = 1e-3 * m / dt;
    GF_CHECK_REL(gf_lubrication_damping(dt, c_weak, m), c_weak, 1e-3);

    /* the series for (1 - exp(-x))/x against libm's expm1 over [0, 0.29]:
     * within 2 epsilon (4.4e-16), the reference -expm1(-x)/x carrying
     * up to 1.5 ulp of its own (expm1 < 1 ulp, the division 0.5) */
    double worst = 0.0, x_worst = 0.0;
    for (int k = 0; k <= 290000; ++k) {
        double x = 1e-6 * k + (k == 0 ? 1e-300 : 0.0);
        double ref = -expm1(-x) / x, err = fabs(gf_lubrication_phi1(x) - ref) / ref;
        if (err > worst)
            worst = err, x_worst = x;
    }
    printf("phi1 series: largest relative difference to expm1 %.3g (x = %.4g)\n", worst, x_worst);
    GF_CHECK(worst <= 2.0 * 2.220446049250313e-16);

    /* x = 0.2 (below the cap ln(4/3) = 0.288): the exact exponential decay, to round-off */
    double c = 0.2 * m / dt, v_min;
    double v = decay(c, m, dt, n, &v_min);
    printf("x = 0.2: v(t) = %.15g, exact %.15g\n", v, exp(-c * t / m));
    GF_CHECK_REL(v, exp(-c * t / m), 1e-10);

    /* x = 10: explicit would give v -> -9 v per step; implicit stays monotone >= 0 */
    double c_stiff = 10.0 * m / dt;
    GF_CHECK(1.0 - c_stiff * dt / m < -1.0); /* explicit unstable at this step */
    v = decay(c_stiff, m, dt, n, &v_min);
    printf("x = 10: v(t) = %.3g, min %.3g\n", v, v_min);
    GF_CHECK(v_min >= 0.0);
    GF_CHECK(v < 1e-3); /* the approach is stopped: the overdamped limit */
    GF_CHECK_REL(gf_lubrication_damping(dt, c_stiff, m), 0.25 * m / dt, 1e-12);
    return gf_test_finish();
}
