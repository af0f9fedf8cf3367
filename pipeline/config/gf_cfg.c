/*
 * YAML -> located tree, with libyaml's event API (see gf_cfg.h for what is
 * accepted and why).
 *
 * The tree is built iteratively with an explicit stack of open containers,
 * so a hostile file cannot exhaust the C stack; the stack is bounded by
 * GF_CFG_MAX_DEPTH and the error names the line where the limit was crossed.
 * Scalars stay text until a reader asks for a type: the schema, not the YAML
 * resolver, decides whether "1e-3" is a number (a quoted "1e-3" never is).
 */
#include "config/gf_cfg.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <yaml.h>

#define MAX_FILE_BYTES (16u << 20)

void gf_cfg_node_free(gf_cfg_node *node)
{
    if (!node)
        return;
    for (int i = 0; i < node->n_items; ++i)
        gf_cfg_node_free(node->items[i]);
    free(node->items);
    free(node->key);
    free(node->text);
    free(node);
}

void gf_cfg_destroy(gf_cfg_doc **doc)
{
    if (!doc || !*doc)
        return;
    gf_cfg_node_free((*doc)->root);
    free((*doc)->path);
    free((*doc)->text);
    free(*doc);
    *doc = NULL;
}

static gf_cfg_node *node_new(gf_cfg_kind kind, int line, int column)
{
    gf_cfg_node *n = calloc(1, sizeof *n);
    if (n) {
        n->kind = kind;
        n->line = n->key_line = line;
        n->column = n->key_column = column;
    }
    return n;
}

static int node_append(gf_cfg_node *parent, gf_cfg_node *child)
{
    if (parent->n_items == parent->cap_items) {
        int cap = parent->cap_items ? 2 * parent->cap_items : 8;
        gf_cfg_node **items = realloc(parent->items, (size_t)cap * sizeof *items);
        if (!items)
            return -1;
        parent->items = items;
        parent->cap_items = cap;
    }
    parent->items[parent->n_items++] = child;
    return 0;
}

const char *gf_cfg_where(const gf_cfg_doc *doc, const gf_cfg_node *node, int at_key, char *buf, size_t n)
{
    const char *path = doc && doc->path ? doc->path : "<config>";
    if (node && node->origin)
        snprintf(buf, n, "%s", node->origin);
    else if (node)
        snprintf(buf, n, "%s:%d:%d", path, at_key ? node->key_line : node->line,
                 at_key ? node->key_column : node->column);
    else
        snprintf(buf, n, "%s:1:1", path);
    return buf;
}

gf_status gf_cfg_fail(gf_ctx *ctx, gf_status code, const gf_cfg_doc *doc, const gf_cfg_node *node, int at_key,
                      const char *fmt, ...)
{
    char where[300], msg[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return GF_FAIL(ctx, code, "%s: %s", gf_cfg_where(doc, node, at_key, where, sizeof where), msg);
}

/* Line and column (1-based) of a byte offset, for reader errors. */
static void offset_to_mark(const char *text, size_t len, size_t offset, int *line, int *column)
{
    *line = 1;
    *column = 1;
    for (size_t i = 0; i < offset && i < len; ++i) {
        if (text[i] == '\n') {
            ++*line;
            *column = 1;
        } else {
            ++*column;
        }
    }
}

static gf_status parser_error(gf_ctx *ctx, const gf_cfg_doc *doc, const yaml_parser_t *p)
{
    int line = (int)p->problem_mark.line + 1, column = (int)p->problem_mark.column + 1;
    const char *problem = p->problem ? p->problem : "malformed YAML";
    if (p->error == YAML_READER_ERROR) {
        offset_to_mark(doc->text, doc->text_len, p->problem_offset, &line, &column);
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s:%d:%d: not a text file: %s (byte 0x%02x)", doc->path, line, column,
                       problem, (unsigned)(p->problem_value & 0xff));
    }
    if (p->error == YAML_MEMORY_ERROR)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "%s: out of memory while parsing", doc->path);
    if (p->problem_mark.index < doc->text_len && doc->text[p->problem_mark.index] == '\t')
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s:%d:%d: tab character: YAML indentation must use spaces", doc->path,
                       line, column);
    if (p->context)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s:%d:%d: %s %s (line %d)", doc->path, line, column, problem,
                       p->context, (int)p->context_mark.line + 1);
    return GF_FAIL(ctx, GF_ERR_CONFIG, "%s:%d:%d: %s", doc->path, line, column, problem);
}

/* An open container while the tree is built. */
typedef struct frame {
    gf_cfg_node *node;
    char *pending_key;      /* map: key read, value not yet */
    int key_line, key_column;
} frame;

typedef struct builder {
    gf_ctx *ctx;
    gf_cfg_doc *doc;
    frame stack[GF_CFG_MAX_DEPTH + 1];
    int depth;
} builder;

static gf_status reject_decorations(builder *b, const yaml_event_t *ev, const yaml_char_t *anchor,
                                    const yaml_char_t *tag, int implicit)
{
    int line = (int)ev->start_mark.line + 1, column = (int)ev->start_mark.column + 1;
    if (anchor)
        return GF_FAIL(b->ctx, GF_ERR_CONFIG, "%s:%d:%d: anchors (&%s) are not supported in a configuration",
                       b->doc->path, line, column, (const char *)anchor);
    if (tag && !implicit)
        return GF_FAIL(b->ctx, GF_ERR_CONFIG, "%s:%d:%d: tags (%s) are not supported in a configuration",
                       b->doc->path, line, column, (const char *)tag);
    return GF_OK;
}

/* Places a finished node (scalar or new container) into the current parent. */
static gf_status place(builder *b, gf_cfg_node *n, const yaml_event_t *ev)
{
    int line = (int)ev->start_mark.line + 1, column = (int)ev->start_mark.column + 1;
    if (b->depth == 0) {
        if (b->doc->root) {
            gf_cfg_node_free(n);
            return GF_FAIL(b->ctx, GF_ERR_CONFIG, "%s:%d:%d: more than one document", b->doc->path, line, column);
        }
        b->doc->root = n;
        return GF_OK;
    }
    frame *f = &b->stack[b->depth - 1];
    if (f->node->kind == GF_CFG_MAP) {
        if (!f->pending_key) {
            if (n->kind != GF_CFG_SCALAR) {
                const char *what = n->kind == GF_CFG_MAP ? "mapping" : "sequence";
                gf_cfg_node_free(n);
                return GF_FAIL(b->ctx, GF_ERR_CONFIG, "%s:%d:%d: a key must be a plain name, not a %s",
                               b->doc->path, line, column, what);
            }
            const gf_cfg_node *dup = gf_cfg_get(f->node, n->text);
            if (dup) {
                gf_status st = GF_FAIL(b->ctx, GF_ERR_CONFIG, "%s:%d:%d: duplicate key '%s' (first at line %d)",
                                       b->doc->path, line, column, n->text, dup->key_line);
                gf_cfg_node_free(n);
                return st;
            }
            f->pending_key = n->text;
            n->text = NULL;
            f->key_line = n->line;
            f->key_column = n->column;
            gf_cfg_node_free(n);
            return GF_OK;
        }
        n->key = f->pending_key;
        n->key_line = f->key_line;
        n->key_column = f->key_column;
        f->pending_key = NULL;
    }
    if (node_append(f->node, n) != 0) {
        gf_cfg_node_free(n);
        return GF_FAIL(b->ctx, GF_ERR_NOMEM, "%s: out of memory while parsing", b->doc->path);
    }
    return GF_OK;
}

static gf_status on_event(builder *b, const yaml_event_t *ev, int *done)
{
    int line = (int)ev->start_mark.line + 1, column = (int)ev->start_mark.column + 1;
    switch (ev->type) {
    case YAML_SCALAR_EVENT: {
        GF_TRY(reject_decorations(b, ev, ev->data.scalar.anchor, ev->data.scalar.tag,
                                  ev->data.scalar.plain_implicit || ev->data.scalar.quoted_implicit));
        if (strlen((const char *)ev->data.scalar.value) != ev->data.scalar.length)
            return GF_FAIL(b->ctx, GF_ERR_CONFIG, "%s:%d:%d: NUL character inside a value", b->doc->path, line,
                           column);
        gf_cfg_node *n = node_new(GF_CFG_SCALAR, line, column);
        if (n)
            n->text = strdup((const char *)ev->data.scalar.value);
        if (!n || !n->text) {
            gf_cfg_node_free(n);
            return GF_FAIL(b->ctx, GF_ERR_NOMEM, "%s: out of memory while parsing", b->doc->path);
        }
        n->quoted = ev->data.scalar.style != YAML_PLAIN_SCALAR_STYLE;
        return place(b, n, ev);
    }
    case YAML_MAPPING_START_EVENT:
    case YAML_SEQUENCE_START_EVENT: {
        int is_map = ev->type == YAML_MAPPING_START_EVENT;
        GF_TRY(reject_decorations(b, ev, is_map ? ev->data.mapping_start.anchor : ev->data.sequence_start.anchor,
                                  is_map ? ev->data.mapping_start.tag : ev->data.sequence_start.tag,
                                  is_map ? ev->data.mapping_start.implicit : ev->data.sequence_start.implicit));
        if (b->depth >= GF_CFG_MAX_DEPTH)
            return GF_FAIL(b->ctx, GF_ERR_CONFIG, "%s:%d:%d: nesting deeper than %d levels", b->doc->path, line,
                           column, GF_CFG_MAX_DEPTH);
        gf_cfg_node *n = node_new(is_map ? GF_CFG_MAP : GF_CFG_SEQ, line, column);
        if (!n)
            return GF_FAIL(b->ctx, GF_ERR_NOMEM, "%s: out of memory while parsing", b->doc->path);
        GF_TRY(place(b, n, ev));
        b->stack[b->depth++] = (frame){.node = n};
        return GF_OK;
    }
    case YAML_MAPPING_END_EVENT:
    case YAML_SEQUENCE_END_EVENT:
        if (b->depth > 0) {
            free(b->stack[b->depth - 1].pending_key);
            b->stack[--b->depth].pending_key = NULL;
        }
        return GF_OK;
    case YAML_ALIAS_EVENT:
        return GF_FAIL(b->ctx, GF_ERR_CONFIG, "%s:%d:%d: aliases (*%s) are not supported in a configuration",
                       b->doc->path, line, column, (const char *)ev->data.alias.anchor);
    case YAML_DOCUMENT_START_EVENT:
        if (b->doc->root)
            return GF_FAIL(b->ctx, GF_ERR_CONFIG, "%s:%d:%d: more than one document", b->doc->path, line, column);
        return GF_OK;
    case YAML_STREAM_END_EVENT:
        *done = 1;
        return GF_OK;
    default:
        return GF_OK;
    }
}

gf_status gf_cfg_parse_string(gf_ctx *ctx, const char *name, const char *text, size_t len, gf_cfg_doc **out)
{
    *out = NULL;
    gf_cfg_doc *doc = calloc(1, sizeof *doc);
    if (!doc)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "config: out of memory");
    doc->path = strdup(name ? name : "<config>");
    doc->text = malloc(len + 1);
    if (!doc->path || !doc->text) {
        gf_cfg_destroy(&doc);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "config: out of memory");
    }
    memcpy(doc->text, text, len);
    doc->text[len] = '\0';
    doc->text_len = len;

    yaml_parser_t parser;
    if (!yaml_parser_initialize(&parser)) {
        gf_cfg_destroy(&doc);
        return GF_FAIL(ctx, GF_ERR_NOMEM, "config: cannot initialise the YAML parser");
    }
    yaml_parser_set_input_string(&parser, (const unsigned char *)doc->text, len);
    builder b = {.ctx = ctx, .doc = doc};
    gf_status st = GF_OK;
    for (int done = 0; !done && st == GF_OK;) {
        yaml_event_t ev;
        if (!yaml_parser_parse(&parser, &ev)) {
            st = parser_error(ctx, doc, &parser);
            break;
        }
        st = on_event(&b, &ev, &done);
        yaml_event_delete(&ev);
    }
    yaml_parser_delete(&parser);
    for (int i = 0; i < b.depth; ++i)
        free(b.stack[i].pending_key);
    if (st != GF_OK) {
        gf_cfg_destroy(&doc);
        return st;
    }
    *out = doc;
    return GF_OK;
}

gf_status gf_cfg_parse_file(gf_ctx *ctx, const char *path, gf_cfg_doc **out)
{
    *out = NULL;
    FILE *f = fopen(path, "rb");
    if (!f)
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s:1:1: cannot open: %s", path, strerror(errno));
    size_t cap = 4096, len = 0;
    char *buf = malloc(cap);
    while (buf) {
        if (len == cap) {
            if (cap >= MAX_FILE_BYTES) {
                free(buf);
                fclose(f);
                return GF_FAIL(ctx, GF_ERR_CONFIG, "%s:1:1: larger than %u MiB: not a configuration", path,
                               MAX_FILE_BYTES >> 20);
            }
            char *nb = realloc(buf, cap * 2);
            if (!nb) {
                free(buf);
                buf = NULL;
                break;
            }
            buf = nb;
            cap *= 2;
        }
        size_t got = fread(buf + len, 1, cap - len, f);
        len += got;
        if (got == 0)
            break;
    }
    int read_error = ferror(f);
    fclose(f);
    if (!buf)
        return GF_FAIL(ctx, GF_ERR_NOMEM, "%s: out of memory", path);
    if (read_error) {
        free(buf);
        return GF_FAIL(ctx, GF_ERR_CONFIG, "%s:1:1: read error (is it a directory?)", path);
    }
    gf_status st = gf_cfg_parse_string(ctx, path, buf, len, out);
    free(buf);
    return st;
}

const gf_cfg_node *gf_cfg_get(const gf_cfg_node *map, const char *key)
{
    if (!map || map->kind != GF_CFG_MAP)
        return NULL;
    for (int i = 0; i < map->n_items; ++i)
        if (map->items[i]->key && strcmp(map->items[i]->key, key) == 0)
            return map->items[i];
    return NULL;
}

gf_cfg_node *gf_cfg_scalar_new(const char *text, const char *origin)
{
    gf_cfg_node *n = node_new(GF_CFG_SCALAR, 1, 1);
    if (!n)
        return NULL;
    n->text = strdup(text);
    if (!n->text) {
        free(n);
        return NULL;
    }
    n->origin = origin;
    return n;
}

gf_status gf_cfg_map_set_path(gf_ctx *ctx, gf_cfg_node *map, const char *dotted_path, gf_cfg_node *value)
{
    char part[128];
    const char *p = dotted_path;
    gf_cfg_node *cur = map;
    for (;;) {
        const char *dot = strchr(p, '.');
        size_t n = dot ? (size_t)(dot - p) : strlen(p);
        if (n == 0 || n >= sizeof part) {
            gf_status st = GF_FAIL(ctx, GF_ERR_CONFIG, "%s: malformed key path '%s'",
                                   value && value->origin ? value->origin : "config", dotted_path);
            gf_cfg_node_free(value);
            return st;
        }
        memcpy(part, p, n);
        part[n] = '\0';
        if (cur->kind != GF_CFG_MAP) {
            gf_status st = GF_FAIL(ctx, GF_ERR_CONFIG, "%s: '%s' is not a section",
                                   value && value->origin ? value->origin : "config", part);
            gf_cfg_node_free(value);
            return st;
        }
        gf_cfg_node *child = NULL;
        int index = -1;
        for (int i = 0; i < cur->n_items; ++i)
            if (cur->items[i]->key && strcmp(cur->items[i]->key, part) == 0) {
                child = cur->items[i];
                index = i;
            }
        if (!dot) {
            free(value->key);
            value->key = strdup(part);
            if (index >= 0) {
                value->key_line = child->key_line;
                value->key_column = child->key_column;
                gf_cfg_node_free(child);
                cur->items[index] = value;
            } else if (node_append(cur, value) != 0) {
                gf_cfg_node_free(value);
                return GF_FAIL(ctx, GF_ERR_NOMEM, "config: out of memory");
            }
            return GF_OK;
        }
        if (!child) {
            child = node_new(GF_CFG_MAP, 1, 1);
            if (!child || node_append(cur, child) != 0) {
                free(child);
                gf_cfg_node_free(value);
                return GF_FAIL(ctx, GF_ERR_NOMEM, "config: out of memory");
            }
            child->key = strdup(part);
            child->origin = value->origin;
        }
        cur = child;
        p = dot + 1;
    }
}

static const char *kind_name(gf_cfg_kind k)
{
    return k == GF_CFG_MAP ? "a mapping" : k == GF_CFG_SEQ ? "a list" : "a value";
}

static const char *key_of(const gf_cfg_node *n)
{
    return n->key ? n->key : "list item";
}

gf_status gf_cfg_expect(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, gf_cfg_kind kind)
{
    if (node->kind != kind)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: expected %s, got %s", key_of(node),
                           kind_name(kind), kind_name(node->kind));
    return GF_OK;
}

gf_status gf_cfg_to_double(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, double min, double max,
                           double *out)
{
    if (node->kind != GF_CFG_SCALAR)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: expected a number, got %s", key_of(node),
                           kind_name(node->kind));
    const char *s = node->text;
    if (node->quoted)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: expected a number, got the string \"%.40s\"",
                           key_of(node), s);
    if (!*s)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: expected a number, got nothing", key_of(node));
    errno = 0;
    char *end = NULL;
    double v = strtod(s, &end);
    /* strtod also reads "nan", "inf" and hexadecimal floats; a configuration
     * value must be a finite decimal number. */
    if (end == s || *end || strpbrk(s, "xXnNiI"))
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: expected a number, got '%.40s'", key_of(node), s);
    if (errno == ERANGE && fabs(v) > 1.0)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: %.40s is too large to be a double",
                           key_of(node), s);
    if (errno == ERANGE)
        v = 0.0; /* underflow to zero: the range check below decides */
    if (!isfinite(v))
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: not a finite number", key_of(node));
    if (v < min || v > max)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s = %g is out of range [%g, %g]", key_of(node), v,
                           min, max);
    *out = v;
    return GF_OK;
}

gf_status gf_cfg_to_u64(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, uint64_t *out)
{
    if (node->kind != GF_CFG_SCALAR || node->quoted || !*node->text)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: expected a non-negative integer", key_of(node));
    const char *s = node->text;
    for (const char *c = s; *c; ++c)
        if (*c < '0' || *c > '9')
            return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: expected a non-negative integer, got '%.40s'",
                               key_of(node), s);
    errno = 0;
    unsigned long long v = strtoull(s, NULL, 10);
    if (errno == ERANGE)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: %.40s does not fit in 64 bits", key_of(node), s);
    *out = (uint64_t)v;
    return GF_OK;
}

gf_status gf_cfg_to_bool(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, int *out)
{
    static const char *const yes[] = {"true", "True", "TRUE", "yes", "on", "1"};
    static const char *const no[] = {"false", "False", "FALSE", "no", "off", "0"};
    if (node->kind == GF_CFG_SCALAR && !node->quoted)
        for (size_t i = 0; i < sizeof yes / sizeof *yes; ++i) {
            if (strcmp(node->text, yes[i]) == 0) {
                *out = 1;
                return GF_OK;
            }
            if (strcmp(node->text, no[i]) == 0) {
                *out = 0;
                return GF_OK;
            }
        }
    return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: expected true or false, got %s%.40s%s", key_of(node),
                       node->kind == GF_CFG_SCALAR ? "'" : "", node->kind == GF_CFG_SCALAR ? node->text
                                                                                           : kind_name(node->kind),
                       node->kind == GF_CFG_SCALAR ? "'" : "");
}

gf_status gf_cfg_to_name(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, const char *const *choices,
                         char *buf, size_t n)
{
    if (node->kind != GF_CFG_SCALAR)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: expected a name, got %s", key_of(node),
                           kind_name(node->kind));
    if (!*node->text)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: expected a name, got nothing", key_of(node));
    if (strlen(node->text) >= n)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: name longer than %zu characters", key_of(node),
                           n - 1);
    if (choices) {
        int ok = 0;
        for (const char *const *c = choices; *c; ++c)
            ok |= strcmp(*c, node->text) == 0;
        if (!ok) {
            char list[256] = "";
            for (const char *const *c = choices; *c; ++c) {
                strncat(list, *c, sizeof list - strlen(list) - 1);
                if (c[1])
                    strncat(list, ", ", sizeof list - strlen(list) - 1);
            }
            const char *s = gf_cfg_suggest(node->text, choices);
            if (s)
                return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: unknown value '%.40s' (did you mean '%s'?)",
                                   key_of(node), node->text, s);
            return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 0, "%s: unknown value '%.40s' (one of: %s)",
                               key_of(node), node->text, list);
        }
    }
    snprintf(buf, n, "%s", node->text);
    return GF_OK;
}

int gf_cfg_edit_distance(const char *a, const char *b)
{
    size_t la = strlen(a), lb = strlen(b);
    if (la > 64 || lb > 64)
        return (int)(la > lb ? la : lb);
    int row[65];
    for (size_t j = 0; j <= lb; ++j)
        row[j] = (int)j;
    for (size_t i = 1; i <= la; ++i) {
        int diag = row[0];
        row[0] = (int)i;
        for (size_t j = 1; j <= lb; ++j) {
            int up = row[j];
            int best = diag + (a[i - 1] != b[j - 1]);
            if (up + 1 < best)
                best = up + 1;
            if (row[j - 1] + 1 < best)
                best = row[j - 1] + 1;
            row[j] = best;
            diag = up;
        }
    }
    return row[lb];
}

const char *gf_cfg_suggest(const char *word, const char *const *candidates)
{
    int limit = (int)strlen(word) / 3;
    if (limit < 2)
        limit = 2;
    const char *best = NULL;
    int best_d = limit + 1;
    for (const char *const *c = candidates; c && *c; ++c) {
        int d = gf_cfg_edit_distance(word, *c);
        if (d < best_d) {
            best_d = d;
            best = *c;
        }
    }
    return best;
}

gf_status gf_cfg_fail_unknown_key(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, const char *section,
                                  const char *const *candidates)
{
    const char *s = gf_cfg_suggest(node->key ? node->key : "", candidates);
    if (s)
        return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 1, "unknown key '%.60s' in %s (did you mean '%s'?)",
                           node->key, section, s);
    return gf_cfg_fail(ctx, GF_ERR_CONFIG, doc, node, 1, "unknown key '%.60s' in %s", node->key, section);
}

gf_cfg_node *gf_cfg_clone(const gf_cfg_node *node)
{
    if (!node)
        return NULL;
    gf_cfg_node *c = malloc(sizeof *c);
    if (!c)
        return NULL;
    *c = *node;
    c->items = NULL;
    c->n_items = c->cap_items = 0;
    c->key = node->key ? strdup(node->key) : NULL;
    c->text = node->text ? strdup(node->text) : NULL;
    if ((node->key && !c->key) || (node->text && !c->text)) {
        gf_cfg_node_free(c);
        return NULL;
    }
    for (int i = 0; i < node->n_items; ++i) {
        gf_cfg_node *k = gf_cfg_clone(node->items[i]);
        if (!k || node_append(c, k) != 0) {
            gf_cfg_node_free(k);
            gf_cfg_node_free(c);
            return NULL;
        }
    }
    return c;
}
