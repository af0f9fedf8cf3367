/*
 * janssen_saturation (--full): the Janssen column of tests/scenes/test_janssen.c
 * (scene janssen, 6 D x 30 D section, D = 1 cm, 10 % polydisperse,
 * rho_p = 1319, mu_c = mu_w = 0.25, eps = 0.3; Izard 2014 §2.1.3.2), settled
 * to rest (the scene's done(), at most 40 sqrt(D/g)).
 *
 * Observable: the saturation pressure, the mean vertical stress over the
 * lower half of the column (3 D above the floor up to mid-height; the
 * profile of gf_measure_silo_vertical_stress, weight above a plane minus the
 * load the glued walls carry), / (rho_e g D). Recorded too (aux): f_p K =
 * A / (P lambda) from the fit of Janssen's law
 * sigma(d) = rho_e g lambda (1 - exp(-d/lambda)) (thesis (2.11)-(2.15)).
 * The plateau is a mean over ~11 slabs; the fit's lambda is set by the few
 * slabs where the profile bends, and the profile bends more sharply than the
 * exponential (docs/notes/validation-dem.md, "Janssen (row 6)"), so it is the
 * noisier of the two.
 *
 * Reference: the finest affordable setting (dt = t_c/100, t_c sqrt(g/D) =
 * 5e-3), not the seed's band, which the scene does not meet yet (open row 6).
 * The settled column is chaotic: the packing preparation (gf_packing, its own
 * contacts) does not depend on dt or t_c, yet one seed's plateau moves by
 * 2-15 % between settings (the settling and the floor drop redistribute the
 * wall friction differently), as much as between seeds (sd ~10 % over 9
 * seeds). Every setting is therefore the mean of JAN_SEEDS seeds (as
 * collapse_runout), compared with the same mean at the finest setting, whose
 * seed scatter is printed. Three seeds resolve differences of ~17 % only
 * (2 sd of a difference of two means); ~9 would resolve the tolerance
 * (docs/notes/benchmarks.md, "Janssen column").
 * Tolerance 10 %: the seed quotes its plateau at +-20 % (700 Pa) and f_p K at
 * +-20 % (0.30 +- 0.06); a numerical setting may add half of that band.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "bench_accuracy.h"
#include "gf_bench_clock.h"
#include "gf_sim.h"
#include "scenes/gf_measure.h"
#include "scenes/gf_scene.h"

#define JAN_SIDE_OVER_D 6.0
#define JAN_FILL_OVER_D 30.0
#define JAN_T_MAX_ND 40.0
#define JAN_SEEDS 3
#define JAN_NP 256

const double bench_janssen_dt[] = {1.0 / 20, 1.0 / 50, 1.0 / 100};
const double bench_janssen_tc[] = {2e-2, 1e-2, 5e-3};

typedef struct jan_run {
    double plateau_nd, fpk_fit, sigma_inf_nd, cpu_s;
} jan_run;

int bench_janssen_available(const char **why)
{
    const gf_scene_desc *d = gf_scene_find("janssen");
    if (!d || !d->done) {
        *why = "scene janssen not in this build";
        return 0;
    }
    *why = "";
    return 1;
}

/* The run spec of test_janssen (runner_dry_spec + the seed's material). */
static gf_status janssen_spec(gf_ctx *ctx, const bench_knobs *k, unsigned seed, gf_run_spec *s)
{
    gf_run_spec_defaults(s);
    snprintf(s->scene, sizeof s->scene, "janssen");
    snprintf(s->fluid.model, sizeof s->fluid.model, "none");
    s->seed = seed;
    s->grains.diameter_m = 0.01;
    s->grains.polydispersity = 0.10;
    s->grains.density_kg_m3 = 1319.0;
    s->contact.friction = s->contact.wall_friction = 0.25;
    s->contact.restitution = 0.3;
    s->contact.dt_over_tc = k->dt_over_tc;
    s->contact.t_contact_nd = k->t_contact_nd;
    s->contact.skin_over_D = k->skin_over_D;
    /* the square-lattice walls the case was measured with (docs/notes/benchmarks.md, "Janssen column") */
    GF_TRY(gf_run_spec_set_param(ctx, s, "random_walls", 0.0));
    GF_TRY(gf_run_spec_set_param(ctx, s, "side_over_D", JAN_SIDE_OVER_D));
    return gf_run_spec_set_param(ctx, s, "fill_height_over_D", JAN_FILL_OVER_D);
}

/* Effective section A (the area the packing fills at its interior solid
 * fraction, as test_janssen) and the bulk density rho_e; top: the free surface. */
static void janssen_section(gf_sim *sim, double top, double *A, double *rho_e)
{
    const gf_particles *p = gf_sim_particles(sim);
    double D = gf_sim_spec(sim)->grains.diameter_m, S = JAN_SIDE_OVER_D * D, vol = 0.0, mass = 0.0;
    gf_measure_domain dom;
    gf_sim_box(sim, dom.lo_m, dom.hi_m, dom.periodic);
    for (size_t i = 0; i < p->n_local; ++i)
        if (!(p->flags[i] & GF_P_GLUED))
            vol += 4.0 / 3.0 * M_PI * pow(p->radius_m[i], 3), mass += p->mass_kg[i];
    double lo[3] = {1.5 * D, 3.0 * D, 1.5 * D}, hi[3] = {S - 1.5 * D, top - 3.0 * D, S - 1.5 * D};
    double phi = gf_measure_solid_fraction_box(p, &dom, lo, hi, D / 8.0, 0);
    *A = vol / (phi * top);
    *rho_e = mass / (*A * top);
}

/* Plateau, fitted plateau and f_p K of the settled column (test_janssen's measurement). */
static gf_status janssen_measure_state(gf_ctx *ctx, gf_sim *sim, jan_run *r)
{
    const gf_particles *p = gf_sim_particles(sim);
    double D = gf_sim_spec(sim)->grains.diameter_m, g = gf_sim_spec(sim)->gravity_m_s2;
    double phi[JAN_NP], sig[JAN_NP], dd[JAN_NP], ss[JAN_NP], A, rho_e;
    gf_measure_domain dom;
    gf_sim_box(sim, dom.lo_m, dom.hi_m, dom.periodic);
    int n = (int)fmin(JAN_NP, ceil(dom.hi_m[1] / D)), m = 0, n_low = 0;
    GF_TRY(gf_measure_profile_y(ctx, p, &dom, 0.0, D, n, phi, NULL));
    double top = gf_measure_bed_height_m(phi, n, 0.0, D, 0.5), s_low = 0.0;
    janssen_section(sim, top, &A, &rho_e);
    GF_TRY(gf_measure_silo_vertical_stress(ctx, p, g, A, 0.0, D, n, sig));
    for (int k = 3; k < n; ++k) { /* the lowest 3 D, where the floor lifts the stress, are left out */
        double yk = (k + 0.5) * D;
        if (yk < top)
            dd[m] = top - yk, ss[m] = sig[k], ++m;
        if (yk < 0.5 * top)
            s_low += sig[k], ++n_low;
    }
    double s_inf, lambda;
    GF_TRY(gf_measure_fit_janssen(ctx, dd, ss, m, 0.2 * D, 100.0 * JAN_SIDE_OVER_D * D, &s_inf, &lambda, NULL));
    r->plateau_nd = s_low / n_low / (rho_e * g * D);
    r->sigma_inf_nd = s_inf / (rho_e * g * D);
    r->fpk_fit = A / (4.0 * sqrt(A) * lambda); /* lambda = A / (f_p K P), P = 4 sqrt(A) */
    return GF_OK;
}

/* One column: build (packing, settle, floor drop), run to rest, measure. */
static gf_status janssen_run(gf_ctx *ctx, const bench_knobs *k, unsigned seed, jan_run *r)
{
    gf_run_spec spec;
    GF_TRY(janssen_spec(ctx, k, seed, &spec));
    const gf_scene_desc *d = gf_scene_find("janssen");
    gf_sim *sim = NULL;
    double t0 = gf_bench_cpu_time_s();
    GF_TRY(gf_sim_create(ctx, &spec, &(gf_sim_options){.n_threads = 1}, &sim));
    double tg = sqrt(spec.grains.diameter_m / spec.gravity_m_s2);
    long chunk = (long)ceil(tg / gf_sim_dt_s(sim));
    gf_status st = GF_OK;
    while (st == GF_OK && gf_sim_time_s(sim) < JAN_T_MAX_ND * tg && !d->done(sim))
        st = gf_sim_advance(sim, chunk);
    r->cpu_s = gf_bench_cpu_time_s() - t0;
    if (st == GF_OK)
        st = janssen_measure_state(ctx, sim, r);
    gf_sim_destroy(&sim);
    return st;
}

static int janssen_is_reference(const bench_knobs *k)
{
    return fabs(k->dt_over_tc - 1.0 / 100) < 1e-12 && fabs(k->t_contact_nd - 5e-3) < 1e-15;
}

/* Mean and seed scatter (sd) of the plateau over JAN_SEEDS seeds at setting k; runs[] gets each seed. */
static gf_status janssen_mean(gf_ctx *ctx, const bench_knobs *k, jan_run runs[JAN_SEEDS], jan_run *mean,
                              double *sd)
{
    double s2 = 0.0;
    *mean = (jan_run){0.0, 0.0, 0.0, 0.0};
    for (int s = 0; s < JAN_SEEDS; ++s) {
        jan_run *r = &runs[s];
        GF_TRY(janssen_run(ctx, k, (unsigned)(s + 1), r));
        mean->plateau_nd += r->plateau_nd / JAN_SEEDS, mean->fpk_fit += r->fpk_fit / JAN_SEEDS;
        mean->sigma_inf_nd += r->sigma_inf_nd / JAN_SEEDS, mean->cpu_s += r->cpu_s;
        s2 += r->plateau_nd * r->plateau_nd / JAN_SEEDS;
        printf("janssen_saturation dt = t_c/%.0f, t_c sqrt(g/D) = %g, seed %d: plateau %.3f rho_e g D, fitted "
               "sigma_inf %.3f rho_e g D, f_p K (fit) %.4f, %.1f CPU s\n",
               1.0 / k->dt_over_tc, k->t_contact_nd, s + 1, r->plateau_nd, r->sigma_inf_nd, r->fpk_fit, r->cpu_s);
        fflush(stdout);
    }
    *sd = sqrt(fmax(0.0, s2 - mean->plateau_nd * mean->plateau_nd));
    return GF_OK;
}

/* The mean of JAN_SEEDS seeds at setting k against the same mean at the finest setting. */
gf_status bench_janssen_measure(gf_ctx *ctx, const bench_knobs *k, int full, bench_result *out)
{
    (void)full;
    static jan_run ref_mean;
    static double ref_sd = NAN;
    const bench_knobs fine = {1.0 / 100, BENCH_DEFAULT_SKIN_OVER_D, 5e-3, BENCH_DEFAULT_CELL_OVER_D,
                               BENCH_DEFAULT_RETRACT_DX, BENCH_DEFAULT_FLUID_CFL};
    jan_run runs[JAN_SEEDS], m;
    double sd;
    if (isnan(ref_sd)) {
        GF_TRY(janssen_mean(ctx, &fine, runs, &ref_mean, &ref_sd));
        printf("janssen_saturation reference (dt = t_c/100, t_c sqrt(g/D) = 5e-3, %d seeds): plateau %.3f rho_e g D, "
               "seed scatter (sd) %.1f %%; f_p K (fit) %.4f\n",
               JAN_SEEDS, ref_mean.plateau_nd, 100.0 * ref_sd / ref_mean.plateau_nd, ref_mean.fpk_fit);
    }
    if (janssen_is_reference(k))
        m = ref_mean, sd = ref_sd;
    else
        GF_TRY(janssen_mean(ctx, k, runs, &m, &sd));
    printf("janssen_saturation dt = t_c/%.0f, t_c sqrt(g/D) = %g: plateau mean %.3f, seed sd %.1f %%\n",
           1.0 / k->dt_over_tc, k->t_contact_nd, m.plateau_nd, 100.0 * sd / m.plateau_nd);
    *out = (bench_result){m.plateau_nd, ref_mean.plateau_nd, fabs(m.plateau_nd / ref_mean.plateau_nd - 1.0),
                          m.cpu_s, m.fpk_fit};
    return GF_OK;
}
