//! `sweep <f_start_hz> <f_stop_hz> <amplitude_nm> [<points>]`: the torque
//! loop's frequency response.
use super::super::drive::{self, DriveOps};
use super::super::{write_err, ErrorCode};
use super::{mpdcc_owns, number, Outcome, ParseError, Spec};
use crate::servo::{bandwidth_hz, SweepPoint};
use core::fmt::{self, Write};

/// The `sweep` command.
pub const SWEEP: Spec = Spec {
    name: "sweep",
    args: "<f_start_hz> <f_stop_hz> <amplitude_nm> [<points>]",
    help: "frequency response of the torque loop: a sine torque reference per frequency \
           (log spaced, default 6 points, 2..=32), gain [dB] and phase [deg] of the \
           captured torque against the captured reference, one `f_hz gain_db phase_deg` \
           line each, then the -3 dB bandwidth [Hz]; gates on, f_stop <= control rate / 4",
};

/// Default number of `sweep` frequencies.
pub const SWEEP_POINTS_DEFAULT: u32 = 6;
/// Most `sweep` frequencies.
pub const SWEEP_POINTS_MAX: u32 = 32;

/// `sweep <f_start_hz> <f_stop_hz> <amplitude_nm> [points]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sweep {
    /// First frequency, Hz.
    pub f_start_hz: f64,
    /// Last frequency, Hz.
    pub f_stop_hz: f64,
    /// Sine amplitude, N m.
    pub amp_nm: f64,
    /// Number of frequencies.
    pub points: u32,
}

/// Parses the arguments of `sweep`.
pub fn parse<'a>(args: &[&'a str]) -> Result<Sweep, ParseError<'a>> {
    let (f0, f1, a, n) = match args {
        [f0, f1, a] => (*f0, *f1, *a, None),
        [f0, f1, a, n] => (*f0, *f1, *a, Some(*n)),
        _ => {
            return Err(ParseError::BadArgs(
                "sweep",
                "expected <f_start_hz> <f_stop_hz> <amplitude_nm> [points]",
            ))
        }
    };
    let (Some(f_start_hz), Some(f_stop_hz)) = (number(f0), number(f1)) else {
        return Err(ParseError::BadArgs(
            "sweep",
            "frequencies must be finite numbers [Hz]",
        ));
    };
    if !(f_start_hz > 0.0 && f_stop_hz > f_start_hz) {
        return Err(ParseError::BadArgs(
            "sweep",
            "need 0 < f_start_hz < f_stop_hz",
        ));
    }
    let amp_nm = number(a).ok_or(ParseError::BadArgs(
        "sweep",
        "amplitude must be a finite number [Nm]",
    ))?;
    let points = match n {
        None => SWEEP_POINTS_DEFAULT,
        Some(n) => match n.parse::<u32>() {
            Ok(n) if (2..=SWEEP_POINTS_MAX).contains(&n) => n,
            _ => {
                return Err(ParseError::BadArgs(
                    "sweep",
                    "points must be a whole number in 2..=32",
                ))
            }
        },
    };
    Ok(Sweep {
        f_start_hz,
        f_stop_hz,
        amp_nm,
        points,
    })
}

/// Writes the reply of `sweep`.
pub fn execute<W: Write>(
    c: Sweep,
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Outcome, fmt::Error> {
    if mpdcc_owns(drv, out, "sweep")? {
        return Ok(Outcome::Final);
    }
    let Sweep {
        f_start_hz,
        f_stop_hz,
        amp_nm,
        points,
    } = c;
    let rate = drv.status().control_rate_hz;
    if f_stop_hz > 0.25 * rate {
        write_err(
            out,
            ErrorCode::BadArgs,
            format_args!(
                "sweep: f_stop {f_stop_hz} Hz is above a quarter of the control rate \
                     ({rate:.0} Hz)"
            ),
        )?;
        return Ok(Outcome::Final);
    }
    let mut pts: heapless::Vec<SweepPoint, { SWEEP_POINTS_MAX as usize }> = heapless::Vec::new();
    let ratio = f_stop_hz / f_start_hz;
    out.write_str("f_hz gain_db phase_deg\r\n")?;
    for k in 0..points {
        let f = f_start_hz * libm::pow(ratio, f64::from(k) / f64::from(points - 1));
        let p = match drv.sweep_point(f, amp_nm) {
            Ok(p) => p,
            Err(e) => {
                drv.sweep_end();
                drive::write_error(out, "sweep", e)?;
                return Ok(Outcome::Final);
            }
        };
        write!(out, "{:.1} {:.2} {:.1}\r\n", p.f_hz, p.gain_db, p.phase_deg)?;
        // Capacity is SWEEP_POINTS_MAX, the parser's bound on `points`.
        let _ = pts.push(p);
    }
    drv.sweep_end();
    match bandwidth_hz(&pts) {
        Some(b) => write!(out, "bandwidth: {b:.0} Hz\r\n")?,
        None => write!(
            out,
            "bandwidth: none (gain above -3 dB up to {f_stop_hz:.0} Hz)\r\n"
        )?,
    }
    Ok(Outcome::Ok)
}
