// C ABI around the Verilated mpdtc_core, for rtl-sim (Rust): one call runs
// one decision (state load, input strobe, clock until out_valid) and
// returns every output, the next state and the measured latency.
#include <cstdint>

#include "mpdtc_core_ports.h"
#include "verilated.h"

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
    mpdtc_core_set_st_s_applied_i(t, st->s_applied);
    mpdtc_core_set_st_s_prev_i(t, st->s_prev);
    mpdtc_core_set_st_eta_d_i(t, st->eta_d);
    mpdtc_core_set_st_eta_q_i(t, st->eta_q);
    mpdtc_core_set_st_x_i(t, st->x);
    mpdtc_core_set_st_band_i(t, st->band);
    mpdtc_core_set_st_iq_ref_prev_i(t, st->iq_ref_prev);
    mpdtc_core_set_st_i_hat_d_i(t, st->i_hat_d);
    mpdtc_core_set_st_i_hat_q_i(t, st->i_hat_q);
    mpdtc_core_set_st_nu_d_i(t, st->nu_d);
    mpdtc_core_set_st_nu_q_i(t, st->nu_q);
    t->st_load_i = 1;
    t->eval();
    tick(t);
    t->st_load_i = 0;

    mpdtc_core_set_i_d_i(t, in->i_d);
    mpdtc_core_set_i_q_i(t, in->i_q);
    mpdtc_core_set_cos0_i(t, in->cos0);
    mpdtc_core_set_sin0_i(t, in->sin0);
    mpdtc_core_set_cos1_i(t, in->cos1);
    mpdtc_core_set_sin1_i(t, in->sin1);
    mpdtc_core_set_cos2_i(t, in->cos2);
    mpdtc_core_set_sin2_i(t, in->sin2);
    mpdtc_core_set_w_ts_i(t, in->w_ts);
    mpdtc_core_set_t_ref_i(t, in->t_ref);
    mpdtc_core_set_p_a_i(t, pr->a);
    mpdtc_core_set_p_lambda_i(t, pr->lambda);
    mpdtc_core_set_p_u0_i(t, pr->u0);
    mpdtc_core_set_p_u0_half_i(t, pr->u0_half);
    mpdtc_core_set_p_u0_h_i(t, pr->u0_h);
    mpdtc_core_set_p_psi_l_i(t, pr->psi_l);
    mpdtc_core_set_p_kinv_t_i(t, pr->kinv_t);
    mpdtc_core_set_p_tol_i(t, pr->tol);
    mpdtc_core_set_p_k_int_i(t, pr->k_int);
    mpdtc_core_set_p_int_lim_i(t, pr->int_lim);
    mpdtc_core_set_p_int_cond_i(t, pr->int_cond);
    mpdtc_core_set_p_kp_o_i(t, pr->kp_o);
    mpdtc_core_set_p_ki_o_i(t, pr->ki_o);
    mpdtc_core_set_p_eta_lim_i(t, pr->eta_lim);
    for (int i = 0; i < mpdtc_core_p_w2_i_LANES; i++) mpdtc_core_set_p_w2_i_lane(t, i, pr->w2[i]);
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
    out->s_next = (int32_t)mpdtc_core_get_s_next_o(t);
    out->iq_ref = (int32_t)mpdtc_core_get_iq_ref_o(t);
    out->eta_d = (int32_t)mpdtc_core_get_eta_d_o(t);
    out->eta_q = (int32_t)mpdtc_core_get_eta_q_o(t);
    out->i1_d = (int32_t)mpdtc_core_get_i1_d_o(t);
    out->i1_q = (int32_t)mpdtc_core_get_i1_q_o(t);
    for (int s = 0; s < mpdtc_core_i2_d_o_LANES; s++) {
        out->i2_d[s] = (int32_t)mpdtc_core_get_i2_d_o_lane(t, s);
        out->i2_q[s] = (int32_t)mpdtc_core_get_i2_q_o_lane(t, s);
        out->err[s] = (int32_t)mpdtc_core_get_err_o_lane(t, s);
        out->cost2[s] = mpdtc_core_get_cost2_o_lane(t, s);
    }
    out->next.s_applied = (int32_t)mpdtc_core_get_st_s_applied_o(t);
    out->next.s_prev = (int32_t)mpdtc_core_get_st_s_prev_o(t);
    out->next.eta_d = (int32_t)mpdtc_core_get_st_eta_d_o(t);
    out->next.eta_q = (int32_t)mpdtc_core_get_st_eta_q_o(t);
    out->next.x = (int32_t)mpdtc_core_get_st_x_o(t);
    out->next.band = (int32_t)mpdtc_core_get_st_band_o(t);
    out->next.iq_ref_prev = (int32_t)mpdtc_core_get_st_iq_ref_prev_o(t);
    out->next.i_hat_d = (int32_t)mpdtc_core_get_st_i_hat_d_o(t);
    out->next.i_hat_q = (int32_t)mpdtc_core_get_st_i_hat_q_o(t);
    out->next.nu_d = (int32_t)mpdtc_core_get_st_nu_d_o(t);
    out->next.nu_q = (int32_t)mpdtc_core_get_st_nu_q_o(t);
    out->ready_after = t->in_ready_o ? 0 : -1;
}

void mc_free(void* p) {
    auto* sim = static_cast<McSim*>(p);
    sim->top->final();
    delete sim->top;
    delete sim;
}
}
