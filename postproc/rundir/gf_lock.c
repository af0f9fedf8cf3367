/* Lock files with flock(2); see gf_lock.h. */
#include "rundir/gf_lock.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <time.h>
#include <unistd.h>

struct gf_lock {
    int fd;
};

/* The record in a lock file: one line "pid P host H since T what W". */
static int read_holder(int fd, gf_lock_holder *h)
{
    char buf[256];
    ssize_t n = pread(fd, buf, sizeof buf - 1, 0);
    memset(h, 0, sizeof *h);
    if (n <= 0)
        return 0;
    buf[n] = '\0';
    if (sscanf(buf, "pid %ld host %63s since %ld what %95[^\n]", &h->pid, h->host, &h->since, h->what) < 3) {
        snprintf(h->what, sizeof h->what, "unreadable lock record");
        return 1;
    }
    return 1;
}

static int write_holder(int fd, const char *what)
{
    char host[64] = "unknown", buf[256];
    gethostname(host, sizeof host - 1);
    host[sizeof host - 1] = '\0';
    int len = snprintf(buf, sizeof buf, "pid %ld host %s since %ld what %s\n", (long)getpid(), host,
                       (long)time(NULL), what && *what ? what : "grainflow");
    if (len >= (int)sizeof buf)
        len = (int)sizeof buf - 1;
    return ftruncate(fd, 0) == 0 && pwrite(fd, buf, (size_t)len, 0) == len ? 0 : -1;
}

gf_status gf_lock_take(gf_ctx *ctx, const char *lock_path, const char *what, double wait_s, gf_lock **out,
                       gf_lock_holder *other, int *stale)
{
    *out = NULL;
    if (stale)
        *stale = 0;
    memset(other, 0, sizeof *other);
    int fd = open(lock_path, O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd < 0)
        return GF_FAIL(ctx, GF_ERR_IO, "%s: cannot open the lock file: %s", lock_path, strerror(errno));
    struct timespec t0;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    for (;;) {
        if (flock(fd, LOCK_EX | LOCK_NB) == 0)
            break;
        if (errno != EWOULDBLOCK && errno != EINTR) {
            int e = errno;
            close(fd);
            return GF_FAIL(ctx, GF_ERR_IO, "%s: cannot lock: %s", lock_path, strerror(e));
        }
        struct timespec now;
        clock_gettime(CLOCK_MONOTONIC, &now);
        if ((double)(now.tv_sec - t0.tv_sec) + 1e-9 * (double)(now.tv_nsec - t0.tv_nsec) >= wait_s) {
            read_holder(fd, other);
            close(fd);
            return GF_OK;
        }
        struct timespec pause = {0, 100 * 1000 * 1000};
        nanosleep(&pause, NULL);
    }
    /* a record left in an unlocked file: its holder ended without releasing */
    if (read_holder(fd, other) && stale)
        *stale = 1;
    if (write_holder(fd, what) != 0) {
        int e = errno;
        close(fd);
        return GF_FAIL(ctx, GF_ERR_IO, "%s: cannot write the lock record: %s", lock_path, strerror(e));
    }
    gf_lock *l = malloc(sizeof *l);
    if (!l) {
        close(fd);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "out of memory");
    }
    l->fd = fd;
    *out = l;
    return GF_OK;
}

void gf_lock_release(gf_lock **lock)
{
    if (!lock || !*lock)
        return;
    if (ftruncate((*lock)->fd, 0) != 0) {
        /* the record stays: the next holder reports a stale lock, which is harmless */
    }
    flock((*lock)->fd, LOCK_UN);
    close((*lock)->fd);
    free(*lock);
    *lock = NULL;
}

void gf_lock_describe(const gf_lock_holder *h, char *buf, size_t n)
{
    char when[64] = "an unknown time";
    if (h->since > 0) {
        time_t t = (time_t)h->since;
        struct tm tm;
        gmtime_r(&t, &tm);
        strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S UTC", &tm);
    }
    if (h->pid > 0)
        snprintf(buf, n, "pid %ld on %s (%s) since %s", h->pid, h->host[0] ? h->host : "an unknown host",
                 h->what[0] ? h->what : "grainflow", when);
    else
        snprintf(buf, n, "another process (%s)", h->what[0] ? h->what : "no record");
}
