/* The names of the film's modes in overlap (fluid.lub_overlap); the physics is in gf_lubrication.h. */
#include "contact/gf_lubrication.h"

#include <string.h>

const char *const gf_lub_overlap_names[] = {"clamp", "off", "film", NULL};

int gf_lub_overlap_from_name(const char *name, gf_lub_overlap *out)
{
    for (int i = 0; gf_lub_overlap_names[i]; ++i)
        if (strcmp(name, gf_lub_overlap_names[i]) == 0) {
            *out = (gf_lub_overlap)i;
            return 0;
        }
    return -1;
}
