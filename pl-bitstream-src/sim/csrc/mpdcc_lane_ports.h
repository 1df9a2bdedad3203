// Generated from pl-bitstream-src/rtl/mpdcc_lane.v (its port list) by `cargo run -p
// regmap-gen`; do not edit (a test fails when this file is stale).
//
// Setters mask to the port's width; getters of signed ports sign-extend;
// ports wider than 64 bits go as 32-bit words, least significant first.
#pragma once
#include <cstdint>

#include "Vmpdcc_lane.h"

// input [0:0] clk_i
static inline void mpdcc_lane_set_clk_i(Vmpdcc_lane* t, int64_t x) {
    t->clk_i = (uint64_t)x & 0x1ULL;
}
// input [0:0] rst_i
static inline void mpdcc_lane_set_rst_i(Vmpdcc_lane* t, int64_t x) {
    t->rst_i = (uint64_t)x & 0x1ULL;
}
// input [0:0] in_valid_i
static inline void mpdcc_lane_set_in_valid_i(Vmpdcc_lane* t, int64_t x) {
    t->in_valid_i = (uint64_t)x & 0x1ULL;
}
// input signed [15:0] e0_i
static inline void mpdcc_lane_set_e0_i(Vmpdcc_lane* t, int64_t x) {
    t->e0_i = (uint64_t)x & 0xffffULL;
}
// input signed [17:0] n0_i
static inline void mpdcc_lane_set_n0_i(Vmpdcc_lane* t, int64_t x) {
    t->n0_i = (uint64_t)x & 0x3ffffULL;
}
// input signed [17:0] n1_i
static inline void mpdcc_lane_set_n1_i(Vmpdcc_lane* t, int64_t x) {
    t->n1_i = (uint64_t)x & 0x3ffffULL;
}
// input signed [17:0] n2_i
static inline void mpdcc_lane_set_n2_i(Vmpdcc_lane* t, int64_t x) {
    t->n2_i = (uint64_t)x & 0x3ffffULL;
}
// input signed [17:0] n3_i
static inline void mpdcc_lane_set_n3_i(Vmpdcc_lane* t, int64_t x) {
    t->n3_i = (uint64_t)x & 0x3ffffULL;
}
// input [14:0] bnd_i
static inline void mpdcc_lane_set_bnd_i(Vmpdcc_lane* t, int64_t x) {
    t->bnd_i = (uint64_t)x & 0x7fffULL;
}
// output [0:0] out_valid_o
static inline uint64_t mpdcc_lane_get_out_valid_o(const Vmpdcc_lane* t) { return (uint64_t)t->out_valid_o; }
// output [7:0] lj_o
static inline uint64_t mpdcc_lane_get_lj_o(const Vmpdcc_lane* t) { return (uint64_t)t->lj_o; }
