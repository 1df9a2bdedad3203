// Generated from pl-bitstream-src/rtl/mpdtc_core.v (its port list) by `cargo run -p
// regmap-gen`; do not edit (a test fails when this file is stale).
//
// Setters mask to the port's width; getters of signed ports sign-extend;
// ports wider than 64 bits go as 32-bit words, least significant first.
#pragma once
#include <cstdint>

#include "Vmpdtc_core.h"

// input [0:0] clk_i
static inline void mpdtc_core_set_clk_i(Vmpdtc_core* t, int64_t x) {
    t->clk_i = (uint64_t)x & 0x1ULL;
}
// input [0:0] rst_i
static inline void mpdtc_core_set_rst_i(Vmpdtc_core* t, int64_t x) {
    t->rst_i = (uint64_t)x & 0x1ULL;
}
// input [0:0] in_valid_i
static inline void mpdtc_core_set_in_valid_i(Vmpdtc_core* t, int64_t x) {
    t->in_valid_i = (uint64_t)x & 0x1ULL;
}
// output [0:0] in_ready_o
static inline uint64_t mpdtc_core_get_in_ready_o(const Vmpdtc_core* t) { return (uint64_t)t->in_ready_o; }
// input signed [24:0] i_d_i
static inline void mpdtc_core_set_i_d_i(Vmpdtc_core* t, int64_t x) {
    t->i_d_i = (uint64_t)x & 0x1ffffffULL;
}
// input signed [24:0] i_q_i
static inline void mpdtc_core_set_i_q_i(Vmpdtc_core* t, int64_t x) {
    t->i_q_i = (uint64_t)x & 0x1ffffffULL;
}
// input signed [17:0] cos0_i
static inline void mpdtc_core_set_cos0_i(Vmpdtc_core* t, int64_t x) {
    t->cos0_i = (uint64_t)x & 0x3ffffULL;
}
// input signed [17:0] sin0_i
static inline void mpdtc_core_set_sin0_i(Vmpdtc_core* t, int64_t x) {
    t->sin0_i = (uint64_t)x & 0x3ffffULL;
}
// input signed [17:0] cos1_i
static inline void mpdtc_core_set_cos1_i(Vmpdtc_core* t, int64_t x) {
    t->cos1_i = (uint64_t)x & 0x3ffffULL;
}
// input signed [17:0] sin1_i
static inline void mpdtc_core_set_sin1_i(Vmpdtc_core* t, int64_t x) {
    t->sin1_i = (uint64_t)x & 0x3ffffULL;
}
// input signed [17:0] cos2_i
static inline void mpdtc_core_set_cos2_i(Vmpdtc_core* t, int64_t x) {
    t->cos2_i = (uint64_t)x & 0x3ffffULL;
}
// input signed [17:0] sin2_i
static inline void mpdtc_core_set_sin2_i(Vmpdtc_core* t, int64_t x) {
    t->sin2_i = (uint64_t)x & 0x3ffffULL;
}
// input signed [17:0] w_ts_i
static inline void mpdtc_core_set_w_ts_i(Vmpdtc_core* t, int64_t x) {
    t->w_ts_i = (uint64_t)x & 0x3ffffULL;
}
// input signed [17:0] t_ref_i
static inline void mpdtc_core_set_t_ref_i(Vmpdtc_core* t, int64_t x) {
    t->t_ref_i = (uint64_t)x & 0x3ffffULL;
}
// input signed [17:0] p_a_i
static inline void mpdtc_core_set_p_a_i(Vmpdtc_core* t, int64_t x) {
    t->p_a_i = (uint64_t)x & 0x3ffffULL;
}
// input signed [17:0] p_lambda_i
static inline void mpdtc_core_set_p_lambda_i(Vmpdtc_core* t, int64_t x) {
    t->p_lambda_i = (uint64_t)x & 0x3ffffULL;
}
// input signed [24:0] p_u0_i
static inline void mpdtc_core_set_p_u0_i(Vmpdtc_core* t, int64_t x) {
    t->p_u0_i = (uint64_t)x & 0x1ffffffULL;
}
// input signed [24:0] p_u0_half_i
static inline void mpdtc_core_set_p_u0_half_i(Vmpdtc_core* t, int64_t x) {
    t->p_u0_half_i = (uint64_t)x & 0x1ffffffULL;
}
// input signed [24:0] p_u0_h_i
static inline void mpdtc_core_set_p_u0_h_i(Vmpdtc_core* t, int64_t x) {
    t->p_u0_h_i = (uint64_t)x & 0x1ffffffULL;
}
// input signed [24:0] p_psi_l_i
static inline void mpdtc_core_set_p_psi_l_i(Vmpdtc_core* t, int64_t x) {
    t->p_psi_l_i = (uint64_t)x & 0x1ffffffULL;
}
// input signed [24:0] p_kinv_t_i
static inline void mpdtc_core_set_p_kinv_t_i(Vmpdtc_core* t, int64_t x) {
    t->p_kinv_t_i = (uint64_t)x & 0x1ffffffULL;
}
// input signed [24:0] p_tol_i
static inline void mpdtc_core_set_p_tol_i(Vmpdtc_core* t, int64_t x) {
    t->p_tol_i = (uint64_t)x & 0x1ffffffULL;
}
// input signed [17:0] p_k_int_i
static inline void mpdtc_core_set_p_k_int_i(Vmpdtc_core* t, int64_t x) {
    t->p_k_int_i = (uint64_t)x & 0x3ffffULL;
}
// input signed [24:0] p_int_lim_i
static inline void mpdtc_core_set_p_int_lim_i(Vmpdtc_core* t, int64_t x) {
    t->p_int_lim_i = (uint64_t)x & 0x1ffffffULL;
}
// input [0:0] p_int_cond_i
static inline void mpdtc_core_set_p_int_cond_i(Vmpdtc_core* t, int64_t x) {
    t->p_int_cond_i = (uint64_t)x & 0x1ULL;
}
// input signed [17:0] p_kp_o_i
static inline void mpdtc_core_set_p_kp_o_i(Vmpdtc_core* t, int64_t x) {
    t->p_kp_o_i = (uint64_t)x & 0x3ffffULL;
}
// input signed [17:0] p_ki_o_i
static inline void mpdtc_core_set_p_ki_o_i(Vmpdtc_core* t, int64_t x) {
    t->p_ki_o_i = (uint64_t)x & 0x3ffffULL;
}
// input signed [24:0] p_eta_lim_i
static inline void mpdtc_core_set_p_eta_lim_i(Vmpdtc_core* t, int64_t x) {
    t->p_eta_lim_i = (uint64_t)x & 0x1ffffffULL;
}
// input [71:0] p_w2_i
static inline void mpdtc_core_set_p_w2_i(Vmpdtc_core* t, const uint32_t* w) {
    for (int k = 0; k < 3; k++) t->p_w2_i[k] = w[k];
    t->p_w2_i[2] &= 0xffu;
}
// p_w2_i: 4 lanes of 18 bits (signed), lane k in [18 k +: 18]
static const int mpdtc_core_p_w2_i_LANES = 4;
static inline void mpdtc_core_set_p_w2_i_lane(Vmpdtc_core* t, int k, int64_t x) {
    for (int i = 0; i < 18; i++) {
        const int b = 18 * k + i;
        const uint32_t bit = 1u << (b % 32);
        if (((uint64_t)x >> i) & 1u) t->p_w2_i[b / 32] |= bit;
        else t->p_w2_i[b / 32] &= ~bit;
    }
}
// input [0:0] st_load_i
static inline void mpdtc_core_set_st_load_i(Vmpdtc_core* t, int64_t x) {
    t->st_load_i = (uint64_t)x & 0x1ULL;
}
// input [2:0] st_s_applied_i
static inline void mpdtc_core_set_st_s_applied_i(Vmpdtc_core* t, int64_t x) {
    t->st_s_applied_i = (uint64_t)x & 0x7ULL;
}
// input [2:0] st_s_prev_i
static inline void mpdtc_core_set_st_s_prev_i(Vmpdtc_core* t, int64_t x) {
    t->st_s_prev_i = (uint64_t)x & 0x7ULL;
}
// input signed [24:0] st_eta_d_i
static inline void mpdtc_core_set_st_eta_d_i(Vmpdtc_core* t, int64_t x) {
    t->st_eta_d_i = (uint64_t)x & 0x1ffffffULL;
}
// input signed [24:0] st_eta_q_i
static inline void mpdtc_core_set_st_eta_q_i(Vmpdtc_core* t, int64_t x) {
    t->st_eta_q_i = (uint64_t)x & 0x1ffffffULL;
}
// input signed [24:0] st_x_i
static inline void mpdtc_core_set_st_x_i(Vmpdtc_core* t, int64_t x) {
    t->st_x_i = (uint64_t)x & 0x1ffffffULL;
}
// input [0:0] st_band_i
static inline void mpdtc_core_set_st_band_i(Vmpdtc_core* t, int64_t x) {
    t->st_band_i = (uint64_t)x & 0x1ULL;
}
// input signed [24:0] st_iq_ref_prev_i
static inline void mpdtc_core_set_st_iq_ref_prev_i(Vmpdtc_core* t, int64_t x) {
    t->st_iq_ref_prev_i = (uint64_t)x & 0x1ffffffULL;
}
// input signed [24:0] st_i_hat_d_i
static inline void mpdtc_core_set_st_i_hat_d_i(Vmpdtc_core* t, int64_t x) {
    t->st_i_hat_d_i = (uint64_t)x & 0x1ffffffULL;
}
// input signed [24:0] st_i_hat_q_i
static inline void mpdtc_core_set_st_i_hat_q_i(Vmpdtc_core* t, int64_t x) {
    t->st_i_hat_q_i = (uint64_t)x & 0x1ffffffULL;
}
// input signed [24:0] st_nu_d_i
static inline void mpdtc_core_set_st_nu_d_i(Vmpdtc_core* t, int64_t x) {
    t->st_nu_d_i = (uint64_t)x & 0x1ffffffULL;
}
// input signed [24:0] st_nu_q_i
static inline void mpdtc_core_set_st_nu_q_i(Vmpdtc_core* t, int64_t x) {
    t->st_nu_q_i = (uint64_t)x & 0x1ffffffULL;
}
// output [0:0] out_valid_o
static inline uint64_t mpdtc_core_get_out_valid_o(const Vmpdtc_core* t) { return (uint64_t)t->out_valid_o; }
// output [2:0] s_next_o
static inline uint64_t mpdtc_core_get_s_next_o(const Vmpdtc_core* t) { return (uint64_t)t->s_next_o; }
// output signed [24:0] iq_ref_o
static inline int64_t mpdtc_core_get_iq_ref_o(const Vmpdtc_core* t) {
    const uint64_t m = 1ULL << 24;
    return (int64_t)((((uint64_t)t->iq_ref_o & 0x1ffffffULL) ^ m) - m);
}
// output signed [24:0] eta_d_o
static inline int64_t mpdtc_core_get_eta_d_o(const Vmpdtc_core* t) {
    const uint64_t m = 1ULL << 24;
    return (int64_t)((((uint64_t)t->eta_d_o & 0x1ffffffULL) ^ m) - m);
}
// output signed [24:0] eta_q_o
static inline int64_t mpdtc_core_get_eta_q_o(const Vmpdtc_core* t) {
    const uint64_t m = 1ULL << 24;
    return (int64_t)((((uint64_t)t->eta_q_o & 0x1ffffffULL) ^ m) - m);
}
// output signed [24:0] i1_d_o
static inline int64_t mpdtc_core_get_i1_d_o(const Vmpdtc_core* t) {
    const uint64_t m = 1ULL << 24;
    return (int64_t)((((uint64_t)t->i1_d_o & 0x1ffffffULL) ^ m) - m);
}
// output signed [24:0] i1_q_o
static inline int64_t mpdtc_core_get_i1_q_o(const Vmpdtc_core* t) {
    const uint64_t m = 1ULL << 24;
    return (int64_t)((((uint64_t)t->i1_q_o & 0x1ffffffULL) ^ m) - m);
}
// output [199:0] i2_d_o
static inline void mpdtc_core_get_i2_d_o(const Vmpdtc_core* t, uint32_t* w) {
    for (int k = 0; k < 7; k++) w[k] = t->i2_d_o[k];
}
// i2_d_o: 8 lanes of 25 bits (signed), lane k in [25 k +: 25]
static const int mpdtc_core_i2_d_o_LANES = 8;
static inline int64_t mpdtc_core_get_i2_d_o_lane(const Vmpdtc_core* t, int k) {
    uint64_t r = 0;
    for (int i = 0; i < 25; i++) {
        const int b = 25 * k + i;
        r |= (uint64_t)((t->i2_d_o[b / 32] >> (b % 32)) & 1u) << i;
    }
    const uint64_t m = 1ULL << 24;
    return (int64_t)((r ^ m) - m);
}
// output [199:0] i2_q_o
static inline void mpdtc_core_get_i2_q_o(const Vmpdtc_core* t, uint32_t* w) {
    for (int k = 0; k < 7; k++) w[k] = t->i2_q_o[k];
}
// i2_q_o: 8 lanes of 25 bits (signed), lane k in [25 k +: 25]
static const int mpdtc_core_i2_q_o_LANES = 8;
static inline int64_t mpdtc_core_get_i2_q_o_lane(const Vmpdtc_core* t, int k) {
    uint64_t r = 0;
    for (int i = 0; i < 25; i++) {
        const int b = 25 * k + i;
        r |= (uint64_t)((t->i2_q_o[b / 32] >> (b % 32)) & 1u) << i;
    }
    const uint64_t m = 1ULL << 24;
    return (int64_t)((r ^ m) - m);
}
// output [199:0] err_o
static inline void mpdtc_core_get_err_o(const Vmpdtc_core* t, uint32_t* w) {
    for (int k = 0; k < 7; k++) w[k] = t->err_o[k];
}
// err_o: 8 lanes of 25 bits (signed), lane k in [25 k +: 25]
static const int mpdtc_core_err_o_LANES = 8;
static inline int64_t mpdtc_core_get_err_o_lane(const Vmpdtc_core* t, int k) {
    uint64_t r = 0;
    for (int i = 0; i < 25; i++) {
        const int b = 25 * k + i;
        r |= (uint64_t)((t->err_o[b / 32] >> (b % 32)) & 1u) << i;
    }
    const uint64_t m = 1ULL << 24;
    return (int64_t)((r ^ m) - m);
}
// output [383:0] cost2_o
static inline void mpdtc_core_get_cost2_o(const Vmpdtc_core* t, uint32_t* w) {
    for (int k = 0; k < 12; k++) w[k] = t->cost2_o[k];
}
// cost2_o: 8 lanes of 48 bits (signed), lane k in [48 k +: 48]
static const int mpdtc_core_cost2_o_LANES = 8;
static inline int64_t mpdtc_core_get_cost2_o_lane(const Vmpdtc_core* t, int k) {
    uint64_t r = 0;
    for (int i = 0; i < 48; i++) {
        const int b = 48 * k + i;
        r |= (uint64_t)((t->cost2_o[b / 32] >> (b % 32)) & 1u) << i;
    }
    const uint64_t m = 1ULL << 47;
    return (int64_t)((r ^ m) - m);
}
// output [2:0] st_s_applied_o
static inline uint64_t mpdtc_core_get_st_s_applied_o(const Vmpdtc_core* t) { return (uint64_t)t->st_s_applied_o; }
// output [2:0] st_s_prev_o
static inline uint64_t mpdtc_core_get_st_s_prev_o(const Vmpdtc_core* t) { return (uint64_t)t->st_s_prev_o; }
// output signed [24:0] st_eta_d_o
static inline int64_t mpdtc_core_get_st_eta_d_o(const Vmpdtc_core* t) {
    const uint64_t m = 1ULL << 24;
    return (int64_t)((((uint64_t)t->st_eta_d_o & 0x1ffffffULL) ^ m) - m);
}
// output signed [24:0] st_eta_q_o
static inline int64_t mpdtc_core_get_st_eta_q_o(const Vmpdtc_core* t) {
    const uint64_t m = 1ULL << 24;
    return (int64_t)((((uint64_t)t->st_eta_q_o & 0x1ffffffULL) ^ m) - m);
}
// output signed [24:0] st_x_o
static inline int64_t mpdtc_core_get_st_x_o(const Vmpdtc_core* t) {
    const uint64_t m = 1ULL << 24;
    return (int64_t)((((uint64_t)t->st_x_o & 0x1ffffffULL) ^ m) - m);
}
// output [0:0] st_band_o
static inline uint64_t mpdtc_core_get_st_band_o(const Vmpdtc_core* t) { return (uint64_t)t->st_band_o; }
// output signed [24:0] st_iq_ref_prev_o
static inline int64_t mpdtc_core_get_st_iq_ref_prev_o(const Vmpdtc_core* t) {
    const uint64_t m = 1ULL << 24;
    return (int64_t)((((uint64_t)t->st_iq_ref_prev_o & 0x1ffffffULL) ^ m) - m);
}
// output signed [24:0] st_i_hat_d_o
static inline int64_t mpdtc_core_get_st_i_hat_d_o(const Vmpdtc_core* t) {
    const uint64_t m = 1ULL << 24;
    return (int64_t)((((uint64_t)t->st_i_hat_d_o & 0x1ffffffULL) ^ m) - m);
}
// output signed [24:0] st_i_hat_q_o
static inline int64_t mpdtc_core_get_st_i_hat_q_o(const Vmpdtc_core* t) {
    const uint64_t m = 1ULL << 24;
    return (int64_t)((((uint64_t)t->st_i_hat_q_o & 0x1ffffffULL) ^ m) - m);
}
// output signed [24:0] st_nu_d_o
static inline int64_t mpdtc_core_get_st_nu_d_o(const Vmpdtc_core* t) {
    const uint64_t m = 1ULL << 24;
    return (int64_t)((((uint64_t)t->st_nu_d_o & 0x1ffffffULL) ^ m) - m);
}
// output signed [24:0] st_nu_q_o
static inline int64_t mpdtc_core_get_st_nu_q_o(const Vmpdtc_core* t) {
    const uint64_t m = 1ULL << 24;
    return (int64_t)((((uint64_t)t->st_nu_q_o & 0x1ffffffULL) ^ m) - m);
}
