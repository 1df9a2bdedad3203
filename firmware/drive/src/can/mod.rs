//! The Zynq-7000 PS CAN controller (CAN0 at `regmap::ps_can::CAN0_BASE`),
//! the link the CANopen slave (`canopen`) runs over. Generic over
//! [`RegisterBus`], like the PL drivers: MMIO on a board, the register model
//! `simpl::ps_can` in host tests.
//!
//! Modules, one job each:
//! - [`timing`]: prescaler and segments from the reference clock and the bit
//!   rate.
//! - [`wire`]: a frame as the controller's message words; an acceptance
//!   filter as its mask and identifier words.
//!
//! The driver polls: it enables no interrupt. [`PsCan::configure`] checks
//! every setting before it touches a register (a refused configuration
//! leaves the controller as it was), then resets the controller and
//! programs it in configuration mode (`BRPR`, `BTR` and `MSR` are writable
//! only there). [`PsCan::send`] refuses a frame when `SR.TXFLL` says the
//! TX FIFO is full, so no frame is dropped without an error.
//! [`PsCan::poll_events`] reads and clears the sticky flags of `ISR`
//! (receive overflow, bus off, errors) and counts them.
//!
//! Bus off: the controller returns to error active by itself after 128
//! occurrences of 11 consecutive recessive bits (ISO 11898-1 fault
//! confinement); [`PsCan::recover`] does not wait for that: it resets the
//! controller (`SRR.SRST` clears both error counters) and programs it again
//! with the last configuration.

pub mod timing;
pub mod wire;

use canopen::CanFrame;
use regmap::bus::{BusError, RegisterBus};
use regmap::ps_can as reg;
use timing::{bit_timing, BitTimingError};
use wire::{decode, encode, AcceptanceFilter, MessageWords};

/// Reads of `SR` a mode change may take before the driver gives up. The
/// controller changes mode within a few reference-clock cycles after the
/// write; the bound only keeps a dead bus from hanging the caller.
const MODE_POLLS: u32 = 1000;

/// What the controller does on the bus.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mode {
    /// Transmits, receives and acknowledges.
    Normal,
    /// Internal loopback: transmitted frames are received back by this
    /// controller and not driven onto the bus.
    Loopback,
    /// Receives only: no acknowledge, no error frames, no transmission.
    Snoop,
}

impl Mode {
    /// The `MSR` value.
    fn msr(self) -> u32 {
        match self {
            Mode::Normal => 0,
            Mode::Loopback => reg::MSR_LBACK,
            Mode::Snoop => reg::MSR_SNOOP,
        }
    }

    /// The `SR` bit that confirms the mode.
    fn status_bit(self) -> u32 {
        match self {
            Mode::Normal => reg::SR_NORMAL,
            Mode::Loopback => reg::SR_LBACK,
            Mode::Snoop => reg::SR_SNOOP,
        }
    }
}

/// A configuration of the controller.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CanConfig<'a> {
    /// The controller's reference clock (`CAN_REF_CLK`), Hz.
    pub ref_clock_hz: u32,
    /// Bit rate, bit/s.
    pub bit_rate_bps: u32,
    /// Bus mode.
    pub mode: Mode,
    /// Acceptance filters, at most [`reg::FILTER_COUNT`]; a frame passes
    /// when any of them passes it. None: every frame is received.
    pub filters: &'a [AcceptanceFilter],
}

/// Why an operation failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CanError {
    /// The register access failed.
    Bus(BusError),
    /// No bit timing gives the bit rate from the reference clock.
    BitTiming(BitTimingError),
    /// More than [`reg::FILTER_COUNT`] acceptance filters.
    TooManyFilters,
    /// A filter's identifier or mask has bits above the 11.
    FilterOutOfRange,
    /// The controller has not been configured.
    NotConfigured,
    /// `SR` did not report the requested mode within the poll bound.
    ModeNotReached,
    /// The acceptance filter registers stayed busy (`SR.ACFBSY`).
    FilterBusy,
    /// The TX FIFO is full; the frame was not queued.
    TxFifoFull,
}

impl From<BusError> for CanError {
    fn from(e: BusError) -> Self {
        CanError::Bus(e)
    }
}

/// Fault confinement state (`SR.ESTAT`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorState {
    /// Configuration mode: not on the bus.
    Configuration,
    /// Both counters below 128.
    Active,
    /// A counter at 128 or more: passive error flags only.
    Passive,
    /// Transmit counter above 255: off the bus until recovery.
    BusOff,
}

/// The error counters and the state.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ErrorStatus {
    /// Transmit error counter (`ECR.TEC`).
    pub tec: u8,
    /// Receive error counter (`ECR.REC`).
    pub rec: u8,
    /// `SR.ESTAT`.
    pub state: ErrorState,
}

/// Counts since the driver was made, kept across reconfiguration.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct CanStats {
    /// Times `ISR.RXOFLW` was found set (each one or more frames the RX
    /// FIFO dropped).
    pub rx_overflows: u32,
    /// Times `ISR.BSOFF` was found set.
    pub bus_off_entries: u32,
    /// Times `ISR.ERROR` was found set.
    pub error_flags: u32,
    /// Received extended or remote frames, read out and dropped.
    pub rx_unsupported: u32,
    /// Requested recoveries ([`PsCan::recover`]).
    pub recoveries: u32,
}

/// What [`PsCan::poll_events`] found and cleared.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Events {
    /// `ISR.RXOFLW`: the RX FIFO dropped a frame.
    pub rx_overflow: bool,
    /// `ISR.BSOFF`: the controller went bus off.
    pub bus_off: bool,
    /// `ESR` (CRC, form, stuff, bit, acknowledge error bits) when
    /// `ISR.ERROR` was set, else 0.
    pub errors: u32,
}

/// The register values of a checked configuration.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Settings {
    brpr: u32,
    btr: u32,
    mode: Mode,
    afr: u32,
    /// `(AFMR, AFIR)` of each filter in use, in `AFR` bit order.
    filters: [(u32, u32); reg::FILTER_COUNT],
}

impl Settings {
    fn check(cfg: &CanConfig) -> Result<Self, CanError> {
        let t = bit_timing(cfg.ref_clock_hz, cfg.bit_rate_bps).map_err(CanError::BitTiming)?;
        if cfg.filters.len() > reg::FILTER_COUNT {
            return Err(CanError::TooManyFilters);
        }
        let mut filters = [(0, 0); reg::FILTER_COUNT];
        let mut afr = 0;
        for (i, (f, slot)) in cfg.filters.iter().zip(filters.iter_mut()).enumerate() {
            *slot = f.words().ok_or(CanError::FilterOutOfRange)?;
            afr |= 1 << i;
        }
        Ok(Self {
            brpr: t.brpr(),
            btr: t.btr(),
            mode: cfg.mode,
            afr,
            filters,
        })
    }
}

/// The PS CAN controller at `base`.
pub struct PsCan<B> {
    bus: B,
    base: usize,
    settings: Option<Settings>,
    stats: CanStats,
}

impl<B: RegisterBus> PsCan<B> {
    /// A driver for the controller at `base` (e.g. [`reg::CAN0_BASE`]);
    /// touches nothing until [`PsCan::configure`].
    pub fn new(bus: B, base: usize) -> Self {
        Self {
            bus,
            base,
            settings: None,
            stats: CanStats::default(),
        }
    }

    /// The register bus (for the caller's own accesses, and for tests).
    pub fn bus_mut(&mut self) -> &mut B {
        &mut self.bus
    }

    /// The counts so far.
    pub fn stats(&self) -> CanStats {
        self.stats
    }

    /// Resets the controller and programs `cfg`, then enables it in
    /// `cfg.mode`. Every value is checked first; a refused configuration
    /// writes nothing.
    pub fn configure(&mut self, cfg: &CanConfig) -> Result<(), CanError> {
        let s = Settings::check(cfg)?;
        self.settings = Some(s);
        self.apply(&s)
    }

    /// Leaves bus off (or any state) now: resets the controller, which
    /// clears both error counters, and programs the last configuration
    /// again. Frames queued for transmission are lost with the reset.
    pub fn recover(&mut self) -> Result<(), CanError> {
        let s = self.settings.ok_or(CanError::NotConfigured)?;
        self.stats.recoveries += 1;
        self.apply(&s)
    }

    /// Queues `f` in the TX FIFO; [`CanError::TxFifoFull`] when it has no
    /// room (nothing is written then).
    pub fn send(&mut self, f: &CanFrame) -> Result<(), CanError> {
        if self.settings.is_none() {
            return Err(CanError::NotConfigured);
        }
        if self.read(reg::SR)? & reg::SR_TXFLL != 0 {
            return Err(CanError::TxFifoFull);
        }
        let w = encode(f);
        // DATA2 last: its write queues the message.
        self.write(reg::TXFIFO_ID, w.id)?;
        self.write(reg::TXFIFO_DLC, w.dlc)?;
        self.write(reg::TXFIFO_DATA1, w.data1)?;
        self.write(reg::TXFIFO_DATA2, w.data2)?;
        Ok(())
    }

    /// The oldest received standard data frame, or `None` when the RX FIFO
    /// is empty. Extended and remote frames (only possible without
    /// filters) are read out, counted in [`CanStats::rx_unsupported`] and
    /// skipped.
    pub fn receive(&mut self) -> Result<Option<CanFrame>, CanError> {
        // At most the FIFO's content: a bus that always reports "not
        // empty" cannot keep the caller here.
        for _ in 0..=reg::RX_FIFO_DEPTH {
            if self.read(reg::ISR)? & reg::IXR_RXNEMP == 0 {
                return Ok(None);
            }
            let addrs = [
                self.base + reg::RXFIFO_ID,
                self.base + reg::RXFIFO_DLC,
                self.base + reg::RXFIFO_DATA1,
                // Read last: this read removes the message.
                self.base + reg::RXFIFO_DATA2,
            ];
            let mut v = [0u32; 4];
            self.bus.read_many(&addrs, &mut v)?;
            // The flag stays set while messages remain (a set condition
            // wins over the clear).
            self.write(reg::ICR, reg::IXR_RXNEMP)?;
            let w = MessageWords {
                id: v[0],
                dlc: v[1],
                data1: v[2],
                data2: v[3],
            };
            match decode(&w) {
                Some(f) => return Ok(Some(f)),
                None => self.stats.rx_unsupported += 1,
            }
        }
        Ok(None)
    }

    /// Reads `ISR`'s receive-overflow, bus-off and error flags, counts and
    /// clears the ones set (with `ESR` for an error).
    pub fn poll_events(&mut self) -> Result<Events, CanError> {
        let isr = self.read(reg::ISR)?;
        let mut ev = Events {
            rx_overflow: isr & reg::IXR_RXOFLW != 0,
            bus_off: isr & reg::IXR_BSOFF != 0,
            errors: 0,
        };
        if isr & reg::IXR_ERROR != 0 {
            ev.errors = self.read(reg::ESR)?;
            self.write(reg::ESR, ev.errors)?;
            self.stats.error_flags += 1;
        }
        self.stats.rx_overflows += u32::from(ev.rx_overflow);
        self.stats.bus_off_entries += u32::from(ev.bus_off);
        let clear = isr & (reg::IXR_RXOFLW | reg::IXR_BSOFF | reg::IXR_ERROR);
        if clear != 0 {
            self.write(reg::ICR, clear)?;
        }
        Ok(ev)
    }

    /// The error counters and the fault confinement state.
    pub fn error_status(&mut self) -> Result<ErrorStatus, CanError> {
        let ecr = self.read(reg::ECR)?;
        let sr = self.read(reg::SR)?;
        let state = match (sr >> reg::SR_ESTAT_SHIFT) & reg::SR_ESTAT_MASK {
            reg::ESTAT_ACTIVE => ErrorState::Active,
            reg::ESTAT_PASSIVE => ErrorState::Passive,
            reg::ESTAT_BUS_OFF => ErrorState::BusOff,
            _ => ErrorState::Configuration,
        };
        Ok(ErrorStatus {
            tec: ((ecr >> reg::ECR_TEC_SHIFT) & reg::ECR_COUNT_MASK) as u8,
            rec: ((ecr >> reg::ECR_REC_SHIFT) & reg::ECR_COUNT_MASK) as u8,
            state,
        })
    }

    fn apply(&mut self, s: &Settings) -> Result<(), CanError> {
        self.write(reg::SRR, reg::SRR_SRST)?;
        self.wait_status(reg::SR_CONFIG, reg::SR_CONFIG, CanError::ModeNotReached)?;
        self.write(reg::BRPR, s.brpr)?;
        self.write(reg::BTR, s.btr)?;
        self.write(reg::MSR, s.mode.msr())?;
        // Mask and identifier registers are writable only while their
        // filter is off and the filter logic is not busy.
        self.write(reg::AFR, 0)?;
        self.wait_status(reg::SR_ACFBSY, 0, CanError::FilterBusy)?;
        for (n, (afmr, afir)) in s.filters.iter().enumerate() {
            if s.afr & (1 << n) == 0 {
                continue;
            }
            if let (Some(m), Some(i)) = (reg::afmr(n), reg::afir(n)) {
                self.write(m, *afmr)?;
                self.write(i, *afir)?;
            }
        }
        self.write(reg::AFR, s.afr)?;
        self.write(reg::IER, 0)?;
        self.write(reg::SRR, reg::SRR_CEN)?;
        let bit = s.mode.status_bit();
        self.wait_status(bit, bit, CanError::ModeNotReached)
    }

    /// Polls `SR` until `SR & mask == want`, at most [`MODE_POLLS`] reads.
    fn wait_status(&mut self, mask: u32, want: u32, err: CanError) -> Result<(), CanError> {
        for _ in 0..MODE_POLLS {
            if self.read(reg::SR)? & mask == want {
                return Ok(());
            }
        }
        Err(err)
    }

    fn read(&mut self, offset: usize) -> Result<u32, BusError> {
        self.bus.read(self.base + offset)
    }

    fn write(&mut self, offset: usize, v: u32) -> Result<(), BusError> {
        self.bus.write(self.base + offset, v)
    }
}
