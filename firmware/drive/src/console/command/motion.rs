//! `mode`, `enable`, `disable`, `torque`, `step`: the drive's control mode,
//! its gates and its torque reference.
use super::super::drive::{self, DriveOps};
use super::{mpdcc_owns, no_args, number, Outcome, ParseError, Spec};
use crate::pl::top::Mode;
use crate::servo::StepResult;
use core::fmt::{self, Write};

/// The `mode` command.
pub const MODE: Spec = Spec {
    name: "mode",
    args: "[off|foc|mpdtc|mpdcc]",
    help: "print or set the control mode; any change turns the gates off; `mpdcc` runs \
           paper 001's hardware-in-the-loop arrangement continuously (the IM + 5L-ANPC \
           plant on the PS feeds the PL's MPDCC core one decision per control period; \
           progress in `status`), the PMSM gates stay off",
};

/// The `enable` command.
pub const ENABLE: Spec = Spec {
    name: "enable",
    args: "",
    help: "gates on (refused in mode off or with a fault latched)",
};

/// The `disable` command.
pub const DISABLE: Spec = Spec {
    name: "disable",
    args: "",
    help: "gates off",
};

/// The `torque` command.
pub const TORQUE: Spec = Spec {
    name: "torque",
    args: "[<Nm>]",
    help: "print or set the torque reference [Nm] (|x| <= the limit, 1.0 Nm)",
};

/// The `step` command.
pub const STEP: Spec = Spec {
    name: "step",
    args: "<Nm> [<window_ms>]",
    help: "torque step from the reference to <Nm>, torque sampled at the control rate for \
           the window [ms] (default 2, at most 20); prints settling [ms], overshoot [%], \
           switching [kHz], final [Nm]",
};

/// What `mode` selects: a PL mode of the PMSM drive, or paper 001's HIL
/// loop (the PL in mode off, the MPDCC page driven from the PS).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ModeSel {
    /// `off`, `foc`, `mpdtc`.
    Pl(Mode),
    /// `mpdcc`.
    Mpdcc,
}

impl ModeSel {
    /// Parses a console name.
    pub fn from_name(s: &str) -> Option<Self> {
        match s {
            "mpdcc" => Some(ModeSel::Mpdcc),
            _ => Mode::from_name(s).map(ModeSel::Pl),
        }
    }
}

/// Default `step` window, s.
pub const STEP_WINDOW_DEFAULT_S: f64 = 2e-3;
/// Longest `step` window, s (the recorder holds 1280 samples: 20 ms at 64 kHz).
pub const STEP_WINDOW_MAX_S: f64 = 20e-3;

/// `mode`, `enable`, `disable`, `torque` or `step`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MotionCmd {
    /// `mode [m]`.
    Mode(Option<ModeSel>),
    /// `enable`.
    Enable,
    /// `disable`.
    Disable,
    /// `torque [Nm]` (the number is checked against the limit by the drive).
    Torque(Option<f64>),
    /// `step <Nm> [<window_ms>]`, window in seconds.
    Step(f64, f64),
}

/// Parses `mode`, `enable`, `disable`, `torque` or `step` (`name`).
pub fn parse<'a>(name: &'static str, args: &[&'a str]) -> Result<MotionCmd, ParseError<'a>> {
    match name {
        "mode" => match args {
            [] => Ok(MotionCmd::Mode(None)),
            [m] => ModeSel::from_name(m)
                .map(|m| MotionCmd::Mode(Some(m)))
                .ok_or(ParseError::BadArgs(
                    "mode",
                    "expected off, foc, mpdtc or mpdcc",
                )),
            _ => Err(ParseError::BadArgs("mode", "takes at most one argument")),
        },
        "enable" => no_args(args, MotionCmd::Enable, "enable"),
        "disable" => no_args(args, MotionCmd::Disable, "disable"),
        "torque" => match args {
            [] => Ok(MotionCmd::Torque(None)),
            [x] => number(x)
                .map(|x| MotionCmd::Torque(Some(x)))
                .ok_or(ParseError::BadArgs(
                    "torque",
                    "expected a finite number [Nm]",
                )),
            _ => Err(ParseError::BadArgs("torque", "takes at most one argument")),
        },
        "step" => {
            let (nm, w) = match args {
                [nm] => (*nm, None),
                [nm, w] => (*nm, Some(*w)),
                _ => return Err(ParseError::BadArgs("step", "expected <Nm> [<window_ms>]")),
            };
            let nm =
                number(nm).ok_or(ParseError::BadArgs("step", "expected a finite torque [Nm]"))?;
            let w = match w {
                None => STEP_WINDOW_DEFAULT_S,
                Some(w) => match number(w) {
                    Some(ms) if ms > 0.0 && ms * 1e-3 <= STEP_WINDOW_MAX_S => ms * 1e-3,
                    _ => {
                        return Err(ParseError::BadArgs(
                            "step",
                            "window must be a number of ms in (0, 20]",
                        ))
                    }
                },
            };
            Ok(MotionCmd::Step(nm, w))
        }
        _ => Err(ParseError::Unknown(name)),
    }
}

/// Writes the reply of a motion command.
pub fn execute<W: Write>(
    c: MotionCmd,
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Outcome, fmt::Error> {
    let name = match c {
        MotionCmd::Enable => "enable",
        MotionCmd::Step(..) => "step",
        _ => "",
    };
    if !name.is_empty() && mpdcc_owns(drv, out, name)? {
        return Ok(Outcome::Final);
    }
    match c {
        MotionCmd::Mode(None) => match drv.mpdcc_live() {
            Some(_) => out.write_str("mode: mpdcc\r\n")?,
            None => write!(out, "mode: {}\r\n", drv.mode().name())?,
        },
        MotionCmd::Mode(Some(ModeSel::Pl(m))) => {
            try_drive!(out, "mode", drv.set_mode(m));
            write!(out, "mode: {}\r\ngates: off (safe state)\r\n", m.name())?;
        }
        MotionCmd::Mode(Some(ModeSel::Mpdcc)) => {
            try_drive!(out, "mode", drv.set_mpdcc_mode());
            out.write_str(
                "mode: mpdcc\r\ngates: off (safe state)\r\nmpdcc_loop: started, one decision \
                 per control period (IM + 5L-ANPC plant on the PS, core on the PL; `status`)\r\n",
            )?;
        }
        MotionCmd::Enable => {
            try_drive!(out, "enable", drv.enable());
            out.write_str("gates: on\r\n")?;
        }
        MotionCmd::Disable => {
            try_drive!(out, "disable", drv.disable());
            out.write_str("gates: off (safe state)\r\n")?;
        }
        MotionCmd::Torque(None) => write!(out, "torque_ref: {:.4} Nm\r\n", drv.torque_ref())?,
        MotionCmd::Torque(Some(x)) => {
            try_drive!(out, "torque", drv.set_torque_ref(x));
            write!(out, "torque_ref: {:.4} Nm\r\n", drv.torque_ref())?;
        }
        MotionCmd::Step(nm, w) => {
            let r = try_drive!(out, "step", drv.step(nm, w));
            write_step(out, &r)?;
        }
    }
    Ok(Outcome::Ok)
}

/// The `step` reply lines.
pub fn write_step<W: Write>(out: &mut W, r: &StepResult) -> fmt::Result {
    match r.settling_s {
        Some(t) => write!(out, "settling_time: {:.4} ms\r\n", t * 1e3)?,
        None => write!(
            out,
            "settling_time: none (not settled within {:.2} ms)\r\n",
            r.window_s * 1e3
        )?,
    }
    write!(out, "overshoot: {:.1} %\r\n", r.overshoot_percent)?;
    write!(
        out,
        "switching: {:.1} kHz\r\n",
        r.switching_per_leg_per_s * 1e-3
    )?;
    write!(out, "final: {:.4} Nm\r\n", r.final_nm)
}
