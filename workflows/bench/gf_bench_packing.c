/*
 * gf-bench-packing: cost of the packing preparation (gf_packing.h) for a
 * given number of grains, through the public calls only, so that two builds
 * of the preparation compare side by side (workflows/bench/packing.sh).
 *
 *   gf-bench-packing [--grains N] [--mu MU] [--phi PHI] [--seed S]
 *
 * The container is a square periodic bed (x and z periodic, floor at y = 0),
 * of the immersed collapse's grains (Izard 2014 §5.2: D = 7.6 mm, 5 %
 * polydisperse, 2500 kg/m3), sized so that the deposit holds about N grains
 * (side L = H). One deposit at mu_prep = MU (gf_packing_deposit: the DEM
 * cost alone), then, when --phi is given, the whole preparation to that
 * Phi_i (gf_packing_build: the bisection). Prints the CPU seconds of the
 * process (all threads) of each and the interior Phi reached.
 */
#include <math.h>
#include <stdio.h>

#include "gf_bench_args.h"
#include "gf_bench_clock.h"
#include "particles/gf_packing.h"

typedef struct packing_args {
    long n, seed;
    double mu, phi;
} packing_args;

static const gf_bench_flag flags[] = {
    GF_BENCH_FLAG("--grains", LONG, packing_args, n),
    GF_BENCH_FLAG("--mu", REAL, packing_args, mu),
    GF_BENCH_FLAG("--phi", REAL, packing_args, phi),
    GF_BENCH_FLAG("--seed", LONG, packing_args, seed),
};

int main(int argc, char **argv)
{
    packing_args a = {.n = 500, .seed = 1, .mu = 0.2, .phi = NAN};
    if (!gf_bench_parse_flags(argc, argv, flags, sizeof flags / sizeof *flags, &a) || a.n < 50)
        return gf_bench_usage("gf-bench-packing", "[--grains N >= 50] [--mu MU] [--phi PHI] [--seed S]");
    const long n = a.n, seed = a.seed;
    const double mu = a.mu, phi = a.phi;
    gf_ctx ctx = {.log_level = GF_LOG_WARN};
    const double D = 7.6e-3, p = 0.05;
    /* N grains at Phi ~ 0.6 fill L^3 = N V / 0.6 */
    double L = cbrt((double)n * M_PI / 6.0 * D * D * D * (1.0 + p * p) / 0.6);
    gf_packing_spec sp = {.lo_m = {0, 0, 0}, .hi_m = {L, L, L}, .periodic = {1, 0, 1}, .phi_target = NAN,
                          .mu_natural = mu, .psd = {D / 2, p}, .density_kg_m3 = 2500, .gravity_m_s2 = 9.81,
                          .seed = (uint64_t)seed};
    gf_particles *g = NULL;
    if (gf_particles_create(&ctx, 1024, &g) != GF_OK)
        return 1;
    double phi_local = NAN, t0 = gf_bench_cpu_time_s();
    if (gf_packing_deposit(&ctx, &sp, mu, g, &phi_local) != GF_OK) {
        fprintf(stderr, "gf-bench-packing: %s\n", ctx.last_msg);
        return 1;
    }
    double t1 = gf_bench_cpu_time_s();
    printf("deposit: %zu grains, side %.1f D, mu_prep %.3f: Phi_local %.4f, %.2f CPU s\n", g->n_local, L / D, mu,
           phi_local, t1 - t0);
    if (!isnan(phi)) {
        gf_particles *h = NULL;
        gf_packing_result r = {0};
        sp.phi_target = phi;
        if (gf_particles_create(&ctx, 1024, &h) != GF_OK || gf_packing_build(&ctx, &sp, h, &r) != GF_OK) {
            fprintf(stderr, "gf-bench-packing: %s\n", ctx.last_msg);
            return 1;
        }
        double t2 = gf_bench_cpu_time_s();
        printf("build: Phi_i %.3f asked: Phi_local %.4f, global %.4f, mu_prep %.3f, %d deposits, %zu grains, "
               "%.2f CPU s\n", phi, r.phi_local, r.phi_global, r.mu_prep, r.iterations, r.n_grains, t2 - t1);
        gf_particles_destroy(&h);
    }
    gf_particles_destroy(&g);
    return 0;
}
