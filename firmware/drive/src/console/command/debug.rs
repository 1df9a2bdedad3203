//! `debug panic|stall <ms>|bench|fault <f>|flash-pace <ms>`: diagnostics.
use super::super::drive::{self, DriveOps};
use super::{Outcome, ParseError, Spec};
use core::fmt::{self, Write};

/// The `debug` command.
pub const DEBUG: Spec = Spec {
    name: "debug",
    args: "panic|stall <ms>|bench|fault <f>|flash-pace <ms>",
    help: "diagnostics: `panic` forces a firmware panic (gates off, message, halt); \
           `stall <ms>` stops the control loop and heartbeat for <ms> of PL time (the \
           simulated PL's under QEMU); `bench` counts guest instructions of the control \
           code; `fault <f>` makes a fault happen (<f>: external, adc-stuck or overrun); \
           `flash-pace <ms>` holds each flash erase and program of a `config save` \
           <ms> longer (0 ends it), so that a power cut lands inside the write",
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
    /// `debug fault <f>`.
    Fault(drive::Injection),
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
        ["bench"] => Ok(DebugCmd::Bench),
        ["fault", f] => {
            drive::Injection::from_name(f)
                .map(DebugCmd::Fault)
                .ok_or(ParseError::BadArgs(
                    "debug",
                    "fault takes external, adc-stuck or overrun",
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
            "expected `debug panic`, `debug stall <ms>`, `debug bench`, `debug fault <f>` or `debug flash-pace <ms>`",
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
        DebugCmd::Fault(f) => {
            try_drive!(out, "debug", drv.inject(f));
            out.write_str("injected\r\n")?;
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
            write!(out, "runs: {}\r\n", b.runs)?;
        }
        DebugCmd::FlashPace(ms) => {
            try_drive!(out, "debug", drv.flash_pace(ms));
            write!(out, "flash_pace: {ms} ms\r\n")?;
        }
    }
    Ok(Outcome::Ok)
}
