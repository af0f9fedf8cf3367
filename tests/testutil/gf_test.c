/* Minimal test harness; see gf_test.h. */
#include "gf_test.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

int gf_test_run_mode(const gf_test_mode *table, int n, const char *name)
{
    for (int k = 0; k < n; ++k)
        if (strcmp(table[k].name, name) == 0) {
            table[k].run();
            return 1;
        }
    return 0;
}

int gf_test_remove_tree(const char *dir)
{
    char cmd[4200];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0;
}

int gf_test_finish_removing(const char *dir)
{
    int rc = gf_test_finish();
    if (rc == 0 && !gf_test_remove_tree(dir))
        printf("could not remove %s\n", dir);
    return rc;
}
