/* The per-run summary row (gf_stage.h): a fixed-size dictionary of named
 * results, plain data so that a forked worker can send it back in one write. */
#include "stages/gf_stage.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void gf_post_row_init(gf_post_row *row, const char *run_dir)
{
    memset(row, 0, sizeof *row);
    snprintf(row->run_dir, sizeof row->run_dir, "%s", run_dir ? run_dir : "");
    snprintf(row->status, sizeof row->status, "ok");
}

static gf_post_field *slot(gf_post_row *row, const char *name)
{
    for (int i = 0; i < row->n_fields; ++i)
        if (strcmp(row->fields[i].name, name) == 0)
            return &row->fields[i];
    if (row->n_fields >= GF_ROW_MAX_FIELDS)
        return NULL;
    gf_post_field *f = &row->fields[row->n_fields++];
    memset(f, 0, sizeof *f);
    snprintf(f->name, sizeof f->name, "%s", name);
    return f;
}

void gf_post_row_set(gf_post_row *row, const char *name, double value)
{
    gf_post_field *f = slot(row, name);
    if (f) {
        f->value = value;
        f->is_text = 0;
    }
}

void gf_post_row_set_text(gf_post_row *row, const char *name, const char *text)
{
    gf_post_field *f = slot(row, name);
    if (f) {
        snprintf(f->text, sizeof f->text, "%s", text ? text : "");
        f->is_text = 1;
        f->value = NAN;
    }
}

double gf_post_row_get(const gf_post_row *row, const char *name)
{
    for (int i = 0; i < row->n_fields; ++i)
        if (strcmp(row->fields[i].name, name) == 0 && !row->fields[i].is_text)
            return row->fields[i].value;
    return NAN;
}

const char *gf_post_row_get_text(const gf_post_row *row, const char *name)
{
    for (int i = 0; i < row->n_fields; ++i)
        if (strcmp(row->fields[i].name, name) == 0 && row->fields[i].is_text)
            return row->fields[i].text;
    return NULL;
}

void gf_post_row_add_error(gf_post_row *row, const char *status, const char *msg)
{
    size_t len = strlen(row->error);
    if (len + 3 < sizeof row->error)
        snprintf(row->error + len, sizeof row->error - len, "%s%s", len ? "; " : "", msg);
    /* a failed or corrupt run stays so; otherwise the latest status wins */
    if (strcmp(row->status, "failed") != 0 && strcmp(row->status, "corrupt") != 0 && status)
        snprintf(row->status, sizeof row->status, "%s", status);
}
