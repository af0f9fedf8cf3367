/*
 * Status codes and the error context.
 *
 * Every fallible call in grainflow returns a gf_status. A failing function
 * records one human-readable line in the context (what, and where: for
 * configuration errors the YAML file:line:column) and returns; only main()
 * of the command-line tool turns a status into an exit code. The library
 * never calls exit().
 *
 * The status list is one X-macro so that enum and message cannot drift
 * (the SUNDIALS convention).
 */
#ifndef GF_STATUS_H
#define GF_STATUS_H

#include <stdarg.h>

#define GF_STATUS_LIST(X)                                          \
    X(GF_OK, "ok")                                                 \
    X(GF_ERR_ARG, "invalid argument")                              \
    X(GF_ERR_CONFIG, "invalid configuration")                      \
    X(GF_ERR_NOMEM, "out of memory")                               \
    X(GF_ERR_IO, "I/O failure")                                    \
    X(GF_ERR_NUMERIC, "non-finite or unstable")                    \
    X(GF_ERR_PHYSICS, "physically impossible input")               \
    X(GF_ERR_CAPACITY, "capacity exceeded")                        \
    X(GF_ERR_NOT_CONVERGED, "solver did not converge")             \
    X(GF_ERR_UNSUPPORTED, "unsupported")                           \
    X(GF_ERR_INTERRUPTED, "interrupted")

typedef enum gf_status {
#define GF_STATUS_ENUM(code, msg) code,
    GF_STATUS_LIST(GF_STATUS_ENUM)
#undef GF_STATUS_ENUM
    GF_STATUS_COUNT
} gf_status;

/* Static text for a code; never NULL. */
const char *gf_status_str(gf_status st);

typedef enum gf_log_level { GF_LOG_QUIET = 0, GF_LOG_WARN, GF_LOG_INFO, GF_LOG_DEBUG } gf_log_level;

/*
 * The context replaces globals: last error, log level. One per thread of
 * control (a campaign worker owns its own). Plain struct: zero-initialised
 * is valid (quiet logging, no error).
 */
typedef struct gf_ctx {
    gf_status last_code;
    char last_msg[512];      /* one line, no trailing newline */
    char last_where[128];    /* source file:line of the GF_FAIL */
    gf_log_level log_level;
} gf_ctx;

/* Records code and message (printf-style) and returns code. ctx may be NULL. */
gf_status gf_fail(gf_ctx *ctx, gf_status code, const char *file, int line, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));

/* Clears the last error. */
void gf_ctx_clear(gf_ctx *ctx);

/* Message of the last error, "" if none. */
const char *gf_ctx_message(const gf_ctx *ctx);

/* Logging to stderr, filtered by ctx->log_level. */
void gf_log(const gf_ctx *ctx, gf_log_level level, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

#define GF_FAIL(ctx, code, ...) gf_fail((ctx), (code), __FILE__, __LINE__, __VA_ARGS__)

#define GF_TRY(expr)                        \
    do {                                    \
        gf_status gf_try_st_ = (expr);      \
        if (gf_try_st_ != GF_OK)            \
            return gf_try_st_;              \
    } while (0)

#endif
