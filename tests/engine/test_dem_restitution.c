/*
 * Normal binary collision of two equal grains, linear spring-dashpot
 * (Izard 2014 (3.13), (3.16)-(3.17)):
 *  - clipped law (F_n >= 0): restitution equals the closed form of the
 *    clipped oscillator (Schäfer et al. 1996: 0.550, 0.873, 0.970 for eps_max =
 *    0.5, 0.87, 0.97), within 1 % at t_c/dt = 50 and 100 (Izard 2014 (3.16); the
 *    half-step evaluation of the dashpot is an O(dt) shift, see gf_integrate.h);
 *  - the geometric contact (overlap > 0) lasts t_c within 3 % (row 2; for the
 *    clipped law the force vanishes a little before the overlap does, at the
 *    closed-form instant, and the grains then separate freely);
 *  - unclipped law: restitution eps_max within 1 % (exact for the ODE).
 * Times and speeds are measured after separation, from free flight, so they
 * are not quantised by dt.
 * Onset phase: the dashpot force jumps from 0 to gamma_n V when the overlap
 * opens, somewhere inside a step; the kick integrates it over a whole step,
 * an impulse error up to +-gamma_n V dt/2, i.e. +-zeta (pi dt/t_c)/(1+eps) of
 * the restitution (0.9 % for eps = 0.5 at t_c/dt = 50), first order in dt and
 * random in the onset phase (LAMMPS and every fixed-step DEM share it). So the
 * claims are: the restitution AVERAGED over 8 onset phases is within 1 % at
 * t_c/dt = 50 and 100, and EVERY phase is within 1 % at t_c/dt = 100 (the
 * stricter condition).
 * Hertz row of the table (Tsuji et al. 1992 damping ~ delta^(1/4)): the
 * restitution does not depend on the impact speed (0.25, 1 and 4 sqrt(gD)
 * agree within 0.5 %, the onset-phase scatter at t_c/dt = 100), unlike a
 * Hertz spring with a constant dashpot.
 * Viscoelastic Hertz row (hertz_kk: damping ~ contact radius, Kuwabara & Kono
 * 1987; Brilliantov et al. 1996): the restitution asked (0.87) is met at the
 * calibration speed sqrt(gD) within 1 %, and the restitution falls with the
 * impact speed as the two-term expansion of Schwager & Pöschel (PRE 57,
 * 1998, eq. 24) predicts, 1 - e = C1 x - C2 x^2 with x ~ v^(1/5): the x of
 * the 1 sqrt(gD) collision gives e at 0.25 and 4 sqrt(gD) within 1 %.
 */
#include <math.h>
#include <stdio.h>

#include "contact/gf_contact.h"
#include "dem_testutil.h"

typedef struct collision_result {
    double restitution, overlap_duration_over_tc;
} collision_result;

static const char *law = "linear";
static double impact_nd = 1.0;

static collision_result run_collision(double eps, double steps_per_tc, int attraction, double phase)
{
    gf_ctx ctx = {0};
    gf_run_spec spec = gf_test_spec("binary_collision");
    snprintf(spec.contact.law, sizeof spec.contact.law, "%s", law);
    gf_run_spec_set_param(&ctx, &spec, "impact_speed_nd", impact_nd);
    spec.contact.restitution = eps;
    spec.contact.dt_over_tc = 1.0 / steps_per_tc;
    spec.contact.allow_attraction = attraction;
    spec.contact.friction = 0.0;
    /* the contact starts at a fraction `phase` of a step: gap = (0.01 D / (V dt) rounded + phase) V dt */
    double V0 = impact_nd * sqrt(spec.gravity_m_s2 * spec.grains.diameter_m);
    double dt0 = gf_run_spec_dt_s(&spec);
    double gap_over_D = (floor(0.01 * spec.grains.diameter_m / (V0 * dt0)) + phase) * V0 * dt0 / spec.grains.diameter_m;
    gf_run_spec_set_param(&ctx, &spec, "gap_over_D", gap_over_D);
    gf_sim *sim = NULL;
    collision_result r = {NAN, NAN};
    GF_CHECK_OK(gf_test_sim(&ctx, &spec, 1, &sim), &ctx);
    if (!sim)
        return r;
    gf_particles *p = gf_sim_particles(sim);
    double D = spec.grains.diameter_m, tc = gf_run_spec_t_contact_s(&spec);
    double V = impact_nd * sqrt(spec.gravity_m_s2 * D);
    /* run until well separated: gap/V + t_c + a margin */
    long n = (long)ceil((gap_over_D * D / V + 1.5 * tc) / gf_sim_dt_s(sim));
    GF_CHECK_OK(gf_sim_advance(sim, n), &ctx);
    double v_sep = p->vx_m_s[1] - p->vx_m_s[0];
    double dist = p->x_m[1] - p->x_m[0];
    double t = gf_sim_time_s(sim);
    /* overlap ended when dist was 2R: back-extrapolate the free flight */
    double t_end = t - (dist - D) / v_sep;
    double t_start = gap_over_D * D / V; /* free approach, exact */
    r.restitution = v_sep / V;
    r.overlap_duration_over_tc = (t_end - t_start) / tc;
    gf_sim_destroy(&sim);
    return r;
}

/* 1 - e = C1 x - C2 x^2 (Schwager & Pöschel 1998, eq. 24): x from e. */
static double kk_x(double e)
{
    const double C1 = 1.15344, C2 = 0.79826;
    return (C1 - sqrt(C1 * C1 - 4.0 * C2 * (1.0 - e))) / (2.0 * C2);
}

static void viscoelastic_hertz(const double speeds[3])
{
    const double C1 = 1.15344, C2 = 0.79826;
    double e[3];
    law = "hertz_kk";
    for (int k = 0; k < 3; ++k) {
        impact_nd = speeds[k];
        e[k] = run_collision(0.87, 100.0, 0, 0.5).restitution;
    }
    const double x1 = kk_x(e[1]);
    printf("hertz_kk (eps 0.87 at sqrt(gD)): restitution %.5f, %.5f, %.5f at 0.25, 1, 4 sqrt(gD)\n", e[0], e[1], e[2]);
    GF_CHECK_REL(e[1], 0.87, 0.01);
    for (int k = 0; k < 3; k += 2) {
        const double x = x1 * pow(speeds[k], 0.2), predicted = 1.0 - C1 * x + C2 * x * x;
        printf("  at %.2f sqrt(gD): %.5f, Schwager & Pöschel %.5f (%+.2f %%)\n", speeds[k], e[k], predicted,
               100.0 * (e[k] / predicted - 1.0));
        GF_CHECK_REL(e[k], predicted, 0.01);
    }
    GF_CHECK(e[0] > e[1] && e[1] > e[2]);
}

int main(void)
{
    const double eps_max[3] = {0.5, 0.87, 0.97};
    const double published[3] = {0.550, 0.873, 0.970}; /* closed form of the clipped oscillator */
    for (int k = 0; k < 3; ++k) {
        double closed, force_duration;
        gf_contact_clipped_restitution(eps_max[k], &closed, &force_duration);
        /* the closed form used below reproduces the three printed values */
        GF_CHECK_ABS(closed, published[k], 0.0006);
        for (int q = 0; q < 2; ++q) {
            double steps = q == 0 ? 50.0 : 100.0, mean = 0.0, worst = 0.0, dur_worst = 0.0;
            const int n_phase = 8;
            for (int ph = 0; ph < n_phase; ++ph) {
                collision_result r = run_collision(eps_max[k], steps, 0, (ph + 0.5) / n_phase);
                mean += r.restitution / n_phase;
                if (fabs(r.restitution / closed - 1.0) > fabs(worst))
                    worst = r.restitution / closed - 1.0;
                if (fabs(r.overlap_duration_over_tc - 1.0) > fabs(dur_worst))
                    dur_worst = r.overlap_duration_over_tc - 1.0;
            }
            printf("clipped eps_max %.2f  t_c/dt %3.0f: restitution mean %.5f (closed form %.5f, error %+.3f %%), "
                   "worst phase %+.3f %%; overlap duration worst %+.3f %% of t_c (force lasts %.4f t_c)\n",
                   eps_max[k], steps, mean, closed, 100.0 * (mean / closed - 1.0), 100.0 * worst, 100.0 * dur_worst,
                   force_duration);
            GF_CHECK_REL(mean, closed, 0.01);        /* 1 %, phase-averaged */
            if (steps >= 100.0)
                GF_CHECK_ABS(worst, 0.0, 0.01);      /* 1 %, every phase at t_c/dt = 100 */
            GF_CHECK_ABS(dur_worst, 0.0, 0.03);      /* 3 %, Izard 2014 (3.17) */
        }
        collision_result u = run_collision(eps_max[k], 100.0, 1, 0.5);
        printf("unclipped eps_max %.2f  t_c/dt 100: restitution %.5f (error %+.3f %%), duration %.4f t_c\n",
               eps_max[k], u.restitution, 100.0 * (u.restitution / eps_max[k] - 1.0), u.overlap_duration_over_tc);
        GF_CHECK_REL(u.restitution, eps_max[k], 0.01);
        GF_CHECK_ABS(u.overlap_duration_over_tc, 1.0, 0.03);
    }
    law = "hertz";
    double e_h[3], speeds[3] = {0.25, 1.0, 4.0};
    for (int k = 0; k < 3; ++k) {
        impact_nd = speeds[k];
        e_h[k] = run_collision(0.87, 100.0, 0, 0.5).restitution;
    }
    printf("hertz (zeta of eps 0.87): restitution %.5f, %.5f, %.5f at 0.25, 1, 4 sqrt(gD)\n", e_h[0], e_h[1], e_h[2]);
    GF_CHECK_REL(e_h[0], e_h[1], 0.005);
    GF_CHECK_REL(e_h[2], e_h[1], 0.005);
    viscoelastic_hertz(speeds);
    return gf_test_finish();
}
