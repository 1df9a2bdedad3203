// C ABI around the Verilated mpdcc_core (N = 6 explorers, n_use_i of them
// used), for rtl-sim (Rust): one call = one decision (common terms and
// constants held, start strobe, clock until done_o).
#include <cstdint>

#include "Vmpdcc_core.h"
#include "verilated.h"

static void tick(Vmpdcc_core* t) {
    t->clk_i = 1;
    t->eval();
    t->clk_i = 0;
    t->eval();
}

template <typename W>
static void put(W& w, int lo, int n, uint64_t v) {
    for (int i = 0; i < n; i++) {
        int b = lo + i;
        uint32_t bit = 1u << (b % 32);
        if ((v >> i) & 1u) w[b / 32] |= bit;
        else w[b / 32] &= ~bit;
    }
}
// Ports of 33..64 bits are one 64-bit word in Verilator.
static void put(uint64_t& w, int lo, int n, uint64_t v) {
    uint64_t m = (n >= 64 ? ~0ull : ((1ull << n) - 1)) << lo;
    w = (w & ~m) | ((v << lo) & m);
}

struct MkSim {
    VerilatedContext ctx;
    Vmpdcc_core* top;
};

extern "C" {

struct MkCommon {
    int32_t s_prev[3];
    int32_t e0[7];
    int32_t dn[4][3];
    int32_t dn1[3];
    int64_t pn[3];
    int64_t pph[3];
    int32_t v_n;
    int32_t v_ph[3];
    int32_t vdc_half, g3, gd, g3_1;
    int32_t bnd[7];
    int32_t lambda_n;
};
struct MkOut {
    int32_t s[3];
    int32_t kind;
    int32_t l_star;
    uint32_t cost;
    int32_t j_dl;
    int32_t candidates;
    int32_t cycles;           // cycles_o
    int32_t measured_cycles;  // clock edges from the start cycle to the done_o cycle
};

void* mk_new() {
    auto* sim = new MkSim;
    sim->top = new Vmpdcc_core(&sim->ctx, "mpdcc_core");
    auto* t = sim->top;
    t->clk_i = 0;
    t->rst_i = 1;
    t->start_i = 0;
    t->eval();
    tick(t);
    tick(t);
    t->rst_i = 0;
    t->eval();
    return sim;
}

void mk_decide(void* p, const MkCommon* c, int32_t n_use, MkOut* out) {
    auto* t = static_cast<MkSim*>(p)->top;
    t->s_prev_i = (c->s_prev[0] & 7) | ((c->s_prev[1] & 7) << 3) | ((c->s_prev[2] & 7) << 6);
    for (int j = 0; j < 7; j++) {
        put(t->e0_i, 16 * j, 16, (uint16_t)c->e0[j]);
        put(t->bnd_i, 16 * j, 16, (uint16_t)c->bnd[j]);
    }
    for (int m = 0; m < 4; m++)
        for (int ph = 0; ph < 3; ph++) put(t->dn_i, 16 * (3 * m + ph), 16, (uint16_t)c->dn[m][ph]);
    for (int ph = 0; ph < 3; ph++) {
        put(t->dn1_i, 16 * ph, 16, (uint16_t)c->dn1[ph]);
        put(t->pn_i, 32 * ph, 32, (uint32_t)c->pn[ph]);
        put(t->pph_i, 32 * ph, 32, (uint32_t)c->pph[ph]);
        put(t->v_ph_i, 16 * ph, 16, (uint16_t)c->v_ph[ph]);
    }
    t->v_n_i = (uint16_t)c->v_n;
    t->vdc_half_i = (uint16_t)c->vdc_half;
    t->g3_i = (uint16_t)c->g3;
    t->gd_i = (uint16_t)c->gd;
    t->g3_1_i = (uint16_t)c->g3_1;
    t->lambda_n_i = (uint16_t)c->lambda_n;
    t->n_use_i = n_use & 7;
    t->start_i = 1;
    t->eval();
    tick(t);
    t->start_i = 0;
    t->eval();
    int n = 1;
    while (!t->done_o && n < 2000) {
        tick(t);
        n++;
    }
    out->measured_cycles = t->done_o ? n : -1;
    out->s[0] = t->s_o & 7;
    out->s[1] = (t->s_o >> 3) & 7;
    out->s[2] = (t->s_o >> 6) & 7;
    out->kind = t->kind_o;
    out->l_star = t->l_star_o;
    out->cost = t->cost_o;
    out->j_dl = (int32_t)t->j_dl_o;
    out->candidates = t->candidates_o;
    out->cycles = t->cycles_o;
    tick(t);  // done_o falls, the core is idle again
}

void mk_free(void* p) {
    auto* sim = static_cast<MkSim*>(p);
    sim->top->final();
    delete sim->top;
    delete sim;
}
}
