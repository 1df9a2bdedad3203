//! Safe wrapper of the Verilated `pl_top` (shim: `csrc/pl_top_shim.cpp`)
//! and a cycle-level AXI4-Lite master to drive it. The shim and the port
//! structs [`PtIn`]/[`PtOut`] are generated from `regmap_gen::ports::PL_TOP_PORTS`
//! (`cargo run -p regmap-gen`).
//!
//! [`PlTopSim::step`] is one clock cycle: the inputs in [`PlTopSim::inp`]
//! are applied, the outputs are sampled just before the rising edge (what the
//! slave's flops and the master see at that edge) and returned. AXI
//! addresses are byte offsets in the 15-bit GP0 window (page << 12 | offset,
//! i.e. the absolute address minus `regmap::BASE_ADDR`).
use core::ffi::c_void;
use core::ptr::NonNull;
use simpl::adc::Converter;

pub use crate::pl_top_ports::{PtIn, PtOut};

extern "C" {
    fn pt_new() -> *mut c_void;
    fn pt_step(p: *mut c_void, inp: *const PtIn, before_edge: *mut PtOut);
    fn pt_peek(p: *mut c_void, out: *mut PtOut);
    fn pt_free(p: *mut c_void);
}

/// AXI response codes.
pub const OKAY: u8 = 0;
/// Slave error.
pub const SLVERR: u8 = 2;

/// Cycles an AXI transfer may take before the master gives up.
const TIMEOUT: u32 = 1000;

/// One Verilated `pl_top`.
pub struct PlTopSim {
    ptr: NonNull<c_void>,
    /// Inputs applied at the next [`Self::step`].
    pub inp: PtIn,
    /// Clock cycles run.
    pub cycles: u64,
    /// Built-in converter model (the simulated PL's [`Converter`]): drives
    /// `adc_drdy_i` in every [`Self::step`] (so also during AXI transfers)
    /// and `adc_data_i` = [`Self::adc_data`]. `None` (default): the test
    /// drives the ADC pins.
    pub adc: Option<Converter>,
    /// The converter's data bus while [`Self::adc`] is set.
    pub adc_data: u64,
}

impl PlTopSim {
    /// A new model, held in reset for 4 cycles, then released.
    pub fn new() -> Self {
        // SAFETY: pt_new returns a fresh heap object owned by this value.
        let ptr = NonNull::new(unsafe { pt_new() }).expect("pt_new returned null");
        let mut s = Self {
            ptr,
            inp: PtIn::IDLE,
            cycles: 0,
            adc: None,
            adc_data: 0,
        };
        for _ in 0..4 {
            s.step();
        }
        s.inp.aresetn = 1;
        s
    }

    /// One clock cycle; returns the outputs as sampled by the rising edge.
    pub fn step(&mut self) -> PtOut {
        if let Some(c) = &self.adc {
            self.inp.adc_drdy = u8::from(c.drdy());
            self.inp.adc_data = self.adc_data;
        }
        let mut out = PtOut::default();
        // SAFETY: live object; both structs are repr(C) and match the shim.
        unsafe { pt_step(self.ptr.as_ptr(), &self.inp, &mut out) };
        self.cycles += 1;
        if let Some(c) = &mut self.adc {
            c.edge(out.adc_cnv == 1);
        }
        out
    }

    /// Outputs now (after the last edge).
    pub fn peek(&self) -> PtOut {
        let mut out = PtOut::default();
        // SAFETY: live object, repr(C) output struct.
        unsafe { pt_peek(self.ptr.as_ptr(), &mut out) };
        out
    }

    /// Runs `n` cycles with the current inputs.
    pub fn idle(&mut self, n: u32) {
        for _ in 0..n {
            self.step();
        }
    }

    /// AXI write with AW and W presented in the same cycle, all strobes;
    /// returns BRESP. Panics after a timeout (a hung bus is a test failure).
    pub fn write(&mut self, addr: u16, data: u32) -> u8 {
        self.write_strb(addr, data, 0xF)
    }

    /// AXI write with byte strobes.
    pub fn write_strb(&mut self, addr: u16, data: u32, strb: u8) -> u8 {
        self.write_skewed(addr, data, strb, 0, 0)
    }

    /// AXI write where AW is raised after `aw_delay` cycles and W after
    /// `w_delay` cycles; BREADY is held high. Returns BRESP.
    pub fn write_skewed(
        &mut self,
        addr: u16,
        data: u32,
        strb: u8,
        aw_delay: u32,
        w_delay: u32,
    ) -> u8 {
        let (mut aw_done, mut w_done) = (false, false);
        self.inp.bready = 1;
        for t in 0..TIMEOUT {
            self.inp.awvalid = u8::from(!aw_done && t >= aw_delay);
            self.inp.awaddr = addr;
            self.inp.wvalid = u8::from(!w_done && t >= w_delay);
            self.inp.wdata = data;
            self.inp.wstrb = strb;
            let o = self.step();
            aw_done |= self.inp.awvalid == 1 && o.awready == 1;
            w_done |= self.inp.wvalid == 1 && o.wready == 1;
            if o.bvalid == 1 {
                assert!(
                    aw_done && w_done,
                    "BVALID before both AW and W were accepted"
                );
                self.inp.awvalid = 0;
                self.inp.wvalid = 0;
                return o.bresp;
            }
        }
        panic!("AXI write to {addr:#06x} timed out");
    }

    /// AXI read; returns (RDATA, RRESP).
    pub fn read(&mut self, addr: u16) -> (u32, u8) {
        let mut ar_done = false;
        self.inp.rready = 1;
        for _ in 0..TIMEOUT {
            self.inp.arvalid = u8::from(!ar_done);
            self.inp.araddr = addr;
            let o = self.step();
            ar_done |= self.inp.arvalid == 1 && o.arready == 1;
            if o.rvalid == 1 && ar_done {
                self.inp.arvalid = 0;
                return (o.rdata, o.rresp);
            }
        }
        panic!("AXI read of {addr:#06x} timed out");
    }

    /// Reads a register that must answer OKAY.
    pub fn read_ok(&mut self, addr: u16) -> u32 {
        let (d, r) = self.read(addr);
        assert_eq!(r, OKAY, "read of {addr:#06x} answered {r}");
        d
    }
}

impl Default for PlTopSim {
    fn default() -> Self {
        Self::new()
    }
}

impl Drop for PlTopSim {
    fn drop(&mut self) {
        // SAFETY: the pointer came from pt_new and is freed exactly once.
        unsafe { pt_free(self.ptr.as_ptr()) }
    }
}

/// AXI offset (15-bit window) of a register of the map.
pub fn axi_addr(block: &regmap::Block, reg: &regmap::Register) -> u16 {
    (block.addr(reg) - regmap::BASE_ADDR) as u16
}

/// The Verilated `pl_top` as the drivers' register bus (absolute GP0
/// addresses; one AXI access each, `SLVERR` as [`BusError::SlaveError`]).
impl regmap::bus::RegisterBus for PlTopSim {
    fn read(&mut self, addr: usize) -> Result<u32, regmap::bus::BusError> {
        let rel = axi_rel(addr)?;
        match PlTopSim::read(self, rel) {
            (d, OKAY) => Ok(d),
            _ => Err(regmap::bus::BusError::SlaveError),
        }
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), regmap::bus::BusError> {
        let rel = axi_rel(addr)?;
        match PlTopSim::write(self, rel, value) {
            OKAY => Ok(()),
            _ => Err(regmap::bus::BusError::SlaveError),
        }
    }
}

/// The AXI address of an absolute one (outside the window: `SlaveError`).
fn axi_rel(addr: usize) -> Result<u16, regmap::bus::BusError> {
    addr.checked_sub(regmap::BASE_ADDR)
        .filter(|r| *r < 1 << regmap::AXI_ADDR_BITS)
        .map(|r| r as u16)
        .ok_or(regmap::bus::BusError::SlaveError)
}
