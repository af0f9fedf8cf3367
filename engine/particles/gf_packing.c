/* Packing preparation to a target Phi_i; the protocol and the measures are in gf_packing.h. */
#include "particles/gf_packing.h"

#include <math.h>
#include <stdlib.h>
#include <time.h>

#include "core/gf_rng.h"
#include "scenes/gf_packing_settle.h"

/* Preparation constants (see gf_packing.h): contact duration and step in
 * sqrt(D/g), restitution, and the terminal speed of the settling drag in
 * sqrt(gD). */
static const double PREP_TC_ND = 0.02, PREP_DT_OVER_TC = 1.0 / 15.0, PREP_RESTITUTION = 0.3;
static const double PREP_TERMINAL_ND = 2.0;

static double container_base_m(const gf_packing_spec *sp)
{
    double base = sp->lo_m[1];
    const gf_particles *o = sp->obstacles;
    if (o)
        for (size_t i = 0; i < o->n_local; ++i) {
            /* only grains under the column footprint and near the floor form the base */
            if (o->y_m[i] < sp->lo_m[1] + 2.0 * sp->psd.mean_radius_m)
                base = fmax(base, o->y_m[i] + o->radius_m[i]);
        }
    return base;
}

/* The grains of a deposit, at rest on nothing yet: a loose jittered lattice
 * of spacing 2.2 x the largest radius (solid fraction ~0.3) over the
 * container footprint, enough grains for a deposit at Phi = 0.66 to reach
 * H + 2D (at any looser Phi the top is higher), each with a small random
 * velocity (0.1 sqrt(gD)). */
static gf_status loose_lattice(gf_ctx *ctx, const gf_packing_spec *sp, gf_particles *out)
{
    const double D = 2.0 * sp->psd.mean_radius_m, g = sp->gravity_m_s2, H = sp->hi_m[1];
    const double base = container_base_m(sp), r_max = gf_psd_max_radius_m(&sp->psd);
    double len[3];
    int per[3];
    for (int c = 0; c < 3; ++c)
        len[c] = sp->hi_m[c] - sp->lo_m[c], per[c] = c == 1 ? 0 : sp->periodic[c];
    size_t n_mob = (size_t)ceil(0.66 * len[0] * len[2] * (H - base + 2.0 * D) / gf_psd_mean_volume_m3(&sp->psd));
    GF_TRY(gf_particles_reserve(ctx, out, out->n_local + n_mob));
    gf_rng rng;
    gf_rng_seed(&rng, sp->seed);
    const double spacing = 2.2 * r_max, margin_w = 1.05 * r_max;
    int nl[3];
    double x0[3], step[3];
    for (int c = 0; c < 3; c += 2) {
        double avail = len[c] - (per[c] ? 0.0 : 2.0 * margin_w);
        nl[c] = (int)floor(avail / spacing) + (per[c] ? 0 : 1);
        if (nl[c] < 1)
            nl[c] = 1;
        step[c] = per[c] ? len[c] / nl[c] : (nl[c] > 1 ? avail / (nl[c] - 1) : 0.0);
        x0[c] = sp->lo_m[c] + (per[c] ? 0.5 * step[c] : margin_w);
        if (!per[c] && nl[c] == 1)
            x0[c] = 0.5 * (sp->lo_m[c] + sp->hi_m[c]);
    }
    const double jit = 0.1 * (spacing - 2.0 * r_max);
    for (size_t i = 0; i < n_mob; ++i) {
        size_t layer = i / (size_t)(nl[0] * nl[2]), in = i % (size_t)(nl[0] * nl[2]);
        int a = (int)(in % (size_t)nl[0]), b = (int)(in / (size_t)nl[0]);
        double x = x0[0] + a * step[0] + gf_rng_range(&rng, -jit, jit);
        double y = base + margin_w + 0.1 * D + (double)layer * spacing + gf_rng_range(&rng, -jit, jit);
        double z = x0[2] + b * step[2] + gf_rng_range(&rng, -jit, jit);
        double r = gf_psd_draw_radius_m(&sp->psd, &rng);
        size_t k;
        GF_TRY(gf_particles_add(ctx, out, x, y, z, r, sp->density_kg_m3, 0, &k));
        out->vx_m_s[k] = 0.1 * sqrt(g * D) * gf_rng_normal(&rng);
        out->vy_m_s[k] = 0.1 * sqrt(g * D) * gf_rng_normal(&rng);
        out->vz_m_s[k] = 0.1 * sqrt(g * D) * gf_rng_normal(&rng);
    }
    return GF_OK;
}

static void control_box(const gf_packing_spec *sp, double lo[3], double hi[3])
{
    double D = 2.0 * sp->psd.mean_radius_m;
    double m = sp->interior_margin_m > 0.0 ? sp->interior_margin_m : 1.5 * D;
    for (int c = 0; c < 3; ++c) {
        int open = c == 1 || !sp->periodic[c];
        lo[c] = sp->lo_m[c] + (open ? m : 0.0);
        hi[c] = sp->hi_m[c] - (open ? m : 0.0);
    }
    lo[1] = container_base_m(sp) + m;
}

/* Copies the grains of s with centre at or below y_max into out, at rest. */
static gf_status export_grains(gf_ctx *ctx, const gf_particles *s, const gf_packing_spec *sp, double y_max,
                               gf_particles *out)
{
    for (size_t i = 0; i < s->n_local; ++i)
        if (s->y_m[i] <= y_max)
            GF_TRY(gf_particles_add(ctx, out, s->x_m[i], s->y_m[i], s->z_m[i], s->radius_m[i], sp->density_kg_m3, 0,
                                    NULL));
    return GF_OK;
}

static gf_status check_spec(gf_ctx *ctx, const gf_packing_spec *sp)
{
    GF_TRY(gf_psd_check(ctx, &sp->psd));
    double D = 2.0 * sp->psd.mean_radius_m;
    for (int c = 0; c < 3; ++c)
        if (!(sp->hi_m[c] - sp->lo_m[c] >= 2.0 * D))
            return GF_FAIL(ctx, GF_ERR_CONFIG, "packing: container axis %d is %g m long, below 2 D = %g m", c,
                           sp->hi_m[c] - sp->lo_m[c], 2.0 * D);
    if (sp->periodic[1])
        return GF_FAIL(ctx, GF_ERR_CONFIG, "packing: the vertical axis cannot be periodic");
    if (!(sp->density_kg_m3 > 0.0) || !(sp->gravity_m_s2 > 0.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "packing: grain density and gravity must be > 0");
    if (sp->relax.mu > 0.0 && !(sp->relax.t_contact_s > 0.0 && sp->relax.restitution > 0.0 &&
                                sp->relax.restitution <= 1.0))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "packing: the relaxation needs t_c > 0 and 0 < eps <= 1 (got %g s, %g)",
                       sp->relax.t_contact_s, sp->relax.restitution);
    if (sp->free_pour && !isnan(sp->phi_target))
        return GF_FAIL(ctx, GF_ERR_CONFIG,
                       "packing: a free pour takes the packing it reaches; phi_initial %g cannot be requested with it",
                       sp->phi_target);
    if (!isnan(sp->phi_target) && !(sp->phi_target >= 0.5 && sp->phi_target <= 0.645))
        return GF_FAIL(ctx, GF_ERR_PHYSICS,
                       "packing: phi_initial %g outside what deposition can build [0.50, 0.645]", sp->phi_target);
    return GF_OK;
}

double gf_packing_solid_fraction_box(const gf_particles *p, const double dom_lo[3], const double dom_hi[3],
                                     const int periodic[3], const double lo[3], const double hi[3], double h,
                                     int include_glued)
{
    long n[3];
    for (int c = 0; c < 3; ++c) {
        n[c] = (long)floor((hi[c] - lo[c]) / h);
        if (n[c] < 1)
            return NAN;
    }
    size_t total = (size_t)n[0] * (size_t)n[1] * (size_t)n[2];
    uint8_t *mark = calloc(total, 1);
    if (!mark)
        return NAN;
    /* lattice point (a, b, c) sits at lo + (index + 1/2) h: cell-centred sampling */
    for (size_t i = 0; i < p->n_local; ++i) {
        if (!include_glued && (p->flags[i] & GF_P_GLUED))
            continue;
        double r = p->radius_m[i];
        double ctr[3] = {p->x_m[i], p->y_m[i], p->z_m[i]};
        /* periodic images: shifts -L, 0, +L on periodic axes */
        for (int sx = -1; sx <= 1; ++sx)
            for (int sz = -1; sz <= 1; ++sz) {
                int shift[3] = {sx, 0, sz};
                double c3[3];
                int skip = 0;
                for (int c = 0; c < 3; ++c) {
                    if (shift[c] != 0 && !periodic[c]) {
                        skip = 1;
                        break;
                    }
                    c3[c] = ctr[c] + shift[c] * (dom_hi[c] - dom_lo[c]);
                }
                if (skip)
                    continue;
                long a0[3], a1[3];
                int empty = 0;
                for (int c = 0; c < 3; ++c) {
                    a0[c] = (long)ceil((c3[c] - r - lo[c]) / h - 0.5);
                    a1[c] = (long)floor((c3[c] + r - lo[c]) / h - 0.5);
                    if (a0[c] < 0)
                        a0[c] = 0;
                    if (a1[c] > n[c] - 1)
                        a1[c] = n[c] - 1;
                    if (a1[c] < a0[c])
                        empty = 1;
                }
                if (empty)
                    continue;
                double r2 = r * r;
                for (long a = a0[0]; a <= a1[0]; ++a) {
                    double dx = lo[0] + (a + 0.5) * h - c3[0];
                    for (long b = a0[1]; b <= a1[1]; ++b) {
                        double dy = lo[1] + (b + 0.5) * h - c3[1];
                        double rem = r2 - dx * dx - dy * dy;
                        if (rem < 0.0)
                            continue;
                        for (long k = a0[2]; k <= a1[2]; ++k) {
                            double dz = lo[2] + (k + 0.5) * h - c3[2];
                            if (dz * dz <= rem)
                                mark[((size_t)k * (size_t)n[1] + (size_t)b) * (size_t)n[0] + (size_t)a] = 1;
                        }
                    }
                }
            }
    }
    size_t count = 0;
    for (size_t q = 0; q < total; ++q)
        count += mark[q];
    free(mark);
    return (double)count / (double)total;
}

/* One deposit (owned store *s of the settled grains) and its interior Phi:
 * the grains settle at mu_prep with the preparation's contacts, then, with
 * relax.mu > 0, relax with the run's contacts from unloaded tangential
 * springs (a new phase starts without contact history; gf_packing.h, step 3). */
static gf_status deposit(gf_ctx *ctx, const gf_packing_spec *sp, double mu_prep, gf_particles **s, double *phi_local)
{
    GF_TRY(check_spec(ctx, sp));
    const double D = 2.0 * sp->psd.mean_radius_m, t_unit = sqrt(D / sp->gravity_m_s2);
    /* g tau = terminal speed PREP_TERMINAL_ND sqrt(gD); a free pour has no drag and free rotations */
    const gf_packing_phase prep = {.t_contact_s = PREP_TC_ND * t_unit, .restitution = PREP_RESTITUTION,
                                   .mu = mu_prep, .dt_over_tc = PREP_DT_OVER_TC, .rotation_locked = !sp->free_pour,
                                   .drag_time_s = sp->free_pour ? INFINITY : PREP_TERMINAL_ND * t_unit};
    gf_status st = gf_particles_create(ctx, 1024, s);
    if (st == GF_OK)
        st = loose_lattice(ctx, sp, *s);
    if (st == GF_OK)
        st = gf_packing_settle(ctx, sp, &prep, *s);
    if (st == GF_OK && sp->relax.mu > 0.0) {
        gf_packing_phase relax = prep;
        relax.t_contact_s = sp->relax.t_contact_s, relax.restitution = sp->relax.restitution, relax.mu = sp->relax.mu;
        st = gf_packing_settle(ctx, sp, &relax, *s);
    }
    if (st != GF_OK) {
        gf_particles_destroy(s);
        return st;
    }
    /* interior Phi of the untrimmed deposit: the control box ends a margin below H */
    double lo[3], hi[3];
    control_box(sp, lo, hi);
    *phi_local = gf_packing_solid_fraction_box(*s, sp->lo_m, sp->hi_m, sp->periodic, lo, hi,
                                               sp->psd.mean_radius_m / 8.0, 0);
    return GF_OK;
}

gf_status gf_packing_deposit(gf_ctx *ctx, const gf_packing_spec *sp, double mu_prep, gf_particles *out,
                             double *phi_local)
{
    gf_particles *s = NULL;
    GF_TRY(deposit(ctx, sp, mu_prep, &s, phi_local));
    gf_status st = export_grains(ctx, s, sp, INFINITY, out);
    gf_particles_destroy(&s);
    return st;
}

/* First guess of mu_prep for a target, from the calibration of this protocol
 * (6D x 3D periodic footprint, 12D deep, seed 7): Phi = 0.6375 at mu = 0,
 * 0.612 at 0.1, 0.578 at 0.2, 0.557 at 0.3, 0.518 at 0.4; further up the
 * non-rolling grains arch across narrow boxes and the deposit becomes a
 * loose skeleton, hence MU_MAX = 0.4. Only a starting point: the table
 * comes from an earlier integrator of the preparation; the engine's deposits
 * of that bed give 0.640, 0.608, 0.573, 0.527, 0.493 (a few 1e-3 to 0.03
 * looser at mu >= 0.2), which the regula falsi corrects within its first
 * deposits. */
static double mu_guess(double phi)
{
    static const double tab_phi[] = {0.6375, 0.612, 0.578, 0.557, 0.518};
    static const double tab_mu[] = {0.0, 0.10, 0.20, 0.30, 0.40};
    int n = (int)(sizeof tab_phi / sizeof tab_phi[0]);
    if (phi >= tab_phi[0])
        return 0.0;
    for (int k = 1; k < n; ++k)
        if (phi >= tab_phi[k]) {
            double f = (tab_phi[k - 1] - phi) / (tab_phi[k - 1] - tab_phi[k]);
            return tab_mu[k - 1] + f * (tab_mu[k] - tab_mu[k - 1]);
        }
    return tab_mu[n - 1];
}

/* Search of mu_prep (gf_packing.h, step 3). MU_MAX: the most frictional
 * deposit; MU_NOISE: a bracket narrower than this spans less change of Phi
 * than one small deposit's scatter (a control box of a few D samples few
 * grains: 0.01-0.02 between lattice draws at one mu, against a slope
 * dPhi/dmu ~ -0.37); SLOPE_MIN/MAX bound the fitted slope to the range the
 * calibration bed spans (mu_guess). */
static const double MU_MAX = 0.4, MU_NOISE = 0.02, SLOPE_MIN = -0.6, SLOPE_MAX = -0.2;

/* What the search knows: the bracket [mu_lo, mu_hi] with Phi(mu_lo) >= target
 * >= Phi(mu_hi) (Phi decreases with mu), the least-squares sums of every
 * deposit, and whether the bracket has shrunk into the scatter. */
typedef struct mu_search {
    double mu_lo, phi_lo, mu_hi, phi_hi;
    double n, s_mu, s_phi, s_mumu, s_muphi;
    int noisy;
} mu_search;

static void search_add(mu_search *q, double target, double mu, double phi)
{
    if (phi > target)
        q->mu_lo = mu, q->phi_lo = phi;
    else
        q->mu_hi = mu, q->phi_hi = phi;
    q->n += 1.0, q->s_mu += mu, q->s_phi += phi, q->s_mumu += mu * mu, q->s_muphi += mu * phi;
    if (!isnan(q->phi_lo) && !isnan(q->phi_hi) && q->mu_hi - q->mu_lo < MU_NOISE)
        q->noisy = 1;
}

/* The next mu_prep: a step of 0.05 towards the target until both ends are
 * measured, then safeguarded regula falsi (Phi is close to linear in mu over
 * the useful range); once the bracket is inside the scatter, where its ends
 * are as much noise as trend, the mu at which the least-squares line through
 * every deposit meets the target (each deposit then a new draw of the
 * lattice, so that the line averages the scatter out). */
static double search_next(const mu_search *q, double target, double mu)
{
    if (q->noisy) {
        double m_mu = q->s_mu / q->n, m_phi = q->s_phi / q->n, var = q->s_mumu / q->n - m_mu * m_mu;
        double slope = var > 0.0 ? (q->s_muphi / q->n - m_mu * m_phi) / var : SLOPE_MAX;
        slope = fmin(fmax(slope, SLOPE_MIN), SLOPE_MAX);
        return fmin(fmax(m_mu + (target - m_phi) / slope, 0.0), MU_MAX);
    }
    if (!isnan(q->phi_lo) && !isnan(q->phi_hi)) {
        double f = (q->phi_lo - target) / (q->phi_lo - q->phi_hi);
        f = fmin(fmax(f, 0.2), 0.8); /* noise of a finite deposit: stay well inside the bracket */
        return q->mu_lo + f * (q->mu_hi - q->mu_lo);
    }
    return isnan(q->phi_hi) ? fmin(MU_MAX, mu + 0.05) : fmax(0.0, mu - 0.05);
}

gf_status gf_packing_build(gf_ctx *ctx, const gf_packing_spec *sp, gf_particles *out, gf_packing_result *res)
{
    GF_TRY(check_spec(ctx, sp));
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    double tol = sp->tolerance > 0.0 ? sp->tolerance : 0.005;
    int max_it = sp->max_iterations > 0 ? sp->max_iterations : 16;
    gf_particles *best = NULL;
    double best_phi = NAN, best_mu = NAN, best_err = INFINITY;
    int it = 0;
    if (isnan(sp->phi_target)) {
        GF_TRY(deposit(ctx, sp, sp->mu_natural, &best, &best_phi));
        best_mu = sp->mu_natural, it = 1;
    } else {
        mu_search q = {.mu_lo = 0.0, .phi_lo = NAN, .mu_hi = MU_MAX, .phi_hi = NAN};
        double mu = mu_guess(sp->phi_target);
        gf_packing_spec draw = *sp; /* the deposit's lattice: the spec's seed, then new ones (below) */
        for (it = 1; it <= max_it; ++it) {
            gf_particles *s = NULL;
            double phi;
            gf_status st = deposit(ctx, &draw, mu, &s, &phi);
            if (st != GF_OK) {
                gf_particles_destroy(&best);
                return st;
            }
            double err = fabs(phi - sp->phi_target);
            gf_log(ctx, GF_LOG_INFO, "packing: deposit %d at mu_prep = %.4f: Phi_local = %.4f (target %.4f)", it, mu,
                   phi, sp->phi_target);
            if (err < best_err) {
                gf_particles_destroy(&best);
                best = s, s = NULL, best_phi = phi, best_mu = mu, best_err = err;
            } else {
                gf_particles_destroy(&s);
            }
            if (err <= tol)
                break;
            search_add(&q, sp->phi_target, mu, phi);
            if (phi > sp->phi_target && mu >= MU_MAX) {
                gf_particles_destroy(&best);
                return GF_FAIL(ctx, GF_ERR_PHYSICS,
                               "packing: phi_initial %.3f is looser than deposition reaches (%.3f at mu_prep = %g)",
                               sp->phi_target, phi, MU_MAX);
            }
            if (phi < sp->phi_target && mu <= 0.0) {
                gf_particles_destroy(&best);
                return GF_FAIL(ctx, GF_ERR_PHYSICS,
                               "packing: phi_initial %.3f is denser than frictionless deposition reaches (%.3f)",
                               sp->phi_target, phi);
            }
            if (q.noisy)
                draw.seed += 0x9e3779b97f4a7c15ull;
            mu = search_next(&q, sp->phi_target, mu);
        }
        if (best_err > tol) {
            /* a small control box samples few grains: its Phi scatters by more than the tolerance */
            double lo[3], hi[3], D = 2.0 * sp->psd.mean_radius_m;
            control_box(sp, lo, hi);
            gf_particles_destroy(&best);
            return GF_FAIL(ctx, GF_ERR_PHYSICS,
                           "packing: phi_initial %.4f not reached within %.2g in %d deposits (closest %.4f at "
                           "mu_prep = %.4f), measured over an interior box of %.1f x %.1f x %.1f D: a larger "
                           "container or a larger phi_tolerance may help",
                           sp->phi_target, tol, max_it, best_phi, best_mu, (hi[0] - lo[0]) / D, (hi[1] - lo[1]) / D,
                           (hi[2] - lo[2]) / D);
        }
    }
    /* trim at H and export */
    double H = sp->hi_m[1];
    size_t n_before = out->n_local;
    gf_status st = export_grains(ctx, best, sp, H, out);
    gf_particles_destroy(&best);
    GF_TRY(st);
    double vol = 0.0, top = 0.0;
    for (size_t i = n_before; i < out->n_local; ++i) {
        double r = out->radius_m[i];
        vol += 4.0 / 3.0 * M_PI * r * r * r;
        top = fmax(top, out->y_m[i] + r);
    }
    double footprint = (sp->hi_m[0] - sp->lo_m[0]) * (sp->hi_m[2] - sp->lo_m[2]);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    res->phi_global = vol / (footprint * (H - container_base_m(sp)));
    res->phi_local = best_phi;
    res->mu_prep = best_mu;
    res->iterations = it > max_it ? max_it : it;
    res->n_grains = out->n_local - n_before;
    res->top_m = top;
    res->cpu_s = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    res->reused = 0;
    return GF_OK;
}

gf_status gf_packing_rough_base(gf_ctx *ctx, gf_particles *out, const gf_psd *psd, double density, double y,
                                double x0, double x1, double z0, double z1, const int periodic_xz[2], uint64_t seed)
{
    GF_TRY(gf_psd_check(ctx, psd));
    if (!(x1 - x0 > 2.0 * psd->mean_radius_m) || !(z1 - z0 > 2.0 * psd->mean_radius_m))
        return GF_FAIL(ctx, GF_ERR_CONFIG, "packing: rough base of %g x %g m is smaller than one grain", x1 - x0,
                       z1 - z0);
    gf_rng rng;
    gf_rng_seed(&rng, seed ^ 0x9e3779b97f4a7c15ull);
    double lx = x1 - x0, lz = z1 - z0;
    size_t first = out->n_local;
    for (int fails = 0; fails < 500;) {
        double r = gf_psd_draw_radius_m(psd, &rng);
        double x = x0 + lx * gf_rng_uniform(&rng), z = z0 + lz * gf_rng_uniform(&rng);
        /* non-periodic sides: keep the grain inside the strip */
        if ((!periodic_xz[0] && (x - r < x0 || x + r > x1)) || (!periodic_xz[1] && (z - r < z0 || z + r > z1))) {
            ++fails;
            continue;
        }
        int ok = 1;
        for (size_t j = first; j < out->n_local && ok; ++j) {
            double dx = out->x_m[j] - x, dz = out->z_m[j] - z;
            if (periodic_xz[0])
                dx -= lx * round(dx / lx);
            if (periodic_xz[1])
                dz -= lz * round(dz / lz);
            double rr = out->radius_m[j] + r;
            ok = dx * dx + dz * dz >= rr * rr;
        }
        if (!ok) {
            ++fails;
            continue;
        }
        fails = 0;
        GF_TRY(gf_particles_add(ctx, out, x, y, z, r, density, GF_P_GLUED, NULL));
    }
    return GF_OK;
}
