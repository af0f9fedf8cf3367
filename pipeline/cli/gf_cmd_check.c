/*
 * `grainflow check FILE.yaml`: validate a configuration and print every
 * resolved run: each value (defaults included, with its unit), the groups the
 * physical values realise (St, r, Ar, Re* = St/r) and the time scales
 * (T_v, T_i, T_ff, T_visq; gf_groups.h). Runs nothing.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "campaign/gf_groups_map.h"
#include "campaign/gf_spec_schema.h"
#include "cli/gf_cli.h"
#include "scenes/gf_scene.h"
#include "schedule/gf_sched.h"

#define MAX_SETS 64

static const char help[] =
    "usage: grainflow check FILE.yaml [--set key.path=value ...] [--brief]\n"
    "\n"
    "Validates FILE.yaml (a run or a campaign) and prints every resolved run:\n"
    "all values with their units (defaults included), the realised St, r, Ar,\n"
    "Re* and the time scales T_v, T_i, T_ff, T_visq. An error is one line\n"
    "file:line:column: message. Runs nothing.\n"
    "\n"
    "options:\n"
    "      --set KEY=VALUE  override a value, as for run and campaign\n"
    "      --brief          one line per run (id, groups, realised St, r, T_ff)\n"
    "\n"
    "exit status: 0 valid, 2 invalid\n";

static void print_field_line(const char *indent, const char *key, const char *value, const char *unit,
                             const char *doc)
{
    char left[160];
    snprintf(left, sizeof left, "%s%s: %s", indent, key, value);
    printf("%-44s # %s%s%s\n", left, unit && *unit && strcmp(unit, "1") ? unit : "", unit && *unit &&
           strcmp(unit, "1") ? ", " : "", doc ? doc : "");
}

static void print_run(const gf_campaign *c, const gf_campaign_run *r)
{
    const gf_run_spec *s = &r->spec;
    char what[200], value[64];
    gf_sched_describe(r, what, sizeof what);
    printf("# run %d of %d: %s  %s\n", r->index, c->n_runs, s->run_id, what);
    int nf;
    const gf_spec_field *f = gf_spec_fields(&nf);
    for (int i = 0; i < nf; ++i)
        if (!f[i].section[0]) {
            gf_spec_field_format(&f[i], s, value, sizeof value);
            if (f[i].type == GF_FIELD_DOUBLE)
                snprintf(value, sizeof value, "%.10g", *(const double *)((const char *)s + f[i].offset));
            print_field_line("", f[i].key, value, f[i].unit, f[i].doc);
        }
    const gf_scene_desc *scene = gf_scene_find(s->scene);
    printf("scene:\n  name: %s\n", s->scene);
    for (int i = 0; scene && i < scene->n_params; ++i) {
        snprintf(value, sizeof value, "%.10g", gf_run_spec_param(s, scene->params[i].key, NAN));
        print_field_line("  ", scene->params[i].key, value, scene->params[i].unit, scene->params[i].doc);
    }
    const char *sections[] = {"grains", "contact", "fluid", "output"};
    for (int k = 0; k < 4; ++k) {
        printf("%s:\n", sections[k]);
        for (int i = 0; i < nf; ++i)
            if (!strcmp(f[i].section, sections[k])) {
                gf_spec_field_format(&f[i], s, value, sizeof value);
                if (f[i].type == GF_FIELD_DOUBLE)
                    snprintf(value, sizeof value, "%.10g", *(const double *)((const char *)s + f[i].offset));
                print_field_line("  ", f[i].key, value, f[i].unit, f[i].doc);
            }
    }
    int any = 0;
    for (int g = 0; g < 4; ++g) {
        double x = *gf_spec_group((gf_run_spec *)s, g);
        if (!isnan(x))
            printf("%s  %s: %.10g\n", any++ ? "" : "groups:   # asked\n", gf_group_names[g], x);
    }
    const gf_scales *sc = &r->scales;
    printf("# realised: St = %.4g  r = %.4g  Ar = %.4g  Re* = St/r = %.4g  rho_p/rho_f = %.4g\n", sc->stokes_St,
           sc->density_ratio_r, sc->archimedes_Ar, sc->reynolds_Re, sc->rho_ratio);
    printf("# time scales: T_v = %.4g s  T_i = %.4g s  T_ff = %.4g s  T_visq = %.4g s  sqrt(D/g) = %.4g s\n",
           sc->t_viscous_s, sc->t_inertial_s, sc->t_freefall_s, sc->t_visq_s, sc->t_grain_s);
    printf("# contact: t_c = %.4g s  dt = %.4g s", gf_run_spec_t_contact_s(s), gf_run_spec_dt_s(s));
    if (s->end_time_nd > 0)
        printf("  end = %.4g s = %.3g steps", s->end_time_nd * sc->t_grain_s,
               s->end_time_nd * sc->t_grain_s / gf_run_spec_dt_s(s));
    printf("\n\n");
}

int gf_cmd_check(int argc, char **argv)
{
    const char *file = NULL, *v, *sets[MAX_SETS];
    int n_sets = 0, brief = 0;
    for (int i = 1; i < argc; ++i) {
        int m;
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            fputs(help, stdout);
            return GF_EXIT_OK;
        } else if ((m = gf_cli_opt_value(argc, argv, &i, NULL, "--set", &v))) {
            if (m < 0 || n_sets == MAX_SETS)
                return gf_cli_usage_error("check", "--set needs KEY=VALUE (at most %d)", MAX_SETS);
            sets[n_sets++] = v;
        } else if (!strcmp(argv[i], "--brief")) {
            brief = 1;
        } else if (argv[i][0] == '-' && argv[i][1]) {
            return gf_cli_usage_error("check", "unknown option '%s'", argv[i]);
        } else if (!file) {
            file = argv[i];
        } else {
            return gf_cli_usage_error("check", "unexpected argument '%s'", argv[i]);
        }
    }
    if (!file)
        return gf_cli_usage_error("check", "missing FILE.yaml");
    gf_ctx ctx = {.log_level = GF_LOG_WARN};
    gf_campaign *c = NULL;
    if (gf_campaign_load_file(&ctx, file, sets, n_sets, &c) != GF_OK) {
        gf_cli_print_error(&ctx);
        return GF_EXIT_USAGE;
    }
    printf("# %s: campaign %s, scene %s, %d runs (%d grid points x %d variants)\n\n", file, c->name,
           c->runs[0].spec.scene, c->n_runs, c->n_points, c->n_variants);
    for (int i = 0; i < c->n_runs; ++i) {
        if (brief) {
            char what[200];
            gf_sched_describe(&c->runs[i], what, sizeof what);
            printf("%4d  %s  %-40s St=%-9.4g r=%-9.4g T_ff=%.4g s\n", i, c->runs[i].spec.run_id, what,
                   c->runs[i].scales.stokes_St, c->runs[i].scales.density_ratio_r, c->runs[i].scales.t_freefall_s);
        } else {
            print_run(c, &c->runs[i]);
        }
    }
    gf_campaign_destroy(&c);
    return GF_EXIT_OK;
}
