//! `pos <rev>|zero`: a trapezoidal trajectory and the position loop.
use super::super::drive::{self, DriveOps};
use super::{mpdcc_owns, number, Outcome, ParseError, Spec};
use core::fmt::{self, Write};

/// The `pos` command.
pub const POS: Spec = Spec {
    name: "pos",
    args: "<rev>|zero",
    help: "position loop: trapezoidal trajectory to <rev> under traj_vel_limit and \
           traj_accel_limit (within pos_min..pos_max; gates on); `zero` makes the present \
           position 0",
};

/// A `pos` command.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PosCmd {
    /// `pos <rev>`.
    To(f64),
    /// `pos zero`.
    Zero,
}

/// Parses the arguments of `pos`.
pub fn parse<'a>(args: &[&'a str]) -> Result<PosCmd, ParseError<'a>> {
    match args {
        ["zero"] => Ok(PosCmd::Zero),
        [v] => number(v).map(PosCmd::To).ok_or(ParseError::BadArgs(
            "pos",
            "expected a finite number [rev] or `zero`",
        )),
        _ => Err(ParseError::BadArgs("pos", "expected <rev> or `zero`")),
    }
}

/// Writes the reply of `pos`.
pub fn execute<W: Write>(
    c: PosCmd,
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Outcome, fmt::Error> {
    match c {
        PosCmd::Zero => {
            try_drive!(out, "pos", drv.zero_position());
            out.write_str("position: 0.000000 rev\r\n")?;
        }
        PosCmd::To(p) => {
            if mpdcc_owns(drv, out, "pos")? {
                return Ok(Outcome::Final);
            }
            try_drive!(out, "pos", drv.set_position(p));
            write!(out, "loop: position\r\nposition_target: {p:.6} rev\r\n")?;
        }
    }
    Ok(Outcome::Ok)
}
