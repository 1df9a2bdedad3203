//! `debug panic|stall <ms>|bench|fault <f>`: diagnostics.
use super::super::drive::{self, DriveOps};
use super::{Outcome, ParseError, Spec};
use core::fmt::{self, Write};

/// The `debug` command.
pub const DEBUG: Spec = Spec {
    name: "debug",
    args: "panic|stall <ms>|bench|fault <f>",
    help: "diagnostics: `panic` forces a firmware panic (gates off, message, halt); \
           `stall <ms>` stops the control loop and heartbeat for <ms> of PL time (the \
           simulated PL's under QEMU); `bench` counts guest instructions of the control \
           code; `fault <f>` makes a fault happen (<f>: external, adc-stuck or overrun)",
};

/// Longest `debug stall`, ms.
pub const STALL_MAX_MS: u32 = 10_000;

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
        _ => Err(ParseError::BadArgs(
            "debug",
            "expected `debug panic`, `debug stall <ms>`, `debug bench` or `debug fault <f>`",
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
    }
    Ok(Outcome::Ok)
}
