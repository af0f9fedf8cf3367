/*
 * State hashes: the engine's results held bit for bit across changes that
 * must not change them (moving code, splitting files, a new step driver).
 * Each case builds a scene through gf_sim_create, advances it with
 * gf_sim_advance in calls of a given length (one step per call takes the
 * plain path of the step, longer calls the fused one), and hashes with
 * FNV-1a 64 (Fowler, Noll & Vo) the raw bytes of
 *   motion:   ids, positions, velocities and spins in store order, the
 *             clock and the step count;
 *   contacts: every grain-grain and grain-wall contact with a non-zero
 *             tangential history or an overlap (ids, wall, history bytes),
 *             hashed one by one and summed, so that the walk's order does
 *             not matter (gf_sim_foreach_contact).
 * The recorded values were produced by this program on the tree before the
 * engine was split into engine/sim/ (GF_STATE_HASH_RECORD=1 prints the
 * table). They hold on x86-64 with the project's Release flags; a
 * different compiler or -ffast-math may legitimately change them.
 * Cases marked from_packing start from a deposit prepared by
 * particles/gf_packing (column collapse): a change of the preparation
 * changes their initial state and so their hashes; the others start from a
 * lattice or explicit placements and are the ones that must never move.
 * The two from_packing hashes were re-recorded once, when the preparation
 * moved from its own integrator to runs of this engine (gf_packing_settle);
 * the 14 others did not change.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gf_test.h"
#include "gf_test_sim.h"

#define FNV_OFFSET 14695981039346656037ull
#define FNV_PRIME 1099511628211ull

static uint64_t fnv1a(uint64_t h, const void *data, size_t n)
{
    const unsigned char *b = data;
    for (size_t k = 0; k < n; ++k)
        h = (h ^ b[k]) * FNV_PRIME;
    return h;
}

static uint64_t motion_hash(gf_sim *sim)
{
    const gf_particles *p = gf_sim_particles(sim);
    const size_t n = p->n_local, z = n * sizeof(double);
    uint64_t h = fnv1a(FNV_OFFSET, p->id, n * sizeof *p->id);
    const double *const f[9] = {p->x_m, p->y_m, p->z_m, p->vx_m_s, p->vy_m_s, p->vz_m_s,
                                p->wx_rad_s, p->wy_rad_s, p->wz_rad_s};
    for (int k = 0; k < 9; ++k)
        h = fnv1a(h, f[k], z);
    const double t = gf_sim_time_s(sim);
    const long step = gf_sim_step_count(sim);
    h = fnv1a(h, &t, sizeof t);
    return fnv1a(h, &step, sizeof step);
}

typedef struct contact_sum {
    const gf_particles *p;
    uint64_t sum;
    size_t n;
} contact_sum;

static int add_contact(void *user, const gf_sim_contact *c)
{
    contact_sum *cs = user;
    const double *hc = c->history;
    if (!(c->overlap_m > 0.0) && hc[0] == 0.0 && hc[1] == 0.0 && hc[2] == 0.0)
        return 0;
    const int64_t key[3] = {cs->p->id[c->i], c->wall < 0 ? cs->p->id[c->j] : -1, c->wall};
    uint64_t h = fnv1a(FNV_OFFSET, key, sizeof key);
    cs->sum += fnv1a(h, hc, 3 * sizeof *hc);
    cs->n++;
    return 0;
}

static uint64_t contact_hash(gf_ctx *ctx, gf_sim *sim, size_t *n)
{
    contact_sum cs = {.p = gf_sim_particles(sim)};
    GF_CHECK_OK(gf_sim_foreach_contact(sim, add_contact, &cs), ctx);
    *n = cs.n;
    return cs.sum;
}

typedef struct hash_case {
    const char *name;
    int from_packing;
    long steps, per_call;
    uint64_t motion, contacts;
} hash_case;

/* Each case's spec, tuning and thread count. */
static void case_setup(gf_ctx *ctx, const char *name, gf_run_spec *s, gf_sim_options *opt)
{
    memset(opt, 0, sizeof *opt);
    opt->n_threads = 1;
    if (strncmp(name, "gas", 3) == 0) { /* 125 grains on a cubic lattice, random velocities and spins */
        *s = gf_test_spec("elastic_gas");
        s->contact.restitution = 0.8, s->contact.friction = strstr(name, "frictionless") ? 0.0 : 0.5;
        gf_run_spec_set_param(ctx, s, "n_grains", 125);
        gf_run_spec_set_param(ctx, s, "box_over_D", 6.0);
    } else if (strncmp(name, "collision", 9) == 0) { /* explicit placements */
        *s = gf_test_spec("binary_collision");
        s->contact.friction = 0.4, s->contact.restitution = 0.7;
        gf_run_spec_set_param(ctx, s, "psi1", 2.0);
        gf_run_spec_set_param(ctx, s, "spin_nd", 3.0);
        gf_run_spec_set_param(ctx, s, "with_wall", strstr(name, "wall") ? 1.0 : 0.0);
        if (strstr(name, "hertz"))
            snprintf(s->contact.law, sizeof s->contact.law, "hertz");
    } else if (strncmp(name, "bed", 3) == 0) { /* the jittered body-centred stack settling */
        *s = gf_test_bed_spec(ctx, strstr(name, "small") ? 400 : 1200, 0.0);
        if (strstr(name, "hertz_kk"))
            snprintf(s->contact.law, sizeof s->contact.law, "hertz_kk");
        else if (strstr(name, "hertz"))
            snprintf(s->contact.law, sizeof s->contact.law, "hertz");
        if (strstr(name, "sorted"))
            opt->tuning.sort_every = 1;
        if (strstr(name, "2threads"))
            opt->n_threads = 2;
        if (strstr(name, "generic"))
            opt->tuning.generic_pair_loop = 1, opt->tuning.near_skin = -1.0, opt->tuning.keep_all_work = 1;
        if (strstr(name, "immersed"))
            gf_test_immerse(s);
        if (strstr(name, "sleep"))
            s->contact.sleep_speed_nd = 0.05;
        if (strstr(name, "prepared"))
            gf_run_spec_set_param(ctx, s, "settle_time_nd", 0.5);
    } else { /* collapse: a deposit of particles/gf_packing */
        *s = gf_test_small_collapse_spec(ctx);
        if (strstr(name, "immersed"))
            gf_test_immerse(s);
    }
}

static hash_case cases[] = {
    /* name                          packing steps call  motion                 contacts */
    {"gas_frictional",                 0, 3000, 100, 0x881c18c17ba18c06ull, 0x11318e477beb5f4aull},
    {"gas_frictionless",               0, 3000, 100, 0xa1f99c4d68d4b0a7ull, 0x34ea390182435726ull},
    {"collision_wall",                 0,   70,   1, 0xde0d8e1072a97ad7ull, 0x3d2832f3448082beull},
    {"collision_pair_hertz",           0,   70,   7, 0xb6eee784072231fcull, 0x38ceda02031d7099ull},
    {"bed_small_hertz",                0,  600,  50, 0x837ce1d639539171ull, 0xf7b1d9d0b8deb0b3ull},
    {"bed_small_hertz_kk",             0,  600,  50, 0xdb80b93ace8ef2a5ull, 0x6040b909f36c2978ull},
    {"bed_small_prepared",             0,  300,  50, 0xaa2039f538057c87ull, 0x6058776c0940ef6eull},
    {"bed_small_sleep",                0, 2000,  50, 0x83dacbfc59f46a72ull, 0xc1d13836d7689f08ull},
    {"bed_small_generic",              0,  600,  50, 0x4ff273e198f0c3d9ull, 0x9269407c60282bddull},
    {"bed_sorted",                     0, 1500,  50, 0x811a79392547cb62ull, 0x9f706fd22703205dull},
    {"bed_sorted_2threads",            0, 1500,  50, 0xee41a21e85530affull, 0xa9916adeaab4cc7full},
    {"bed_sorted_stepwise",            0,  100,   1, 0xd15c7f77dc883de4ull, 0x79e99a62c45623e2ull},
    {"bed_immersed",                   0,  800,  40, 0xbb8be68497465d81ull, 0x5dffe2703362d7e1ull},
    {"bed_immersed_2threads",          0,  800,  40, 0xee486092434121faull, 0x3ddb6396a5cd98aeull},
    {"collapse",                       1,  600,  50, 0x4029e4da61932f43ull, 0x373c82663a76cd7aull},
    {"collapse_immersed",              1,  400,  40, 0x4ffc909465d9fe01ull, 0x39bc430d7d8853cdull},
};

static void run_case(gf_ctx *ctx, hash_case *c, int record)
{
    gf_run_spec spec;
    gf_sim_options opt;
    case_setup(ctx, c->name, &spec, &opt);
    gf_sim *sim = NULL;
    GF_CHECK_OK(gf_sim_create(ctx, &spec, &opt, &sim), ctx);
    if (!sim)
        return;
    gf_status st = GF_OK;
    for (long done = 0; done < c->steps && st == GF_OK; done += c->per_call)
        st = gf_sim_advance(sim, c->per_call < c->steps - done ? c->per_call : c->steps - done);
    GF_CHECK_OK(st, ctx);
    size_t n_contacts = 0;
    const uint64_t m = motion_hash(sim), k = contact_hash(ctx, sim, &n_contacts);
    if (record)
        printf("    {\"%s\",%*s %d, %4ld, %3ld, 0x%016llxull, 0x%016llxull},\n", c->name,
               (int)(30 - strlen(c->name)), "", c->from_packing, c->steps, c->per_call, (unsigned long long)m,
               (unsigned long long)k);
    else {
        printf("%-24s %s %zu grains, %ld steps in calls of %ld, %zu contacts with history: motion %s, contacts %s\n",
               c->name, c->from_packing ? "(packing)" : "         ", gf_sim_particles(sim)->n_local, c->steps,
               c->per_call, n_contacts, m == c->motion ? "same" : "DIFFERENT",
               k == c->contacts ? "same" : "DIFFERENT");
        gf_test_check(m == c->motion && k == c->contacts, __FILE__, __LINE__,
                      "%s: state hash 0x%016llx/0x%016llx, recorded 0x%016llx/0x%016llx%s", c->name,
                      (unsigned long long)m, (unsigned long long)k, (unsigned long long)c->motion,
                      (unsigned long long)c->contacts,
                      c->from_packing ? " (starts from a deposit of particles/gf_packing: a new preparation changes it; "
                                         "re-record with GF_STATE_HASH_RECORD=1)" : "");
    }
    gf_sim_destroy(&sim);
}

int main(void)
{
    gf_ctx ctx = {0};
    const char *rec = getenv("GF_STATE_HASH_RECORD");
    const int record = rec && rec[0] == '1';
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k)
        run_case(&ctx, &cases[k], record);
    return gf_test_finish();
}
