//! `capture arm|trigger|status|dump`: the PL capture buffer.
use super::super::drive::{self, DriveOps};
use super::super::{write_err, ErrorCode};
use super::{number, Outcome, ParseError, Spec};
use crate::pl::capture::{self as pl_capture, CapState, Channel, Trigger};
use core::fmt::{self, Write};

/// The `capture` command.
pub const CAPTURE: Spec = Spec {
    name: "capture",
    args: "arm <trigger> [<pre_samples> [<every>]]|trigger|status|dump",
    help: "PL capture buffer at the control rate (1024 samples: i_d, i_q [A], torque, \
           torque_ref [Nm], switching state, ADC_IA, position [counts], velocity [rev/s], \
           following error [counts]): `arm` with trigger manual, step (reference step >= \
           0.05 Nm), fault, or <channel>>x / <channel><x (channel i_d, i_q [A], torque, \
           torque_ref [Nm]), pre-trigger samples (default 64, at most 1023) and one sample \
           every <every> control periods (1..=256, default 1; at most 256 ADC results); a \
           `move` triggers an armed record at its start; `trigger` triggers by hand; \
           `status`; `dump` prints the record as CSV",
};

/// Default pre-trigger length of `capture arm`, samples.
pub const CAPTURE_PRE_DEFAULT: u32 = 64;
/// Largest `every` of `capture arm` (`CAP_DECIM` + 1 is at most 256).
pub const CAPTURE_EVERY_MAX: u32 = 256;
/// Reference step that triggers `capture arm step`, N m.
pub const CAPTURE_STEP_NM: f64 = 0.05;

/// A `capture` subcommand.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CaptureCmd {
    /// `capture arm <trigger> [pre [every]]`.
    Arm(Trigger, u32, u32),
    /// `capture trigger`.
    Trigger,
    /// `capture status`.
    Status,
    /// `capture dump`.
    Dump,
}

/// `capture arm`'s trigger word.
fn capture_trigger(w: &str) -> Option<Trigger> {
    match w {
        "manual" => return Some(Trigger::Manual),
        "step" => return Some(Trigger::RefStep(CAPTURE_STEP_NM)),
        "fault" => return Some(Trigger::Fault),
        _ => {}
    }
    let (i, falling) = match (w.find('>'), w.find('<')) {
        (Some(i), None) => (i, false),
        (None, Some(i)) => (i, true),
        _ => return None,
    };
    let channel = Channel::from_name(&w[..i])?;
    let level = number(&w[i + 1..])?;
    Some(Trigger::Threshold {
        channel,
        level,
        falling,
    })
}

/// Parses the arguments of `capture`.
pub fn parse<'a>(args: &[&'a str]) -> Result<CaptureCmd, ParseError<'a>> {
    const USAGE: &str = "expected `capture arm <trigger> [pre_samples]`, `capture trigger`, \
                         `capture status` or `capture dump`";
    match args {
        ["trigger"] => Ok(CaptureCmd::Trigger),
        ["status"] => Ok(CaptureCmd::Status),
        ["dump"] => Ok(CaptureCmd::Dump),
        ["arm", t, rest @ ..] if rest.len() <= 2 => {
            let t = capture_trigger(t).ok_or(ParseError::BadArgs(
                "capture",
                "trigger must be manual, step, fault or <channel>>x / <channel><x with channel \
                 i_d, i_q, torque or torque_ref and a finite level",
            ))?;
            let pre = match rest.first() {
                None => CAPTURE_PRE_DEFAULT,
                Some(p) => match p.parse::<u32>() {
                    Ok(p) if p < pl_capture::DEPTH => p,
                    _ => {
                        return Err(ParseError::BadArgs(
                            "capture",
                            "pre_samples must be a whole number in 0..=1023",
                        ))
                    }
                },
            };
            let every = match rest.get(1) {
                None => 1,
                Some(e) => match e.parse::<u32>() {
                    Ok(e @ 1..=CAPTURE_EVERY_MAX) => e,
                    _ => {
                        return Err(ParseError::BadArgs(
                            "capture",
                            "every must be a whole number of control periods in 1..=256",
                        ))
                    }
                },
            };
            Ok(CaptureCmd::Arm(t, pre, every))
        }
        _ => Err(ParseError::BadArgs("capture", USAGE)),
    }
}

/// Writes the reply of `capture`.
pub fn execute<W: Write>(
    c: CaptureCmd,
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Outcome, fmt::Error> {
    match c {
        CaptureCmd::Arm(t, pre, every) => {
            try_drive!(out, "capture", drv.capture_arm(t, pre, every));
            write!(out, "capture: armed, pre {pre} samples\r\n")?;
            write!(
                out,
                "sample_period: {:.3} us\r\n",
                drv.capture_period_s() * 1e6
            )?;
        }
        CaptureCmd::Trigger => {
            try_drive!(out, "capture", drv.capture_trigger());
            out.write_str("capture: triggered by hand\r\n")?;
        }
        CaptureCmd::Status => {
            let st = try_drive!(out, "capture", drv.capture_status());
            write!(out, "capture: {}\r\n", st.state.name())?;
            write!(out, "samples: {}\r\n", st.count)?;
            write!(out, "trigger_index: {}\r\n", st.trig_index)?;
            write!(
                out,
                "sample_period: {:.3} us\r\n",
                drv.capture_period_s() * 1e6
            )?;
        }
        CaptureCmd::Dump => {
            let st = try_drive!(out, "capture", drv.capture_status());
            if st.state != CapState::Done {
                write_err(
                    out,
                    ErrorCode::BadArgs,
                    format_args!(
                        "capture: no complete record (state {}; `capture arm` first)",
                        st.state.name()
                    ),
                )?;
                return Ok(Outcome::Final);
            }
            let ts = drv.capture_period_s();
            out.write_str(
                "t_ms,i_d_A,i_q_A,torque_Nm,torque_ref_Nm,sw_state,adc_ia_raw,position_counts,\
                 velocity_rev_s,following_error_counts\r\n",
            )?;
            for i in 0..st.count {
                let x = try_drive!(out, "capture", drv.capture_sample(i));
                let t = (f64::from(i) - f64::from(st.trig_index)) * ts * 1e3;
                write!(
                    out,
                    "{t:.4},{:.3},{:.3},{:.4},{:.4},{},{},{},{:.5},{:.4}\r\n",
                    x.i_d_a,
                    x.i_q_a,
                    x.torque_nm,
                    x.torque_ref_nm,
                    x.sw,
                    x.sel as i16,
                    x.position_counts,
                    x.velocity_rev_s,
                    x.following_error_counts
                )?;
            }
        }
    }
    Ok(Outcome::Ok)
}
