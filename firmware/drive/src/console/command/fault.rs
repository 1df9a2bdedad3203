//! `fault [clear|history]`: the latched faults and their history.
use super::super::drive::{self, DriveOps};
use super::{Outcome, ParseError, Spec};
use core::fmt::{self, Write};

/// The `fault` command.
pub const FAULT: Spec = Spec {
    name: "fault",
    args: "[clear|history]",
    help: "list the latched faults, clear them (the gates stay off until `enable`), or \
           the last 16 with drive time [s], code and the samples before [A, Nm]",
};

/// `fault`, `fault clear` or `fault history`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FaultCmd {
    /// `fault`.
    Show,
    /// `fault clear`.
    Clear,
    /// `fault history`.
    History,
}

/// Parses the arguments of `fault`.
pub fn parse<'a>(args: &[&'a str]) -> Result<FaultCmd, ParseError<'a>> {
    match args {
        [] => Ok(FaultCmd::Show),
        ["clear"] => Ok(FaultCmd::Clear),
        ["history"] => Ok(FaultCmd::History),
        _ => Err(ParseError::BadArgs(
            "fault",
            "expected `fault`, `fault clear` or `fault history`",
        )),
    }
}

/// Writes the reply of `fault`.
pub fn execute<W: Write>(
    c: FaultCmd,
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Outcome, fmt::Error> {
    match c {
        FaultCmd::Show => {
            let f = try_drive!(out, "fault", drv.faults());
            out.write_str("fault: ")?;
            f.write_names(out)?;
            out.write_str("\r\n")?;
        }
        FaultCmd::Clear => {
            let f = try_drive!(out, "fault", drv.clear_faults());
            out.write_str("fault: ")?;
            f.write_names(out)?;
            out.write_str("\r\ngates: off (safe state)\r\n")?;
        }
        FaultCmd::History => {
            let mut shown = 0;
            let mut total = 0;
            for k in 0..crate::servo::faults::HISTORY_LEN {
                let (r, t) = try_drive!(out, "fault", drv.fault_record(k));
                total = t;
                let Some(r) = r else { break };
                shown += 1;
                write!(out, "#{shown} ")?;
                r.write_summary(out)?;
                out.write_str("\r\n")?;
            }
            write!(out, "history: {shown} shown, {total} since boot\r\n")?;
        }
    }
    Ok(Outcome::Ok)
}
