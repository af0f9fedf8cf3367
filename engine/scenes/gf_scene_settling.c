/*
 * Settling in a fluid: the validation scene of the unresolved tier.
 *
 *  mode 0, single sphere: one grain released at rest in a periodic cube of
 *    box_over_D diameters (Stokes/Schiller–Naumann terminal velocity;
 *    Izard 2014 §2.2.3 uses rho_p/rho_f = 4, Ar = 800, Re_t = 20.3).
 *  mode 1, homogeneous suspension: grains at solid fraction phi_suspension on a
 *    jittered simple cubic lattice filling a periodic cube (Richardson & Zaki
 *    1954 hindered settling, U/U_t = (1 - phi)^4.65 at low Re); with
 *    arrangement 1, at random instead (sequential addition, no two grains
 *    closer than 1.05 D across the periodic faces, phi <= 0.3), the cube kept
 *    at box_over_D and the count rounded to phi L^3 / V_grain.
 * Axes: y vertical (docs/output.md), all three axes periodic. With periodic
 * gravity and no glued grains the coupling applies the mean pressure
 * gradient that carries the excess weight, so the mixture's momentum stays
 * zero, as in a tank whose bottom is far away (gf_coupling_unresolved.c).
 *
 * Diagnostics: grain_velocity_y, the mean vertical grain velocity; and
 * settling_velocity, the grains' velocity relative to the zero-volume-flux
 * frame, U = (1 - phi)(v_p - u_f), with the mean fluid velocity from the
 * mixture momentum balance, u_f = -phi rho_p v_p / ((1 - phi) rho_f); and
 * settling_velocity_ratio = U / U_Stokes (U_Stokes from gf_groups).
 */
#include <math.h>

#include "scenes/gf_scene.h"
#include "scenes/gf_scene_box.h"

static const gf_param_info settling_params[] = {
    {"mode", "1", 1.0, 0.0, 1.0, "0: single sphere; 1: homogeneous suspension"},
    {"box_over_D", "1", 16.0, 2.0, 1000.0, "periodic cube edge / D (the suspension rounds it to whole lattice cells)"},
    {"phi_suspension", "1", 0.2, 0.001, 0.5, "solid fraction of the suspension (mode 1)"},
    {"arrangement", "1", 0.0, 0.0, 1.0, "suspension: 0 jittered simple cubic lattice; 1 random sequential addition"},
};

#define SETTLING_RANDOM_GAP 1.05      /* smallest centre distance / D of the random arrangement */
#define SETTLING_RANDOM_PHI_MAX 0.3   /* sequential addition stalls well above (jamming near 0.38) */
#define SETTLING_RANDOM_TRIES 100000  /* draws per grain before giving up */

/* Squared distance between a and b in the periodic cube of edge L (minimum image). */
static double periodic_dist2(const double a[3], const double b[3], double L)
{
    double s = 0.0;
    for (int d = 0; d < 3; ++d) {
        double x = fabs(a[d] - b[d]);
        x = fmin(x, L - x);
        s += x * x;
    }
    return s;
}

/* n grains of diameter D at random in the periodic cube [0, L)^3, none closer than SETTLING_RANDOM_GAP D. */
static gf_status random_suspension(gf_sim *sim, double L, size_t n, double D, double rho)
{
    gf_ctx *ctx = gf_sim_ctx(sim);
    gf_particles *p = gf_sim_particles(sim);
    gf_rng *rng = gf_sim_rng(sim);
    size_t i0 = p->n_local;
    double gap2 = SETTLING_RANDOM_GAP * D * SETTLING_RANDOM_GAP * D;
    for (size_t k = 0; k < n; ++k) {
        double x[3];
        int placed = 0;
        for (long t = 0; t < SETTLING_RANDOM_TRIES && !placed; ++t) {
            for (int d = 0; d < 3; ++d)
                x[d] = gf_rng_range(rng, 0.0, L);
            placed = 1;
            for (size_t j = i0; j < p->n_local && placed; ++j)
                placed = periodic_dist2(x, (const double[3]){p->x_m[j], p->y_m[j], p->z_m[j]}, L) >= gap2;
        }
        if (!placed)
            return GF_FAIL(ctx, GF_ERR_CONFIG, "settling: no room for grain %zu of %zu at random", k + 1, n);
        GF_TRY(gf_particles_add(ctx, p, x[0], x[1], x[2], 0.5 * D, rho, 0, NULL));
    }
    return GF_OK;
}

static const gf_var_info settling_diag[] = {
    {"grain_velocity_y", "m s-1", "mean vertical grain velocity", NULL},
    {"settling_velocity", "m s-1", "grain velocity relative to the zero-volume-flux frame (positive downwards)", NULL},
    {"settling_velocity_ratio", "1", "settling velocity over the Stokes velocity", NULL},
};

static gf_status settling_build(gf_sim *sim, const gf_run_spec *spec)
{
    gf_ctx *ctx = gf_sim_ctx(sim);
    gf_particles *p = gf_sim_particles(sim);
    double D = spec->grains.diameter_m, rho = spec->grains.density_kg_m3;
    int suspension = gf_run_spec_param(spec, "mode", 1.0) > 0.5;
    double L = gf_run_spec_param(spec, "box_over_D", 16.0) * D;
    double phi = gf_run_spec_param(spec, "phi_suspension", 0.2);
    int n = 1;
    double a = L;
    if (suspension && gf_run_spec_param(spec, "arrangement", 0.0) > 0.5) {
        if (phi > SETTLING_RANDOM_PHI_MAX)
            return GF_FAIL(ctx, GF_ERR_CONFIG, "settling: the random arrangement takes phi_suspension <= %g (%g asked)",
                           SETTLING_RANDOM_PHI_MAX, phi);
        const double lo[3] = {0, 0, 0}, hi[3] = {L, L, L};
        GF_TRY(gf_scene_box_under_gravity(sim, lo, hi, (const int[3]){1, 1, 1}, spec->gravity_m_s2));
        return random_suspension(sim, L, (size_t)lround(phi * L * L * L / (M_PI / 6.0 * D * D * D)), D, rho);
    }
    if (suspension) {
        a = D * cbrt(M_PI / (6.0 * phi));  /* lattice spacing at phi */
        n = (int)lround(L / a);
        if (n < 2)
            return GF_FAIL(ctx, GF_ERR_CONFIG, "settling: box_over_D = %g holds fewer than 2 lattice cells at phi %g",
                           L / D, phi);
        L = n * a;
    }
    const double lo[3] = {0, 0, 0}, hi[3] = {L, L, L};
    GF_TRY(gf_scene_box_under_gravity(sim, lo, hi, (const int[3]){1, 1, 1}, spec->gravity_m_s2));
    if (!suspension)
        return gf_particles_add(ctx, p, 0.43 * L, 0.9 * L, 0.57 * L, 0.5 * D, rho, 0, NULL);
    gf_rng *rng = gf_sim_rng(sim);
    double jit = 0.45 * (a - D);
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                GF_TRY(gf_particles_add(ctx, p, (i + 0.5) * a + gf_rng_range(rng, -jit, jit),
                                        (j + 0.5) * a + gf_rng_range(rng, -jit, jit),
                                        (k + 0.5) * a + gf_rng_range(rng, -jit, jit), 0.5 * D, rho, 0, NULL));
    return GF_OK;
}

static gf_status settling_diagnose(gf_sim *sim, double *v)
{
    const gf_particles *p = gf_sim_particles(sim);
    const gf_run_spec *s = gf_sim_spec(sim);
    double lo[3], hi[3], vs = 0.0, mv = 0.0, vy = 0.0;
    int per[3];
    gf_sim_box(sim, lo, hi, per);
    for (size_t i = 0; i < p->n_local; ++i) {
        double r = p->radius_m[i];
        vs += 4.0 / 3.0 * M_PI * r * r * r;
        mv += p->mass_kg[i] * p->vy_m_s[i];
        vy += p->vy_m_s[i];
    }
    double vbox = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
    double phi = vs / vbox, rho_f = s->fluid.density_kg_m3;
    vy /= (double)(p->n_local ? p->n_local : 1);
    double uf = rho_f > 0.0 ? -mv / vbox / ((1.0 - phi) * rho_f) : 0.0;  /* zero mixture momentum */
    double U = (1.0 - phi) * (uf - vy);
    double ust = gf_sim_scales(sim)->stokes_velocity_m_s;
    v[0] = vy;
    v[1] = U;
    v[2] = ust > 0.0 && isfinite(ust) ? U / ust : NAN;
    return GF_OK;
}

/* One sphere, or the suspension's phi L^3 over the grain volume. */
static double settling_grain_count(const gf_run_spec *spec)
{
    if (gf_run_spec_param(spec, "mode", 1.0) <= 0.5)
        return 1.0;
    double L = gf_run_spec_param(spec, "box_over_D", 16.0);
    return gf_run_spec_param(spec, "phi_suspension", 0.2) * L * L * L / (M_PI / 6.0);
}

/* The periodic cube of box_over_D (the lattice rounds its side to whole spacings, within half of one). */
static void settling_fluid_box(const gf_run_spec *spec, double size_m[3])
{
    size_m[0] = size_m[1] = size_m[2] = gf_run_spec_param(spec, "box_over_D", 16.0) * spec->grains.diameter_m;
}

const gf_scene_desc gf_scene_settling = {
    .name = "settling",
    .caption = "single sphere or homogeneous suspension settling in a periodic box (Stokes; Richardson & Zaki 1954)",
    .needs = GF_NEED_CONTACTS | GF_NEED_FLUID,
    GF_SCENE_PARAMS(settling_params),
    .default_end_time_nd = 20.0,
    .build = settling_build,
    GF_SCENE_DIAG(settling_diag),
    .diagnose = settling_diagnose,
    .grain_count = settling_grain_count,
    .fluid_box = settling_fluid_box,
};
