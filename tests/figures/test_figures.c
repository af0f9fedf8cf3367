/*
 * Campaign figures from synthetic data. Each SVG is parsed as XML by
 * tests/figures/check_svg.py (well-formed, or the test fails), the markers,
 * curves and reference lines are counted, the log axes must carry the right
 * decades, and one known point must sit where the drawn axis ticks say it
 * should (the inverse map, to 0.02 px: coordinates are printed with two
 * decimals). The tick generator is also checked on its own against the
 * 1-2-5 rule and decades.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "figures/gf_figures.h"
#include "figures/gf_svg.h"
#include "gf_test.h"

static const char *python = "python3";
static char out_dir[1024];

static const char *fig_path(const char *name)
{
    static char p[1200];
    snprintf(p, sizeof p, "%s/%s", out_dir, name);
    return p;
}

static void check_svg(const char *file, int n, const char *const *checks)
{
    const char *src = getenv("GF_SOURCE_DIR");
    char cmd[4096];
    int len = snprintf(cmd, sizeof cmd, "'%s' '%s/tests/figures/check_svg.py' '%s'", python, src ? src : ".",
                       fig_path(file));
    for (int i = 0; i < n; ++i)
        len += snprintf(cmd + len, sizeof cmd - (size_t)len, " '%s'", checks[i]);
    int rc = system(cmd);
    gf_test_check(rc == 0, __FILE__, __LINE__, "check_svg.py %s exits 0 (got %d)", file, rc);
}

/* Linear ticks follow 1-2-5 steps; log ticks are the decades inside the range. */
static void test_ticks_are_nice(void)
{
    gf_svg_ticks t;
    gf_svg_ticks_compute(GF_SVG_LINEAR, 0.0, 1.0, &t);
    GF_CHECK(t.n_major == 6);   /* step 0.2: 1.0/6 = 0.167 rounds to 2e-1 */
    GF_CHECK_ABS(t.major[1], 0.2, 1e-15);
    GF_CHECK_ABS(t.major[5], 1.0, 1e-15);
    gf_svg_ticks_compute(GF_SVG_LINEAR, -35.0, 35.0, &t);
    GF_CHECK(t.n_major == 7 && t.major[0] == -30.0 && t.major[6] == 30.0);   /* 70/6 = 11.7 -> step 10 */
    gf_svg_ticks_compute(GF_SVG_LINEAR, 0.0, 0.03, &t);
    GF_CHECK(t.n_major == 7 && fabs(t.major[6] - 0.03) < 1e-15);   /* step 5e-3 */
    gf_svg_ticks_compute(GF_SVG_LOG, 0.01, 1000.0, &t);
    GF_CHECK(t.n_major == 6);
    GF_CHECK_REL(t.major[0], 0.01, 1e-15);
    GF_CHECK_REL(t.major[5], 1000.0, 1e-15);
    GF_CHECK(t.n_minor == 5 * 8);   /* 2..9 in each of five decades */
    gf_svg_ticks_compute(GF_SVG_LOG, 1e-20, 1e20, &t);
    GF_CHECK(t.n_major <= 9 && t.n_minor == 0);   /* 41 decades: every 6th, no minors */
    double lo, hi;
    gf_svg_nice_range(GF_SVG_LOG, 0.013, 870.0, &lo, &hi);
    GF_CHECK_REL(lo, 0.01, 1e-15);
    GF_CHECK_REL(hi, 1000.0, 1e-15);
    gf_svg_nice_range(GF_SVG_LINEAR, 0.531, 0.609, &lo, &hi);
    GF_CHECK_ABS(lo, 0.53, 1e-12);   /* 0.078/6 = 0.013 -> step 0.01 */
    GF_CHECK_ABS(hi, 0.61, 1e-12);
    /* 0..4.1: step 0.5 gives [0, 4.5], whose own step is 1: settle on [0, 5] */
    gf_svg_nice_range(GF_SVG_LINEAR, 0.0, 4.1, &lo, &hi);
    GF_CHECK_ABS(lo, 0.0, 1e-15);
    GF_CHECK_ABS(hi, 5.0, 1e-12);
    gf_svg_nice_range(GF_SVG_LINEAR, 2.0, 2.0, &lo, &hi);   /* degenerate: widened */
    GF_CHECK(lo < 2.0 && hi > 2.0);
    char buf[32];
    gf_svg_tick_label(GF_SVG_LOG, 1e5, buf, sizeof buf);
    GF_CHECK(strcmp(buf, "10^5") == 0);
    gf_svg_tick_label(GF_SVG_LOG, 0.01, buf, sizeof buf);
    GF_CHECK(strcmp(buf, "0.01") == 0);
}

/* Izard 2014 Table 4.3 cases (r = 2.58: St 0.04, 0.31 viscous; 7.75, 75.4
 * inertial; r = 12.91: St 0.45 viscous, 4.5 and 111.2 free fall) plus two
 * made-up runs, one transitional and one with no St (dry) that is skipped. */
static void test_regime_diagram(void)
{
    double St[] = {0.04, 0.31, 7.75, 75.4, 0.45, 4.5, 111.2, 1.0, NAN};
    double r[] = {2.58, 2.58, 2.58, 2.58, 12.91, 12.91, 12.91, 3.0, 2.0};
    gf_fig_regime g[] = {GF_FIG_REGIME_VISCOUS,   GF_FIG_REGIME_VISCOUS,   GF_FIG_REGIME_INERTIAL,
                         GF_FIG_REGIME_INERTIAL,  GF_FIG_REGIME_VISCOUS,   GF_FIG_REGIME_FREE_FALL,
                         GF_FIG_REGIME_FREE_FALL, GF_FIG_REGIME_TRANSITIONAL, GF_FIG_REGIME_UNDETERMINED};
    gf_ctx ctx = {0};
    GF_CHECK_OK(gf_fig_regime_diagram(&ctx, fig_path("regime.svg"), NULL, 9, St, r, g), &ctx);
    const char *checks[] = {"markers=8", "shapes=circle:8",
                            /* three pieces per source: vertical, horizontal, Re* line */
                            "reflines=6", "legend=6", "xscale=log", "yscale=log",
                            /* St 0.04..111 widened to include 0.1..100: decades 0.01..1000 */
                            "xticks=0.01,0.1,1,10,100,1000", "xlabels=0.01|0.1|1|10|100|1000",
                            /* r 2.58..12.91 widened to include 1..20 */
                            "yticks=1,10,100", "point=0.31,2.58", "point=111.2,12.91",
                            "caption~1 run not shown", "title=Flow regimes in the (St, r) plane",
                            /* Courrech du Pont: corner (10, 4), Re*_c = 2.5 reaches r = 1 at St = 2.5;
                             * Izard: corner (1, 4), Re*_c = 0.25 reaches r = 1 at St = 0.25 */
                            "refline_through=10,4", "refline_through=2.5,1", "refline_through=1,4",
                            "refline_through=0.25,1", "refline_through=10,100", "refline_through=1000,4"};
    check_svg("regime.svg", 19, checks);
    GF_CHECK(gf_fig_regime_from_name("free-fall") == GF_FIG_REGIME_FREE_FALL);
    GF_CHECK(gf_fig_regime_from_name("free_fall") == GF_FIG_REGIME_FREE_FALL);
    GF_CHECK(gf_fig_regime_from_name("bogus") == GF_FIG_REGIME_UNDETERMINED);
    GF_CHECK(strcmp(gf_fig_regime_name(GF_FIG_REGIME_TRANSITIONAL), "transitional") == 0);
}

static void test_deposit_shape(void)
{
    double a[] = {0.5, 0.7, 1.0, 2.0, 3.0, 4.0};
    double phi[] = {0.55, 0.6, 0.55, 0.6, 0.58, 0.56};
    gf_fig_shape s[] = {GF_FIG_SHAPE_TRAPEZOID, GF_FIG_SHAPE_TRAPEZOID, GF_FIG_SHAPE_TRIANGLE,
                        GF_FIG_SHAPE_TRIANGLE,  GF_FIG_SHAPE_TRIANGLE,  GF_FIG_SHAPE_UNDETERMINED};
    gf_ctx ctx = {0};
    gf_fig_opts opt = {.title = "Deposits: <loose> & \"dense\" columns"};
    GF_CHECK_OK(gf_fig_deposit_shape(&ctx, fig_path("deposit.svg"), &opt, 6, a, phi, s), &ctx);
    /* a from 0 (the axis includes the origin) to 4, padded 4 %: 0..4.16 -> step 1 up to 5;
     * Phi_i 0.55..0.6 padded to 0.548..0.602 -> 0.54..0.61 by 0.01 */
    const char *checks[] = {"markers=6", "shapes=rect:2,polygon:3,circle:1", "legend=3",
                            "xticks=0,1,2,3,4,5", "yticks=0.54,0.55,0.56,0.57,0.58,0.59,0.6,0.61",
                            "point=2,0.6", "point=0.5,0.55",
                            "title=Deposits: <loose> & \"dense\" columns"};
    check_svg("deposit.svg", 8, checks);
}

/* Runs on Lajeunesse's law (1.8 a below a = 3, 2.3 a^(2/3) above) over two
 * decades of a: log axes chosen automatically. */
static void test_runout_log(void)
{
    double a[] = {0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0};
    double run[7];
    for (int i = 0; i < 7; ++i)
        run[i] = a[i] < 3.0 ? 1.8 * a[i] : 2.3 * pow(a[i], 2.0 / 3.0);
    gf_ctx ctx = {0};
    GF_CHECK_OK(gf_fig_runout(&ctx, fig_path("runout_log.svg"), NULL, 7, a, run, NULL), &ctx);
    char p1[64];
    snprintf(p1, sizeof p1, "point=5,%.17g", 2.3 * pow(5.0, 2.0 / 3.0));
    /* two laws x two branches; y from 0.36 to 16.9 -> 0.1..100 */
    const char *checks[] = {"markers=7", "reflines=4", "regions=1", "legend=4", "xscale=log", "yscale=log",
                            "xticks=0.1,1,10,100", "yticks=0.1,1,10,100", p1,
                            /* drawn in order: Lube 1.2 a, 1.9 a^(2/3), Lajeunesse 1.8 a, 2.3 a^(2/3) */
                            "refline_law=0,1.2,1", "refline_law=1,1.9,0.6666666666666667", "refline_law=2,1.8,1",
                            "refline_law=3,2.3,0.6666666666666667"};
    check_svg("runout_log.svg", 13, checks);
}

/* Narrow range of a: linear axes; a run with no runout (NaN) is skipped. */
static void test_runout_linear(void)
{
    double a[] = {0.5, 1.0, 1.5, 2.5, 1.2};
    double run[] = {0.9, 1.7, 2.9, 4.1, NAN};
    gf_fig_regime g[] = {GF_FIG_REGIME_VISCOUS, GF_FIG_REGIME_VISCOUS, GF_FIG_REGIME_INERTIAL,
                         GF_FIG_REGIME_FREE_FALL, GF_FIG_REGIME_UNDETERMINED};
    gf_ctx ctx = {0};
    GF_CHECK_OK(gf_fig_runout(&ctx, fig_path("runout_lin.svg"), NULL, 5, a, run, g), &ctx);
    /* a <= 2.6 (padded 2.5) -> axis to 3: Lube's two branches (switch at 2.3) and Lajeunesse's
     * linear one (switch at 3, the axis end) */
    const char *checks[] = {"markers=4", "reflines=3", "legend=6", "xticks=0,0.5,1,1.5,2,2.5,3",
                            "yticks=0,1,2,3,4,5", "point=1.5,2.9", "caption~1 run not shown"};
    check_svg("runout_lin.svg", 7, checks);
}

/* Front position of three runs; the third has a gap (NaN) that breaks its curve. */
static void test_timeseries(void)
{
    enum { N = 50 };
    double t[N], x1[N], x2[N], x3[N];
    for (int i = 0; i < N; ++i) {
        t[i] = 0.01 * i;
        x1[i] = 0.06 + 0.5 * 9.81 * t[i] * t[i] / (1 + 20 * t[i]);
        x2[i] = 0.06 + 0.2 * t[i];
        x3[i] = i == 25 ? NAN : 0.06 + 0.1 * t[i];
    }
    gf_fig_series s[3] = {{"St = 0.5, r = 2 (loose)", N, t, x1}, {"St = 5 & r < 4", N, t, x2}, {NULL, N, t, x3}};
    gf_ctx ctx = {0};
    gf_fig_opts opt = {.title = "Front position"};
    GF_CHECK_OK(gf_fig_timeseries(&ctx, fig_path("front.svg"), &opt, "time t (s)", "front position x_f (m)", 3, s),
                &ctx);
    char c0[64];
    snprintf(c0, sizeof c0, "curve_start=1,0,%.17g", x2[0]);
    const char *checks[] = {"curves=4", "markers=0", "legend=3", "xticks=0,0.1,0.2,0.3,0.4,0.5", c0,
                            "title=Front position"};
    check_svg("front.svg", 6, checks);
}

/* A decaying quantity over ten decades: AUTO picks a log y axis; decades
 * beyond 10^+-3 are labelled 10^k with a superscript (text "10" + "k"). */
static void test_timeseries_log(void)
{
    enum { N = 41 };
    double t[N], e1[N], e2[N];
    for (int i = 0; i < N; ++i) {
        t[i] = 0.05 * i;
        e1[i] = 5e4 * exp(-t[i] / 0.09);   /* 5e4 down to ~1e-5 */
        e2[i] = 2e3 * exp(-t[i] / 0.2);
    }
    gf_fig_series s[2] = {{"kinetic energy, run A", N, t, e1}, {"kinetic energy, run B", N, t, e2}};
    gf_ctx ctx = {0};
    GF_CHECK_OK(gf_fig_timeseries(&ctx, fig_path("energy_log.svg"), NULL, "time t (s)", "kinetic energy (J)", 2, s),
                &ctx);
    char c1[64];
    snprintf(c1, sizeof c1, "curve_start=1,0,%.17g", e2[0]);
    const char *checks[] = {"curves=2", "legend=2", "yscale=log",
                            "ylabels=10-5|10-4|0.001|0.01|0.1|1|10|100|1000|104|105", c1};
    check_svg("energy_log.svg", 5, checks);
}

/* A campaign of 20 runs: every curve is drawn, the legend keeps 13 rows and
 * says how many more there are, so it never outgrows the page. */
static void test_timeseries_many(void)
{
    enum { NS = 20, N = 10 };
    static double t[N], y[NS][N];
    gf_fig_series s[NS];
    static char labels[NS][16];
    for (int i = 0; i < N; ++i)
        t[i] = i;
    for (int k = 0; k < NS; ++k) {
        for (int i = 0; i < N; ++i)
            y[k][i] = k + 0.1 * i;
        snprintf(labels[k], sizeof labels[k], "run %02d", k);
        s[k] = (gf_fig_series){labels[k], N, t, y[k]};
    }
    gf_ctx ctx = {0};
    GF_CHECK_OK(gf_fig_timeseries(&ctx, fig_path("many.svg"), NULL, "t (s)", "y (m)", NS, s), &ctx);
    const char *checks[] = {"curves=20", "legend=14"};
    check_svg("many.svg", 2, checks);
}

/* A campaign of two variants, dry and immersed, at the same four (a, Phi_i):
 * each point carries two markers, filled (dry) and outlined (immersed), side
 * by side and each at its data position once its shift is removed; the
 * legend names the shapes and the variants drawn, and nothing else. */
static void test_variants_side_by_side(void)
{
    double a[] = {0.5, 0.5, 1.0, 1.0, 0.5, 0.5, 1.0, 1.0};
    double phi[] = {0.58, 0.6, 0.58, 0.6, 0.58, 0.6, 0.58, 0.6};
    double run[] = {0.58, 0.59, 1.36, 1.67, 0.084, 0.098, 0.134, 0.143};
    gf_fig_shape shp[] = {GF_FIG_SHAPE_TRAPEZOID,    GF_FIG_SHAPE_TRAPEZOID, GF_FIG_SHAPE_TRIANGLE,
                          GF_FIG_SHAPE_TRIANGLE,     GF_FIG_SHAPE_TRIANGLE,  GF_FIG_SHAPE_UNDETERMINED,
                          GF_FIG_SHAPE_UNDETERMINED, GF_FIG_SHAPE_UNDETERMINED};
    int variant[] = {0, 0, 0, 0, 1, 1, 1, 1};
    const char *names[] = {"dry", "immersed"};
    gf_fig_opts opt = {.n_variants = 2, .variant = variant, .variant_names = names};
    gf_ctx ctx = {0};
    GF_CHECK_OK(gf_fig_deposit_shape(&ctx, fig_path("deposit_variants.svg"), &opt, 8, a, phi, shp), &ctx);
    const char *checks[] = {"markers=8", "hollow=4", "apart=0.5,0.58,2", "apart=0.5,0.6,2", "apart=1,0.58,2",
                            "apart=1,0.6,2",
                            "legend_labels=triangle;trapezoid;undetermined;dry: filled markers;immersed: outlined markers"};
    check_svg("deposit_variants.svg", 7, checks);
    /* runout over a <= 1: the shaded transition a0 = 1.8-2.8 of Lube et al. is off the axis,
     * so neither it nor its legend row is drawn; only one variant drawn, only its row */
    gf_fig_opts one = {.n_variants = 2, .variant = variant, .variant_names = names};
    GF_CHECK_OK(gf_fig_runout(&ctx, fig_path("runout_variants.svg"), &one, 4, a, run, NULL), &ctx);
    const char *checks2[] = {"markers=4", "hollow=0", "regions=0",
                             "legend_labels=runs;dry: filled markers;Lube 2005 (dry): 1.2a | 1.9a^(2/3);"
                             "Lajeunesse 2005 (dry): 1.8a | 2.3a^(2/3)"};
    check_svg("runout_variants.svg", 4, checks2);
}

/* A series with no finite sample is not drawn, so it has no legend row; the caption says so. */
static void test_timeseries_empty_series(void)
{
    double t[3] = {0.0, 1.0, 2.0}, y[3] = {0.0, 0.5, 0.7}, none[3] = {NAN, NAN, NAN};
    gf_fig_series s[3] = {{"dry, a=1", 3, t, y}, {"immersed, a=1", 3, t, none}, {"immersed, a=0.5", 0, NULL, NULL}};
    gf_ctx ctx = {0};
    GF_CHECK_OK(gf_fig_timeseries(&ctx, fig_path("empty_series.svg"), NULL, "t (s)", "y (m)", 3, s), &ctx);
    const char *checks[] = {"curves=1", "legend_labels=dry, a=1", "caption~2 series not shown"};
    check_svg("empty_series.svg", 3, checks);
}

/* Errors: bad arguments say what; an unwritable path leaves nothing behind. */
static void test_errors(void)
{
    gf_ctx ctx = {0};
    double St[1] = {1.0};
    GF_CHECK(gf_fig_regime_diagram(&ctx, fig_path("bad.svg"), NULL, 1, St, NULL, NULL) == GF_ERR_ARG);
    GF_CHECK(strstr(ctx.last_msg, "NULL data array") != NULL);
    GF_CHECK(gf_fig_timeseries(&ctx, fig_path("bad.svg"), NULL, "t", "y", 0, NULL) == GF_ERR_ARG);
    char bad[1200];
    snprintf(bad, sizeof bad, "%s/missing/dir/regime.svg", out_dir);
    double r[1] = {2.0};
    GF_CHECK(gf_fig_regime_diagram(&ctx, bad, NULL, 1, St, r, NULL) == GF_ERR_IO);
    GF_CHECK(strstr(ctx.last_msg, "missing/dir/regime.svg.tmp") != NULL);
    struct stat sb;
    GF_CHECK(stat(fig_path("bad.svg"), &sb) != 0);
    GF_CHECK(stat(fig_path("regime.svg.tmp"), &sb) != 0);   /* renamed, not left as tmp */
}

int main(int argc, char **argv)
{
    if (argc > 1)
        python = argv[1];
    const char *bin = getenv("GF_BINARY_DIR");
    snprintf(out_dir, sizeof out_dir, "%s/test-figures", bin ? bin : "/tmp");
    char cmd[1100];
    snprintf(cmd, sizeof cmd, "mkdir -p '%s'", out_dir);
    if (system(cmd) != 0)
        fprintf(stderr, "cannot create %s\n", out_dir);
    test_ticks_are_nice();
    test_regime_diagram();
    test_deposit_shape();
    test_runout_log();
    test_runout_linear();
    test_timeseries();
    test_timeseries_log();
    test_timeseries_many();
    test_variants_side_by_side();
    test_timeseries_empty_series();
    test_errors();
    return gf_test_finish();
}
