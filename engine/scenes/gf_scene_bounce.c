/*
 * Bounce: one sphere released at rest in a viscous fluid above a plane wall,
 * falling onto it (Gondret, Lance & Petit, Phys. Fluids 14, 2002; Izard,
 * Bonometti & Lacaze, J. Fluid Mech. 747, 2014 = Izard 2014 §3.1.3.1).
 * A closed box box_over_D x height_over_D x box_over_D, gravity along -y, the
 * sphere centred across and release_depth_over_D below the top; the bottom is a
 * contact wall, no-slip for the fluid (bottom_no_slip = 1, the thesis'
 * impact wall) or free-slip; every other face is free-slip.
 * With a tall box and the run stopped before the sphere nears the floor, the
 * same scene is the settling-sphere validation of Izard 2014 §2.2.3 (slip walls
 * everywhere, the sphere 5 radii below the top).
 *
 * Oblique bounce (Joseph & Hunt, J. Fluid Mech. 510, 2004; Izard 2014 §3.4):
 * gravity turned by impact_angle_deg in the (x, y) plane, g = |g| (sin xi,
 * -cos xi, 0), so that the sphere released from rest falls along it, at xi
 * to the wall's normal (in a fluid the film slows the normal motion before the
 * contact, so the angle at impact is larger); release_x_over_D moves the release point
 * upstream and span_z_over_D sets the box's extent across (the thesis' box is
 * 10 D x 10 D x 4 D, the sphere released at (2 D, 8 D, 2 D)). The defaults
 * (0°, centred, a square box) are the normal bounce.
 *
 * Head-on (Yang & Hunt, Phys. Fluids 18, 2006; Izard 2014 §3.2):
 * target_gap_over_D > 0 puts a second sphere of the same size, at rest, that
 * far below the first (gap between surfaces) instead of the wall, launches the
 * first at launch_speed_nd sqrt(g D) towards it and turns gravity off (the
 * pendulums of the experiment carry the weights). The velocity and gap of the
 * diagnostics are then the pair's (sphere 1 relative to the target; the gap
 * between their surfaces), so that the `bounce` post stage's e = V_R/V_I is
 * Yang & Hunt's eps_B = -(U_r1 - U_r2)/(U_i1 - U_i2).
 *
 * Diagnostics: the sphere's vertical velocity, its gap to the wall over D, and
 * the vertical fluid force on it over its buoyant weight (the forces of the
 * last DEM step less gravity: hydrodynamic, lubrication and contact); for the
 * oblique bounce its velocity along x and its spin about z (the contact
 * point's velocity along the wall is v_x + R w_z); the target's vertical
 * velocity (0 without one).
 */
#include <math.h>

#include "coupling/gf_coupling.h"
#include "scenes/gf_scene.h"

static const gf_param_info bounce_params[] = {
    {"box_over_D", "1", 8.0, 2.0, 1000.0, "box width and depth / D"},
    {"height_over_D", "1", 20.0, 2.0, 1000.0, "box height / D"},
    {"release_depth_over_D", "1", 4.0, 0.5, 1000.0, "depth of the sphere's centre below the top / D"},
    {"bottom_no_slip", "1", 1.0, 0.0, 1.0, "1: the wall the sphere falls on is no-slip for the fluid, 0: free-slip"},
    {"impact_angle_deg", "degree", 0.0, 0.0, 80.0, "gravity's angle to the wall normal, in the (x, y) plane: the angle of the fall"},
    {"release_x_over_D", "1", 0.0, 0.0, 1000.0, "release abscissa of the sphere's centre / D; 0: centred"},
    {"span_z_over_D", "1", 0.0, 0.0, 1000.0, "box extent along z / D; 0: box_over_D"},
    {"target_gap_over_D", "1", 0.0, 0.0, 1000.0, "0: the wall; > 0: a sphere at rest this gap below instead, no gravity"},
    {"launch_speed_nd", "1", 0.0, 0.0, 1000.0, "initial speed of the sphere towards the wall or the target / sqrt(g D)"},
};

static const gf_var_info bounce_diag[] = {
    {"sphere_velocity_y", "m s-1", "vertical velocity of the sphere (relative to the target's, head-on)", NULL},
    {"gap_over_D", "1", "gap between the sphere and the bottom wall (or the target) / D", NULL},
    {"force_y_over_buoyant_weight", "1", "vertical non-gravity force on the sphere / ((rho_p - rho_f) V g)", NULL},
    {"sphere_velocity_x", "m s-1", "velocity of the sphere along the wall (x)", NULL},
    {"sphere_spin_z", "rad s-1", "angular velocity of the sphere about z", NULL},
    {"target_velocity_y", "m s-1", "vertical velocity of the target sphere (head-on; 0 without one)", NULL},
    {"hydrodynamic_force_y_over_buoyant_weight", "1",
     "vertical force of the resolved flow on the sphere beyond the buoyancy (the drag) / ((rho_p - rho_f) V g)", NULL},
    {"wall_force_y_over_buoyant_weight", "1",
     "vertical contact and lubrication force of the wall (or the target) on the sphere / ((rho_p - rho_f) V g)", NULL},
};

/* The release point and the box's far corner, from the scene's parameters. */
static void bounce_geometry(const gf_run_spec *spec, double release[3], double hi[3])
{
    double D = spec->grains.diameter_m;
    double L = gf_run_spec_param(spec, "box_over_D", 8.0) * D, H = gf_run_spec_param(spec, "height_over_D", 20.0) * D;
    double span = gf_run_spec_param(spec, "span_z_over_D", 0.0) * D, x0 = gf_run_spec_param(spec, "release_x_over_D", 0.0) * D;
    if (span <= 0.0)
        span = L;
    hi[0] = L, hi[1] = H, hi[2] = span;
    release[0] = x0 > 0.0 ? x0 : 0.5 * L;
    release[1] = H - gf_run_spec_param(spec, "release_depth_over_D", 4.0) * D;
    release[2] = 0.5 * span;
}

/* Gravity turned by the impact angle in the (x, y) plane; none head-on. */
static void bounce_gravity(const gf_run_spec *spec, int head_on, double grav[3])
{
    double xi = gf_run_spec_param(spec, "impact_angle_deg", 0.0) * M_PI / 180.0, g = head_on ? 0.0 : spec->gravity_m_s2;
    grav[0] = xi > 0.0 ? g * sin(xi) : 0.0;   /* xi = 0: exactly (0, -g, 0) */
    grav[1] = -g * cos(xi);
    grav[2] = 0.0;
}

/* The sphere at c, launched downwards, and head-on its target at rest below. */
static gf_status add_spheres(gf_sim *sim, const gf_run_spec *spec, const double c[3], double target_gap)
{
    gf_ctx *ctx = gf_sim_ctx(sim);
    gf_particles *p = gf_sim_particles(sim);
    double D = spec->grains.diameter_m, rho = spec->grains.density_kg_m3;
    size_t i;
    double launch = gf_run_spec_param(spec, "launch_speed_nd", 0.0) * sqrt(spec->gravity_m_s2 * D);
    GF_TRY(gf_particles_add(ctx, p, c[0], c[1], c[2], 0.5 * D, rho, 0, &i));
    if (launch > 0.0)
        p->vy_m_s[i] = -launch;
    if (target_gap > 0.0)
        GF_TRY(gf_particles_add(ctx, p, c[0], c[1] - D - target_gap, c[2], 0.5 * D, rho, 0, NULL));
    return GF_OK;
}

static gf_status bounce_build(gf_sim *sim, const gf_run_spec *spec)
{
    double D = spec->grains.diameter_m, lo[3] = {0, 0, 0}, hi[3], c[3], grav[3];
    double target_gap = gf_run_spec_param(spec, "target_gap_over_D", 0.0) * D;
    bounce_geometry(spec, c, hi);
    if (c[1] - (target_gap > 0.0 ? D + target_gap : 0.0) < D || c[0] < 0.5 * D || c[0] > hi[0] - 0.5 * D ||
        hi[2] < D)
        return GF_FAIL(gf_sim_ctx(sim), GF_ERR_CONFIG,
                       "bounce: the sphere released at (%g, %g) D%s does not fit a box %g x %g x %g D", c[0] / D,
                       c[1] / D, target_gap > 0.0 ? " with its target below" : "", hi[0] / D, hi[1] / D, hi[2] / D);
    bounce_gravity(spec, target_gap > 0.0, grav);
    int periodic[3] = {0, 0, 0};
    GF_TRY(gf_sim_set_box(sim, lo, hi, periodic));
    GF_TRY(gf_sim_set_gravity(sim, grav));
    double floor_pt[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    if (target_gap <= 0.0)
        GF_TRY(gf_sim_add_wall(sim, floor_pt, up, spec->contact.wall_friction, NULL));
    for (int a = 0; a < 3; ++a)
        for (int side = 0; side < 2; ++side)
            GF_TRY(gf_sim_set_fluid_bc(sim, a, side, GF_BC_FREE_SLIP));
    if (gf_run_spec_param(spec, "bottom_no_slip", 1.0) > 0.5)
        GF_TRY(gf_sim_set_fluid_bc(sim, 1, 0, GF_BC_NO_SLIP));
    return add_spheres(sim, spec, c, target_gap);
}

static gf_status bounce_diagnose(gf_sim *sim, double *v)
{
    const gf_particles *p = gf_sim_particles(sim);
    const gf_run_spec *s = gf_sim_spec(sim);
    double D = s->grains.diameter_m, R = p->radius_m[0], m = p->mass_kg[0], g = s->gravity_m_s2;
    double rho_f = s->fluid.density_kg_m3, vol = 4.0 / 3.0 * M_PI * R * R * R;
    int head_on = p->n_local > 1;
    v[0] = p->vy_m_s[0] - (head_on ? p->vy_m_s[1] : 0.0);
    v[1] = (p->y_m[0] - R - (head_on ? p->y_m[1] + p->radius_m[1] : 0.0)) / D;
    double w = (m - rho_f * vol) * g;
    v[2] = w > 0.0 ? p->fy_N[0] / w : NAN;
    v[3] = p->vx_m_s[0];
    v[4] = p->wz_rad_s[0];
    v[5] = head_on ? p->vy_m_s[1] : 0.0;
    /* The non-gravity force splits into the flow's (the tier's held force, which carries the buoyancy
     * -rho_f V g: the fluid holds the excess pressure) and the DEM's contact and lubrication. */
    double f_fluid[3], grav[3];
    struct gf_coupling *c = gf_sim_coupling(sim);
    if (c && w > 0.0 && gf_coupling_grain_force(c, p, 0, f_fluid)) {
        gf_sim_gravity(sim, grav);
        v[6] = (f_fluid[1] + rho_f * vol * grav[1]) / w;
        v[7] = (p->fy_N[0] - f_fluid[1]) / w;
    } else {
        v[6] = v[7] = NAN;
    }
    return GF_OK;
}

/* The box of bounce_geometry. */
static void bounce_fluid_box(const gf_run_spec *spec, double size_m[3])
{
    double release[3];
    bounce_geometry(spec, release, size_m);
}

/* The sphere, and head-on its target. */
static double bounce_grain_count(const gf_run_spec *spec)
{
    return gf_run_spec_param(spec, "target_gap_over_D", 0.0) > 0.0 ? 2.0 : 1.0;
}

const gf_scene_desc gf_scene_bounce = {
    .name = "bounce",
    .caption = "a sphere bouncing off a wall, normally or obliquely, or off a second sphere, in a viscous fluid "
               "(Gondret et al. 2002; Joseph & Hunt 2004; Yang & Hunt 2006; Izard 2014 §3.1-3.4)",
    .needs = GF_NEED_CONTACTS | GF_NEED_FLUID,
    GF_SCENE_PARAMS(bounce_params),
    .default_end_time_nd = 30.0,
    .build = bounce_build,
    GF_SCENE_DIAG(bounce_diag),
    .diagnose = bounce_diagnose,
    .grain_count = bounce_grain_count,
    .fluid_box = bounce_fluid_box,
};
