/* Staggered struct-of-arrays blocks; see gf_soa.h. */
#include "core/gf_soa.h"

#include <stdlib.h>
#include <string.h>

enum { GF_LINE = 64, GF_PAGE = 4096 };

void *gf_soa_alloc(size_t n, size_t elem_size, size_t cap, size_t first_line, void **ptrs, void *const *old,
                   size_t n_keep)
{
    /* each array's slot: its bytes rounded up to whole pages and one page
     * more, in which the array is shifted by first_line + a lines (mod 64).
     * Arrays a and a + 1 then start slot/64 + 1 lines apart, an odd number,
     * so element i of different arrays also falls in distinct sets of a
     * 64 KiB-indexed L2 (1024 sets). */
    size_t bytes = cap * elem_size, slot = (bytes + GF_PAGE - 1) / GF_PAGE * GF_PAGE + GF_PAGE;
    char *block = aligned_alloc(GF_PAGE, n * slot);
    if (!block)
        return NULL;
    for (size_t a = 0; a < n; ++a) {
        char *arr = block + a * slot + ((first_line + a) % (GF_PAGE / GF_LINE)) * GF_LINE;
        size_t kept = old && old[a] ? n_keep * elem_size : 0;
        if (kept)
            memcpy(arr, old[a], kept);
        memset(arr + kept, 0, bytes - kept);
        ptrs[a] = arr;
    }
    return block;
}

void gf_soa_free(void *block)
{
    free(block);
}
