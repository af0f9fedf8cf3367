/*
 * gf_cfg: a YAML document as a small tree whose every node remembers where it
 * came from (file:line:column), so that every configuration error can point
 * at the exact spot. This module is the only caller of libyaml.
 *
 * Only the subset of YAML a configuration needs is accepted: one document of
 * block or flow mappings, sequences and scalars. Anchors and aliases, tags,
 * non-scalar keys, duplicate keys and nesting deeper than GF_CFG_MAX_DEPTH are
 * refused with a located message; a configuration never needs them and each
 * is a way to write a file whose meaning is not what it looks like (aliases
 * also allow "billion laughs" expansion).
 *
 * Errors are one line, "file:line:column: message" (libyaml marks are
 * 0-based; we add 1), recorded in the gf_ctx with GF_ERR_CONFIG. Reader
 * errors (invalid UTF-8, control characters) carry only a byte offset; the
 * line and column are then recomputed from the buffer.
 */
#ifndef GF_CFG_H
#define GF_CFG_H

#include <stddef.h>
#include <stdint.h>

#include "core/gf_status.h"

#define GF_CFG_MAX_DEPTH 32

typedef enum gf_cfg_kind { GF_CFG_SCALAR, GF_CFG_MAP, GF_CFG_SEQ } gf_cfg_kind;

typedef struct gf_cfg_node gf_cfg_node;
struct gf_cfg_node {
    gf_cfg_kind kind;
    int line, column;        /* 1-based position of the value */
    int key_line, key_column;/* 1-based position of the key (children of a map) */
    char *key;               /* key when the parent is a map, else NULL */
    char *text;              /* scalar text; NULL for maps and sequences */
    int quoted;              /* scalar was quoted: a string, never a number */
    const char *origin;      /* non-NULL: where the node came from instead of file:line:col
                                (e.g. "--set fluid.model=none"); borrowed, static or owned by doc */
    gf_cfg_node **items;     /* children (map values carry their key) */
    int n_items, cap_items;
};

typedef struct gf_cfg_doc {
    char *path;              /* file name used in messages */
    char *text;              /* the document text, NUL-terminated */
    size_t text_len;
    gf_cfg_node *root;       /* NULL for an empty document */
} gf_cfg_doc;

/* Parses a file / a buffer into a tree. Returns owned *out.
 * Errors: GF_ERR_CONFIG (missing file, malformed YAML, unsupported feature). */
gf_status gf_cfg_parse_file(gf_ctx *ctx, const char *path, gf_cfg_doc **out);
gf_status gf_cfg_parse_string(gf_ctx *ctx, const char *name, const char *text, size_t len, gf_cfg_doc **out);
void gf_cfg_destroy(gf_cfg_doc **doc);

/* Child of a map by key, NULL when absent or when map is not a map. */
const gf_cfg_node *gf_cfg_get(const gf_cfg_node *map, const char *key);

/* New scalar node (owned by the caller until added with gf_cfg_map_set). */
gf_cfg_node *gf_cfg_scalar_new(const char *text, const char *origin);
/* Sets dotted_path ("fluid.model") in map to value, replacing an existing
 * child and creating missing intermediate maps; takes ownership of value. */
gf_status gf_cfg_map_set_path(gf_ctx *ctx, gf_cfg_node *map, const char *dotted_path, gf_cfg_node *value);
void gf_cfg_node_free(gf_cfg_node *node);
/* Deep copy (positions and origins kept). Returns owned node or NULL (no memory). */
gf_cfg_node *gf_cfg_clone(const gf_cfg_node *node);

/* Records "where: message" for node and returns code. */
gf_status gf_cfg_fail(gf_ctx *ctx, gf_status code, const gf_cfg_doc *doc, const gf_cfg_node *node, int at_key,
                      const char *fmt, ...) __attribute__((format(printf, 6, 7)));
/* "file:line:column" (or the node's origin) of node into buf. */
const char *gf_cfg_where(const gf_cfg_doc *doc, const gf_cfg_node *node, int at_key, char *buf, size_t n);

/* Typed reads; the error names the key and says what was expected.
 * Numbers must be finite and in [min, max]. */
gf_status gf_cfg_to_double(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, double min, double max,
                           double *out);
gf_status gf_cfg_to_u64(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, uint64_t *out);
gf_status gf_cfg_to_bool(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, int *out);
/* String into buf (size n); choices (NULL-terminated, may be NULL) restricts the value. */
gf_status gf_cfg_to_name(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, const char *const *choices,
                         char *buf, size_t n);
/* Error unless node is of kind. */
gf_status gf_cfg_expect(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, gf_cfg_kind kind);

/* Levenshtein distance (bytes), for "did you mean". */
int gf_cfg_edit_distance(const char *a, const char *b);
/* The closest of candidates (NULL-terminated) to word, or NULL when none is
 * within max(2, strlen(word)/3) edits. */
const char *gf_cfg_suggest(const char *word, const char *const *candidates);
/* "unknown key 'k' in section (did you mean 'x'?)" at the key of node. */
gf_status gf_cfg_fail_unknown_key(gf_ctx *ctx, const gf_cfg_doc *doc, const gf_cfg_node *node, const char *section,
                                  const char *const *candidates);

#endif
