/*
 * The canonical text of a resolved run spec, and the run id derived from it.
 *
 * The text is YAML in the configuration schema itself (gf_spec_schema.h), so
 * the run.yaml written next to a run's outputs is also a valid input:
 * `grainflow run <dir>/run.yaml` reproduces the run and gets the same id.
 * Every field is printed, in table order, numbers with %.17g (the shortest
 * format that round-trips every double exactly), scene parameters sorted by
 * key, asked groups under `groups:` (absent ones omitted). Nothing else (no
 * date, no path, no version) enters the text, so equal specs give equal text.
 *
 * Run id: 64-bit FNV-1a (Fowler, Noll & Vo) of that text, the first 12 hex
 * digits (48 bits: for a campaign of 10^4 runs the chance of any collision
 * is ~2e-7, and a collision is detected and refused at expansion).
 */
#ifndef GF_SPEC_TEXT_H
#define GF_SPEC_TEXT_H

#include <stddef.h>
#include <stdint.h>

#include "gf_run_spec.h"

#define GF_SPEC_TEXT_MAX 8192

/* Canonical text into buf (size n, >= GF_SPEC_TEXT_MAX is always enough).
 * Returns the length written. */
size_t gf_spec_text(const gf_run_spec *spec, char *buf, size_t n);

uint64_t gf_fnv1a64(const void *data, size_t n);

/* Sets spec->run_id from the canonical text (run_id itself is not part of it). */
void gf_spec_set_run_id(gf_run_spec *spec);

#endif
