/*
 * The Janssen silo's glued walls hold its column (Izard 2014 §2.1.3.2: "walls made of glued grains, so that
 * the wall friction is under control"; docs/notes/validation-dem.md, row 6, "The wall").
 *
 * The frictionless planes behind the glued grains are a safety net only: a grain that leans on them meets
 * a wall without friction, and one that ends behind the glued layer has left the column. A random layer
 * of glued grains alone has holes nearly a grain wide: at the seed's section it put 10.7 % of the side
 * load on the planes, and with the planes a grain further back 14 grains of a 6 D x 20 D column passed
 * through. Both wall kinds of the scene (random_walls = 1, the default: the random layer backed by a
 * lattice; 0: the lattice alone) are built here in a 6 D x 12 D column (the test's grains: D = 1 cm,
 * +-10 %, mu_c = 0.25, packing seed 1; about 5 s each on one core: preparation, settling and the floor
 * drop of the scene's build, then 2 sqrt(D/g) more).
 * Claims, for each wall kind: the four side planes carry under 1 % of the horizontal load the side walls
 * receive (glued grains and planes together), and no grain's centre lies behind the face by more than
 * the largest glued radius (behind the glued front layer's centres).
 */
#include <math.h>
#include <stdio.h>

#include "scene_runner.h"


/* Builds the 6 D x 12 D silo with the given wall kind and lets it rest 2 sqrt(D/g) more. */
static gf_sim *build_silo(int random_walls, gf_ctx *ctx)
{
    gf_run_spec spec;
    runner_dry_spec(&spec, "janssen");
    spec.seed = 1;
    spec.grains.density_kg_m3 = 1319.0;
    spec.contact.friction = spec.contact.wall_friction = 0.25;
    spec.contact.restitution = 0.3;
    GF_CHECK_OK(gf_run_spec_set_param(ctx, &spec, "side_over_D", 6.0), ctx);
    GF_CHECK_OK(gf_run_spec_set_param(ctx, &spec, "fill_height_over_D", 12.0), ctx);
    GF_CHECK_OK(gf_run_spec_set_param(ctx, &spec, "random_walls", random_walls), ctx);
    gf_sim *sim = runner_create(ctx, &spec);
    if (sim)
        GF_CHECK_OK(gf_sim_advance(sim, (long)ceil(2.0 * sqrt(spec.grains.diameter_m / spec.gravity_m_s2) /
                                                    gf_sim_dt_s(sim))),
                    ctx);
    return sim;
}

/* How far the deepest grain's centre lies behind the walls' faces x, z = 0 and S (m; <= 0 when none). */
static double deepest_behind_face(gf_sim *sim, double S)
{
    const gf_particles *p = gf_sim_particles(sim);
    double deepest = 0.0;
    for (size_t i = 0; i < p->n_local; ++i)
        if (!(p->flags[i] & GF_P_GLUED)) {
            double out[4] = {-p->x_m[i], p->x_m[i] - S, -p->z_m[i], p->z_m[i] - S};
            for (int k = 0; k < 4; ++k)
                deepest = fmax(deepest, out[k]);
        }
    return deepest;
}

static void check_walls(int random_walls)
{
    gf_ctx ctx = {0};
    double t0 = runner_now_s();
    gf_sim *sim = build_silo(random_walls, &ctx);
    if (!sim)
        return;
    const gf_run_spec *s = gf_sim_spec(sim);
    double D = s->grains.diameter_m, S = 6.0 * D, r_w = 0.5 * D * (1.0 + s->grains.polydispersity);
    double share = runner_silo_plane_share(sim, S), deepest = deepest_behind_face(sim, S);
    printf("%s walls: %zu grains, safety planes carry %.2f %% of the side load, deepest grain centre %.3f D "
           "behind the face (front layer's centres at %.3f D), %.1f s\n",
           random_walls ? "random" : "lattice", gf_sim_particles(sim)->n_local, 100.0 * share, deepest / D, r_w / D,
           runner_now_s() - t0);
    GF_CHECK(share < 0.01);
    GF_CHECK(deepest < r_w);
    gf_sim_destroy(&sim);
}

int main(void)
{
    check_walls(1);
    check_walls(0);
    return gf_test_finish();
}
