/* icount_smp.c - per-vCPU guest-instruction counter for QEMU 7.2 (plugin API v1), for
 * firmware that runs on two (or more) cores.
 *
 * Each vCPU counts its own executed instructions (a callback per instruction, keyed by
 * the vCPU index: exact, no sampling) and its own marker regions:
 *   start=0xADDR,end=0xADDR  instructions a vCPU executes from its hit of `start` to its
 *                            next hit of `end` are summed for that vCPU (marker pairs)
 *   mark=0xADDR              at each hit, print that vCPU's running region sum and pair
 *                            count: `icount: mark cpu=C region_sum=S pairs=P first_pair=F`
 * Report at exit, one line per vCPU: `icount: cpu=C total=T pairs=P region_sum=S
 * first_pair=F`.
 * Build: gcc -O2 -shared -fPIC -o libicount_smp.so icount_smp.c
 */
#include "qemu-plugin-min.h"
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

QEMU_PLUGIN_EXPORT int qemu_plugin_version = QEMU_PLUGIN_VERSION;

#define MAXCPU 8
static uint64_t start_addr = UINT64_MAX, end_addr = UINT64_MAX, mark_addr = UINT64_MAX;
static uint64_t total[MAXCPU], snap[MAXCPU], pairs[MAXCPU], sum[MAXCPU], first[MAXCPU];
static int open_pair[MAXCPU];

static void on_insn(unsigned int vcpu, void *u)
{
    (void)u;
    if (vcpu < MAXCPU) total[vcpu]++;
}

static void on_start(unsigned int vcpu, void *u)
{
    (void)u;
    if (vcpu >= MAXCPU) return;
    snap[vcpu] = total[vcpu];
    open_pair[vcpu] = 1;
}

static void on_end(unsigned int vcpu, void *u)
{
    (void)u;
    if (vcpu >= MAXCPU || !open_pair[vcpu]) return;
    uint64_t d = total[vcpu] - snap[vcpu];
    if (pairs[vcpu] == 0) first[vcpu] = d;
    pairs[vcpu]++;
    sum[vcpu] += d;
    open_pair[vcpu] = 0;
}

static void on_mark(unsigned int vcpu, void *u)
{
    (void)u;
    if (vcpu >= MAXCPU) return;
    uint64_t running = sum[vcpu] + (open_pair[vcpu] ? total[vcpu] - snap[vcpu] : 0);
    fprintf(stderr, "icount: mark cpu=%u region_sum=%" PRIu64 " pairs=%" PRIu64
            " first_pair=%" PRIu64 "\n", vcpu, running, pairs[vcpu], first[vcpu]);
}

static void tb_trans(qemu_plugin_id_t id, struct qemu_plugin_tb *tb)
{
    (void)id;
    size_t n = qemu_plugin_tb_n_insns(tb);
    for (size_t i = 0; i < n; i++) {
        struct qemu_plugin_insn *insn = qemu_plugin_tb_get_insn(tb, i);
        uint64_t va = qemu_plugin_insn_vaddr(insn);
        /* markers first, then the count: as icount.c, a marker's snapshot excludes the
         * marker's own first instruction. */
        if (va == start_addr)
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_start, QEMU_PLUGIN_CB_NO_REGS, NULL);
        if (va == end_addr)
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_end, QEMU_PLUGIN_CB_NO_REGS, NULL);
        if (va == mark_addr)
            qemu_plugin_register_vcpu_insn_exec_cb(insn, on_mark, QEMU_PLUGIN_CB_NO_REGS, NULL);
        qemu_plugin_register_vcpu_insn_exec_cb(insn, on_insn, QEMU_PLUGIN_CB_NO_REGS, NULL);
    }
}

static void at_exit(qemu_plugin_id_t id, void *u)
{
    (void)id; (void)u;
    for (unsigned c = 0; c < MAXCPU; c++)
        if (total[c])
            fprintf(stderr, "icount: cpu=%u total=%" PRIu64 " pairs=%" PRIu64
                    " region_sum=%" PRIu64 " first_pair=%" PRIu64 "\n",
                    c, total[c], pairs[c], sum[c], first[c]);
}

QEMU_PLUGIN_EXPORT int qemu_plugin_install(qemu_plugin_id_t id, const qemu_info_t *info,
                                           int argc, char **argv)
{
    (void)info;
    for (int i = 0; i < argc; i++) {
        char *eq = strchr(argv[i], '=');
        if (!eq) { fprintf(stderr, "icount_smp: bad arg %s\n", argv[i]); return -1; }
        *eq = 0;
        const char *k = argv[i], *v = eq + 1;
        if (!strcmp(k, "start")) start_addr = strtoull(v, NULL, 0) & ~1ull;
        else if (!strcmp(k, "end")) end_addr = strtoull(v, NULL, 0) & ~1ull;
        else if (!strcmp(k, "mark")) mark_addr = strtoull(v, NULL, 0) & ~1ull;
        else { fprintf(stderr, "icount_smp: unknown arg %s\n", k); return -1; }
    }
    qemu_plugin_register_vcpu_tb_trans_cb(id, tb_trans);
    qemu_plugin_register_atexit_cb(id, at_exit, NULL);
    return 0;
}
