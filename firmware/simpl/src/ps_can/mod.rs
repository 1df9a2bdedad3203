//! A register-level model of the Zynq-7000 PS CAN controller (UG585
//! chapter 18 and appendix B; the offsets and fields of
//! `regmap::ps_can`), behind [`regmap::bus::RegisterBus`] at one
//! controller's base address, for host tests of the driver `drive::can`.
//!
//! Modules: [`fifo`] (messages and the 64-deep FIFOs), [`confinement`]
//! (error counters by ISO 11898-1), [`bus`] (the wire between models:
//! arbitration, acknowledge, delivery); `registers` decodes the register
//! accesses.
//!
//! What it models, as the TRM describes the controller:
//! - `SRR`: `SRST` resets every register and both FIFOs; `CEN = 0` is
//!   configuration mode (`SR.CONFIG`, `SR.ESTAT = 00`), where alone
//!   `MSR`, `BRPR` and `BTR` take writes (writes while enabled are ignored
//!   and counted in [`PsCanModel::ignored_config_writes`]).
//! - `MSR`: loopback (frames go to the own RX FIFO, not onto the bus), snoop
//!   (receives, never acknowledges or transmits), sleep (off the bus).
//! - TX FIFO (64) and high-priority buffer (1, sent first): the write of
//!   `DATA2` queues the staged words; a `DATA2` write with no room drops
//!   the message and counts it in [`PsCanModel::dropped_tx_writes`].
//! - RX FIFO (64): the read of `RXFIFO_DATA2` removes the oldest message; a
//!   read while empty sets `ISR.RXUFLW`; a received message with no room
//!   is dropped, sets `ISR.RXOFLW` and is counted in
//!   [`PsCanModel::rx_dropped`].
//! - Acceptance filters: with no `AFR.UAFn` set every message passes;
//!   otherwise a message passes when for some filter in use
//!   `ID & AFMR == AFIR & AFMR`. `AFMRn`/`AFIRn` take writes only while
//!   `UAFn` is 0 (`SR.ACFBSY` never reads 1 here: the model is immediate).
//! - `ISR`/`IER`/`ICR`: sticky flags cleared by `ICR`, a condition still
//!   present (RX FIFO not empty, TX FIFO full or empty, buffer full) wins
//!   over the clear. `ESR` is write 1 to clear.
//! - `ECR` and `SR.ESTAT`/`SR.ERRWRN` from [`confinement`].
//!
//! The bus compares bit times (`BRPR`, `BTR` and the reference clock):
//! a node at another bit rate neither acknowledges nor receives a frame, it
//! detects an error instead. Otherwise not modelled: timing (a frame is one
//! [`bus::step`]), the sample point and resynchronisation, the timestamp
//! (`RXT` reads 0), watermark interrupts, sleep wake-up, the stuff, form and
//! CRC checks themselves (errors come from the hooks
//! [`PsCanModel::inject_tx_bit_errors`] and
//! [`PsCanModel::inject_rx_errors`], or from a missing acknowledge), and
//! whether entering configuration mode clears the error counters (here it
//! does not; `SRST` does).

pub mod bus;
pub mod confinement;
pub mod fifo;
mod registers;

use confinement::{Confinement, State};
use fifo::{Fifo, Message};
use regmap::ps_can as reg;

/// Error warning limit of `SR.ERRWRN`: a counter at 96 or more.
const ERROR_WARNING_AT: u8 = 96;
/// `MSR`'s implemented bits.
const MSR_BITS: u32 = reg::MSR_SLEEP | reg::MSR_LBACK | reg::MSR_SNOOP;
/// `BTR`'s implemented bits (SJW 8:7, TS2 6:4, TS1 3:0).
const BTR_BITS: u32 = 0x1FF;
/// `AFR`'s implemented bits.
const AFR_BITS: u32 = 0xF;
/// `ESR`'s implemented bits.
const ESR_BITS: u32 = 0x1F;

/// What the controller does on the bus, from `SRR` and `MSR`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BusMode {
    /// `CEN = 0`.
    Configuration,
    /// Transmits, receives and acknowledges.
    Normal,
    /// Internal loopback.
    Loopback,
    /// Receives only.
    Snoop,
    /// Sleep.
    Sleep,
}

/// One controller.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PsCanModel {
    base: usize,
    ref_clock_hz: u32,
    cen: bool,
    msr: u32,
    brpr: u32,
    btr: u32,
    esr: u32,
    isr: u32,
    ier: u32,
    tcr: u32,
    wir: u32,
    afr: u32,
    afmr: [u32; reg::FILTER_COUNT],
    afir: [u32; reg::FILTER_COUNT],
    tx_stage: Message,
    hpb_stage: Message,
    tx_fifo: Fifo,
    hpb: Option<Message>,
    rx_fifo: Fifo,
    errors: Confinement,
    bit_errors_pending: u32,
    /// Writes to `MSR`, `BRPR` or `BTR` while enabled (ignored, as the TRM
    /// says those registers are writable in configuration mode only).
    pub ignored_config_writes: u32,
    /// Writes to `AFMRn`/`AFIRn` while `AFR.UAFn` was set (ignored).
    pub ignored_filter_writes: u32,
    /// `DATA2` writes with no room in the TX FIFO or buffer (message lost).
    pub dropped_tx_writes: u32,
    /// Received messages the full RX FIFO dropped.
    pub rx_dropped: u32,
}

impl PsCanModel {
    /// A controller after reset at `base` (e.g. `regmap::ps_can::CAN0_BASE`)
    /// with a reference clock of `ref_clock_hz` (Hz; with `BRPR` and `BTR`
    /// it sets the bit rate the bus compares).
    pub fn new(base: usize, ref_clock_hz: u32) -> Self {
        Self {
            base,
            ref_clock_hz,
            cen: false,
            msr: 0,
            brpr: 0,
            btr: 0,
            esr: 0,
            isr: 0,
            ier: 0,
            tcr: 0,
            wir: 0,
            afr: 0,
            afmr: [0; reg::FILTER_COUNT],
            afir: [0; reg::FILTER_COUNT],
            tx_stage: Message::default(),
            hpb_stage: Message::default(),
            tx_fifo: Fifo::default(),
            hpb: None,
            rx_fifo: Fifo::default(),
            errors: Confinement::default(),
            bit_errors_pending: 0,
            ignored_config_writes: 0,
            ignored_filter_writes: 0,
            dropped_tx_writes: 0,
            rx_dropped: 0,
        }
        .with_levels()
    }

    fn with_levels(mut self) -> Self {
        self.assert_levels();
        self
    }

    /// `SRR.SRST`: every register and FIFO to reset; the model-side counts
    /// and pending injected errors stay.
    fn reset(&mut self) {
        let keep = (
            self.ignored_config_writes,
            self.ignored_filter_writes,
            self.dropped_tx_writes,
            self.rx_dropped,
            self.bit_errors_pending,
        );
        *self = Self::new(self.base, self.ref_clock_hz);
        (
            self.ignored_config_writes,
            self.ignored_filter_writes,
            self.dropped_tx_writes,
            self.rx_dropped,
            self.bit_errors_pending,
        ) = keep;
    }

    /// The mode `SRR` and `MSR` select.
    pub fn mode(&self) -> BusMode {
        if !self.cen {
            BusMode::Configuration
        } else if self.msr & reg::MSR_LBACK != 0 {
            BusMode::Loopback
        } else if self.msr & reg::MSR_SNOOP != 0 {
            BusMode::Snoop
        } else if self.msr & reg::MSR_SLEEP != 0 {
            BusMode::Sleep
        } else {
            BusMode::Normal
        }
    }

    /// Reference-clock cycles per bit from `BRPR` and `BTR`: the prescaler
    /// times the quanta (1 + `TS1 + 1` + `TS2 + 1`).
    fn cycles_per_bit(&self) -> u64 {
        let ts1 = (self.btr >> reg::BTR_TS1_SHIFT) & reg::BTR_TS1_MASK;
        let ts2 = (self.btr >> reg::BTR_TS2_SHIFT) & reg::BTR_TS2_MASK;
        u64::from(self.brpr + 1) * u64::from(3 + ts1 + ts2)
    }

    /// The bit time as a fraction: (reference cycles per bit, reference
    /// clock in Hz).
    fn bit_time(&self) -> (u64, u64) {
        (self.cycles_per_bit(), u64::from(self.ref_clock_hz))
    }

    /// True when this node's bit time is `t` (from [`Self::bit_time`]):
    /// equal fractions, compared without division.
    fn bit_time_is(&self, t: (u64, u64)) -> bool {
        let (c, f) = self.bit_time();
        c * t.1 == t.0 * f
    }

    /// The fault confinement state.
    pub fn state(&self) -> State {
        self.errors.state()
    }

    /// Messages waiting in the RX FIFO.
    pub fn rx_len(&self) -> usize {
        self.rx_fifo.len()
    }

    /// Messages waiting for transmission (FIFO and buffer).
    pub fn tx_len(&self) -> usize {
        self.tx_fifo.len() + usize::from(self.hpb.is_some())
    }

    /// Hook: the next `n` transmission attempts of this node each meet a
    /// bit error (the node reads back a level it did not send).
    pub fn inject_tx_bit_errors(&mut self, n: u32) {
        self.bit_errors_pending = self.bit_errors_pending.saturating_add(n);
    }

    /// Hook: this node, on the bus, detects `n` errors while receiving
    /// (recorded as CRC errors).
    pub fn inject_rx_errors(&mut self, n: u32) {
        for _ in 0..n {
            self.receive_error(reg::ESR_CRCER);
        }
    }

    /// Hook: the bus stays recessive (idle) for `bits` bit times.
    pub fn idle_bits(&mut self, bits: u32) {
        if self.on_bus() {
            self.errors.recessive(bits);
        }
    }

    /// Watches the bus: enabled in normal or snoop mode (also in bus off,
    /// where it counts recessive bits toward recovery). A loopback node
    /// keeps its frames to itself.
    pub fn on_bus(&self) -> bool {
        matches!(self.mode(), BusMode::Normal | BusMode::Snoop)
    }

    /// Acknowledges frames: on the bus in normal mode, not bus off.
    pub fn acknowledges(&self) -> bool {
        self.mode() == BusMode::Normal && self.errors.state() != State::BusOff
    }

    /// The message this node would send next (buffer first), if it may
    /// transmit (normal or loopback mode, not bus off).
    pub fn pending(&self) -> Option<Message> {
        if !matches!(self.mode(), BusMode::Normal | BusMode::Loopback)
            || self.errors.state() == State::BusOff
        {
            return None;
        }
        self.hpb.or_else(|| self.tx_fifo.front().copied())
    }

    /// The pending message went out: removes it; `TXOK`; TEC down by one.
    fn transmitted(&mut self) {
        if self.hpb.take().is_none() {
            self.tx_fifo.pop();
        }
        self.errors.transmit_ok();
        self.isr |= reg::IXR_TXOK;
        self.assert_levels();
    }

    /// The pending message met an error (it stays queued for the
    /// automatic retransmission).
    fn transmit_error(&mut self, esr: u32, ack: bool) {
        self.esr |= esr;
        self.isr |= reg::IXR_ERROR;
        if self.errors.transmit_error(ack) {
            self.isr |= reg::IXR_BSOFF;
        }
    }

    fn receive_error(&mut self, esr: u32) {
        if self.on_bus() && self.errors.state() != State::BusOff {
            self.esr |= esr;
            self.isr |= reg::IXR_ERROR;
            self.errors.receive_error();
        }
    }

    /// Consumes one injected bit error, if any.
    fn take_bit_error(&mut self) -> bool {
        let hit = self.bit_errors_pending > 0;
        self.bit_errors_pending = self.bit_errors_pending.saturating_sub(1);
        hit
    }

    /// Hook for a test peer, and the bus's delivery: a frame `m` arrived
    /// from the bus without error. Ignored unless the node watches the bus
    /// and is not bus off.
    pub fn deliver(&mut self, m: &Message) {
        if self.on_bus() && self.errors.state() != State::BusOff {
            self.receive(m);
        }
    }

    /// A frame received without error (from the bus, or looped back):
    /// counts the reception, then filters and stores it.
    fn receive(&mut self, m: &Message) {
        self.errors.receive_ok();
        if !self.accepts(m) {
            return;
        }
        let stored = Message {
            dlc: m.dlc & (reg::DLC_MASK << reg::DLC_SHIFT),
            ..*m
        };
        if self.rx_fifo.push(stored) {
            self.isr |= reg::IXR_RXOK;
        } else {
            self.rx_dropped += 1;
            self.isr |= reg::IXR_RXOFLW;
        }
        self.assert_levels();
    }

    /// The acceptance filters' verdict on `m`.
    pub fn accepts(&self, m: &Message) -> bool {
        if self.afr & AFR_BITS == 0 {
            return true;
        }
        (0..reg::FILTER_COUNT)
            .filter(|n| self.afr & (1 << n) != 0)
            .any(|n| m.id & self.afmr[n] == self.afir[n] & self.afmr[n])
    }

    /// Sets the flags whose condition holds.
    fn assert_levels(&mut self) {
        let mut set = 0;
        if !self.rx_fifo.is_empty() {
            set |= reg::IXR_RXNEMP;
        }
        if self.tx_fifo.is_full() {
            set |= reg::IXR_TXFLL;
        }
        if self.hpb.is_some() {
            set |= reg::IXR_TXBFLL;
        }
        if self.tx_fifo.is_empty() && self.hpb.is_none() {
            set |= reg::IXR_TXFEMP;
        }
        self.isr |= set;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use regmap::bus::{BusError, RegisterBus};

    const B: usize = reg::CAN0_BASE;

    #[test]
    fn configuration_registers_take_writes_only_in_configuration_mode() {
        let mut m = PsCanModel::new(B, 100_000_000);
        assert_eq!(m.read(B + reg::SR), Ok(reg::SR_CONFIG));
        m.write(B + reg::BRPR, 0x1FF).unwrap();
        assert_eq!(m.read(B + reg::BRPR), Ok(0xFF));
        m.write(B + reg::SRR, reg::SRR_CEN).unwrap();
        m.write(B + reg::BRPR, 3).unwrap();
        m.write(B + reg::MSR, reg::MSR_LBACK).unwrap();
        assert_eq!(m.read(B + reg::BRPR), Ok(0xFF));
        assert_eq!(m.read(B + reg::MSR), Ok(0));
        assert_eq!(m.ignored_config_writes, 2);
        // Enabled, normal, error active, bus idle: 0x08 | 0x80 | 0x10.
        assert_eq!(m.read(B + reg::SR), Ok(0x98));
        m.write(B + reg::SRR, reg::SRR_SRST).unwrap();
        assert_eq!(m.read(B + reg::BRPR), Ok(0));
        assert_eq!(m.read(B + reg::SR), Ok(reg::SR_CONFIG));
        assert_eq!(m.read(B + reg::LAST_OFFSET + 4), Err(BusError::SlaveError));
        assert_eq!(m.read(B + 2), Err(BusError::SlaveError));
    }

    fn queue(m: &mut PsCanModel, window: usize, id: u16) {
        for (k, v) in [u32::from(id) << 21, 0, 0, 0].into_iter().enumerate() {
            m.write(B + window + 4 * k, v).unwrap();
        }
    }

    #[test]
    fn the_high_priority_buffer_goes_first_and_holds_one_message() {
        let mut m = PsCanModel::new(B, 100_000_000);
        m.write(B + reg::SRR, reg::SRR_CEN).unwrap();
        queue(&mut m, reg::TXFIFO_ID, 0x001);
        queue(&mut m, reg::TXHPB_ID, 0x7FF);
        assert_eq!(m.pending().map(|p| p.id), Some(0x7FF << 21));
        assert_eq!(
            m.read(B + reg::SR).unwrap() & reg::SR_TXBFLL,
            reg::SR_TXBFLL
        );
        queue(&mut m, reg::TXHPB_ID, 0x7FE);
        assert_eq!(m.dropped_tx_writes, 1);
        assert_eq!(m.tx_len(), 2);
        m.transmitted();
        assert_eq!(m.pending().map(|p| p.id), Some(0x001 << 21));
        // Write-only windows read 0.
        assert_eq!(m.read(B + reg::TXHPB_ID), Ok(0));
    }

    #[test]
    fn reading_an_empty_rx_fifo_sets_underflow_and_a_clear_does_not_hide_a_message() {
        let mut m = PsCanModel::new(B, 100_000_000);
        m.write(B + reg::SRR, reg::SRR_CEN).unwrap();
        assert_eq!(m.read(B + reg::RXFIFO_DATA2), Ok(0));
        assert_eq!(
            m.read(B + reg::ISR).unwrap() & reg::IXR_RXUFLW,
            reg::IXR_RXUFLW
        );
        m.deliver(&Message {
            id: 0x55 << 21,
            dlc: 0xF000_FFFF,
            data1: 1,
            data2: 2,
        });
        m.write(B + reg::ICR, reg::IXR_ALL).unwrap();
        // RXNEMP and TXFEMP: conditions still present.
        assert_eq!(m.read(B + reg::ISR), Ok(reg::IXR_RXNEMP | reg::IXR_TXFEMP));
        // The timestamp bits read 0.
        assert_eq!(m.read(B + reg::RXFIFO_DLC), Ok(0xF000_0000));
        assert_eq!(m.read(B + reg::RXFIFO_DATA2), Ok(2));
        m.write(B + reg::ICR, reg::IXR_RXNEMP).unwrap();
        assert_eq!(m.read(B + reg::ISR), Ok(reg::IXR_TXFEMP));
    }

    #[test]
    fn filter_registers_are_locked_while_their_filter_is_in_use() {
        let mut m = PsCanModel::new(B, 100_000_000);
        m.write(B + 0x64, 0xFFE0_0000).unwrap();
        m.write(B + 0x68, 0x123 << 21).unwrap();
        m.write(B + reg::AFR, 1).unwrap();
        m.write(B + 0x68, 0x456 << 21).unwrap();
        assert_eq!(m.read(B + 0x68), Ok(0x123 << 21));
        assert_eq!(m.ignored_filter_writes, 1);
        let msg = |id: u32| Message {
            id: id << 21,
            ..Message::default()
        };
        assert!(m.accepts(&msg(0x123)));
        assert!(!m.accepts(&msg(0x124)));
    }
}
