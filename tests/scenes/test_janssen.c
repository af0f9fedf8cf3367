/*
 * Janssen silo (Izard 2014 §2.1.3.2, (2.11)-(2.15)).
 *
 * Seed: a 0.1 x 0.1 x 5 m box with walls of glued grains, R = 5 mm +- 10 %,
 * rho_p = 1319, mu_c = 0.25, eps = 0.3, C_tot = 0.59; measured f_p K = 0.30
 * +- 0.06 (local) and a plateau ~700 Pa. Here the same grains and walls in a
 * smaller column (argv: side/D and fill height/D; default 6 D x 30 D, the
 * `slow` variant keeps the seed's side 10 D = 0.1 m with 60 D of fill),
 * t_c = 0.02 sqrt(D/g) (softer than the seed's 1e-4 s; overlaps stay < 0.1 % D).
 *
 * The vertical stress on planes 1 D apart (weight above minus the load
 * carried by the glued walls) is fitted from the top down with the Janssen
 * law sigma(d) = rho_e g lambda (1 - exp(-d/lambda)), skipping the lowest
 * 3 D where the floor lets the pressure rise again (thesis: "arches cannot
 * form" near the bottom). Claims:
 *   f_p K = A/(P lambda) inside the seed's band 0.24-0.36 (row 6); the
 *   seed's inverse estimate (2.13) rho_e g A/(P_inf P) from the fitted
 *   plateau, and the local one (2.14)-(2.15): f_p = wall shear / wall normal
 *   stress on the glued walls, K = wall normal / vertical stress, both over
 *   the lower half, inside the same band.
 *   A is the area the packing fills at its interior solid fraction
 *   (V_grains / (Phi_interior h)), P = 4 sqrt(A): grains of the first layer
 *   nest into the glued walls, so the free box S^2 underestimates the
 *   cross-section (both values are printed);
 *   the pressure saturates: the mean stress of the lower half of the column
 *   is within 15 % of the fitted plateau and below half of the hydrostatic
 *   rho_e g d at its mean depth;
 *   the fitted plateau agrees with rho_e g lambda (the law's own
 *   consistency, +-15 %);
 *   interior Phi within 0.02 of the seed's 0.59 (row 4: local Phi spread);
 *   K from the wall loads and K = (S_xx + S_zz)/(2 S_yy) of the granular
 *   stress tensor over the section [0, S]^2 (the seed's definition in (2.11))
 *   within 10 % of each other. f_p K with the tensor's K is printed too;
 *   the frictionless safety planes behind the glued walls carry under 1 %
 *   of the side load (the glued walls hold the column).
 * Walls: the scene's default random wall (a random layer backed by a
 * lattice, gf_scene_janssen.c). At the seed's section, seeds 1-5: plateau
 * 699 +- 54 Pa, local f_p K 0.270 +- 0.022 (f_p 0.34, K 0.79); filled to 120 D,
 * 647 +- 13 Pa and 0.286 +- 0.014, but the law's consistency then fails on 3 of 5
 * seeds (flat from ~1.5 lambda down, rising over the last 20 D): the profile is not
 * the exponential, so the 60 D column stays the slow test.
 * Measured with the square lattice alone (GF_TEST_RANDOM_WALLS=0), 6 D x 30 D:
 * the lattice mobilises an effective wall friction f_p ~ mu_c (0.22-0.30),
 * K = 0.78-1.02, so f_p K = 0.18-0.28 across floor drops 0.05-0.6 D and packing seeds 1, 7, 31 (no
 * trend with the drop: the scatter of a 6 D section dominates; measured
 * before the preparation got its safety planes behind the glued walls, after
 * which the default gives 0.248 fit, 0.150 local); the profile
 * turns from hydrostatic to flat over ~4 D, sharper than the exponential.
 * At the seed's t_c = 1e-4 s: f_p 0.253, K 0.893, f_p K 0.226 (local). The
 * seed's plateau is P_G = tr/3 = sigma_v (1 + 2K)/3 under Janssen's
 * redirection; (2.13) with it is printed beside the vertical-stress value.
 * Ensemble: `--seeds N` before side and fill (or GF_TEST_SEEDS=N) runs
 * packing seeds 1 .. N (GF_TEST_SEED moves the first) and checks the three
 * f_p K estimates on their means over the packing seeds: the seed's band
 * 0.30 +- 0.06 is the spread of its own measurement, and one 10 D section
 * scatters by more than the distance of a single realisation to the band's
 * edge. Each seed's
 * values are printed; saturation, the law's consistency and the interior
 * Phi stay checked on every realisation.
 * GF_TEST_TC, GF_TEST_DROP (floor_drop_over_D), GF_TEST_PHI (phi_target),
 * GF_TEST_POUR (free_pour: the thesis' filling), GF_TEST_RANDOM_WALLS
 * (random_walls: 0 for the square lattice) and GF_TEST_SEED override the
 * set-up (exploration).
 */
#include <stddef.h>
#include <stdlib.h>

#include "scene_runner.h"
#include "scenes/gf_measure.h"


enum { NP = 2000, NS = 16 };

/* What one realisation measures. */
typedef struct {
    double shear[NP], normal[NP];                    /* wall loads per 1 D slab (N) */
    double c_tot, phi_int, top, side_eff, rho_e;     /* packing and effective section (m, kg/m3) */
    double s_inf, lambda, rms;                       /* Janssen fit (Pa, m, Pa) */
    double fpk, fpk_inv, fpk_inv_pg, fp, kk, loc;    /* f_p K: fit, inverse (2.13) two ways, local (2.14)-(2.15) */
    double k_bulk, k_inner, loc_bulk;                /* K from the granular stress tensor (section, interior), f_p K */
    double s_low, d_low;                             /* lower half: mean stress (Pa) at mean depth (m) */
    double plane_share;                              /* side load on the safety planes / all side load */
    double sig[NP];                                  /* vertical stress per 1 D slab */
    int n;                                           /* slabs */
    size_t grains;
    double build_s, settle_s;
} silo;

/* Fills and settles the column of packing seed `seed`; NULL when the preparation fails. */
static gf_sim *settle(double side, double fill, unsigned seed, silo *o)
{
    gf_ctx ctx = {0};
    gf_run_spec spec;
    runner_dry_spec(&spec, "janssen");
    spec.seed = seed;
    spec.grains.density_kg_m3 = 1319.0;
    spec.contact.friction = 0.25;
    spec.contact.wall_friction = 0.25;
    spec.contact.restitution = 0.3;
    spec.contact.t_contact_nd = getenv("GF_TEST_TC") ? atof(getenv("GF_TEST_TC")) : 0.02;
    if (getenv("GF_TEST_PHI"))
        gf_run_spec_set_param(&ctx, &spec, "phi_target", atof(getenv("GF_TEST_PHI")));
    if (getenv("GF_TEST_POUR"))
        gf_run_spec_set_param(&ctx, &spec, "free_pour", atof(getenv("GF_TEST_POUR")));
    if (getenv("GF_TEST_RANDOM_WALLS"))
        gf_run_spec_set_param(&ctx, &spec, "random_walls", atof(getenv("GF_TEST_RANDOM_WALLS")));
    if (getenv("GF_TEST_DROP"))
        gf_run_spec_set_param(&ctx, &spec, "floor_drop_over_D", atof(getenv("GF_TEST_DROP")));
    gf_run_spec_set_param(&ctx, &spec, "side_over_D", side);
    gf_run_spec_set_param(&ctx, &spec, "fill_height_over_D", fill);
    double t0 = runner_now_s();
    gf_sim *sim = runner_create(&ctx, &spec);
    if (!sim)
        return NULL;
    double t1 = runner_now_s(), phi_local;
    gf_scene_find("janssen")->initial_packing(sim, &o->c_tot, &phi_local);
    runner_until_done(sim, 40.0, 1.0);
    o->build_s = t1 - t0, o->settle_s = runner_now_s() - t1;
    return sim;
}

/*
 * Free surface, interior Phi and the effective cross-section: the area the
 * packing fills at its interior solid fraction (the grains of the first layer
 * nest into the glued walls, so the free box S^2 underestimates it).
 */
static void section(gf_sim *sim, double S, silo *o)
{
    const gf_particles *p = gf_sim_particles(sim);
    double D = gf_sim_spec(sim)->grains.diameter_m;
    gf_measure_domain dom;
    gf_sim_box(sim, dom.lo_m, dom.hi_m, dom.periodic);
    static double phi[NP];
    gf_ctx ctx = {0};
    o->n = (int)fmin(NP, ceil(dom.hi_m[1] / D));
    /* free surface: half-plateau of the slab solid fraction (footprint of the box incl. the glued layers) */
    gf_measure_profile_y(&ctx, p, &dom, 0.0, D, o->n, phi, NULL);
    o->top = gf_measure_bed_height_m(phi, o->n, 0.0, D, 0.5);
    double vol = 0.0, mass = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        if (!(p->flags[i] & GF_P_GLUED))
            vol += 4.0 / 3.0 * M_PI * pow(p->radius_m[i], 3), mass += p->mass_kg[i];
    double lo[3] = {1.5 * D, 3.0 * D, 1.5 * D}, hi[3] = {S - 1.5 * D, o->top - 3.0 * D, S - 1.5 * D};
    o->phi_int = gf_measure_solid_fraction_box(p, &dom, lo, hi, D / 8.0, 0);
    double A = vol / (o->phi_int * o->top);
    o->side_eff = sqrt(A), o->rho_e = mass / (A * o->top), o->grains = p->n_local;
}

/* Wall load per slab: minus the vertical force the grains put on the glued grains of the slab (shear),
 * and the horizontal force normal to their wall (normal). */
static void wall_loads(gf_sim *sim, double S, int n, double *shear, double *normal)
{
    const gf_particles *p = gf_sim_particles(sim);
    double D = gf_sim_spec(sim)->grains.diameter_m;
    for (int k = 0; k < n; ++k)
        shear[k] = normal[k] = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        if (p->flags[i] & GF_P_GLUED) {
            int k = (int)floor(p->y_m[i] / D);
            int on_x = p->x_m[i] < 0.0 || p->x_m[i] > S; /* x walls hold the corner columns */
            if (k >= 0 && k < n)
                shear[k] -= p->fy_N[i], normal[k] += fabs(on_x ? p->fx_N[i] : p->fz_N[i]);
        }
}

/* Janssen fit from the top down, skipping the lowest 3 D where the floor lets the pressure rise again. */
static void fit(double D, double S, silo *o)
{
    static double dd[NP], ss[NP];
    int m = 0;
    for (int k = 3; k < o->n; ++k) {
        double yk = (k + 0.5) * D;
        if (yk < o->top)
            dd[m] = o->top - yk, ss[m] = o->sig[k], ++m;
    }
    gf_ctx ctx = {0};
    GF_CHECK_OK(gf_measure_fit_janssen(&ctx, dd, ss, m, 0.2 * D, 100.0 * S, &o->s_inf, &o->lambda, &o->rms), &ctx);
}

/*
 * Local estimate, the thesis' wall-stress method (2.14)-(2.15) over the lower
 * half: f_p = wall shear / wall normal stress and K = wall normal / vertical
 * stress, each a ratio of sums over the region (the glued rows are 1.1 D
 * apart, so one 1 D slab in 11 holds no wall grain: a mean of per-slab ratios
 * would count it as a zero).
 */
static void local(double D, const double *shear, const double *normal, silo *o)
{
    double fp = 0.0, kk = 0.0, sk = 0.0;
    int n_low = 0;
    o->s_low = o->d_low = 0.0;
    for (int k = 3; k < o->n; ++k) {
        double yk = (k + 0.5) * D;
        if (yk < 0.5 * o->top && o->sig[k] > 0.0) {
            o->s_low += o->sig[k], o->d_low += o->top - yk, ++n_low;
            fp += shear[k], kk += normal[k], sk += o->sig[k];
        }
    }
    o->s_low /= n_low, o->d_low /= n_low;
    o->fp = fp / kk;
    o->kk = kk / (4.0 * o->side_eff * D * sk);
    o->loc = o->fp * o->kk;
}

/* K as the redirection of the granular stress tensor (2.11), sigma^p_xx = sigma^p_zz = K sigma^p_yy, with
 * sigma^p coarse-grained (2.16)-(2.20) over footprint fp, summed over the 1 D slabs of the lower half that
 * local() uses: (S_xx + S_zz) / (2 S_yy). */
static double tensor_k(gf_sim *sim, const double fp[4], double D, const silo *o)
{
    static double S[6 * NP];
    gf_ctx ctx = {0};
    GF_CHECK_OK(gf_sim_stress_tensor_slabs_in(sim, fp, 0.0, D, o->n, S), &ctx);
    double h = 0.0, v = 0.0;
    for (int k = 3; k < o->n; ++k)
        if ((k + 0.5) * D < 0.5 * o->top && o->sig[k] > 0.0)
            h += 0.5 * (S[6 * k] + S[6 * k + 2]), v += S[6 * k + 1];
    return h / v;
}

/* K from the tensor over the column's section [0, S]^2 (contacts with the glued grains counted up to the
 * wall face) and over the interior 1.5 D inside the walls; f_p K with the former. */
static void bulk_k(gf_sim *sim, double D, double S, silo *o)
{
    const double section[4] = {0.0, S, 0.0, S}, inner[4] = {1.5 * D, S - 1.5 * D, 1.5 * D, S - 1.5 * D};
    o->k_bulk = tensor_k(sim, section, D, o);
    o->k_inner = tensor_k(sim, inner, D, o);
    o->loc_bulk = o->fp * o->k_bulk;
}

/* Measures one settled column: section, stress profile, the three f_p K estimates. */
static void measure(gf_sim *sim, double side, silo *o)
{
    const gf_run_spec *spec = gf_sim_spec(sim);
    double D = spec->grains.diameter_m, S = side * D, g = spec->gravity_m_s2;
    section(sim, S, o);
    double A = o->side_eff * o->side_eff, perim = 4.0 * o->side_eff;
    gf_ctx ctx = {0};
    GF_CHECK_OK(gf_measure_silo_vertical_stress(&ctx, gf_sim_particles(sim), g, A, 0.0, D, o->n, o->sig), &ctx);
    wall_loads(sim, S, o->n, o->shear, o->normal);
    o->plane_share = runner_silo_plane_share(sim, S);
    fit(D, S, o);
    local(D, o->shear, o->normal, o);
    bulk_k(sim, D, S, o);
    o->fpk = A / (perim * o->lambda);
    o->fpk_inv = o->rho_e * g * A / (o->s_inf * perim); /* the seed's inverse method (2.13), from the plateau */
    /* the seed's plateau is the mean pressure P_G = tr(sigma^p)/3; with Janssen's redirection
     * (horizontal = K vertical) P_G = sigma_v (1 + 2K)/3, and (2.13) with it reads */
    o->fpk_inv_pg = o->rho_e * g * A / (o->s_inf * (1.0 + 2.0 * o->kk) / 3.0 * perim);
}

static void print_silo(double side, double fill, unsigned seed, double D, double g, const silo *o)
{
    double S = side * D;
    printf("Janssen %.0f D x %.0f D, packing seed %u: %zu grains, C_tot %.4f (of the free box), interior Phi %.4f, "
           "top %.2f D, effective side %.2f D, rho_e %.1f kg/m3\n",
           side, fill, seed, o->grains, o->c_tot, o->phi_int, o->top / D, o->side_eff / D, o->rho_e);
    printf("  fit: sigma_inf = %.1f Pa (rho_e g lambda = %.1f Pa), lambda = %.2f D, f_p K = %.3f "
           "(with the free box side: %.3f), rms %.1f Pa\n",
           o->s_inf, o->rho_e * g * o->lambda, o->lambda / D, o->fpk, S / (4.0 * o->lambda), o->rms);
    printf("  inverse (2.13), rho_e g S / (P_inf P_m) with the fitted plateau: f_p K = %.3f (vertical stress), "
           "%.3f (P_G = sigma_v (1 + 2K)/3, the seed's pressure)\n",
           o->fpk_inv, o->fpk_inv_pg);
    printf("  local (2.14)-(2.15), lower half: f_p = wall shear / normal = %.3f (mu_c 0.25), K = wall normal / "
           "vertical = %.3f, f_p K = %.3f; seed 0.30 +- 0.06; safety planes behind the glued walls carry %.1f %% "
           "of the side load\n",
           o->fp, o->kk, o->loc, 100.0 * o->plane_share);
    printf("  K from the granular stress tensor (2.11), lower half: (S_xx + S_zz) / (2 S_yy) = %.3f over the "
           "section, %.3f 1.5 D inside the walls; f_p K = %.3f with the section's\n",
           o->k_bulk, o->k_inner, o->loc_bulk);
    printf("  sigma_yy by depth (d/D: Pa):");
    for (int k = o->n - 1; k >= 0; --k) {
        double dk = o->top - (k + 0.5) * D;
        if (dk > 0 && ((int)(dk / D) % 4 == 0))
            printf(" %.0f:%.0f", dk / D, o->sig[k]);
    }
    /* bins of 11 slabs hold 10 glued rows (spacing 1.1 D) each */
    printf("\n  local f_p K by height, bins of 11 D (y/D from-to: f_p, K, f_p K):");
    for (int b0 = 3; b0 + 11 <= o->n && (b0 + 11) * D < o->top; b0 += 11) {
        double sh = 0.0, no = 0.0, sg = 0.0;
        for (int k = b0; k < b0 + 11; ++k)
            sh += o->shear[k], no += o->normal[k], sg += o->sig[k];
        double kk = no / (4.0 * o->side_eff * D * sg);
        printf(" %d-%d: %.3f, %.3f, %.3f", b0, b0 + 11, sh / no, kk, sh / no * kk);
    }
    printf("\n  lower half: mean sigma %.1f Pa at mean depth %.1f D (hydrostatic %.1f Pa)\n", o->s_low,
           o->d_low / D, o->rho_e * g * o->d_low);
    printf("  build %.1f s, settle %.1f s\n", o->build_s, o->settle_s);
    fflush(stdout);
}

/* Claims every realisation must meet: saturation, the law's own consistency, the interior Phi. */
static void check_silo(double g, const silo *o)
{
    GF_CHECK_ABS(o->phi_int, 0.59, 0.02);
    GF_CHECK_REL(o->s_inf, o->rho_e * g * o->lambda, 0.15);
    GF_CHECK_REL(o->s_low, o->s_inf, 0.15);
    GF_CHECK(o->s_low < 0.5 * o->rho_e * g * o->d_low);
    /* the horizontal stress the walls receive is the column's: K from the wall loads and K from the stress
     * tensor over the section agree within 10 % (branch vectors reaching the glued centres, not clipped at
     * the face, would read ~10 % more for S = 10 D) */
    GF_CHECK(fabs(o->k_bulk / o->kk - 1.0) < 0.10);
    /* the glued walls hold the column: the frictionless planes behind them are a safety net only (a random
     * layer without its backing put 10.7 % of the side load on them) */
    GF_CHECK(o->plane_share < 0.01);
}

/* Mean and sd over the seeds of one field of silo, printed with `digits` decimals; returns the mean. */
static double over_seeds(const silo *o, int ns, size_t offset, const char *name, int digits)
{
    double x[NS], mean, sd;
    for (int s = 0; s < ns; ++s)
        x[s] = *(const double *)((const char *)&o[s] + offset);
    runner_mean_sd(x, ns, &mean, &sd);
    printf("  %-30s %.*f +- %.*f (sd) over %d seed(s):", name, digits, mean, digits, sd, ns);
    for (int s = 0; s < ns; ++s)
        printf(" %.*f", digits, x[s]);
    printf("\n");
    return mean;
}

int main(int argc, char **argv)
{
    int argi, ns = runner_seeds(argc, argv, &argi, NS);
    double side = argc > argi ? atof(argv[argi]) : 6.0, fill = argc > argi + 1 ? atof(argv[argi + 1]) : 30.0;
    unsigned seed0 = getenv("GF_TEST_SEED") ? (unsigned)atoi(getenv("GF_TEST_SEED")) : 1u;
    static silo o[NS];
    double D = 0.01, g = 9.81, t0 = runner_now_s();
    for (int s = 0; s < ns; ++s) {
        gf_sim *sim = settle(side, fill, seed0 + (unsigned)s, &o[s]);
        if (!sim)
            return gf_test_finish();
        D = gf_sim_spec(sim)->grains.diameter_m, g = gf_sim_spec(sim)->gravity_m_s2;
        measure(sim, side, &o[s]);
        print_silo(side, fill, seed0 + (unsigned)s, D, g, &o[s]);
        check_silo(g, &o[s]);
        gf_sim_destroy(&sim);
    }
    printf("Janssen %.0f D x %.0f D, packing seeds %u-%u (%.0f s wall):\n", side, fill, seed0, seed0 + (unsigned)ns - 1,
           runner_now_s() - t0);
    over_seeds(o, ns, offsetof(silo, s_inf), "plateau sigma_inf (Pa)", 1);
    over_seeds(o, ns, offsetof(silo, fp), "local f_p", 3);
    over_seeds(o, ns, offsetof(silo, kk), "local K", 3);
    over_seeds(o, ns, offsetof(silo, fpk_inv_pg), "f_p K inverse with P_G", 3);
    double fpk = over_seeds(o, ns, offsetof(silo, fpk), "f_p K fit (A / (P lambda))", 3);
    double inv = over_seeds(o, ns, offsetof(silo, fpk_inv), "f_p K inverse (2.13)", 3);
    double loc = over_seeds(o, ns, offsetof(silo, loc), "f_p K local (2.14)-(2.15)", 3);
    over_seeds(o, ns, offsetof(silo, k_bulk), "K from sigma^p, section", 3);
    over_seeds(o, ns, offsetof(silo, k_inner), "K from sigma^p, interior", 3);
    over_seeds(o, ns, offsetof(silo, loc_bulk), "f_p K, K from sigma^p", 3);
    GF_CHECK(fpk >= 0.24 && fpk <= 0.36);
    GF_CHECK(inv >= 0.24 && inv <= 0.36);
    GF_CHECK(loc >= 0.24 && loc <= 0.36);
    return gf_test_finish();
}
