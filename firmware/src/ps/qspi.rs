//! Zynq QSPI controller (UG585 ch. 12) in I/O mode, one byte per transfer,
//! manual chip select on CS 0 of the lower bus: what the configuration
//! store needs (a few hundred bytes per save), not speed.
//!
//! Under QEMU 7.2 (`xlnx.ps7-qspi`) the flash on that chip select is an
//! n25q128 backed by `-drive if=mtd,index=8` (indices 0..=7 are the two SPI
//! controllers' flashes). Each byte written to `TXD1` is shifted out at
//! once (auto start) and the byte shifted in lands in the top byte of
//! `RXD`. On a board the FSBL has set the QSPI clocks and MIO pins; this
//! path is not tested on hardware.
use drive::config::spi_nor::SpiBus;
use drive::config::store::FlashError;
use volatile_register::RW;

const BASE: usize = 0xE000_D000;
const CONFIG: usize = 0x00;
const ISR: usize = 0x04;
const EN: usize = 0x14;
const RXD: usize = 0x20;
const TXD1: usize = 0x80;

/// `CONFIG` without a chip select (`drive::zynq::QSPI_CONFIG`, host
/// tested: `Holdb_dr` set).
const CONFIG_BASE: u32 = drive::zynq::QSPI_CONFIG;
/// `CONFIG.Holdb_dr`.
const HOLDB_DR: u32 = drive::zynq::QSPI_HOLDB_DR;
/// `CONFIG.PCS` (bits 13:10): all ones releases the chip select, bit 10
/// low selects CS 0.
const CS_MASK: u32 = 0xF << 10;
const CS_NONE: u32 = 0xF << 10;
const CS_0: u32 = 0xE << 10;
/// `ISR.RX_NEMPTY`.
const ISR_RX_NOT_EMPTY: u32 = 1 << 4;
/// Polls of `ISR` for one byte before the transfer counts as failed.
const POLLS_MAX: u32 = 100_000;

fn reg(off: usize) -> &'static RW<u32> {
    // SAFETY: a documented QSPI controller register (UG585 B.20).
    unsafe { &*((BASE + off) as *const RW<u32>) }
}

/// The QSPI controller as an [`SpiBus`] (after [`Qspi::init`] at boot).
pub struct Qspi;

impl Qspi {
    /// Configures the controller (I/O mode, chip select released) and
    /// enables it.
    pub fn init() -> Self {
        // SAFETY: writes of documented values to the controller's registers.
        unsafe {
            reg(EN).write(0);
            reg(CONFIG).write(CONFIG_BASE | CS_NONE);
            reg(EN).write(1);
        }
        Self
    }

    fn set_cs(&mut self, cs: u32) {
        // SAFETY: as in `init`; `Holdb_dr` kept set whatever was read.
        unsafe { reg(CONFIG).modify(|c| (c & !CS_MASK) | cs | HOLDB_DR) };
    }

    fn drain_rx(&mut self) {
        for _ in 0..64 {
            if reg(ISR).read() & ISR_RX_NOT_EMPTY == 0 {
                return;
            }
            let _ = reg(RXD).read();
        }
    }

    fn byte(&mut self, out: u8) -> Result<u8, FlashError> {
        // SAFETY: as in `init`.
        unsafe { reg(TXD1).write(u32::from(out)) };
        for _ in 0..POLLS_MAX {
            if reg(ISR).read() & ISR_RX_NOT_EMPTY != 0 {
                return Ok((reg(RXD).read() >> 24) as u8);
            }
        }
        Err(FlashError)
    }
}

impl SpiBus for Qspi {
    fn transaction(&mut self, out: &[&[u8]], inp: &mut [u8]) -> Result<(), FlashError> {
        self.drain_rx();
        self.set_cs(CS_0);
        let r = (|| {
            for &b in out.iter().flat_map(|s| s.iter()) {
                self.byte(b)?;
            }
            for b in inp.iter_mut() {
                *b = self.byte(0)?;
            }
            Ok(())
        })();
        self.set_cs(CS_NONE);
        r
    }
}
