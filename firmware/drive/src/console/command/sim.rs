//! `sim list|set|reset`: the simulated motor's own true parameters (only
//! with the simulated PL or the co-simulation; elsewhere `ERR unsupported`).
use super::super::drive::{self, DriveOps};
use super::super::{write_err, ErrorCode};
use super::{clip, number, Outcome, ParseError, Spec};
use core::fmt::{self, Write};
use models::pmsm::sim_motor::{SimSetError, SIM_PARAMS};

/// The `sim` command.
pub const SIM: Spec = Spec {
    name: "sim",
    args: "list|set <name> <value>|reset",
    help: "the simulated motor's own parameters (not the controllers' `config`): `list` \
           every one with unit and range, `set` one (checked), `reset` to the defaults \
           (the paper's motor, rotor held)",
};

/// A `sim` subcommand.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SimCmd<'a> {
    /// `sim list`.
    List,
    /// `sim set <name> <value>`.
    Set(&'a str, f64),
    /// `sim reset`.
    Reset,
}

/// Parses the arguments of `sim`.
pub fn parse<'a>(args: &[&'a str]) -> Result<SimCmd<'a>, ParseError<'a>> {
    match args {
        ["list"] => Ok(SimCmd::List),
        ["reset"] => Ok(SimCmd::Reset),
        ["set", n, v] => number(v)
            .map(|v| SimCmd::Set(n, v))
            .ok_or(ParseError::BadArgs("sim", "set: expected a finite number")),
        _ => Err(ParseError::BadArgs(
            "sim",
            "expected `sim list|set <name> <value>|reset`",
        )),
    }
}

/// Writes the reply of `sim`.
pub fn execute<W: Write>(
    c: SimCmd<'_>,
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Outcome, fmt::Error> {
    match c {
        SimCmd::List => {
            let m = try_drive!(out, "sim", drv.sim_motor());
            for (i, p) in SIM_PARAMS.iter().enumerate() {
                write!(
                    out,
                    "{} = {} {}  [{}..{}]  {}\r\n",
                    p.name,
                    m.get(i),
                    p.unit,
                    p.min,
                    p.max,
                    p.description
                )?;
            }
        }
        SimCmd::Set(name, v) => match try_drive!(out, "sim", drv.sim_set(name, v)) {
            Ok(()) => {
                let m = try_drive!(out, "sim", drv.sim_motor());
                if let Some(i) = SIM_PARAMS.iter().position(|p| p.name == name) {
                    let p = &SIM_PARAMS[i];
                    write!(out, "{} = {} {}\r\n", p.name, m.get(i), p.unit)?;
                }
            }
            Err(e) => {
                let (w, more) = clip(name);
                match e {
                    SimSetError::Unknown => write_err(
                        out,
                        ErrorCode::BadArgs,
                        format_args!("sim: {w}{more}: no such parameter (see `sim list`)"),
                    )?,
                    SimSetError::Bad(e) => write_err(
                        out,
                        ErrorCode::BadArgs,
                        format_args!("sim: {w}{more}: {}, nothing changed", e.reason),
                    )?,
                }
                return Ok(Outcome::Final);
            }
        },
        SimCmd::Reset => {
            try_drive!(out, "sim", drv.sim_reset());
            out.write_str("sim: defaults (the paper's motor, rotor held)\r\n")?;
        }
    }
    Ok(Outcome::Ok)
}
