//! `vel <rev/s>`: the velocity loop over the torque loop of the mode.
use super::super::drive::{self, DriveOps};
use super::{mpdcc_owns, number, Outcome, ParseError, Spec};
use core::fmt::{self, Write};

/// The `vel` command.
pub const VEL: Spec = Spec {
    name: "vel",
    args: "<rev/s>",
    help: "velocity loop (PI with anti-windup) to <rev/s> behind traj_accel_limit \
           (|x| <= vel_limit; gates on); `torque` returns to the torque loop",
};

/// Parses the arguments of `vel`.
pub fn parse<'a>(args: &[&'a str]) -> Result<f64, ParseError<'a>> {
    match args {
        [v] => number(v).ok_or(ParseError::BadArgs(
            "vel",
            "expected a finite number [rev/s]",
        )),
        _ => Err(ParseError::BadArgs("vel", "expected <rev/s>")),
    }
}

/// Writes the reply of `vel`.
pub fn execute<W: Write>(
    v: f64,
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Outcome, fmt::Error> {
    if mpdcc_owns(drv, out, "vel")? {
        return Ok(Outcome::Final);
    }
    try_drive!(out, "vel", drv.set_velocity(v));
    write!(out, "loop: velocity\r\nvelocity_target: {v:.4} rev/s\r\n")?;
    Ok(Outcome::Ok)
}
