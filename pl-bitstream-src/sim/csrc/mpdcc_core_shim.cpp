// C ABI around the Verilated mpdcc_core (N = 6 explorers, n_use_i of them
// used), for rtl-sim (Rust): one call = one decision (state registers and
// constants held, start strobe, clock until done_o).
#include <cstdint>

#include "mpdcc_core_ports.h"
#include "verilated.h"

static void tick(Vmpdcc_core* t) {
    t->clk_i = 1;
    t->eval();
    t->clk_i = 0;
    t->eval();
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
    for (int k = 0; k < mpdcc_core_s_prev_i_LANES; k++) mpdcc_core_set_s_prev_i_lane(t, k, c->s_prev[k]);
    for (int j = 0; j < mpdcc_core_bnd_i_LANES; j++) mpdcc_core_set_bnd_i_lane(t, j, c->bnd[j]);
    for (int ph = 0; ph < mpdcc_core_v_ph_i_LANES; ph++) mpdcc_core_set_v_ph_i_lane(t, ph, c->v_ph[ph]);
    mpdcc_core_set_i_a_i(t, c->i_ab[0]);
    mpdcc_core_set_i_b_i(t, c->i_ab[1]);
    mpdcc_core_set_psi_a_i(t, c->psi_ab[0]);
    mpdcc_core_set_psi_b_i(t, c->psi_ab[1]);
    mpdcc_core_set_v_n_i(t, c->v_n);
    mpdcc_core_set_ir_a_i(t, c->i_ref_ab[0]);
    mpdcc_core_set_ir_b_i(t, c->i_ref_ab[1]);
    mpdcc_core_set_omega_r_i(t, c->omega_r);
    mpdcc_core_set_omega_s_i(t, c->omega_s);
    mpdcc_core_set_c_tau_i(t, c->c_tau);
    mpdcc_core_set_c_r_i(t, c->c_r);
    mpdcc_core_set_c_w_i(t, c->c_w);
    mpdcc_core_set_c_p_i(t, c->c_p);
    mpdcc_core_set_c_s_i(t, c->c_s);
    mpdcc_core_set_c_3_i(t, c->c_3);
    mpdcc_core_set_c_d_i(t, c->c_d);
    mpdcc_core_set_c_n_i(t, c->c_n);
    mpdcc_core_set_c_ph_i(t, c->c_ph);
    mpdcc_core_set_s3h_i(t, c->s3h);
    mpdcc_core_set_v_ph_ref_i(t, c->v_ph_ref);
    mpdcc_core_set_c_tau1_i(t, c->c_tau1);
    mpdcc_core_set_c_r1_i(t, c->c_r1);
    mpdcc_core_set_c_w1_i(t, c->c_w1);
    mpdcc_core_set_c_s1_i(t, c->c_s1);
    mpdcc_core_set_vdc_half_i(t, c->vdc_half);
    mpdcc_core_set_g3_i(t, c->g3);
    mpdcc_core_set_gd_i(t, c->gd);
    mpdcc_core_set_g3_1_i(t, c->g3_1);
    mpdcc_core_set_lambda_n_i(t, c->lambda_n);
    mpdcc_core_set_n_use_i(t, n_use);
    t->start_i = 1;
    t->eval();
    tick(t);
    t->start_i = 0;
    t->eval();
    int n = 1;
    while (!mpdcc_core_get_done_o(t) && n < 2000) {
        tick(t);
        n++;
    }
    out->measured_cycles = mpdcc_core_get_done_o(t) ? n : -1;
    for (int k = 0; k < mpdcc_core_s_o_LANES; k++) out->s[k] = (int32_t)mpdcc_core_get_s_o_lane(t, k);
    out->kind = mpdcc_core_get_kind_o(t);
    out->l_star = mpdcc_core_get_l_star_o(t);
    out->cost = mpdcc_core_get_cost_o(t);
    out->j_dl = (int32_t)mpdcc_core_get_j_dl_o(t);
    out->candidates = mpdcc_core_get_candidates_o(t);
    out->cycles = mpdcc_core_get_cycles_o(t);
    tick(t);  // done_o falls, the core is idle again
}

void mk_free(void* p) {
    auto* sim = static_cast<MkSim*>(p);
    sim->top->final();
    delete sim->top;
    delete sim;
}
}
