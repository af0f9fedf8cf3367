/* Status messages and the error context; see gf_status.h. */
#include "core/gf_status.h"

#include <stdio.h>
#include <string.h>

const char *gf_status_str(gf_status st)
{
    static const char *const text[] = {
#define GF_STATUS_TEXT(code, msg) msg,
        GF_STATUS_LIST(GF_STATUS_TEXT)
#undef GF_STATUS_TEXT
    };
    if ((int)st < 0 || st >= GF_STATUS_COUNT)
        return "unknown status";
    return text[st];
}

gf_status gf_fail(gf_ctx *ctx, gf_status code, const char *file, int line, const char *fmt, ...)
{
    if (!ctx)
        return code;
    ctx->last_code = code;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(ctx->last_msg, sizeof ctx->last_msg, fmt, ap);
    va_end(ap);
    /* A message is one line: a stray newline would break "file:line:col: msg". */
    for (char *c = ctx->last_msg; *c; ++c)
        if (*c == '\n')
            *c = ' ';
    const char *base = strrchr(file, '/');
    snprintf(ctx->last_where, sizeof ctx->last_where, "%s:%d", base ? base + 1 : file, line);
    return code;
}

void gf_ctx_clear(gf_ctx *ctx)
{
    if (!ctx)
        return;
    ctx->last_code = GF_OK;
    ctx->last_msg[0] = '\0';
    ctx->last_where[0] = '\0';
}

const char *gf_ctx_message(const gf_ctx *ctx)
{
    return ctx ? ctx->last_msg : "";
}

void gf_log(const gf_ctx *ctx, gf_log_level level, const char *fmt, ...)
{
    gf_log_level current = ctx ? ctx->log_level : GF_LOG_WARN;
    if (level > current)
        return;
    va_list ap;
    va_start(ap, fmt);
    fputs("grainflow: ", stderr);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
}
