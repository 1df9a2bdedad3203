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
// s_i: 3 lanes of 3 bits, lane k in [3 k +: 3]
static const int mpdcc_explorer_s_i_LANES = 3;
static inline void mpdcc_explorer_set_s_i_lane(Vmpdcc_explorer* t, int k, int64_t x) {
    const uint64_t m = 0x7ULL << (3 * k);
    t->s_i = ((uint64_t)t->s_i & ~m) | (((uint64_t)x << (3 * k)) & m);
}
// input [8:0] s_prev_i
static inline void mpdcc_explorer_set_s_prev_i(Vmpdcc_explorer* t, int64_t x) {
    t->s_prev_i = (uint64_t)x & 0x1ffULL;
}
// s_prev_i: 3 lanes of 3 bits, lane k in [3 k +: 3]
static const int mpdcc_explorer_s_prev_i_LANES = 3;
static inline void mpdcc_explorer_set_s_prev_i_lane(Vmpdcc_explorer* t, int k, int64_t x) {
    const uint64_t m = 0x7ULL << (3 * k);
    t->s_prev_i = ((uint64_t)t->s_prev_i & ~m) | (((uint64_t)x << (3 * k)) & m);
}
// input [111:0] e0_i
static inline void mpdcc_explorer_set_e0_i(Vmpdcc_explorer* t, const uint32_t* w) {
    for (int k = 0; k < 4; k++) t->e0_i[k] = w[k];
    t->e0_i[3] &= 0xffffu;
}
// e0_i: 7 lanes of 16 bits (signed), lane k in [16 k +: 16]
static const int mpdcc_explorer_e0_i_LANES = 7;
static inline void mpdcc_explorer_set_e0_i_lane(Vmpdcc_explorer* t, int k, int64_t x) {
    for (int i = 0; i < 16; i++) {
        const int b = 16 * k + i;
        const uint32_t bit = 1u << (b % 32);
        if (((uint64_t)x >> i) & 1u) t->e0_i[b / 32] |= bit;
        else t->e0_i[b / 32] &= ~bit;
    }
}
// input [191:0] dn_i
static inline void mpdcc_explorer_set_dn_i(Vmpdcc_explorer* t, const uint32_t* w) {
    for (int k = 0; k < 6; k++) t->dn_i[k] = w[k];
    t->dn_i[5] &= 0xffffffffu;
}
// dn_i: 12 lanes of 16 bits (signed), lane k in [16 k +: 16]
static const int mpdcc_explorer_dn_i_LANES = 12;
static inline void mpdcc_explorer_set_dn_i_lane(Vmpdcc_explorer* t, int k, int64_t x) {
    for (int i = 0; i < 16; i++) {
        const int b = 16 * k + i;
        const uint32_t bit = 1u << (b % 32);
        if (((uint64_t)x >> i) & 1u) t->dn_i[b / 32] |= bit;
        else t->dn_i[b / 32] &= ~bit;
    }
}
// input [47:0] dn1_i
static inline void mpdcc_explorer_set_dn1_i(Vmpdcc_explorer* t, int64_t x) {
    t->dn1_i = (uint64_t)x & 0xffffffffffffULL;
}
// dn1_i: 3 lanes of 16 bits (signed), lane k in [16 k +: 16]
static const int mpdcc_explorer_dn1_i_LANES = 3;
static inline void mpdcc_explorer_set_dn1_i_lane(Vmpdcc_explorer* t, int k, int64_t x) {
    const uint64_t m = 0xffffULL << (16 * k);
    t->dn1_i = ((uint64_t)t->dn1_i & ~m) | (((uint64_t)x << (16 * k)) & m);
}
// input [95:0] pn_i
static inline void mpdcc_explorer_set_pn_i(Vmpdcc_explorer* t, const uint32_t* w) {
    for (int k = 0; k < 3; k++) t->pn_i[k] = w[k];
    t->pn_i[2] &= 0xffffffffu;
}
// pn_i: 3 lanes of 32 bits (signed), lane k in [32 k +: 32]
static const int mpdcc_explorer_pn_i_LANES = 3;
static inline void mpdcc_explorer_set_pn_i_lane(Vmpdcc_explorer* t, int k, int64_t x) {
    for (int i = 0; i < 32; i++) {
        const int b = 32 * k + i;
        const uint32_t bit = 1u << (b % 32);
        if (((uint64_t)x >> i) & 1u) t->pn_i[b / 32] |= bit;
        else t->pn_i[b / 32] &= ~bit;
    }
}
// input [95:0] pph_i
static inline void mpdcc_explorer_set_pph_i(Vmpdcc_explorer* t, const uint32_t* w) {
    for (int k = 0; k < 3; k++) t->pph_i[k] = w[k];
    t->pph_i[2] &= 0xffffffffu;
}
// pph_i: 3 lanes of 32 bits (signed), lane k in [32 k +: 32]
static const int mpdcc_explorer_pph_i_LANES = 3;
static inline void mpdcc_explorer_set_pph_i_lane(Vmpdcc_explorer* t, int k, int64_t x) {
    for (int i = 0; i < 32; i++) {
        const int b = 32 * k + i;
        const uint32_t bit = 1u << (b % 32);
        if (((uint64_t)x >> i) & 1u) t->pph_i[b / 32] |= bit;
        else t->pph_i[b / 32] &= ~bit;
    }
}
// input signed [15:0] v_n_i
static inline void mpdcc_explorer_set_v_n_i(Vmpdcc_explorer* t, int64_t x) {
    t->v_n_i = (uint64_t)x & 0xffffULL;
}
// input [47:0] v_ph_i
static inline void mpdcc_explorer_set_v_ph_i(Vmpdcc_explorer* t, int64_t x) {
    t->v_ph_i = (uint64_t)x & 0xffffffffffffULL;
}
// v_ph_i: 3 lanes of 16 bits (signed), lane k in [16 k +: 16]
static const int mpdcc_explorer_v_ph_i_LANES = 3;
static inline void mpdcc_explorer_set_v_ph_i_lane(Vmpdcc_explorer* t, int k, int64_t x) {
    const uint64_t m = 0xffffULL << (16 * k);
    t->v_ph_i = ((uint64_t)t->v_ph_i & ~m) | (((uint64_t)x << (16 * k)) & m);
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
// bnd_i: 7 lanes of 16 bits (signed), lane k in [16 k +: 16]
static const int mpdcc_explorer_bnd_i_LANES = 7;
static inline void mpdcc_explorer_set_bnd_i_lane(Vmpdcc_explorer* t, int k, int64_t x) {
    for (int i = 0; i < 16; i++) {
        const int b = 16 * k + i;
        const uint32_t bit = 1u << (b % 32);
        if (((uint64_t)x >> i) & 1u) t->bnd_i[b / 32] |= bit;
        else t->bnd_i[b / 32] &= ~bit;
    }
}
// input [15:0] lambda_n_i
static inline void mpdcc_explorer_set_lambda_n_i(Vmpdcc_explorer* t, int64_t x) {
    t->lambda_n_i = (uint64_t)x & 0xffffULL;
}
// output [0:0] out_valid_o
static inline uint64_t mpdcc_explorer_get_out_valid_o(const Vmpdcc_explorer* t) { return (uint64_t)t->out_valid_o; }
// output [8:0] s_o
static inline uint64_t mpdcc_explorer_get_s_o(const Vmpdcc_explorer* t) { return (uint64_t)t->s_o; }
// s_o: 3 lanes of 3 bits, lane k in [3 k +: 3]
static const int mpdcc_explorer_s_o_LANES = 3;
static inline int64_t mpdcc_explorer_get_s_o_lane(const Vmpdcc_explorer* t, int k) {
    const uint64_t r = ((uint64_t)t->s_o >> (3 * k)) & 0x7ULL;
    return (int64_t)r;
}
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
// d0_o: 7 lanes of 16 bits (signed), lane k in [16 k +: 16]
static const int mpdcc_explorer_d0_o_LANES = 7;
static inline int64_t mpdcc_explorer_get_d0_o_lane(const Vmpdcc_explorer* t, int k) {
    uint64_t r = 0;
    for (int i = 0; i < 16; i++) {
        const int b = 16 * k + i;
        r |= (uint64_t)((t->d0_o[b / 32] >> (b % 32)) & 1u) << i;
    }
    const uint64_t m = 1ULL << 15;
    return (int64_t)((r ^ m) - m);
}
