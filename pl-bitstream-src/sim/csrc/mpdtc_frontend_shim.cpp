// C ABI around the Verilated mpdtc_frontend, for rtl-sim (Rust).
// fe_set takes the inputs as one array in the order of FE_IN below (the
// ports of rtl/mpdtc_frontend.v); fe_get writes the outputs in the order of
// FE_OUT. One call to fe_tick is one rising clock edge.
#include <cstdint>

#include "Vmpdtc_frontend.h"
#include "verilated.h"

namespace {
struct FrontendSim {
    VerilatedContext ctx;
    Vmpdtc_frontend* top;
};
uint32_t m(int64_t v, int bits) { return (uint32_t)((uint64_t)v & ((1ull << bits) - 1)); }
}  // namespace

extern "C" {

void* fe_new() {
    auto* sim = new FrontendSim;
    sim->top = new Vmpdtc_frontend(&sim->ctx, "mpdtc_frontend");
    sim->top->clk_i = 0;
    sim->top->rst_i = 1;
    sim->top->in_valid_i = 0;
    sim->top->eval();
    return sim;
}

// FE_IN: rst, in_valid, pos, speed, adc_a, adc_b, adc_c, t_ref, cpr,
// align_pos, ang_scale, spd_scale, age0, age1, age2, off_a, off_b, off_c,
// gain_a, gain_b, gain_c (21 values).
void fe_set(void* p, const int64_t* v) {
    auto* t = static_cast<FrontendSim*>(p)->top;
    t->rst_i = m(v[0], 1);
    t->in_valid_i = m(v[1], 1);
    t->pos_i = m(v[2], 16);
    t->speed_i = m(v[3], 16);
    t->adc_a_i = m(v[4], 16);
    t->adc_b_i = m(v[5], 16);
    t->adc_c_i = m(v[6], 16);
    t->t_ref_i = m(v[7], 18);
    t->cpr_i = m(v[8], 16);
    t->align_pos_i = m(v[9], 16);
    t->ang_scale_i = m(v[10], 32);
    t->spd_scale_i = m(v[11], 32);
    t->age0_i = m(v[12], 18);
    t->age1_i = m(v[13], 18);
    t->age2_i = m(v[14], 18);
    t->off_a_i = m(v[15], 16);
    t->off_b_i = m(v[16], 16);
    t->off_c_i = m(v[17], 16);
    t->gain_a_i = m(v[18], 18);
    t->gain_b_i = m(v[19], 18);
    t->gain_c_i = m(v[20], 18);
    t->eval();
}

void fe_tick(void* p) {
    auto* t = static_cast<FrontendSim*>(p)->top;
    t->clk_i = 1;
    t->eval();
    t->clk_i = 0;
    t->eval();
}

// FE_OUT (raw port bits, zero-extended): out_valid, i_d, i_q, cos0, sin0,
// cos1, sin1, cos2, sin2, w_ts, t_ref, phi, dphi, i_alpha, i_beta (15).
void fe_get(void* p, uint64_t* o) {
    auto* t = static_cast<FrontendSim*>(p)->top;
    o[0] = t->out_valid_o;
    o[1] = t->i_d_o;
    o[2] = t->i_q_o;
    o[3] = t->cos0_o;
    o[4] = t->sin0_o;
    o[5] = t->cos1_o;
    o[6] = t->sin1_o;
    o[7] = t->cos2_o;
    o[8] = t->sin2_o;
    o[9] = t->w_ts_o;
    o[10] = t->t_ref_o;
    o[11] = t->phi_o;
    o[12] = t->dphi_o;
    o[13] = t->i_alpha_o;
    o[14] = t->i_beta_o;
}

void fe_free(void* p) {
    auto* sim = static_cast<FrontendSim*>(p);
    sim->top->final();
    delete sim->top;
    delete sim;
}
}
