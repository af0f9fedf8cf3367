/*
 * Impossible or unstable inputs are refused at gf_sim_create with a specific
 * status and one line that names the problem (no crash, no NaN, no sim):
 *  - grains overlapping by 10 % of D at start        -> GF_ERR_PHYSICS, "overlap"
 *  - a grain overlapping a wall by 10 % of D         -> GF_ERR_PHYSICS, "wall"
 *  - dt = t_c/2 (above the t_c/5 stability bound)     -> GF_ERR_NUMERIC, "stability limit"
 *  - negative grain diameter                          -> GF_ERR_PHYSICS, "diameter"
 *  - unknown contact law / scene / scene parameter    -> GF_ERR_CONFIG
 *  - a parameter outside its range                    -> GF_ERR_CONFIG naming the range
 * And the limit itself is usable: dt = t_c/5 runs a collision without NaN.
 * A state that becomes non-finite during a run (here: a NaN velocity
 * injected into a grain) stops the run within 1000 steps with
 * GF_ERR_NUMERIC naming the grain and the time.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "dem_testutil.h"

static void expect(const char *what, gf_run_spec *spec, gf_status code, const char *needle)
{
    gf_ctx ctx = {0};
    gf_sim *sim = NULL;
    gf_status st = gf_test_sim(&ctx, spec, 1, &sim);
    printf("%-28s -> %s: %s\n", what, gf_status_str(st), ctx.last_msg);
    GF_CHECK(st == code);
    GF_CHECK(sim == NULL);
    GF_CHECK(strstr(ctx.last_msg, needle) != NULL);
    gf_sim_destroy(&sim);
}

int main(void)
{
    gf_ctx ctx = {0};
    gf_run_spec s = gf_test_spec("binary_collision");
    gf_run_spec_set_param(&ctx, &s, "gap_over_D", -0.1);
    expect("pair overlap 10 % D", &s, GF_ERR_PHYSICS, "overlap");

    s = gf_test_spec("binary_collision");
    gf_run_spec_set_param(&ctx, &s, "gap_over_D", -0.1);
    gf_run_spec_set_param(&ctx, &s, "with_wall", 1);
    expect("wall overlap 10 % D", &s, GF_ERR_PHYSICS, "wall");

    s = gf_test_spec("binary_collision");
    s.contact.dt_over_tc = 0.5;
    expect("dt = t_c/2", &s, GF_ERR_NUMERIC, "stability limit");

    s = gf_test_spec("binary_collision");
    s.grains.diameter_m = -3e-3;
    expect("negative diameter", &s, GF_ERR_PHYSICS, "diameter");

    s = gf_test_spec("binary_collision");
    snprintf(s.contact.law, sizeof s.contact.law, "glue");
    expect("unknown law", &s, GF_ERR_CONFIG, "glue");

    s = gf_test_spec("no_such_scene");
    expect("unknown scene", &s, GF_ERR_CONFIG, "no_such_scene");

    s = gf_test_spec("binary_collision");
    gf_run_spec_set_param(&ctx, &s, "impact_angle_typo", 1.0);
    expect("unknown scene parameter", &s, GF_ERR_CONFIG, "impact_angle_typo");

    s = gf_test_spec("binary_collision");
    gf_run_spec_set_param(&ctx, &s, "with_wall", 3.0);
    expect("parameter out of range", &s, GF_ERR_CONFIG, "[0, 1]");

    /* at the bound itself the run is stable (coarse but finite) */
    s = gf_test_spec("binary_collision");
    s.contact.dt_over_tc = 0.2;
    gf_sim *sim = NULL;
    GF_CHECK_OK(gf_test_sim(&ctx, &s, 1, &sim), &ctx);
    if (sim) {
        GF_CHECK_OK(gf_sim_advance(sim, 200), &ctx);
        gf_particles *p = gf_sim_particles(sim);
        GF_CHECK(isfinite(p->vx_m_s[0]) && fabs(p->vx_m_s[0]) < 1.0);
        gf_sim_destroy(&sim);
    }
    s = gf_test_spec("elastic_gas");
    GF_CHECK_OK(gf_test_sim(&ctx, &s, 1, &sim), &ctx);
    if (sim) {
        gf_sim_particles(sim)->vx_m_s[3] = NAN;
        gf_status st = gf_sim_advance(sim, 5000);
        printf("%-28s -> %s: %s (step %ld)\n", "NaN injected in a run", gf_status_str(st), ctx.last_msg,
               gf_sim_step_count(sim));
        GF_CHECK(st == GF_ERR_NUMERIC && strstr(ctx.last_msg, "non-finite") && gf_sim_step_count(sim) <= 1000);
        gf_sim_destroy(&sim);
    }
    return gf_test_finish();
}
