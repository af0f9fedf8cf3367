/*
 * `grainflow check` refuses what the resolved tier cannot run, in one line at
 * the key that sets it (file:line:column) with the limit (issue #32):
 *   D/dx < 6 (the solid fraction's shell is ~3 cells), rho_p/rho < 1.7 (the
 *   force formula of Izard 2014 eq. (2.32) is singular at 1), and a DEM step
 *   longer than the fluid step's viscous limit nu dt/dx^2 <= 1 (the fluid step
 *   is a whole number of DEM steps); an unknown fluid.time_scheme,
 *   fluid.advection or fluid.ibm_forcing names the ones there are; a
 *   fluid.diffusion_number (nu dt/dx^2 of the fluid step) beyond the viscous
 *   limit 1 is refused. A good file loads.
 */
#include <stdio.h>
#include <string.h>

#include "campaign/gf_campaign.h"
#include "gf_test.h"

#define SPHERE                                                                                        \
    "scene: {name: bounce, box_over_D: 6, height_over_D: 12}\n"               \
    "grains:\n  diameter_m: 0.01\n  density_kg_m3: 4000\n"                                          \
    "fluid:\n  model: resolved\n  density_kg_m3: 1000\n  viscosity_Pa_s: 0.19183\n"

static void expect(const char *text, gf_status code, const char *want_start, const char *want_inside)
{
    gf_ctx ctx = {0};
    gf_campaign *c = NULL;
    gf_status st = gf_campaign_load_string(&ctx, "t.yaml", text, strlen(text), NULL, 0, &c);
    gf_test_check(st == code, __FILE__, __LINE__, "status %s, expected %s (%s)", gf_status_str(st),
                  gf_status_str(code), ctx.last_msg);
    if (code == GF_OK) {
        gf_campaign_destroy(&c);
        return;
    }
    printf("%s\n", ctx.last_msg);
    gf_test_check(strncmp(ctx.last_msg, want_start, strlen(want_start)) == 0, __FILE__, __LINE__,
                  "message\n  got:  %s\n  want: %s...", ctx.last_msg, want_start);
    gf_test_check(strstr(ctx.last_msg, want_inside) != NULL, __FILE__, __LINE__, "'%s' in the message",
                  want_inside);
    gf_test_check(strchr(ctx.last_msg, '\n') == NULL, __FILE__, __LINE__, "one line");
    gf_campaign_destroy(&c);
}

int main(void)
{
    expect(SPHERE "  d_over_dx: 16\n", GF_OK, "", "");
    expect(SPHERE "  d_over_dx: 5\n", GF_ERR_CONFIG, "t.yaml:9:14: fluid.d_over_dx = 5", "D/dx >= 6");
    expect("scene: {name: bounce, box_over_D: 6, height_over_D: 12}\n"
           "grains:\n  diameter_m: 0.01\n  density_kg_m3: 1500\n"
           "fluid:\n  model: resolved\n  density_kg_m3: 1000\n  viscosity_Pa_s: 0.19183\n",
           GF_ERR_CONFIG, "t.yaml:4:18: grains.density_kg_m3 / fluid.density_kg_m3 = 1.5", "rho_p/rho >= 1.7");
    expect(SPHERE "  time_scheme: rk3\n  advection: divergence\n", GF_OK, "", "");
    expect(SPHERE "  time_scheme: rk4\n", GF_ERR_CONFIG, "t.yaml:9:16:", "rk3");
    expect(SPHERE "  advection: upwind\n", GF_ERR_CONFIG, "t.yaml:9:14:", "divergence");
    expect(SPHERE "  ibm_forcing: markers\n", GF_OK, "", "");
    expect(SPHERE "  ibm_forcing: lagrangian\n", GF_ERR_CONFIG, "t.yaml:9:16:", "markers");
    expect(SPHERE "  diffusion_number: 1.0\n", GF_OK, "", "");
    expect(SPHERE "  diffusion_number: 1.2\n", GF_ERR_CONFIG, "t.yaml:9:21:", "out of range");
    expect(SPHERE "  d_over_dx: 40\ncontact:\n  t_contact_nd: 0.9\n", GF_ERR_NUMERIC,
           "t.yaml:11:17: contact.dt_over_tc", "viscous limit nu dt/dx^2 <= 1");
    return gf_test_finish();
}
