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
    mpdcc_explorer_set_s_prev_i(t, (c->s_prev[0] & 7) | ((c->s_prev[1] & 7) << 3) | ((c->s_prev[2] & 7) << 6));
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
            mpdcc_explorer_set_s_i(t, (v[0] & 7) | ((v[1] & 7) << 3) | ((v[2] & 7) << 6));
            issued[sent] = cycle;
        }
        t->eval();
        tick(t);
        cycle++;
        if (send) sent++;
        t->eval();
        if (mpdcc_explorer_get_out_valid_o(t) && got < n) {
            MeOut& o = out[got];
            o.s[0] = mpdcc_explorer_get_s_o(t) & 7;
            o.s[1] = (mpdcc_explorer_get_s_o(t) >> 3) & 7;
            o.s[2] = (mpdcc_explorer_get_s_o(t) >> 6) & 7;
            o.l_star = mpdcc_explorer_get_l_star_o(t);
            o.cost = mpdcc_explorer_get_cost_o(t);
            o.j_dl = (int32_t)mpdcc_explorer_get_j_dl_o(t);
            o.fs = mpdcc_explorer_get_fs_o(t);
            for (int j = 0; j < 7; j++) {
                uint32_t w = (t->d0_o[(16 * j) / 32] >> ((16 * j) % 32)) & 0xFFFFu;
                o.d0[j] = (int16_t)w;
            }
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
