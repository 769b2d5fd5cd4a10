/* icount.c - deterministic guest-instruction counter for QEMU 7.2 (plugin API v1).
 *
 * Counts every executed guest instruction with an inline add (exact, no sampling).
 * Optional args (comma separated after the .so path):
 *   start=0xADDR,end=0xADDR  instructions executed from each hit of `start`
 *                            to the next hit of `end` are summed (marker pairs)
 *   hist=PATH                dump per-PC execution counts + disassembly to PATH,
 *                            counting only instructions inside the marker regions
 *                            (so the histogram sums to region_sum exactly)
 *   lo=0xADDR,hi=0xADDR      restrict the histogram to PCs in [lo,hi) (default: all)
 *   mark=0xADDR              at each hit of this address print the running region sum
 *                            and pair count to stderr (`icount: mark region_sum=S pairs=P`),
 *                            (the open region so far included): multi-mode firmwares
 *                            take per-mode counts as differences, scenes their geometry
 * Report goes to stderr at exit: total, pairs, region sum, first pair, min/max pair.
 *
 * (From ../shared/mcu/MEASURE.md, histogram restricted to the regions for fixel.)
 * Build: gcc -O2 -shared -fPIC -fvisibility=hidden -o libicount.so icount.c
 */
#include "qemu-plugin-min.h"
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

QEMU_PLUGIN_EXPORT int qemu_plugin_version = QEMU_PLUGIN_VERSION;

static uint64_t total;                 /* all executed instructions */
static uint64_t start_addr = UINT64_MAX, end_addr = UINT64_MAX, mark_addr = UINT64_MAX;
static uint64_t snap, pairs, sum, first, minv = UINT64_MAX, maxv;
static int open_pair;

static uint64_t lo, hi = UINT64_MAX;
static const char *hist_path;
#define HBITS 16
#define HSIZE (1u << HBITS)
struct pcent { uint64_t vaddr; uint64_t count; char *disas; int used; };
static struct pcent htab[HSIZE];

static struct pcent *lookup(uint64_t va)
{
    uint32_t h = (uint32_t)(va * 0x9E3779B1u) >> (32 - HBITS);
    for (uint32_t i = 0; i < HSIZE; i++) {
        struct pcent *e = &htab[(h + i) & (HSIZE - 1)];
        if (!e->used) { e->used = 1; e->vaddr = va; return e; }
        if (e->vaddr == va) return e;
    }
    return NULL;
}

static void on_start(unsigned int vcpu, void *u)
{
    (void)vcpu; (void)u;
    snap = total;
    open_pair = 1;
}

static void on_end(unsigned int vcpu, void *u)
{
    (void)vcpu; (void)u;
    if (!open_pair) return;
    uint64_t d = total - snap;
    if (pairs == 0) first = d;
    pairs++;
    sum += d;
    if (d < minv) minv = d;
    if (d > maxv) maxv = d;
    open_pair = 0;
}

static void on_mark(unsigned int vcpu, void *u)
{
    (void)vcpu; (void)u;
    /* Inside an open region, the region so far counts too (a mark within a frame). */
    uint64_t running = sum + (open_pair ? total - snap : 0);
    fprintf(stderr, "icount: mark region_sum=%" PRIu64 " pairs=%" PRIu64 " first_pair=%" PRIu64 "\n",
            running, pairs, first);
}

/* Histogram entry += 1 when inside a marker region. A callback (not an inline add) because
 * inline ops cannot be conditional; still well under a second for ~10 M instructions. */
static void on_hist(unsigned int vcpu, void *u)
{
    (void)vcpu;
    if (open_pair) ((struct pcent *)u)->count++;
}

static void tb_trans(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    (void)id;
    size_t n = qemu_plugin_tb_n_insns(tb);
    for (size_t i = 0; i < n; i++) {
        struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, i);
        uint64_t va = qemu_plugin_insn_vaddr(insn);
        /* callbacks first, then the inline add: at a marker the snapshot
         * excludes the marker's own first instruction (consistent offset). */
        if (va == start_addr)
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_start, QEMU_PLUGIN_CB_NO_REGS, NULL);
        if (va == end_addr)
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_end, QEMU_PLUGIN_CB_NO_REGS, NULL);
        if (va == mark_addr)
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_mark, QEMU_PLUGIN_CB_NO_REGS, NULL);
        qemu_plugin_register_vcpu_insn_exec_inline(insn, QEMU_PLUGIN_INLINE_ADD_U64, &total, 1);
        if (hist_path && va >= lo && va < hi) {
            struct pcent *e = lookup(va);
            if (e) {
                if (!e->disas) e->disas = qemu_plugin_insn_disas(insn);
                qemu_plugin_register_vcpu_insn_exec_cb(insn, on_hist, QEMU_PLUGIN_CB_NO_REGS, e);
            }
        }
    }
}

static int cmp_va(const void *a, const void *b)
{
    const struct pcent *x = a, *y = b;
    return (x->vaddr > y->vaddr) - (x->vaddr < y->vaddr);
}

static void at_exit(qemu_plugin_id_t id, void *u)
{
    (void)id; (void)u;
    fprintf(stderr, "icount: total=%" PRIu64 " pairs=%" PRIu64 " region_sum=%" PRIu64
            " first_pair=%" PRIu64 " min_pair=%" PRIu64 " max_pair=%" PRIu64 "\n",
            total, pairs, sum, first, pairs ? minv : 0, maxv);
    if (hist_path) {
        FILE *f = fopen(hist_path, "w");
        if (!f) { perror(hist_path); return; }
        size_t m = 0;
        for (size_t i = 0; i < HSIZE; i++)
            if (htab[i].used) htab[m++] = htab[i];
        qsort(htab, m, sizeof htab[0], cmp_va);
        for (size_t i = 0; i < m; i++)
            fprintf(f, "0x%08" PRIx64 "\t%" PRIu64 "\t%s\n", htab[i].vaddr, htab[i].count,
                    htab[i].disas ? htab[i].disas : "?");
        fclose(f);
    }
}

QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info,
                                           int argc, char **argv)
{
    (void)info;
    for (int i = 0; i < argc; i++) {
        char *eq = strchr(argv[i], '=');
        if (!eq) { fprintf(stderr, "icount: bad arg %s\n", argv[i]); return -1; }
        *eq = 0;
        const char *k = argv[i], *v = eq + 1;
        if (!strcmp(k, "start")) start_addr = strtoull(v, NULL, 0) & ~1ull; /* drop Thumb bit */
        else if (!strcmp(k, "end")) end_addr = strtoull(v, NULL, 0) & ~1ull;
        else if (!strcmp(k, "mark")) mark_addr = strtoull(v, NULL, 0) & ~1ull;
        else if (!strcmp(k, "lo")) lo = strtoull(v, NULL, 0) & ~1ull;
        else if (!strcmp(k, "hi")) hi = strtoull(v, NULL, 0);
        else if (!strcmp(k, "hist")) hist_path = strdup(v);
        else { fprintf(stderr, "icount: unknown arg %s\n", k); return -1; }
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, tb_trans);
    qemu_plugin_register_atexit_cb(id, at_exit, NULL);
    return 0;
}
