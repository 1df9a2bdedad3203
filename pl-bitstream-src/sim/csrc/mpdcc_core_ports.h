// Generated from pl-bitstream-src/rtl/mpdcc_core.v (its port list) by `cargo run -p
// regmap-gen`; do not edit (a test fails when this file is stale).
//
// Setters mask to the port's width; getters of signed ports sign-extend;
// ports wider than 64 bits go as 32-bit words, least significant first.
#pragma once
#include <cstdint>

#include "Vmpdcc_core.h"

// input [0:0] clk_i
static inline void mpdcc_core_set_clk_i(Vmpdcc_core* t, int64_t x) {
    t->clk_i = (uint64_t)x & 0x1ULL;
}
// input [0:0] rst_i
static inline void mpdcc_core_set_rst_i(Vmpdcc_core* t, int64_t x) {
    t->rst_i = (uint64_t)x & 0x1ULL;
}
// input [0:0] start_i
static inline void mpdcc_core_set_start_i(Vmpdcc_core* t, int64_t x) {
    t->start_i = (uint64_t)x & 0x1ULL;
}
// output [0:0] busy_o
static inline uint64_t mpdcc_core_get_busy_o(const Vmpdcc_core* t) { return (uint64_t)t->busy_o; }
// input [2:0] n_use_i
static inline void mpdcc_core_set_n_use_i(Vmpdcc_core* t, int64_t x) {
    t->n_use_i = (uint64_t)x & 0x7ULL;
}
// input [8:0] s_prev_i
static inline void mpdcc_core_set_s_prev_i(Vmpdcc_core* t, int64_t x) {
    t->s_prev_i = (uint64_t)x & 0x1ffULL;
}
// s_prev_i: 3 lanes of 3 bits, lane k in [3 k +: 3]
static const int mpdcc_core_s_prev_i_LANES = 3;
static inline void mpdcc_core_set_s_prev_i_lane(Vmpdcc_core* t, int k, int64_t x) {
    const uint64_t m = 0x7ULL << (3 * k);
    t->s_prev_i = ((uint64_t)t->s_prev_i & ~m) | (((uint64_t)x << (3 * k)) & m);
}
// input signed [15:0] i_a_i
static inline void mpdcc_core_set_i_a_i(Vmpdcc_core* t, int64_t x) {
    t->i_a_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] i_b_i
static inline void mpdcc_core_set_i_b_i(Vmpdcc_core* t, int64_t x) {
    t->i_b_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] psi_a_i
static inline void mpdcc_core_set_psi_a_i(Vmpdcc_core* t, int64_t x) {
    t->psi_a_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] psi_b_i
static inline void mpdcc_core_set_psi_b_i(Vmpdcc_core* t, int64_t x) {
    t->psi_b_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] v_n_i
static inline void mpdcc_core_set_v_n_i(Vmpdcc_core* t, int64_t x) {
    t->v_n_i = (uint64_t)x & 0xffffULL;
}
// input [47:0] v_ph_i
static inline void mpdcc_core_set_v_ph_i(Vmpdcc_core* t, int64_t x) {
    t->v_ph_i = (uint64_t)x & 0xffffffffffffULL;
}
// v_ph_i: 3 lanes of 16 bits (signed), lane k in [16 k +: 16]
static const int mpdcc_core_v_ph_i_LANES = 3;
static inline void mpdcc_core_set_v_ph_i_lane(Vmpdcc_core* t, int k, int64_t x) {
    const uint64_t m = 0xffffULL << (16 * k);
    t->v_ph_i = ((uint64_t)t->v_ph_i & ~m) | (((uint64_t)x << (16 * k)) & m);
}
// input signed [15:0] ir_a_i
static inline void mpdcc_core_set_ir_a_i(Vmpdcc_core* t, int64_t x) {
    t->ir_a_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] ir_b_i
static inline void mpdcc_core_set_ir_b_i(Vmpdcc_core* t, int64_t x) {
    t->ir_b_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] omega_r_i
static inline void mpdcc_core_set_omega_r_i(Vmpdcc_core* t, int64_t x) {
    t->omega_r_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] omega_s_i
static inline void mpdcc_core_set_omega_s_i(Vmpdcc_core* t, int64_t x) {
    t->omega_s_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] c_tau_i
static inline void mpdcc_core_set_c_tau_i(Vmpdcc_core* t, int64_t x) {
    t->c_tau_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] c_r_i
static inline void mpdcc_core_set_c_r_i(Vmpdcc_core* t, int64_t x) {
    t->c_r_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] c_w_i
static inline void mpdcc_core_set_c_w_i(Vmpdcc_core* t, int64_t x) {
    t->c_w_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] c_p_i
static inline void mpdcc_core_set_c_p_i(Vmpdcc_core* t, int64_t x) {
    t->c_p_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] c_s_i
static inline void mpdcc_core_set_c_s_i(Vmpdcc_core* t, int64_t x) {
    t->c_s_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] c_3_i
static inline void mpdcc_core_set_c_3_i(Vmpdcc_core* t, int64_t x) {
    t->c_3_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] c_d_i
static inline void mpdcc_core_set_c_d_i(Vmpdcc_core* t, int64_t x) {
    t->c_d_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] c_n_i
static inline void mpdcc_core_set_c_n_i(Vmpdcc_core* t, int64_t x) {
    t->c_n_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] c_ph_i
static inline void mpdcc_core_set_c_ph_i(Vmpdcc_core* t, int64_t x) {
    t->c_ph_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] s3h_i
static inline void mpdcc_core_set_s3h_i(Vmpdcc_core* t, int64_t x) {
    t->s3h_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] v_ph_ref_i
static inline void mpdcc_core_set_v_ph_ref_i(Vmpdcc_core* t, int64_t x) {
    t->v_ph_ref_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] c_tau1_i
static inline void mpdcc_core_set_c_tau1_i(Vmpdcc_core* t, int64_t x) {
    t->c_tau1_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] c_r1_i
static inline void mpdcc_core_set_c_r1_i(Vmpdcc_core* t, int64_t x) {
    t->c_r1_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] c_w1_i
static inline void mpdcc_core_set_c_w1_i(Vmpdcc_core* t, int64_t x) {
    t->c_w1_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] c_s1_i
static inline void mpdcc_core_set_c_s1_i(Vmpdcc_core* t, int64_t x) {
    t->c_s1_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] vdc_half_i
static inline void mpdcc_core_set_vdc_half_i(Vmpdcc_core* t, int64_t x) {
    t->vdc_half_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] g3_i
static inline void mpdcc_core_set_g3_i(Vmpdcc_core* t, int64_t x) {
    t->g3_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] gd_i
static inline void mpdcc_core_set_gd_i(Vmpdcc_core* t, int64_t x) {
    t->gd_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] g3_1_i
static inline void mpdcc_core_set_g3_1_i(Vmpdcc_core* t, int64_t x) {
    t->g3_1_i = (uint64_t)x & 0xffffULL;
}
// input [111:0] bnd_i
static inline void mpdcc_core_set_bnd_i(Vmpdcc_core* t, const uint32_t* w) {
    for (int k = 0; k < 4; k++) t->bnd_i[k] = w[k];
    t->bnd_i[3] &= 0xffffu;
}
// bnd_i: 7 lanes of 16 bits (signed), lane k in [16 k +: 16]
static const int mpdcc_core_bnd_i_LANES = 7;
static inline void mpdcc_core_set_bnd_i_lane(Vmpdcc_core* t, int k, int64_t x) {
    for (int i = 0; i < 16; i++) {
        const int b = 16 * k + i;
        const uint32_t bit = 1u << (b % 32);
        if (((uint64_t)x >> i) & 1u) t->bnd_i[b / 32] |= bit;
        else t->bnd_i[b / 32] &= ~bit;
    }
}
// input [15:0] lambda_n_i
static inline void mpdcc_core_set_lambda_n_i(Vmpdcc_core* t, int64_t x) {
    t->lambda_n_i = (uint64_t)x & 0xffffULL;
}
// output [0:0] done_o
static inline uint64_t mpdcc_core_get_done_o(const Vmpdcc_core* t) { return (uint64_t)t->done_o; }
// output [8:0] s_o
static inline uint64_t mpdcc_core_get_s_o(const Vmpdcc_core* t) { return (uint64_t)t->s_o; }
// s_o: 3 lanes of 3 bits, lane k in [3 k +: 3]
static const int mpdcc_core_s_o_LANES = 3;
static inline int64_t mpdcc_core_get_s_o_lane(const Vmpdcc_core* t, int k) {
    const uint64_t r = ((uint64_t)t->s_o >> (3 * k)) & 0x7ULL;
    return (int64_t)r;
}
// output [1:0] kind_o
static inline uint64_t mpdcc_core_get_kind_o(const Vmpdcc_core* t) { return (uint64_t)t->kind_o; }
// output [7:0] l_star_o
static inline uint64_t mpdcc_core_get_l_star_o(const Vmpdcc_core* t) { return (uint64_t)t->l_star_o; }
// output [31:0] cost_o
static inline uint64_t mpdcc_core_get_cost_o(const Vmpdcc_core* t) { return (uint64_t)t->cost_o; }
// output signed [31:0] j_dl_o
static inline int64_t mpdcc_core_get_j_dl_o(const Vmpdcc_core* t) {
    const uint64_t m = 1ULL << 31;
    return (int64_t)((((uint64_t)t->j_dl_o & 0xffffffffULL) ^ m) - m);
}
// output [7:0] candidates_o
static inline uint64_t mpdcc_core_get_candidates_o(const Vmpdcc_core* t) { return (uint64_t)t->candidates_o; }
// output [15:0] cycles_o
static inline uint64_t mpdcc_core_get_cycles_o(const Vmpdcc_core* t) { return (uint64_t)t->cycles_o; }
