/*
 * The Pareto front and figure of the accuracy benchmark (gf_fig_pareto.c).
 *
 * Six settings (cost s, error):
 *   A (1, 1e-1)  B (2, 1e-2)  C (3, 2e-2)  D (4, 1e-3)  E (4, 1e-3)  F (0.5, NaN)
 * C is dominated by B (cheaper and more accurate); D and E tie (neither is
 * strictly better), so both are on the front; F has no error (a failed run)
 * and is never on it. Front: A, B, D, E (4 settings).
 * The figure: an SVG with one marker per plottable setting plus the ring of
 * the recommended one, the staircase of the front (class pareto-front), the
 * tolerance line, and a caption counting the front and the skipped setting.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "figures/gf_figures.h"
#include "gf_test.h"

static int count(const char *text, const char *needle)
{
    int n = 0;
    for (const char *p = strstr(text, needle); p; p = strstr(p + 1, needle))
        n++;
    return n;
}

int main(void)
{
    const double cost[6] = {1.0, 2.0, 3.0, 4.0, 4.0, 0.5};
    const double err[6] = {1e-1, 1e-2, 2e-2, 1e-3, 1e-3, NAN};
    const unsigned char want[6] = {1, 1, 0, 1, 1, 0};
    unsigned char front[6];
    int n_front = gf_fig_pareto_front(6, cost, err, front);
    GF_CHECK(n_front == 4);
    for (int i = 0; i < 6; ++i)
        GF_CHECK(front[i] == want[i]);

    gf_ctx ctx = {0};
    const char *dir = getenv("GF_BINARY_DIR");
    char path[1024];
    snprintf(path, sizeof path, "%s/pareto_test.svg", dir ? dir : ".");
    const char *labels[6] = {"dt=tc/10", "dt=tc/20", "dt=tc/50", "dt=tc/100", "dt=tc/100 skin=0.4", "dt=tc/200"};
    unsigned char on_front[6];
    GF_CHECK_OK(gf_fig_pareto(&ctx, path, NULL, 6, cost, err, labels, "CPU time (s)", "error (1)", 0.015, 1, on_front),
                &ctx);
    for (int i = 0; i < 6; ++i)
        GF_CHECK(on_front[i] == want[i]);
    FILE *f = fopen(path, "r");
    GF_CHECK(f != NULL);
    if (f) {
        static char buf[1 << 18];
        size_t n = fread(buf, 1, sizeof buf - 1, f);
        buf[n] = '\0';
        fclose(f);
        /* 5 plottable settings + the recommended ring */
        GF_CHECK(count(buf, "class=\"marker\"") == 6);
        GF_CHECK(count(buf, "class=\"pareto-front\"") == 1);
        GF_CHECK(count(buf, "class=\"refline\"") == 1);
        GF_CHECK(strstr(buf, "recommended: dt=tc/20") != NULL);
        GF_CHECK(strstr(buf, "4 on the front") != NULL);
        GF_CHECK(strstr(buf, "1 skipped") != NULL);
        GF_CHECK(strstr(buf, "CPU time (s)") != NULL);
        printf("pareto figure %s: %d markers, front of %d\n", path, count(buf, "class=\"marker\""), n_front);
    }
    /* bad input: one line, no file */
    GF_CHECK(gf_fig_pareto(&ctx, path, NULL, 2, NULL, err, NULL, NULL, NULL, 0.1, -1, NULL) == GF_ERR_ARG);
    return gf_test_finish();
}
