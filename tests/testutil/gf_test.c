/* Minimal test harness; see gf_test.h. */
#include "gf_test.h"

#include <stdarg.h>
#include <stdio.h>

int gf_test_passed, gf_test_failed;

void gf_test_check(int ok, const char *file, int line, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    if (ok) {
        ++gf_test_passed;
    } else {
        ++gf_test_failed;
        fprintf(stderr, "FAIL %s:%d: ", file, line);
        vfprintf(stderr, fmt, ap);
        fputc('\n', stderr);
    }
    va_end(ap);
}

int gf_test_finish(void)
{
    printf("%d passed, %d failed\n", gf_test_passed, gf_test_failed);
    return gf_test_failed == 0 ? 0 : 1;
}
