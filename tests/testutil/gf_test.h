/*
 * Minimal test harness: each check prints one line on failure with the
 * values and the tolerance; gf_test_finish prints "N passed, N failed" and
 * returns the exit code.
 */
#ifndef GF_TEST_H
#define GF_TEST_H

#include <math.h>

extern int gf_test_passed, gf_test_failed;

void gf_test_check(int ok, const char *file, int line, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
int gf_test_finish(void);

/* |got - want| <= tol * |want| */
#define GF_CHECK_REL(got, want, tol)                                                                   \
    gf_test_check(fabs((double)(got) - (double)(want)) <= (tol) * fabs((double)(want)), __FILE__, __LINE__, \
                  "%s = %.6g, expected %.6g within %.3g relative", #got, (double)(got), (double)(want),   \
                  (double)(tol))
/* |got - want| <= tol */
#define GF_CHECK_ABS(got, want, tol)                                                                   \
    gf_test_check(fabs((double)(got) - (double)(want)) <= (tol), __FILE__, __LINE__,                    \
                  "%s = %.6g, expected %.6g within %.3g", #got, (double)(got), (double)(want), (double)(tol))
#define GF_CHECK(cond) gf_test_check((cond) != 0, __FILE__, __LINE__, "%s", #cond)
#define GF_CHECK_OK(expr, ctx)                                                                   \
    do {                                                                                         \
        gf_status st_ = (expr);                                                                  \
        gf_test_check(st_ == GF_OK, __FILE__, __LINE__, "%s -> %s: %s", #expr, gf_status_str(st_), \
                      (ctx)->last_msg);                                                          \
    } while (0)

#endif
