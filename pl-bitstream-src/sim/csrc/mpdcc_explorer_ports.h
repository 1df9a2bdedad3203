// Generated from pl-bitstream-src/rtl/mpdcc_explorer.v (its port list) by `cargo run -p
// regmap-gen`; do not edit (a test fails when this file is stale).
//
// Setters mask to the port's width; getters of signed ports sign-extend;
// ports wider than 64 bits go as 32-bit words, least significant first.
#pragma once
#include <cstdint>

#include "Vmpdcc_explorer.h"

// input [0:0] clk_i
static inline void mpdcc_explorer_set_clk_i(Vmpdcc_explorer* t, int64_t x) {
    t->clk_i = (uint64_t)x & 0x1ULL;
}
// input [0:0] rst_i
static inline void mpdcc_explorer_set_rst_i(Vmpdcc_explorer* t, int64_t x) {
    t->rst_i = (uint64_t)x & 0x1ULL;
}
// input [0:0] in_valid_i
static inline void mpdcc_explorer_set_in_valid_i(Vmpdcc_explorer* t, int64_t x) {
    t->in_valid_i = (uint64_t)x & 0x1ULL;
}
// input [8:0] s_i
static inline void mpdcc_explorer_set_s_i(Vmpdcc_explorer* t, int64_t x) {
    t->s_i = (uint64_t)x & 0x1ffULL;
}
// input [8:0] s_prev_i
static inline void mpdcc_explorer_set_s_prev_i(Vmpdcc_explorer* t, int64_t x) {
    t->s_prev_i = (uint64_t)x & 0x1ffULL;
}
// input [111:0] e0_i
static inline void mpdcc_explorer_set_e0_i(Vmpdcc_explorer* t, const uint32_t* w) {
    for (int k = 0; k < 4; k++) t->e0_i[k] = w[k];
    t->e0_i[3] &= 0xffffu;
}
// input [191:0] dn_i
static inline void mpdcc_explorer_set_dn_i(Vmpdcc_explorer* t, const uint32_t* w) {
    for (int k = 0; k < 6; k++) t->dn_i[k] = w[k];
    t->dn_i[5] &= 0xffffffffu;
}
// input [47:0] dn1_i
static inline void mpdcc_explorer_set_dn1_i(Vmpdcc_explorer* t, int64_t x) {
    t->dn1_i = (uint64_t)x & 0xffffffffffffULL;
}
// input [95:0] pn_i
static inline void mpdcc_explorer_set_pn_i(Vmpdcc_explorer* t, const uint32_t* w) {
    for (int k = 0; k < 3; k++) t->pn_i[k] = w[k];
    t->pn_i[2] &= 0xffffffffu;
}
// input [95:0] pph_i
static inline void mpdcc_explorer_set_pph_i(Vmpdcc_explorer* t, const uint32_t* w) {
    for (int k = 0; k < 3; k++) t->pph_i[k] = w[k];
    t->pph_i[2] &= 0xffffffffu;
}
// input signed [15:0] v_n_i
static inline void mpdcc_explorer_set_v_n_i(Vmpdcc_explorer* t, int64_t x) {
    t->v_n_i = (uint64_t)x & 0xffffULL;
}
// input [47:0] v_ph_i
static inline void mpdcc_explorer_set_v_ph_i(Vmpdcc_explorer* t, int64_t x) {
    t->v_ph_i = (uint64_t)x & 0xffffffffffffULL;
}
// input signed [15:0] vdc_half_i
static inline void mpdcc_explorer_set_vdc_half_i(Vmpdcc_explorer* t, int64_t x) {
    t->vdc_half_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] g3_i
static inline void mpdcc_explorer_set_g3_i(Vmpdcc_explorer* t, int64_t x) {
    t->g3_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] gd_i
static inline void mpdcc_explorer_set_gd_i(Vmpdcc_explorer* t, int64_t x) {
    t->gd_i = (uint64_t)x & 0xffffULL;
}
// input signed [15:0] g3_1_i
static inline void mpdcc_explorer_set_g3_1_i(Vmpdcc_explorer* t, int64_t x) {
    t->g3_1_i = (uint64_t)x & 0xffffULL;
}
// input [111:0] bnd_i
static inline void mpdcc_explorer_set_bnd_i(Vmpdcc_explorer* t, const uint32_t* w) {
    for (int k = 0; k < 4; k++) t->bnd_i[k] = w[k];
    t->bnd_i[3] &= 0xffffu;
}
// input [15:0] lambda_n_i
static inline void mpdcc_explorer_set_lambda_n_i(Vmpdcc_explorer* t, int64_t x) {
    t->lambda_n_i = (uint64_t)x & 0xffffULL;
}
// output [0:0] out_valid_o
static inline uint64_t mpdcc_explorer_get_out_valid_o(const Vmpdcc_explorer* t) { return (uint64_t)t->out_valid_o; }
// output [8:0] s_o
static inline uint64_t mpdcc_explorer_get_s_o(const Vmpdcc_explorer* t) { return (uint64_t)t->s_o; }
// output [7:0] l_star_o
static inline uint64_t mpdcc_explorer_get_l_star_o(const Vmpdcc_explorer* t) { return (uint64_t)t->l_star_o; }
// output [31:0] cost_o
static inline uint64_t mpdcc_explorer_get_cost_o(const Vmpdcc_explorer* t) { return (uint64_t)t->cost_o; }
// output signed [31:0] j_dl_o
static inline int64_t mpdcc_explorer_get_j_dl_o(const Vmpdcc_explorer* t) {
    const uint64_t m = 1ULL << 31;
    return (int64_t)((((uint64_t)t->j_dl_o & 0xffffffffULL) ^ m) - m);
}
// output [3:0] fs_o
static inline uint64_t mpdcc_explorer_get_fs_o(const Vmpdcc_explorer* t) { return (uint64_t)t->fs_o; }
// output [111:0] d0_o
static inline void mpdcc_explorer_get_d0_o(const Vmpdcc_explorer* t, uint32_t* w) {
    for (int k = 0; k < 4; k++) w[k] = t->d0_o[k];
}
