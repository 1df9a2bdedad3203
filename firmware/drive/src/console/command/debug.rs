//! `debug panic|abort|mmu|stall <ms>|bench|fault <f>|flash-pace <ms>`: diagnostics.
use super::super::drive::{self, DriveOps};
use super::{Outcome, ParseError, Spec};
use core::fmt::{self, Write};

/// The `debug` command.
pub const DEBUG: Spec = Spec {
    name: "debug",
    args: "panic|abort|mmu|stall <ms>|bench|fault <f>|fault-time|flash-pace <ms>",
    help: "diagnostics: `panic` forces a firmware panic (gates off, message, halt); \
           `abort` reads an unmapped address (data abort: gates off, DFSR/DFAR, halt); \
           `mmu` reads back SCTLR, the L2 and the translation table's memory types; \
           `stall <ms>` stops the control loop and heartbeat for <ms> of PL time (the \
           simulated PL's under QEMU); `bench` counts guest instructions of the control \
           code; `fault <f>` makes a fault happen (with the gates on, overcurrent and \
           external answer once latched, naming it; <f>: external, adc-stuck, overrun, \
           overcurrent, watchdog, encoder-dead, encoder-loss, phase-open, position-limit, \
           overspeed; \
           adc-swap or adc-invert: current channels a and b swapped, or a inverted, in the \
           simulated PL's ADC path until reboot); `fault-time` gives the PL cycle of the \
           last injected fault's cause and of the gates going off; `flash-pace <ms>` holds each flash \
           erase and program of a `config save` <ms> longer (0 ends it), so that a power \
           cut lands inside the write",
};

/// Longest `debug stall`, ms.
pub const STALL_MAX_MS: u32 = 10_000;

/// Longest `debug flash-pace`, ms.
pub const FLASH_PACE_MAX_MS: u32 = 2_000;

/// A `debug` subcommand.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DebugCmd {
    /// `debug panic`.
    Panic,
    /// `debug abort`.
    Abort,
    /// `debug mmu`.
    Mmu,
    /// `debug fault <f>`.
    Fault(drive::Injection),
    /// `debug fault-time`.
    FaultTime,
    /// `debug stall <ms>`.
    Stall(u32),
    /// `debug bench`.
    Bench,
    /// `debug flash-pace <ms>`.
    FlashPace(u32),
}

/// Parses the arguments of `debug`.
pub fn parse<'a>(args: &[&'a str]) -> Result<DebugCmd, ParseError<'a>> {
    match args {
        ["panic"] => Ok(DebugCmd::Panic),
        ["abort"] => Ok(DebugCmd::Abort),
        ["mmu"] => Ok(DebugCmd::Mmu),
        ["bench"] => Ok(DebugCmd::Bench),
        ["fault-time"] => Ok(DebugCmd::FaultTime),
        ["fault", f] => {
            drive::Injection::from_name(f)
                .map(DebugCmd::Fault)
                .ok_or(ParseError::BadArgs(
                    "debug",
                    "fault takes external, adc-stuck, overrun, overcurrent, watchdog, \
                     encoder-dead, encoder-loss, phase-open, position-limit, overspeed, adc-swap \
                     or adc-invert",
                ))
        }
        ["stall", ms] => match ms.parse::<u32>() {
            Ok(ms) if (1..=STALL_MAX_MS).contains(&ms) => Ok(DebugCmd::Stall(ms)),
            _ => Err(ParseError::BadArgs(
                "debug",
                "stall takes a whole number of ms in 1..=10000",
            )),
        },
        ["flash-pace", ms] => match ms.parse::<u32>() {
            Ok(ms) if ms <= FLASH_PACE_MAX_MS => Ok(DebugCmd::FlashPace(ms)),
            _ => Err(ParseError::BadArgs(
                "debug",
                "flash-pace takes a whole number of ms in 0..=2000",
            )),
        },
        _ => Err(ParseError::BadArgs(
            "debug",
            "expected `debug panic`, `debug abort`, `debug mmu`, `debug stall <ms>`, \
             `debug bench`, `debug fault <f>`, `debug fault-time` or `debug flash-pace <ms>`",
        )),
    }
}

/// Writes the reply of `debug` (`debug panic` asks the caller to panic).
pub fn execute<W: Write>(
    c: DebugCmd,
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Outcome, fmt::Error> {
    match c {
        DebugCmd::Panic => return Ok(Outcome::Panic),
        DebugCmd::Abort => {
            try_drive!(out, "debug", drv.provoke_abort());
        }
        DebugCmd::Mmu => {
            let m = try_drive!(out, "debug", drv.mmu());
            write_mmu(out, &m)?;
        }
        DebugCmd::Fault(f) => {
            let latched = try_drive!(out, "debug", drv.inject(f));
            out.write_str("injected\r\n")?;
            // The command waited for the latch: what `fault` now says.
            if let Some(l) = latched {
                out.write_str("fault: ")?;
                l.write_names(out)?;
                out.write_str("\r\n")?;
            }
        }
        DebugCmd::FaultTime => {
            let (cause, off) = try_drive!(out, "debug", drv.fault_time());
            write!(out, "cause: {cause} cycles\r\n")?;
            match off {
                Some(g) => {
                    write!(out, "gates_off: {g} cycles\r\n")?;
                    // Negative: the gates were off before the cause.
                    let l = i128::from(g) - i128::from(cause);
                    write!(out, "latency: {l} cycles\r\n")?;
                }
                None => out.write_str("gates_off: on\r\n")?,
            }
        }
        DebugCmd::Stall(ms) => {
            try_drive!(out, "debug", drv.stall(ms));
            write!(out, "stalled: {ms} ms\r\n")?;
        }
        DebugCmd::Bench => {
            let b = try_drive!(out, "debug", drv.bench());
            write!(out, "foc_step: {} instructions\r\n", b.foc_step)?;
            write!(out, "mpdtc_period: {} instructions\r\n", b.mpdtc_period)?;
            write!(out, "mpdcc_boundary: {} instructions\r\n", b.mpdcc_boundary)?;
            write!(out, "mpdcc_expm: {} instructions\r\n", b.mpdcc_expm)?;
            write!(out, "log_frame: {} instructions\r\n", b.log_frame)?;
            write!(out, "runs: {}\r\n", b.runs)?;
        }
        DebugCmd::FlashPace(ms) => {
            try_drive!(out, "debug", drv.flash_pace(ms));
            write!(out, "flash_pace: {ms} ms\r\n")?;
        }
    }
    Ok(Outcome::Ok)
}

/// The lines of `debug mmu`.
pub(super) fn write_mmu<W: Write>(out: &mut W, m: &drive::MmuReport) -> fmt::Result {
    use crate::mmu::{self, SCTLR_C, SCTLR_I, SCTLR_M, SCTLR_Z};
    let on = |b: bool| if b { "on" } else { "off" };
    write!(
        out,
        "caches: {}\r\n",
        if m.caches_on() { "on" } else { "off" }
    )?;
    write!(
        out,
        "sctlr: 0x{:08x} (mmu {}, d-cache {}, i-cache {}, branch prediction {})\r\n",
        m.sctlr,
        on(m.sctlr & SCTLR_M != 0),
        on(m.sctlr & SCTLR_C != 0),
        on(m.sctlr & SCTLR_I != 0),
        on(m.sctlr & SCTLR_Z != 0)
    )?;
    let l2 = match (m.l2_id, m.l2_ctrl & 1 != 0) {
        (0, _) => "absent",
        (_, b) => on(b),
    };
    write!(
        out,
        "l2: {l2} (PL310 CACHE_ID 0x{:08x}, CTRL 0x{:08x})\r\n",
        m.l2_id, m.l2_ctrl
    )?;
    write!(out, "ttbr0: 0x{:08x}\r\n", m.ttbr0)?;
    for (&(name, addr), &(entry, par)) in mmu::USED.iter().zip(m.regions.iter()) {
        let kind = mmu::decode(entry).map_or("not a section of this map", |r| r.name());
        write!(
            out,
            "region {name} 0x{addr:08x}: {kind} (entry 0x{entry:08x}, "
        )?;
        if par & 1 != 0 {
            write!(out, "translation faults)\r\n")?;
        } else {
            write!(out, "pa 0x{:08x})\r\n", (par & !0xFFF) | (addr & 0xFFF))?;
        }
    }
    Ok(())
}
