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
/* One study of a test program that holds several, chosen by name (argv[1]). */
typedef struct gf_test_mode {
    const char *name;
    void (*run)(void);
} gf_test_mode;
/* Runs the study of the n in table named name; 0 when none has that name. */
int gf_test_run_mode(const gf_test_mode *table, int n, const char *name);
/* Removes the folder dir and all it holds (rm -rf); 1 when that succeeded. */
int gf_test_remove_tree(const char *dir);
/* gf_test_finish, then dir removed when every check passed (kept to be
 * looked at when one failed); the exit code. */
int gf_test_finish_removing(const char *dir);

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
