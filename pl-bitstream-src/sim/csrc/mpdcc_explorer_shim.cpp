// C ABI around the Verilated mpdcc_explorer, for rtl-sim (Rust): loads the
// common terms and constants of one decision, streams its candidates one per
// clock and collects the results in order.
#include <cstdint>
#include <vector>

#include "mpdcc_explorer_ports.h"
#include "verilated.h"

static void tick(Vmpdcc_explorer* t) {
    t->clk_i = 1;
    t->eval();
    t->clk_i = 0;
    t->eval();
}


struct MeSim {
    VerilatedContext ctx;
    Vmpdcc_explorer* top;
};

extern "C" {

struct MeCommon {
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
struct MeOut {
    int32_t s[3];
    int32_t l_star;
    uint32_t cost;
    int32_t j_dl;
    int32_t fs;
    int32_t d0[7];
    int32_t latency;
};

void* me_new() {
    auto* sim = new MeSim;
    sim->top = new Vmpdcc_explorer(&sim->ctx, "mpdcc_explorer");
    auto* t = sim->top;
    t->clk_i = 0;
    t->rst_i = 1;
    t->in_valid_i = 0;
    t->eval();
    tick(t);
    tick(t);
    t->rst_i = 0;
    t->eval();
    return sim;
}

// Candidates as s[i][3]; returns the number of results collected.
int32_t me_run(void* p, const MeCommon* c, int32_t n, const int32_t* s, MeOut* out) {
    auto* t = static_cast<MeSim*>(p)->top;
    for (int k = 0; k < mpdcc_explorer_s_prev_i_LANES; k++) mpdcc_explorer_set_s_prev_i_lane(t, k, c->s_prev[k]);
    for (int j = 0; j < mpdcc_explorer_e0_i_LANES; j++) mpdcc_explorer_set_e0_i_lane(t, j, c->e0[j]);
    for (int j = 0; j < mpdcc_explorer_bnd_i_LANES; j++) mpdcc_explorer_set_bnd_i_lane(t, j, c->bnd[j]);
    // dn_i: lane 3 m + ph.
    for (int k = 0; k < mpdcc_explorer_dn_i_LANES; k++) mpdcc_explorer_set_dn_i_lane(t, k, c->dn[k / 3][k % 3]);
    for (int ph = 0; ph < mpdcc_explorer_dn1_i_LANES; ph++) mpdcc_explorer_set_dn1_i_lane(t, ph, c->dn1[ph]);
    for (int ph = 0; ph < mpdcc_explorer_pn_i_LANES; ph++) mpdcc_explorer_set_pn_i_lane(t, ph, c->pn[ph]);
    for (int ph = 0; ph < mpdcc_explorer_pph_i_LANES; ph++) mpdcc_explorer_set_pph_i_lane(t, ph, c->pph[ph]);
    for (int ph = 0; ph < mpdcc_explorer_v_ph_i_LANES; ph++) mpdcc_explorer_set_v_ph_i_lane(t, ph, c->v_ph[ph]);
    mpdcc_explorer_set_v_n_i(t, c->v_n);
    mpdcc_explorer_set_vdc_half_i(t, c->vdc_half);
    mpdcc_explorer_set_g3_i(t, c->g3);
    mpdcc_explorer_set_gd_i(t, c->gd);
    mpdcc_explorer_set_g3_1_i(t, c->g3_1);
    mpdcc_explorer_set_lambda_n_i(t, c->lambda_n);
    std::vector<int64_t> issued(n > 0 ? n : 1, 0);
    int64_t cycle = 0;
    int32_t sent = 0, got = 0;
    while (got < n && cycle < (int64_t)n + 200) {
        bool send = sent < n;
        t->in_valid_i = send;
        if (send) {
            const int32_t* v = s + 3 * sent;
            for (int k = 0; k < mpdcc_explorer_s_i_LANES; k++) mpdcc_explorer_set_s_i_lane(t, k, v[k]);
            issued[sent] = cycle;
        }
        t->eval();
        tick(t);
        cycle++;
        if (send) sent++;
        t->eval();
        if (mpdcc_explorer_get_out_valid_o(t) && got < n) {
            MeOut& o = out[got];
            for (int k = 0; k < mpdcc_explorer_s_o_LANES; k++) o.s[k] = (int32_t)mpdcc_explorer_get_s_o_lane(t, k);
            o.l_star = mpdcc_explorer_get_l_star_o(t);
            o.cost = mpdcc_explorer_get_cost_o(t);
            o.j_dl = (int32_t)mpdcc_explorer_get_j_dl_o(t);
            o.fs = mpdcc_explorer_get_fs_o(t);
            for (int j = 0; j < mpdcc_explorer_d0_o_LANES; j++) o.d0[j] = (int16_t)mpdcc_explorer_get_d0_o_lane(t, j);
            o.latency = (int32_t)(cycle - issued[got]);
            got++;
        }
    }
    t->in_valid_i = 0;
    t->eval();
    return got;
}

void me_free(void* p) {
    auto* sim = static_cast<MeSim*>(p);
    sim->top->final();
    delete sim->top;
    delete sim;
}
}
