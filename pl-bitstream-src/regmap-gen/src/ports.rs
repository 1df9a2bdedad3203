//! The external ports of `pl_top` besides the clock, the one list the
//! `pl_top` Verilator harness ([`crate::harness`]) is generated from; the
//! test `tests/pl_top_ports.rs` checks `pl_top.v`'s port list against it.
//! It lives with the generator, not in the register map: the firmware never
//! sees the PL's pins.
use regmap::AXI_ADDR_BITS;

/// Direction of a `pl_top` port.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PortDir {
    /// Into the PL.
    In,
    /// Out of the PL.
    Out,
}

/// One external port of `pl_top` besides the clock: the AXI4-Lite slave on
/// GP0 and the pins. The Verilator harness (`csrc/pl_top_shim.cpp` and the
/// `PtIn`/`PtOut` structs of `rtl_sim::pl_top`) is generated from
/// [`PL_TOP_PORTS`], and a test checks `pl_top.v`'s port list against it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Port {
    /// Verilog port name (`_i`/`_o`/`_ni` suffix).
    pub verilog: &'static str,
    /// Field of the harness struct (`PtIn` for inputs, `PtOut` for outputs).
    pub field: &'static str,
    /// Direction.
    pub dir: PortDir,
    /// Width in bits (at most 64).
    pub width: u8,
    /// Inputs: the level the harness drives while it holds the design in
    /// reset (the pin's inactive level).
    pub idle: u64,
    /// Meaning.
    pub doc: &'static str,
}

const fn port_in(verilog: &'static str, field: &'static str, width: u8, doc: &'static str) -> Port {
    Port {
        verilog,
        field,
        dir: PortDir::In,
        width,
        idle: 0,
        doc,
    }
}

const fn port_out(
    verilog: &'static str,
    field: &'static str,
    width: u8,
    doc: &'static str,
) -> Port {
    Port {
        verilog,
        field,
        dir: PortDir::Out,
        width,
        idle: 0,
        doc,
    }
}

/// The external ports of `pl_top` (the clock `clk_i` is the harness's own).
pub const PL_TOP_PORTS: &[Port] = &[
    port_in("s_axi_aresetn_i", "aresetn", 1, "AXI reset, active low."),
    port_in(
        "s_axi_awaddr_i",
        "awaddr",
        AXI_ADDR_BITS as u8,
        "AW channel.",
    ),
    port_in("s_axi_awvalid_i", "awvalid", 1, "AW valid."),
    port_in("s_axi_wdata_i", "wdata", 32, "W data."),
    port_in("s_axi_wstrb_i", "wstrb", 4, "W byte strobes."),
    port_in("s_axi_wvalid_i", "wvalid", 1, "W valid."),
    port_in("s_axi_bready_i", "bready", 1, "B ready."),
    port_in(
        "s_axi_araddr_i",
        "araddr",
        AXI_ADDR_BITS as u8,
        "AR address.",
    ),
    port_in("s_axi_arvalid_i", "arvalid", 1, "AR valid."),
    port_in("s_axi_rready_i", "rready", 1, "R ready."),
    port_in(
        "adc_drdy_i",
        "adc_drdy",
        1,
        "ADC data ready (asynchronous, one result per rising edge).",
    ),
    port_in(
        "adc_data_i",
        "adc_data",
        36,
        "ADC data `{ia, ib, ic}`, 12 bits each, ia in bits 35..24.",
    ),
    port_in("enc_a_i", "enc_a", 1, "Encoder A."),
    port_in("enc_b_i", "enc_b", 1, "Encoder B."),
    port_in("enc_z_i", "enc_z", 1, "Encoder index."),
    Port {
        idle: 1,
        ..port_in(
            "fault_ext_ni",
            "fault_ext_n",
            1,
            "External fault pin, active low.",
        )
    },
    port_out("s_axi_awready_o", "awready", 1, "AW ready."),
    port_out("s_axi_wready_o", "wready", 1, "W ready."),
    port_out("s_axi_bresp_o", "bresp", 2, "B response."),
    port_out("s_axi_bvalid_o", "bvalid", 1, "B valid."),
    port_out("s_axi_arready_o", "arready", 1, "AR ready."),
    port_out("s_axi_rdata_o", "rdata", 32, "R data."),
    port_out("s_axi_rresp_o", "rresp", 2, "R response."),
    port_out("s_axi_rvalid_o", "rvalid", 1, "R valid."),
    port_out("gate_hi_o", "gate_hi", 3, "Upper gates (bit 2 = leg a)."),
    port_out("gate_lo_o", "gate_lo", 3, "Lower gates."),
    port_out(
        "gate_en_o",
        "gate_en",
        1,
        "Gate-driver enable pin (GATE_EN and no trip).",
    ),
    port_out("adc_cnv_o", "adc_cnv", 1, "ADC convert-start pulse."),
    port_out(
        "adc_avg_valid_o",
        "adc_avg_valid",
        1,
        "Averaged-sample strobe.",
    ),
    port_out(
        "irq_o",
        "irq",
        1,
        "Control interrupt (IRQ_F2P[0]), a level.",
    ),
];
