// C ABI around the Verilated gate_driver, for rtl-sim (Rust).
// One call to gd_tick is one rising clock edge; inputs are applied with
// gd_set_inputs while the clock is low.
#include <cstdint>

#include "Vgate_driver.h"
#include "verilated.h"

namespace {
struct GateDriverSim {
    VerilatedContext ctx;
    Vgate_driver* top;
};
}  // namespace

extern "C" {

void* gd_new() {
    auto* sim = new GateDriverSim;
    sim->top = new Vgate_driver(&sim->ctx, "gate_driver");
    sim->top->clk_i = 0;
    sim->top->rst_i = 1;
    sim->top->en_i = 0;
    sim->top->fault_i = 0;
    sim->top->s_i = 0;
    sim->top->dt_i = 0;
    sim->top->eval();
    return sim;
}

void gd_set_inputs(void* p, uint8_t rst, uint8_t en, uint8_t fault, uint8_t s, uint16_t dt) {
    auto* sim = static_cast<GateDriverSim*>(p);
    sim->top->rst_i = rst & 1;
    sim->top->en_i = en & 1;
    sim->top->fault_i = fault & 1;
    sim->top->s_i = s & 7;
    sim->top->dt_i = dt & 0x3ff;
}

void gd_eval(void* p) { static_cast<GateDriverSim*>(p)->top->eval(); }

void gd_tick(void* p) {
    auto* sim = static_cast<GateDriverSim*>(p);
    sim->top->clk_i = 1;
    sim->top->eval();
    sim->top->clk_i = 0;
    sim->top->eval();
}

// Bits 2..0: gate_hi_o (leg a, b, c); bits 5..3: gate_lo_o.
uint32_t gd_get_outputs(void* p) {
    auto* sim = static_cast<GateDriverSim*>(p);
    return (uint32_t)(sim->top->gate_hi_o & 7) | ((uint32_t)(sim->top->gate_lo_o & 7) << 3);
}

void gd_free(void* p) {
    auto* sim = static_cast<GateDriverSim*>(p);
    sim->top->final();
    delete sim->top;
    delete sim;
}
}
