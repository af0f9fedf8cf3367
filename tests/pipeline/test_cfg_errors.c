/*
 * Configuration errors point at the exact spot: each bad file below gives
 * status GF_ERR_CONFIG and exactly the line "file:line:column: message" we
 * expect (lines and columns 1-based, as editors count them), with a
 * did-you-mean for misspelt keys and values. Nothing is expanded from a bad
 * file (the loader returns no campaign).
 */
#include <stdio.h>
#include <string.h>

#include "campaign/gf_campaign.h"
#include "config/gf_cfg.h"
#include "gf_test.h"

/* Loads text as "t.yaml"; checks the status and that the message starts with want. */
static void expect_error(const char *text, gf_status code, const char *want)
{
    gf_ctx ctx = {0};
    gf_campaign *c = NULL;
    gf_status st = gf_campaign_load_string(&ctx, "t.yaml", text, strlen(text), NULL, 0, &c);
    gf_test_check(st == code, __FILE__, __LINE__, "status %s, expected %s (%s)", gf_status_str(st),
                  gf_status_str(code), ctx.last_msg);
    gf_test_check(strncmp(ctx.last_msg, want, strlen(want)) == 0, __FILE__, __LINE__,
                  "message\n  got:  %s\n  want: %s...", ctx.last_msg, want);
    gf_test_check(c == NULL, __FILE__, __LINE__, "no campaign from a bad file");
    gf_test_check(strchr(ctx.last_msg, '\n') == NULL, __FILE__, __LINE__, "one line");
    gf_campaign_destroy(&c);
}

#define BASE "scene: {name: binary_collision}\n"

static void test_unknown_key_suggests_the_nearest(void)
{
    expect_error(BASE "grains:\n  diameter_m: 5e-3\n  densty_kg_m3: 2500\n", GF_ERR_CONFIG,
                 "t.yaml:4:3: unknown key 'densty_kg_m3' in grains (did you mean 'density_kg_m3'?)");
    expect_error(BASE "fluid:\n  modle: none\n", GF_ERR_CONFIG,
                 "t.yaml:3:3: unknown key 'modle' in fluid (did you mean 'model'?)");
    expect_error(BASE "gravty: 9.81\n", GF_ERR_CONFIG,
                 "t.yaml:2:1: unknown key 'gravty' in the top level (did you mean 'gravity'?)");
    /* scene keys come from the scene's own parameter table */
    expect_error("scene:\n  name: binary_collision\n  impact_sped_nd: 2\n", GF_ERR_CONFIG,
                 "t.yaml:3:3: unknown key 'impact_sped_nd' in scene (scene binary_collision) (did you mean "
                 "'impact_speed_nd'?)");
    /* nothing close: no suggestion */
    expect_error(BASE "contact:\n  zzzzzzzzzz: 1\n", GF_ERR_CONFIG, "t.yaml:3:3: unknown key 'zzzzzzzzzz' in contact");
    expect_error("scene: {name: binary_colision}\n", GF_ERR_CONFIG,
                 "t.yaml:1:15: name: unknown value 'binary_colision' (did you mean 'binary_collision'?)");
    /* a scene only the library builds (a packing preparation's container) is not a campaign's */
    expect_error("scene: {name: packing_preparation}\n", GF_ERR_CONFIG,
                 "t.yaml:1:15: name: unknown value 'packing_preparation' (one of: avalanche,");
    expect_error(BASE "fluid: {model: unresolvd}\n", GF_ERR_CONFIG,
                 "t.yaml:2:16: model: unknown value 'unresolvd' (did you mean 'unresolved'?)");
}

static void test_wrong_types_and_ranges(void)
{
    expect_error(BASE "grains: {diameter_m: big}\n", GF_ERR_CONFIG,
                 "t.yaml:2:22: diameter_m: expected a number, got 'big'");
    expect_error(BASE "grains: {diameter_m: \"5e-3\"}\n", GF_ERR_CONFIG,
                 "t.yaml:2:22: diameter_m: expected a number, got the string \"5e-3\"");
    expect_error(BASE "grains: {diameter_m: [1, 2]}\n", GF_ERR_CONFIG,
                 "t.yaml:2:22: diameter_m: expected a number, got a list");
    expect_error(BASE "contact: {restitution: 1.5}\n", GF_ERR_CONFIG,
                 "t.yaml:2:24: restitution = 1.5 is out of range [0, 1]");
    /* the engine's time-step bound, refused at load (grainflow check) and located at the key */
    expect_error(BASE "contact: {dt_over_tc: 0.3}\n", GF_ERR_NUMERIC,
                 "t.yaml:2:23: contact.dt_over_tc = 0.3: dt = ");
    expect_error(BASE "grains: {polydispersity: 0.5}\ncontact:\n  dt_over_tc: 0.1\n", GF_ERR_NUMERIC,
                 "t.yaml:4:15: contact.dt_over_tc = 0.1 exceeds the stability limit t_c/5 x ((1 - p)/0.9)^1.5");
    expect_error(BASE "grains: {diameter_m: 0}\n", GF_ERR_CONFIG,
                 "t.yaml:2:22: diameter_m = 0 is out of range: must be > 0");
    expect_error(BASE "gravity: .nan\n", GF_ERR_CONFIG, "t.yaml:2:10: gravity: expected a number, got '.nan'");
    expect_error(BASE "gravity: nan\n", GF_ERR_CONFIG, "t.yaml:2:10: gravity: expected a number, got 'nan'");
    expect_error(BASE "end_time: 1e999\n", GF_ERR_CONFIG, "t.yaml:2:11: end_time: 1e999 is too large to be a double");
    expect_error(BASE "seed: -3\n", GF_ERR_CONFIG, "t.yaml:2:7: seed: expected a non-negative integer, got '-3'");
    expect_error(BASE "fluid: {lubrication: maybe}\n", GF_ERR_CONFIG,
                 "t.yaml:2:22: lubrication: expected true or false, got 'maybe'");
    expect_error(BASE "grains: 3\n", GF_ERR_CONFIG, "t.yaml:2:9: grains: expected a mapping, got a value");
    expect_error("scene:\n  name: binary_collision\n  psi1: 70\n", GF_ERR_CONFIG,
                 "t.yaml:3:9: psi1 = 70  is out of range [-50, 50]");
}

static void test_malformed_yaml_is_located(void)
{
    /* a tab in the indentation: libyaml stops at the tab, column 1 of line 3 */
    expect_error(BASE "grains:\n\tdiameter_m: 5e-3\n", GF_ERR_CONFIG,
                 "t.yaml:3:1: tab character: YAML indentation must use spaces");
    expect_error(BASE "name: \"unclosed\n", GF_ERR_CONFIG, "t.yaml:3:1: found unexpected end of stream");
    expect_error("", GF_ERR_CONFIG, "t.yaml:1:1: empty configuration");
    expect_error("- a\n- b\n", GF_ERR_CONFIG, "t.yaml:1:1: a configuration is a mapping of sections");
    expect_error(BASE "seed: 1\nseed: 2\n", GF_ERR_CONFIG, "t.yaml:3:1: duplicate key 'seed' (first at line 2)");
    expect_error(BASE "grains: &g {diameter_m: 5e-3}\n", GF_ERR_CONFIG,
                 "t.yaml:2:9: anchors (&g) are not supported");
    expect_error(BASE "x: !!float 3\n", GF_ERR_CONFIG, "t.yaml:2:4: tags (tag:yaml.org,2002:float) are not supported");
    expect_error(BASE "---\nseed: 1\n", GF_ERR_CONFIG, "t.yaml:2:1: more than one document");
    char deep[400] = BASE "a: ";
    for (int i = 0; i < 40; ++i)
        strcat(deep, "[");
    expect_error(deep, GF_ERR_CONFIG, "t.yaml:2:");
    const char junk[] = "scene: {name: x}\n\x01\x02\xff\xfe";
    expect_error(junk, GF_ERR_CONFIG, "t.yaml:2:1: not a text file");
}

static void test_missing_file(void)
{
    gf_ctx ctx = {0};
    gf_campaign *c = NULL;
    gf_status st = gf_campaign_load_file(&ctx, "/nonexistent/campaign.yaml", NULL, 0, &c);
    GF_CHECK(st == GF_ERR_CONFIG);
    gf_test_check(strcmp(ctx.last_msg, "/nonexistent/campaign.yaml:1:1: cannot open: No such file or directory") == 0,
                  __FILE__, __LINE__, "got: %s", ctx.last_msg);
}

static void test_grid_errors(void)
{
    expect_error(BASE "fluid: {model: unresolved}\ngrid: {St: [1, 2], r: [3, 4, 5], combine: zip}\n", GF_ERR_CONFIG,
                 "t.yaml:3:23: combine: zip needs lists of equal length: r has 3 values, the previous 2");
    expect_error(BASE "grid: {St: {from: 0.1, to: 10}}\n", GF_ERR_CONFIG,
                 "t.yaml:2:12: St: a range needs from, to and num");
    expect_error(BASE "grid: {St: {from: 0.1, to: 10, num: 3, scale: logg}}\n", GF_ERR_CONFIG,
                 "t.yaml:2:47: scale: unknown value 'logg' (did you mean 'log'?)");
    expect_error(BASE "grid: {Phi_i: [0.6, 0.9]}\n", GF_ERR_CONFIG,
                 "t.yaml:2:21: Phi_i = 0.9: Phi_i must be in (0, 0.7405]");
    expect_error(BASE "grid: {st: [1]}\n", GF_ERR_CONFIG, "t.yaml:2:8: unknown key 'st' in grid (did you mean 'St'?)");
    /* a group that describes a fluid the run would not have */
    expect_error(BASE "grid: {St: [1, 2], r: [3]}\n", GF_ERR_CONFIG,
                 "t.yaml:2:7: run 0 (St=1 r=3): St and r describe a fluid but fluid.model is none");
    /* the impossible corner: grains lighter than the fluid */
    expect_error(BASE "fluid: {model: unresolved}\ngrid: {St: [1], r: [3, 1.2]}\n", GF_ERR_PHYSICS,
                 "t.yaml:3:7: run 1 (St=1 r=1.2): r = 1.2 <= sqrt(5/3) = 1.291: grains would not be denser than the fluid");
    /* a and Phi_i need the scene's aspect_ratio / phi_initial */
    expect_error(BASE "groups: {a: 2}\n", GF_ERR_CONFIG,
                 "t.yaml:2:9: a (aspect ratio) does not apply: scene binary_collision has no aspect_ratio");
    expect_error(BASE "grid: {St: [1, 1]}\nfluid: {model: unresolved, density_kg_m3: 1000}\n", GF_ERR_CONFIG,
                 "t.yaml:2:7: runs 0 and 1 resolve to the same spec");
}

static void test_command_line_overrides(void)
{
    gf_ctx ctx = {0};
    gf_campaign *c = NULL;
    const char *bad[] = {"fluid.modle=none"};
    gf_status st = gf_campaign_load_string(&ctx, "t.yaml", BASE, strlen(BASE), bad, 1, &c);
    GF_CHECK(st == GF_ERR_CONFIG);
    gf_test_check(strcmp(ctx.last_msg,
                         "--set fluid.modle=none: unknown key 'modle' in fluid (did you mean 'model'?)") == 0,
                  __FILE__, __LINE__, "got: %s", ctx.last_msg);
    const char *good[] = {"scene.impact_speed_nd=2.5", "contact.friction=0.5", "seed=7"};
    GF_CHECK_OK(gf_campaign_load_string(&ctx, "t.yaml", BASE, strlen(BASE), good, 3, &c), &ctx);
    if (c) {
        GF_CHECK_ABS(gf_run_spec_param(&c->runs[0].spec, "impact_speed_nd", 0), 2.5, 0);
        GF_CHECK_ABS(c->runs[0].spec.contact.friction, 0.5, 0);
        GF_CHECK(c->runs[0].spec.seed == 7);
        /* defaults fill every other value, from the one place they live */
        gf_run_spec d;
        gf_run_spec_defaults(&d);
        GF_CHECK_ABS(c->runs[0].spec.contact.restitution, d.contact.restitution, 0);
        GF_CHECK_ABS(gf_run_spec_param(&c->runs[0].spec, "psi1", -1), 0.0, 0);
    }
    gf_campaign_destroy(&c);
}

static void test_edit_distance(void)
{
    GF_CHECK(gf_cfg_edit_distance("kitten", "sitting") == 3); /* the textbook example */
    GF_CHECK(gf_cfg_edit_distance("", "abc") == 3);
    GF_CHECK(gf_cfg_edit_distance("model", "model") == 0);
    const char *cands[] = {"diameter_m", "density_kg_m3", "polydispersity", NULL};
    GF_CHECK(gf_cfg_suggest("diamter_m", cands) == cands[0]);
    GF_CHECK(gf_cfg_suggest("colour", cands) == NULL);
}

int main(void)
{
    test_unknown_key_suggests_the_nearest();
    test_wrong_types_and_ranges();
    test_malformed_yaml_is_located();
    test_missing_file();
    test_grid_errors();
    test_command_line_overrides();
    test_edit_distance();
    return gf_test_finish();
}
