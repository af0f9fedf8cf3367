/*
 * A sphere falling onto a wall in a viscous fluid through the resolved tier
 * (the `bounce` scene): Izard, Bonometti & Lacaze, J. Fluid Mech. 747 (2014)
 * = Izard 2014 §3.1, against Gondret, Lance & Petit, Phys. Fluids 14 (2002).
 *
 * Default case (Izard 2014 §3.1.5, Fig. 3.3): rho_p/rho = 8, Ar = 3700
 * (eta_f = 0.25 Pa s, rho = 1000 kg/m3, D = 15 mm), eps_max = 0.97,
 * t_c sqrt(g/D) = 2.5e-3, mu_c = 0.25, eta_e/R = 4e-4, lubrication cut-off R/2:
 * St ~ 60, and the thesis finds eps = -V_R/V_T = 0.63 (eps/eps_max = 0.65; Gondret
 * et al. measure ~0.6 near St 60); without lubrication 0.98 (several bounces).
 *
 * Measured, sampling every DEM step near the wall, with the definitions of the
 * `bounce` post stage (postproc/stages/gf_bounce_measure.h, one definition for both):
 *   V_T  the largest approach speed while the gap exceeds R (terminal or nearly),
 *   V_I  the approach speed just before the first contact (last sample with gap > 0),
 *   V_R  the first maximum of the upward velocity after that contact starts,
 *   St = (rho_p + rho/2) V_T D / (9 eta) (Izard eq. (3.19)), St_I = rho_p V_I D / (9 eta)
 *   (Gondret et al. 2002), e = V_R/V_I, eps = V_R/V_T, the contact time (gap <= 0 during
 *   the first contact).
 * Usage: resolved_bounce [dx=D/dx] [box=] [height=] [depth=] [end=] [ratio=] [Ar=] [eta_e=] [lub=0|1] [overlap=clamp|off|film] [correct=0|1]
 *        [threads=n] [ibm=smoothed|markers] [retract=c] [check=st60|model|overestimate]
 *   ibm, retract: fluid.ibm_forcing and fluid.ibm_retraction_dx (coupling/gf_ibm_markers.h).
 *   overlap: fluid.lub_overlap, the film while the surfaces overlap (contact/gf_lubrication.h).
 *   check=st60: eps within +-0.05 of the thesis' 0.63.
 *   check=model: eps/eps_max within +-0.05 of the thesis' rebound model at the run's St,
 *     Izard 2014 eq. (3.31), eps/eps_max = (1 - St_c/St) exp(-(pi/2)/sqrt(St - St_c)) with
 *     St_c = ln(R/eta_e), 0 below St_c: the fit without adjustable constant that the thesis
 *     finds inside the scatter of Gondret et al. (2002) and Joseph et al. (2001) (its Fig. 3.5).
 *   check=overestimate: (lub=0) eps/eps_max at least 0.1 above that model, the overestimate the
 *     thesis reports without lubrication below St ~ 200 (§3.1.5).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/gf_timer.h"
#include "gf_sim.h"
#include "gf_test.h"
#include "gf_test_args.h"
#include "stages/gf_bounce_measure.h"

/* the sampled trace: time, vertical velocity, gap to the wall */
typedef struct trace {
    double *t, *v, *gap;
    size_t n, cap;
} trace;

static int trace_push(trace *tr, double t, double v, double gap)
{
    if (tr->n == tr->cap) {
        size_t cap = tr->cap ? 2 * tr->cap : 4096;
        double *a = realloc(tr->t, cap * sizeof *a), *b = a ? realloc(tr->v, cap * sizeof *b) : NULL;
        double *c = b ? realloc(tr->gap, cap * sizeof *c) : NULL;
        if (a) tr->t = a;
        if (b) tr->v = b;
        if (!c)
            return -1;
        tr->gap = c, tr->cap = cap;
    }
    tr->t[tr->n] = t, tr->v[tr->n] = v, tr->gap[tr->n] = gap;
    tr->n++;
    return 0;
}

typedef struct args {
    double dx, box, height, depth, end, ratio, Ar, eta_e, retract;
    int lub, threads; /* threads: OpenMP threads of the run (0: the library default) */
    int correct;                   /* fluid.ibm_contact_correction */
    char check[16], ibm[16], overlap[16]; /* overlap: fluid.lub_overlap (clamp, off, film) */
} args;

static void parse(int argc, char **argv, args *a)
{
    *a = (args){.dx = 8, .box = 6, .height = 24, .depth = 4, .end = 24, .ratio = 8, .Ar = 3700, .eta_e = 4e-4,
                .lub = 1, .correct = 1};
    snprintf(a->check, sizeof a->check, "none");
    snprintf(a->ibm, sizeof a->ibm, "smoothed");
    snprintf(a->overlap, sizeof a->overlap, "clamp");
    const gf_test_arg keys[] = {
        {.key = "dx", .number = &a->dx}, {.key = "box", .number = &a->box}, {.key = "height", .number = &a->height},
        {.key = "depth", .number = &a->depth}, {.key = "end", .number = &a->end}, {.key = "ratio", .number = &a->ratio},
        {.key = "Ar", .number = &a->Ar}, {.key = "eta_e", .number = &a->eta_e}, {.key = "lub", .integer = &a->lub},
        {.key = "overlap", .text = a->overlap, .text_size = sizeof a->overlap}, {.key = "threads", .integer = &a->threads},
        {.key = "correct", .integer = &a->correct}, {.key = "check", .text = a->check, .text_size = sizeof a->check},
        {.key = "ibm", .text = a->ibm, .text_size = sizeof a->ibm}, {.key = "retract", .number = &a->retract}};
    gf_test_parse_args(argc, argv, keys, sizeof keys / sizeof keys[0]);
}

/* Izard 2014 eq. (3.31): the restitution of the two-stage model (the film's approach, then the contact
 * damped by the film) over eps_max, at Stokes number St and roughness eta_e/R. */
static double rebound_model(double St, double eta_e_over_R)
{
    const double St_c = log(1.0 / eta_e_over_R);
    return St <= St_c ? 0.0 : (1.0 - St_c / St) * exp(-0.5 * M_PI / sqrt(St - St_c));
}

int main(int argc, char **argv)
{
    args a;
    parse(argc, argv, &a);
    const double rho = 1000.0, g = 9.81, eta = 0.25;
    const double D = cbrt(a.Ar * eta * eta / (rho * rho * (a.ratio - 1.0) * g)); /* Ar = drho/rho g D^3/nu^2 */
    gf_ctx ctx = {0};
    gf_run_spec spec;
    gf_run_spec_defaults(&spec);
    snprintf(spec.scene, sizeof spec.scene, "bounce");
    spec.grains = (gf_grains_spec){.diameter_m = D, .polydispersity = 0.0, .density_kg_m3 = a.ratio * rho};
    spec.contact.restitution = 0.97;
    spec.contact.t_contact_nd = 2.5e-3;
    spec.contact.friction = spec.contact.wall_friction = 0.25;
    snprintf(spec.fluid.model, sizeof spec.fluid.model, "resolved");
    spec.fluid.density_kg_m3 = rho;
    spec.fluid.viscosity_Pa_s = eta;
    spec.fluid.lubrication = a.lub;
    spec.fluid.roughness_over_R = a.eta_e;
    spec.fluid.lub_cutoff_over_R = 0.5;
    snprintf(spec.fluid.lub_overlap, sizeof spec.fluid.lub_overlap, "%s", a.overlap);
    spec.fluid.d_over_dx = a.dx;
    spec.fluid.ibm_retraction_dx = a.retract;
    spec.fluid.ibm_contact_correction = a.correct;
    snprintf(spec.fluid.ibm_forcing, sizeof spec.fluid.ibm_forcing, "%s", a.ibm);
    spec.end_time_nd = a.end;
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "box_over_D", a.box), &ctx);
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "height_over_D", a.height), &ctx);
    GF_CHECK_OK(gf_run_spec_set_param(&ctx, &spec, "release_depth_over_D", a.depth), &ctx);
    gf_sim_options opt = {.n_threads = a.threads};
    gf_sim *sim = NULL;
    GF_CHECK_OK(gf_sim_create(&ctx, &spec, &opt, &sim), &ctx);
    if (!sim)
        return gf_test_finish();
    const double tg = sqrt(D / g), ug = sqrt(g * D), R = 0.5 * D;
    const gf_particles *p = gf_sim_particles(sim);
    double next_print = 0.0;
    trace tr = {0};
    double t0 = gf_wtime(), c0 = (double)clock() / CLOCKS_PER_SEC;
    printf("# t sqrt(g/D)   u_y/sqrt(gD)   gap/D\n");
    while (gf_sim_time_s(sim) < a.end * tg) {
        double gap = p->y_m[0] - R;
        /* far from the wall: fluid-step-sized chunks; near it: every DEM step */
        long n = gap > 0.6 * D ? 50 : 1;
        gf_status st = gf_sim_advance(sim, n);
        if (st != GF_OK) {
            GF_CHECK_OK(st, &ctx);
            break;
        }
        double t = gf_sim_time_s(sim), v = p->vy_m_s[0];
        gap = p->y_m[0] - R;
        if (trace_push(&tr, t, v, gap) != 0) {
            GF_CHECK(!"out of memory for the trace");
            break;
        }
        if (t >= next_print) {
            printf("%.4f %.5f %.5f\n", t / tg, v / ug, gap / D);
            next_print = t + (gap > 0.6 * D ? 0.25 : 0.02) * tg;
        }
    }
    gf_bounce b;
    gf_bounce_measure(tr.t, tr.v, tr.gap, tr.n, R, &b);
    double VT = b.V_T, VI = b.V_I, e = b.e, eps = b.eps;
    double St = (a.ratio + 0.5) * rho * VT * D / (9.0 * eta), Re = rho * VT * D / eta;
    double St_I = a.ratio * rho * VI * D / (9.0 * eta);
    printf("resolved bounce: D/dx %g, box %g x %g D, rho_p/rho %g, Ar %g, eta_e/R %g, lubrication %d (in overlap %s): V_T = %.4f sqrt(gD) "
           "(Re %.1f, St %.1f, St_I %.1f), V_I/V_T = %.3f, e = V_R/V_I = %.3f, eps = V_R/V_T = %.3f (eps/eps_max %.3f), contact "
           "%.3g t_c; wall %.0f s, cpu %.0f s\n",
           a.dx, a.box, a.height, a.ratio, a.Ar, a.eta_e, a.lub, a.overlap, VT / ug, Re, St, St_I, VI / VT, e, eps,
           eps / 0.97, b.contact_s / gf_run_spec_t_contact_s(&spec), gf_wtime() - t0,
           (double)clock() / CLOCKS_PER_SEC - c0);
    free(tr.t);
    free(tr.v);
    free(tr.gap);
    /* the end comes early once the sphere is back at rest on the wall after its rebound */
    const double model = rebound_model(St, a.eta_e);
    printf("rebound model (Izard 2014 eq. (3.31)) at St %.1f: eps/eps_max %.3f; run %.3f (%+.3f)\n", St, model,
           eps / 0.97, eps / 0.97 - model);
    if (!strcmp(a.check, "st60"))
        GF_CHECK_ABS(eps, 0.63, 0.05);
    if (!strcmp(a.check, "model"))
        GF_CHECK_ABS(eps / 0.97, model, 0.05);
    if (!strcmp(a.check, "overestimate"))
        GF_CHECK(eps / 0.97 >= model + 0.1);
    gf_sim_destroy(&sim);
    return gf_test_finish();
}
