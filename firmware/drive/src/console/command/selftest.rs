//! `selftest sensors`: the sensor check on request, with what it measured.
use super::super::drive::{self, DriveOps};
use super::{Outcome, ParseError, Spec};
use crate::servo::sensors::SensorReport;
use crate::servo::ServoError;
use core::fmt::{self, Write};

/// The `selftest` command.
pub const SELFTEST: Spec = Spec {
    name: "selftest",
    args: "sensors",
    help: "sensor check (gates off, no fault): low-duty voltage vectors along phases a, b, c, \
           current limited; prints each channel's current [A], the encoder's movement \
           [counts] and the PL time [ms]; `enable` runs it by itself the first time",
};

/// Parses the arguments of `selftest`.
pub fn parse<'a>(args: &[&'a str]) -> Result<(), ParseError<'a>> {
    match args {
        ["sensors"] => Ok(()),
        _ => Err(ParseError::BadArgs(
            "selftest",
            "expected `selftest sensors`",
        )),
    }
}

/// Writes the reply of `selftest sensors`: the report, then `OK` on a pass
/// or `ERR sensor-check` on a failure.
pub fn execute<W: Write>(drv: &mut dyn DriveOps, out: &mut W) -> Result<Outcome, fmt::Error> {
    if super::mpdcc_owns(drv, out, "selftest")? {
        return Ok(Outcome::Final);
    }
    let r = try_drive!(out, "selftest", drv.sensor_check());
    write_report(out, &r)?;
    match r.result {
        Ok(()) => Ok(Outcome::Ok),
        Err(e) => {
            drive::write_error(out, "selftest", ServoError::SensorCheck(e).into())?;
            Ok(Outcome::Final)
        }
    }
}

/// The measurement lines.
pub fn write_report<W: Write>(out: &mut W, r: &SensorReport) -> fmt::Result {
    for (k, (i, cyc)) in r.readings_a.iter().zip(r.vector_cycles).enumerate() {
        write!(
            out,
            "vector {}: i_a {:.3} A, i_b {:.3} A, i_c {:.3} A after {:.3} ms\r\n",
            ['a', 'b', 'c'][k],
            i[0],
            i[1],
            i[2],
            cyc as f64 * 1e3 / f64::from(regmap::PL_CLOCK_HZ)
        )?;
    }
    write!(out, "target: {:.3} A\r\n", r.target_a)?;
    let judged = if r.encoder_judged() {
        "direction checked"
    } else {
        "rotor did not turn: direction not checked"
    };
    write!(out, "encoder: {} counts ({judged})\r\n", r.enc_counts)?;
    write!(
        out,
        "duration: {:.3} ms (PL time)\r\n",
        r.cycles as f64 * 1e3 / f64::from(regmap::PL_CLOCK_HZ)
    )?;
    match &r.result {
        Ok(()) => out.write_str("sensor_check: pass\r\n"),
        Err(e) => write!(out, "sensor_check: fail: {e}\r\n"),
    }
}
