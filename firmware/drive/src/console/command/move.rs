//! `move <rev> [<window_ms>]`: a recorded position move and its figures.
use super::super::drive::{self, DriveOps};
use super::{mpdcc_owns, number, Outcome, ParseError, Spec};
use crate::servo::motion::{MoveResult, MOVE_BAND_COUNTS, MOVE_WINDOW_MAX_S};
use core::fmt::{self, Write};

/// The `move` command.
pub const MOVE: Spec = Spec {
    name: "move",
    args: "<rev> [<window_ms>]",
    help: "position move by <rev> from the present position (trajectory as `pos`; the end \
           within pos_min..pos_max, else refused), held for \
           the window [ms] after the trajectory (default 20, at most 500); prints move_time \
           [ms], settling_time [ms] into +-2 counts, overshoot, max_following_error and \
           final_error [counts]",
};

/// Default window after the trajectory, s.
pub const MOVE_WINDOW_DEFAULT_S: f64 = 20e-3;

/// Parses the arguments of `move`: (distance rev, window s).
pub fn parse<'a>(args: &[&'a str]) -> Result<(f64, f64), ParseError<'a>> {
    let (d, w) = match args {
        [d] => (*d, None),
        [d, w] => (*d, Some(*w)),
        _ => return Err(ParseError::BadArgs("move", "expected <rev> [<window_ms>]")),
    };
    let d = number(d).ok_or(ParseError::BadArgs(
        "move",
        "expected a finite distance [rev]",
    ))?;
    let w = match w {
        None => MOVE_WINDOW_DEFAULT_S,
        Some(w) => match number(w) {
            Some(ms) if ms > 0.0 && ms * 1e-3 <= MOVE_WINDOW_MAX_S => ms * 1e-3,
            _ => {
                return Err(ParseError::BadArgs(
                    "move",
                    "window must be a number of ms in (0, 500]",
                ))
            }
        },
    };
    Ok((d, w))
}

/// Writes the reply of `move`.
pub fn execute<W: Write>(
    (d, w): (f64, f64),
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Outcome, fmt::Error> {
    if mpdcc_owns(drv, out, "move")? {
        return Ok(Outcome::Final);
    }
    let r = try_drive!(out, "move", drv.run_move(d, w));
    write_move(out, &r)?;
    Ok(Outcome::Ok)
}

/// The `move` reply lines.
pub fn write_move<W: Write>(out: &mut W, r: &MoveResult) -> fmt::Result {
    write!(out, "move_time: {:.3} ms\r\n", r.move_time_s * 1e3)?;
    match r.settling_s {
        Some(t) => write!(out, "settling_time: {:.3} ms\r\n", t * 1e3)?,
        None => write!(
            out,
            "settling_time: none (not within +-{MOVE_BAND_COUNTS} counts in {:.1} ms)\r\n",
            r.window_s * 1e3
        )?,
    }
    write!(out, "overshoot: {:.0} counts\r\n", r.overshoot_counts)?;
    write!(
        out,
        "max_following_error: {:.1} counts\r\n",
        r.max_following_error_counts
    )?;
    write!(out, "final_error: {:.0} counts\r\n", r.final_error_counts)
}
