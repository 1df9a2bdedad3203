// C ABI around the Verilated mpdcc_core (N = 6 explorers, n_use_i of them
// used), for rtl-sim (Rust): one call = one decision (state registers and
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

struct MkIn {
    int32_t s_prev[3];
    int32_t i_ab[2], psi_ab[2], v_n, v_ph[3], i_ref_ab[2], omega_r, omega_s;
    int32_t c_tau, c_r, c_w, c_p, c_s, c_3, c_d, c_n, c_ph, s3h, v_ph_ref;
    int32_t c_tau1, c_r1, c_w1, c_s1;
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

void mk_decide(void* p, const MkIn* c, int32_t n_use, MkOut* out) {
    auto* t = static_cast<MkSim*>(p)->top;
    t->s_prev_i = (c->s_prev[0] & 7) | ((c->s_prev[1] & 7) << 3) | ((c->s_prev[2] & 7) << 6);
    for (int j = 0; j < 7; j++) put(t->bnd_i, 16 * j, 16, (uint16_t)c->bnd[j]);
    for (int ph = 0; ph < 3; ph++) put(t->v_ph_i, 16 * ph, 16, (uint16_t)c->v_ph[ph]);
    t->i_a_i = (uint16_t)c->i_ab[0];
    t->i_b_i = (uint16_t)c->i_ab[1];
    t->psi_a_i = (uint16_t)c->psi_ab[0];
    t->psi_b_i = (uint16_t)c->psi_ab[1];
    t->v_n_i = (uint16_t)c->v_n;
    t->ir_a_i = (uint16_t)c->i_ref_ab[0];
    t->ir_b_i = (uint16_t)c->i_ref_ab[1];
    t->omega_r_i = (uint16_t)c->omega_r;
    t->omega_s_i = (uint16_t)c->omega_s;
    t->c_tau_i = (uint16_t)c->c_tau;
    t->c_r_i = (uint16_t)c->c_r;
    t->c_w_i = (uint16_t)c->c_w;
    t->c_p_i = (uint16_t)c->c_p;
    t->c_s_i = (uint16_t)c->c_s;
    t->c_3_i = (uint16_t)c->c_3;
    t->c_d_i = (uint16_t)c->c_d;
    t->c_n_i = (uint16_t)c->c_n;
    t->c_ph_i = (uint16_t)c->c_ph;
    t->s3h_i = (uint16_t)c->s3h;
    t->v_ph_ref_i = (uint16_t)c->v_ph_ref;
    t->c_tau1_i = (uint16_t)c->c_tau1;
    t->c_r1_i = (uint16_t)c->c_r1;
    t->c_w1_i = (uint16_t)c->c_w1;
    t->c_s1_i = (uint16_t)c->c_s1;
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
