// C ABI around the Verilated mpdtc_core, for rtl-sim (Rust): one call runs
// one decision (state load, input strobe, clock until out_valid) and
// returns every output, the next state and the measured latency.
#include <cstdint>

#include "Vmpdtc_core.h"
#include "verilated.h"

static uint32_t m25(int32_t v) { return (uint32_t)v & 0x1FFFFFFu; }
static uint32_t m18(int32_t v) { return (uint32_t)v & 0x3FFFFu; }
static int32_t sx(uint64_t v, int w) {
    uint64_t m = 1ull << (w - 1);
    v &= (1ull << w) - 1;
    return (int32_t)(int64_t)((v ^ m) - m);
}
template <typename W>
static uint64_t bits(const W& w, int lo, int n) {
    uint64_t r = 0;
    for (int i = 0; i < n; i++) {
        int b = lo + i;
        r |= (uint64_t)((w[b / 32] >> (b % 32)) & 1u) << i;
    }
    return r;
}

static void tick(Vmpdtc_core* t) {
    t->clk_i = 1;
    t->eval();
    t->clk_i = 0;
    t->eval();
}

struct McSim {
    VerilatedContext ctx;
    Vmpdtc_core* top;
};

extern "C" {

struct McState {
    int32_t s_applied, s_prev, eta_d, eta_q, x, band, iq_ref_prev, i_hat_d, i_hat_q, nu_d, nu_q;
};
struct McIn {
    int32_t i_d, i_q, cos0, sin0, cos1, sin1, cos2, sin2, w_ts, t_ref;
};
struct McParams {
    int32_t a, lambda, u0, u0_half, u0_h, psi_l, kinv_t, tol, k_int, int_lim, int_cond, kp_o,
        ki_o, eta_lim, w2[4];
};
struct McOut {
    int32_t s_next, iq_ref, eta_d, eta_q, i1_d, i1_q;
    int32_t i2_d[8], i2_q[8], err[8];
    int64_t cost2[8];
    McState next;
    int32_t latency;  // cycles from the in_valid cycle to the out_valid cycle
    int32_t ready_after;  // cycles from out_valid until in_ready (0 = same cycle)
};


void* mc_new() {
    auto* sim = new McSim;
    sim->top = new Vmpdtc_core(&sim->ctx, "mpdtc_core");
    auto* t = sim->top;
    t->clk_i = 0;
    t->rst_i = 1;
    t->eval();
    tick(t);
    tick(t);
    t->rst_i = 0;
    t->eval();
    return sim;
}

void mc_decide(void* p, const McState* st, const McIn* in, const McParams* pr, McOut* out) {
    auto* t = static_cast<McSim*>(p)->top;
    t->st_s_applied_i = st->s_applied & 7;
    t->st_s_prev_i = st->s_prev & 7;
    t->st_eta_d_i = m25(st->eta_d);
    t->st_eta_q_i = m25(st->eta_q);
    t->st_x_i = m25(st->x);
    t->st_band_i = st->band & 1;
    t->st_iq_ref_prev_i = m25(st->iq_ref_prev);
    t->st_i_hat_d_i = m25(st->i_hat_d);
    t->st_i_hat_q_i = m25(st->i_hat_q);
    t->st_nu_d_i = m25(st->nu_d);
    t->st_nu_q_i = m25(st->nu_q);
    t->st_load_i = 1;
    t->eval();
    tick(t);
    t->st_load_i = 0;

    t->i_d_i = m25(in->i_d);
    t->i_q_i = m25(in->i_q);
    t->cos0_i = m18(in->cos0);
    t->sin0_i = m18(in->sin0);
    t->cos1_i = m18(in->cos1);
    t->sin1_i = m18(in->sin1);
    t->cos2_i = m18(in->cos2);
    t->sin2_i = m18(in->sin2);
    t->w_ts_i = m18(in->w_ts);
    t->t_ref_i = m18(in->t_ref);
    t->p_a_i = m18(pr->a);
    t->p_lambda_i = m18(pr->lambda);
    t->p_u0_i = m25(pr->u0);
    t->p_u0_half_i = m25(pr->u0_half);
    t->p_u0_h_i = m25(pr->u0_h);
    t->p_psi_l_i = m25(pr->psi_l);
    t->p_kinv_t_i = m25(pr->kinv_t);
    t->p_tol_i = m25(pr->tol);
    t->p_k_int_i = m18(pr->k_int);
    t->p_int_lim_i = m25(pr->int_lim);
    t->p_int_cond_i = pr->int_cond & 1;
    t->p_kp_o_i = m18(pr->kp_o);
    t->p_ki_o_i = m18(pr->ki_o);
    t->p_eta_lim_i = m25(pr->eta_lim);
    // 72-bit port: 4 x 18 bits into 32-bit words.
    for (int w = 0; w < 3; w++) t->p_w2_i[w] = 0;
    for (int i = 0; i < 4; i++) {
        uint32_t v = m18(pr->w2[i]);
        for (int b = 0; b < 18; b++) {
            int bit = 18 * i + b;
            if ((v >> b) & 1u) t->p_w2_i[bit / 32] |= 1u << (bit % 32);
        }
    }
    t->in_valid_i = 1;
    t->eval();
    int lat = 0;
    tick(t);  // capture edge
    t->in_valid_i = 0;
    t->eval();
    lat = 1;
    while (!t->out_valid_o && lat < 100) {
        tick(t);
        lat++;
    }
    out->latency = lat;
    out->s_next = t->s_next_o;
    out->iq_ref = sx(t->iq_ref_o, 25);
    out->eta_d = sx(t->eta_d_o, 25);
    out->eta_q = sx(t->eta_q_o, 25);
    out->i1_d = sx(t->i1_d_o, 25);
    out->i1_q = sx(t->i1_q_o, 25);
    for (int s = 0; s < 8; s++) {
        out->i2_d[s] = sx(bits(t->i2_d_o, 25 * s, 25), 25);
        out->i2_q[s] = sx(bits(t->i2_q_o, 25 * s, 25), 25);
        out->err[s] = sx(bits(t->err_o, 25 * s, 25), 25);
        uint64_t c = bits(t->cost2_o, 48 * s, 48);
        out->cost2[s] = (int64_t)((c ^ (1ull << 47)) - (1ull << 47));
    }
    out->next.s_applied = t->st_s_applied_o;
    out->next.s_prev = t->st_s_prev_o;
    out->next.eta_d = sx(t->st_eta_d_o, 25);
    out->next.eta_q = sx(t->st_eta_q_o, 25);
    out->next.x = sx(t->st_x_o, 25);
    out->next.band = t->st_band_o;
    out->next.iq_ref_prev = sx(t->st_iq_ref_prev_o, 25);
    out->next.i_hat_d = sx(t->st_i_hat_d_o, 25);
    out->next.i_hat_q = sx(t->st_i_hat_q_o, 25);
    out->next.nu_d = sx(t->st_nu_d_o, 25);
    out->next.nu_q = sx(t->st_nu_q_o, 25);
    out->ready_after = t->in_ready_o ? 0 : -1;
}

void mc_free(void* p) {
    auto* sim = static_cast<McSim*>(p);
    sim->top->final();
    delete sim->top;
    delete sim;
}
}
