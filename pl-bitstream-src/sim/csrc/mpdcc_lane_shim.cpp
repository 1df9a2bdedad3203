// C ABI around the Verilated mpdcc_lane, for rtl-sim (Rust): streams a batch
// of lane inputs, one per clock (with optional idle cycles between them),
// and collects the outputs in order with the latency of each.
#include <cstdint>
#include <vector>

#include "mpdcc_lane_ports.h"
#include "verilated.h"

static void tick(Vmpdcc_lane* t) {
    t->clk_i = 1;
    t->eval();
    t->clk_i = 0;
    t->eval();
}

struct MlSim {
    VerilatedContext ctx;
    Vmpdcc_lane* top;
};

extern "C" {

struct MlIn {
    int32_t e0, n[4], bnd;
    int32_t idle_before;  // idle cycles before this input
};
struct MlOut {
    int32_t lj;
    int32_t latency;  // cycles from its in_valid cycle to its out_valid cycle
};

void* ml_new() {
    auto* sim = new MlSim;
    sim->top = new Vmpdcc_lane(&sim->ctx, "mpdcc_lane");
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

// Returns the number of outputs collected (n unless the core lost some).
int32_t ml_run(void* p, int32_t n, const MlIn* in, MlOut* out) {
    auto* t = static_cast<MlSim*>(p)->top;
    std::vector<int64_t> issued_at(n > 0 ? n : 1, 0);
    int64_t cycle = 0;
    int32_t sent = 0, got = 0, idle = n > 0 ? in[0].idle_before : 0;
    while (got < n && cycle < (int64_t)n * 64 + 1000) {
        bool send = sent < n && idle <= 0;
        t->in_valid_i = send;
        if (send) {
            const MlIn& v = in[sent];
            mpdcc_lane_set_e0_i(t, v.e0);
            mpdcc_lane_set_n0_i(t, v.n[0]);
            mpdcc_lane_set_n1_i(t, v.n[1]);
            mpdcc_lane_set_n2_i(t, v.n[2]);
            mpdcc_lane_set_n3_i(t, v.n[3]);
            mpdcc_lane_set_bnd_i(t, v.bnd);
            issued_at[sent] = cycle;
        }
        t->eval();
        tick(t);
        cycle++;
        if (send) {
            sent++;
            idle = sent < n ? in[sent].idle_before : 0;
        } else {
            idle--;
        }
        t->eval();
        if (mpdcc_lane_get_out_valid_o(t) && got < n) {
            out[got].lj = mpdcc_lane_get_lj_o(t);
            out[got].latency = (int32_t)(cycle - issued_at[got]);
            got++;
        }
    }
    t->in_valid_i = 0;
    t->eval();
    return got;
}

void ml_free(void* p) {
    auto* sim = static_cast<MlSim*>(p);
    sim->top->final();
    delete sim->top;
    delete sim;
}
}
