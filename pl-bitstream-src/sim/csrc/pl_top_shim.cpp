// Generated from pl-bitstream-src/regmap-gen/src/ports.rs (PL_TOP_PORTS) by `cargo run -p
// regmap-gen`; do not edit (a test fails when this file is stale).
//
// C ABI around the Verilated pl_top, for rtl-sim (Rust).
// pt_step applies the inputs with the clock low, settles the combinational
// logic, copies the outputs as the rising edge will sample them (so a Rust
// AXI master sees READY exactly as the slave presents it), then gives one
// rising edge: two evaluations per cycle. Only the simulation-only MPDCC
// clock gate uses the falling edge, so the clock returns low in the next
// cycle's first evaluation, with that cycle's inputs. The input-driven
// logic runs only in that first evaluation and only when an input other
// than the clock changed (pl_top_clock.h).
// pt_peek reads the outputs after the edge.
#include <cstdint>

#include "Vpl_top.h"
#include "pl_top_clock.h"
#include "verilated.h"

extern "C" {

struct PtIn {
    uint8_t aresetn;
    uint16_t awaddr;
    uint8_t awvalid;
    uint32_t wdata;
    uint8_t wstrb;
    uint8_t wvalid;
    uint8_t bready;
    uint16_t araddr;
    uint8_t arvalid;
    uint8_t rready;
    uint8_t adc_drdy;
    uint64_t adc_data;
    uint8_t enc_a;
    uint8_t enc_b;
    uint8_t enc_z;
    uint8_t fault_ext_n;
};

struct PtOut {
    uint8_t awready;
    uint8_t wready;
    uint8_t bresp;
    uint8_t bvalid;
    uint8_t arready;
    uint32_t rdata;
    uint8_t rresp;
    uint8_t rvalid;
    uint8_t gate_hi;
    uint8_t gate_lo;
    uint8_t gate_en;
    uint8_t adc_cnv;
    uint8_t adc_avg_valid;
    uint8_t irq;
};

struct PlTopSim {
    VerilatedContext ctx;
    Vpl_top* top;
};

static void apply(Vpl_top* t, const PtIn* in) {
    t->s_axi_aresetn_i = in->aresetn & 0x1;
    t->s_axi_awaddr_i = in->awaddr & 0x7fff;
    t->s_axi_awvalid_i = in->awvalid & 0x1;
    t->s_axi_wdata_i = in->wdata;
    t->s_axi_wstrb_i = in->wstrb & 0xf;
    t->s_axi_wvalid_i = in->wvalid & 0x1;
    t->s_axi_bready_i = in->bready & 0x1;
    t->s_axi_araddr_i = in->araddr & 0x7fff;
    t->s_axi_arvalid_i = in->arvalid & 0x1;
    t->s_axi_rready_i = in->rready & 0x1;
    t->adc_drdy_i = in->adc_drdy & 0x1;
    t->adc_data_i = in->adc_data & 0xfffffffffULL;
    t->enc_a_i = in->enc_a & 0x1;
    t->enc_b_i = in->enc_b & 0x1;
    t->enc_z_i = in->enc_z & 0x1;
    t->fault_ext_ni = in->fault_ext_n & 0x1;
}

// Every input but the clock as `in` would set it.
static bool unchanged(const Vpl_top* t, const PtIn* in) {
    return true
        && t->s_axi_aresetn_i == (in->aresetn & 0x1)
        && t->s_axi_awaddr_i == (in->awaddr & 0x7fff)
        && t->s_axi_awvalid_i == (in->awvalid & 0x1)
        && t->s_axi_wdata_i == (in->wdata)
        && t->s_axi_wstrb_i == (in->wstrb & 0xf)
        && t->s_axi_wvalid_i == (in->wvalid & 0x1)
        && t->s_axi_bready_i == (in->bready & 0x1)
        && t->s_axi_araddr_i == (in->araddr & 0x7fff)
        && t->s_axi_arvalid_i == (in->arvalid & 0x1)
        && t->s_axi_rready_i == (in->rready & 0x1)
        && t->adc_drdy_i == (in->adc_drdy & 0x1)
        && t->adc_data_i == (in->adc_data & 0xfffffffffULL)
        && t->enc_a_i == (in->enc_a & 0x1)
        && t->enc_b_i == (in->enc_b & 0x1)
        && t->enc_z_i == (in->enc_z & 0x1)
        && t->fault_ext_ni == (in->fault_ext_n & 0x1);
}

static void read_out(const Vpl_top* t, PtOut* out) {
    out->awready = t->s_axi_awready_o;
    out->wready = t->s_axi_wready_o;
    out->bresp = t->s_axi_bresp_o;
    out->bvalid = t->s_axi_bvalid_o;
    out->arready = t->s_axi_arready_o;
    out->rdata = t->s_axi_rdata_o;
    out->rresp = t->s_axi_rresp_o;
    out->rvalid = t->s_axi_rvalid_o;
    out->gate_hi = t->gate_hi_o;
    out->gate_lo = t->gate_lo_o;
    out->gate_en = t->gate_en_o;
    out->adc_cnv = t->adc_cnv_o;
    out->adc_avg_valid = t->adc_avg_valid_o;
    out->irq = t->irq_o;
}

void* pt_new() {
    auto* sim = new PlTopSim;
    sim->top = new Vpl_top(&sim->ctx, "pl_top");
    sim->top->clk_i = 0;
    sim->top->s_axi_aresetn_i = 0;
    sim->top->s_axi_awaddr_i = 0;
    sim->top->s_axi_awvalid_i = 0;
    sim->top->s_axi_wdata_i = 0;
    sim->top->s_axi_wstrb_i = 0;
    sim->top->s_axi_wvalid_i = 0;
    sim->top->s_axi_bready_i = 0;
    sim->top->s_axi_araddr_i = 0;
    sim->top->s_axi_arvalid_i = 0;
    sim->top->s_axi_rready_i = 0;
    sim->top->adc_drdy_i = 0;
    sim->top->adc_data_i = 0;
    sim->top->enc_a_i = 0;
    sim->top->enc_b_i = 0;
    sim->top->enc_z_i = 0;
    sim->top->fault_ext_ni = 1;
    sim->top->eval();
    return sim;
}

void pt_step(void* p, const PtIn* in, PtOut* before_edge) {
    auto* t = static_cast<PlTopSim*>(p)->top;
    if (unchanged(t, in)) {
        pl_top_clock::clock(t, 0);
    } else {
        apply(t, in);
        t->clk_i = 0;
        t->eval();
    }
    read_out(t, before_edge);
    pl_top_clock::clock(t, 1);
}

void pt_peek(void* p, PtOut* out) { read_out(static_cast<PlTopSim*>(p)->top, out); }

void pt_free(void* p) {
    auto* sim = static_cast<PlTopSim*>(p);
    sim->top->final();
    delete sim->top;
    delete sim;
}
}
