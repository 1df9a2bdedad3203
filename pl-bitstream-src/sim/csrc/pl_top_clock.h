// A clock edge of the Verilated pl_top without its input-driven region
// (Verilator 5's "ico" functions), for pl_top_shim.cpp. docs/speed.md.
//
// Verilated's eval() runs the whole input-driven combinational region
// first on every call, whether or not an input changed: in the
// co-simulation that region (mostly the register file's write decode) was
// about a sixth of pl-cosim's time, run twice a cycle. After an eval()
// every signal is settled for the inputs it saw (the clock-driven regions
// re-settle the logic that depends on both inputs and registers), so with
// the inputs unchanged a second run of that region computes nothing new,
// except what reads the clock input itself. In pl_top those are four
// wires, the simulation-only clock gates of the MPDCC and MPDTC cores, the
// register file and the MPDTC front end (SIM_MPDCC_CLOCK_GATE,
// SIM_MPDTC_CLOCK_GATE, SIM_REGS_CLOCK_GATE, SIM_FE_CLOCK_GATE):
// mc_clk = clk_i && mc_ce_q, mt_clk = clk_i && mt_ce_q, rg_clk = clk_i &&
// rg_ce_q and fe_clk = clk_i && fe_ce_q, recomputed here. build.rs checks that the
// region reads clk_i nowhere else (and fails the build otherwise).
//
// clock() then runs Verilator's own trigger / active / NBA loop, the same
// loop as the generated Vpl_top___024root___eval after its input region.
#pragma once

#include <cstdint>
#include <cstring>
#include <type_traits>

#include "Vpl_top.h"
#include "Vpl_top___024root.h"
#include "verilated.h"

void Vpl_top___024root___eval_triggers__act(Vpl_top___024root* vlSelf);
void Vpl_top___024root___eval_act(Vpl_top___024root* vlSelf);
void Vpl_top___024root___eval_nba(Vpl_top___024root* vlSelf);

namespace pl_top_clock {

// A trigger vector's flags as one word (Verilator 5.006's VlTriggerVec is
// a std::array<bool, N> and nothing else): its clear / any / set loops ran
// flag by flag, about 270 instructions a PL cycle (docs/speed.md).
template <typename V>
static inline uint64_t flags(const V& v) {
    static_assert(sizeof(V) <= sizeof(uint64_t), "trigger vector wider than a word");
    static_assert(std::is_trivially_copyable<V>::value, "trigger vector not plain flags");
    uint64_t w = 0;
    std::memcpy(&w, &v, sizeof(V));
    return w;
}
template <typename V>
static inline void set_flags(V& v, uint64_t w) {
    std::memcpy(&v, &w, sizeof(V));
}

// Sets clk_i to `level` and evaluates, the other inputs as they were at
// the last full eval().
static inline void clock(Vpl_top* t, uint8_t level) {
    Vpl_top___024root* r = t->rootp;
    r->clk_i = level;
    r->pl_top__DOT__mc_clk = level & r->pl_top__DOT__mc_ce_q;
    r->pl_top__DOT__mt_clk = level & r->pl_top__DOT__mt_ce_q;
    r->pl_top__DOT__rg_clk = level & r->pl_top__DOT__rg_ce_q;
    r->pl_top__DOT__fe_clk = level & r->pl_top__DOT__fe_ce_q;
    // Up to 100 rounds each, as Verilator's loop (a design that does not
    // settle is a fatal error there too).
    for (int nba = 0;; nba++) {
        uint64_t nba_w = 0;
        for (int act = 0;; act++) {
            Vpl_top___024root___eval_triggers__act(r);
            const uint64_t act_w = flags(r->__VactTriggered);
            if (!act_w) break;
            if (VL_UNLIKELY(act > 100)) VL_FATAL_MT(__FILE__, __LINE__, "", "pl_top: active region did not converge");
            nba_w |= act_w;
            set_flags(r->__VnbaTriggered, nba_w);
            Vpl_top___024root___eval_act(r);
        }
        if (!nba_w) break;
        if (VL_UNLIKELY(nba > 100)) VL_FATAL_MT(__FILE__, __LINE__, "", "pl_top: NBA region did not converge");
        Vpl_top___024root___eval_nba(r);
    }
}

}  // namespace pl_top_clock
