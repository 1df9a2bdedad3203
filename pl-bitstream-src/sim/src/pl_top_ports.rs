// Generated from pl-bitstream-src/regmap-gen/src/ports.rs (PL_TOP_PORTS) by `cargo run -p
// regmap-gen`; do not edit (a test fails when this file is stale).
//! The ports of `pl_top` as the harness sees them (C layout shared with
//! `csrc/pl_top_shim.cpp`); re-exported by [`crate::pl_top`].

/// Inputs of `pl_top` (C layout shared with the shim).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct PtIn {
    /// AXI reset, active low.
    pub aresetn: u8,
    /// AW channel.
    pub awaddr: u16,
    /// AW valid.
    pub awvalid: u8,
    /// W data.
    pub wdata: u32,
    /// W byte strobes.
    pub wstrb: u8,
    /// W valid.
    pub wvalid: u8,
    /// B ready.
    pub bready: u8,
    /// AR address.
    pub araddr: u16,
    /// AR valid.
    pub arvalid: u8,
    /// R ready.
    pub rready: u8,
    /// ADC data ready (asynchronous, one result per rising edge).
    pub adc_drdy: u8,
    /// ADC data `{ia, ib, ic}`, 12 bits each, ia in bits 35..24.
    pub adc_data: u64,
    /// Encoder A.
    pub enc_a: u8,
    /// Encoder B.
    pub enc_b: u8,
    /// Encoder index.
    pub enc_z: u8,
    /// External fault pin, active low.
    pub fault_ext_n: u8,
}

/// Outputs of `pl_top`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct PtOut {
    /// AW ready.
    pub awready: u8,
    /// W ready.
    pub wready: u8,
    /// B response.
    pub bresp: u8,
    /// B valid.
    pub bvalid: u8,
    /// AR ready.
    pub arready: u8,
    /// R data.
    pub rdata: u32,
    /// R response.
    pub rresp: u8,
    /// R valid.
    pub rvalid: u8,
    /// Upper gates (bit 2 = leg a).
    pub gate_hi: u8,
    /// Lower gates.
    pub gate_lo: u8,
    /// Gate-driver enable pin (GATE_EN and no trip).
    pub gate_en: u8,
    /// ADC convert-start pulse.
    pub adc_cnv: u8,
    /// Averaged-sample strobe.
    pub adc_avg_valid: u8,
    /// Control interrupt (IRQ_F2P[0]), a level.
    pub irq: u8,
}

impl PtIn {
    /// Every input at its inactive level (reset asserted, the active-low
    /// fault pin high).
    pub const IDLE: Self = Self {
        aresetn: 0,
        awaddr: 0,
        awvalid: 0,
        wdata: 0,
        wstrb: 0,
        wvalid: 0,
        bready: 0,
        araddr: 0,
        arvalid: 0,
        rready: 0,
        adc_drdy: 0,
        adc_data: 0,
        enc_a: 0,
        enc_b: 0,
        enc_z: 0,
        fault_ext_n: 1,
    };
}
