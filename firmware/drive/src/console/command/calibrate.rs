//! `calibrate [all|encoder|resistance|inductance|flux|mechanics]`: measures
//! the motor ([`models::calibration`]) and writes the results into the
//! running configuration through the checks of `config set` (nothing is
//! saved until `config save`).
use super::super::drive::{self, DriveOps};
use super::super::{write_err, ErrorCode};
use super::{Outcome, ParseError, Spec};
use crate::config::{self, Config};
use crate::servo::calibrate::{CalReport, CalStop};
use crate::servo::ServoConfig;
use core::fmt::{self, Write};
use models::calibration::{Estimate, Outcome as Fit, Phase, Phases};

/// The `calibrate` command.
pub const CALIBRATE: Spec = Spec {
    name: "calibrate",
    args: "[all|encoder|resistance|inductance|flux|mechanics]",
    help: "measures the motor (gates off, no fault; within calibration_current [A] and \
           calibration_voltage [V]): encoder direction, zero and pole pairs, R, L, flux \
           linkage, inertia and friction; a progress line per phase, then `<param> = <value> \
           <unit> (was <old>, +-<uncertainty>)`; when every phase fits well they go into the running \
           configuration (`config save` keeps them), else `ERR calibration` and nothing is \
           applied; Ctrl-C stops it",
};

/// Parses the arguments of `calibrate`.
pub fn parse<'a>(args: &[&'a str]) -> Result<Phases, ParseError<'a>> {
    match args {
        [] | ["all"] => Ok(Phases::ALL),
        [p] => Phase::parse(p).map(Phases::only).ok_or(ParseError::BadArgs(
            "calibrate",
            "expected `calibrate [all|encoder|resistance|inductance|flux|mechanics]`",
        )),
        _ => Err(ParseError::BadArgs(
            "calibrate",
            "expected `calibrate [all|encoder|resistance|inductance|flux|mechanics]`",
        )),
    }
}

/// The first problem of the run, for the final `ERR calibration` line,
/// and the phases that fitted well (named in it: a run that ends in `ERR`
/// applies nothing, so the user reruns those alone to apply them).
struct Problems {
    first: Option<(&'static str, &'static str)>,
    good: [&'static str; Phase::ALL.len()],
    n_good: usize,
}

impl Problems {
    fn note(&mut self, what: &'static str, why: &'static str) {
        if self.first.is_none() {
            self.first = Some((what, why));
        }
    }
    fn fitted(&mut self, what: &'static str) {
        if self.n_good < self.good.len() {
            self.good[self.n_good] = what;
            self.n_good += 1;
        }
    }
}

/// Writes the reply of `calibrate`.
pub fn execute<W: Write>(
    phases: Phases,
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Outcome, fmt::Error> {
    if super::mpdcc_owns(drv, out, "calibrate")? {
        return Ok(Outcome::Final);
    }
    let before = try_drive!(out, "calibrate", drv.config());
    let mut failed = Ok(());
    let rep = {
        let mut progress = |p: Option<Phase>| {
            if let Some(p) = p {
                if failed.is_ok() {
                    failed = write!(out, "calibrate: {}: {}\r\n", p.name(), p.what());
                }
            }
        };
        drv.calibrate(phases, &mut progress)
    };
    failed?;
    let rep = try_drive!(out, "calibrate", rep);
    match rep.stopped {
        Some(CalStop::Fault(f)) => {
            write!(
                out,
                "ERR {} calibrate: fault latched during calibration: ",
                ErrorCode::FaultLatched.as_str()
            )?;
            f.write_names(out)?;
            out.write_str("; gates off, configuration unchanged\r\n")?;
            return Ok(Outcome::Final);
        }
        Some(CalStop::Interrupted) => {
            write_err(
                out,
                ErrorCode::Interrupted,
                format_args!("calibrate: stopped (Ctrl-C); gates off, configuration unchanged"),
            )?;
            return Ok(Outcome::Final);
        }
        None => {}
    }
    apply(&rep, &before, drv, out)
}

/// One result line: `<name> = <value> <unit> (was <old>, +-<sigma>)`.
fn line<W: Write>(out: &mut W, name: &str, v: f64, old: f64, sigma: f64) -> fmt::Result {
    let unit = config::lookup(name).map_or("", |(_, p)| p.unit);
    write!(
        out,
        "{name} = {v:.6e} {unit} (was {old:.6e}, +-{sigma:.2e})\r\n"
    )
}

/// The points of the line fits (`drivectl calibrate` plots them):
/// `fit <name>: <x> <unit>, <y> <unit>`.
fn write_points<W: Write>(out: &mut W, rep: &CalReport) -> fmt::Result {
    let r = &rep.results;
    if !matches!(r.resistance, Fit::NotRun) {
        for (i, v) in r.r_points {
            write!(out, "fit resistance: {i:.4} A, {v:.4} V\r\n")?;
        }
    }
    if matches!(r.flux, Fit::Done(_) | Fit::Poor(..)) {
        for (w, v) in r.flux_points {
            write!(out, "fit flux: {w:.2} rad/s, {v:.4} V\r\n")?;
        }
    }
    if matches!(r.mechanics, Fit::Done(_) | Fit::Poor(..)) {
        for (w, t) in r.friction_points {
            write!(out, "fit friction: {w:.3} rad/s, {t:.6} Nm\r\n")?;
        }
    }
    Ok(())
}

/// Prints the results, checks the good ones through `Config::set` and,
/// when every phase run fitted well, reconfigures the drive once. A run
/// with a poor fit, a refused phase or a refused value applies nothing
/// (the configuration is the one the command found) and says which
/// phases fitted well.
fn apply<W: Write>(
    rep: &CalReport,
    before: &ServoConfig,
    drv: &mut dyn DriveOps,
    out: &mut W,
) -> Result<Outcome, fmt::Error> {
    let r = &rep.results;
    let mut cfg = Config::from_servo(before);
    let mut bad = Problems {
        first: None,
        good: [""; Phase::ALL.len()],
        n_good: 0,
    };
    // Whether the configuration's checks took the value.
    let set = |cfg: &mut Config, name: &'static str, v: f64, bad: &mut Problems| {
        let ok = cfg.set(before, name, v).is_ok();
        if !ok {
            bad.note(name, "refused by the configuration's checks");
        }
        ok
    };
    let old = |name: &str| Config::from_servo(before).get(name).unwrap_or(f64::NAN);
    match r.encoder {
        Fit::Done(e) | Fit::Poor(e, _) => {
            write!(
                out,
                "encoder_direction = {} (counts {} with the field a-b-c)\r\n",
                e.dir,
                if e.dir > 0 { "up" } else { "down" }
            )?;
            write!(
                out,
                "motor_pole_pairs = {} 1 (was {}, fitted {:.3})\r\n",
                e.pole_pairs,
                old("motor_pole_pairs"),
                e.pole_pairs_exact
            )?;
            write!(
                out,
                "enc_zero = {} counts (was {}, +-{:.2} electrical deg)\r\n",
                e.zero_counts,
                old("enc_zero"),
                e.sigma_deg
            )?;
            if let Fit::Poor(_, why) = r.encoder {
                bad.note("encoder", why);
            } else if e.dir < 0 {
                bad.note(
                    "encoder",
                    "counts backwards with the field (swap two motor phases or the encoder's A and B)",
                );
            } else {
                let pairs = set(
                    &mut cfg,
                    "motor_pole_pairs",
                    f64::from(e.pole_pairs),
                    &mut bad,
                );
                if set(&mut cfg, "enc_zero", f64::from(e.zero_counts), &mut bad) && pairs {
                    bad.fitted("encoder");
                }
            }
        }
        Fit::Refused(why) => {
            write!(out, "calibrate: encoder: refused: {why}\r\n")?;
            bad.note("encoder", why);
        }
        Fit::NotRun => {}
    }
    let one = |out: &mut W,
               what: &'static str,
               name: &'static str,
               fit: Fit<Estimate>,
               cfg: &mut Config,
               bad: &mut Problems|
     -> fmt::Result {
        match fit {
            Fit::Done(e) => {
                line(out, name, e.value, old(name), e.sigma)?;
                if set(cfg, name, e.value, bad) {
                    bad.fitted(what);
                }
            }
            Fit::Poor(e, why) => {
                line(out, name, e.value, old(name), e.sigma)?;
                write!(out, "calibrate: {what}: poor fit: {why}\r\n")?;
                bad.note(what, why);
            }
            Fit::Refused(why) => {
                write!(out, "calibrate: {what}: refused: {why}\r\n")?;
                bad.note(what, why);
            }
            Fit::NotRun => {}
        }
        Ok(())
    };
    one(
        out,
        "resistance",
        "motor_r_s",
        r.resistance,
        &mut cfg,
        &mut bad,
    )?;
    one(
        out,
        "inductance",
        "motor_l",
        r.inductance,
        &mut cfg,
        &mut bad,
    )?;
    one(out, "flux", "motor_psi_pm", r.flux, &mut cfg, &mut bad)?;
    match r.mechanics {
        Fit::Done(m) | Fit::Poor(m, _) => {
            let fit = match r.mechanics {
                Fit::Poor(_, why) => Fit::Poor(m.j, why),
                _ => Fit::Done(m.j),
            };
            one(out, "mechanics", "load_inertia", fit, &mut cfg, &mut bad)?;
            write!(
                out,
                "viscous_friction = {:.6e} Nm s/rad (no parameter, +-{:.2e})\r\n",
                m.b.value, m.b.sigma
            )?;
            write!(
                out,
                "coulomb_friction = {:.6e} Nm (no parameter, +-{:.2e})\r\n",
                m.coulomb.value, m.coulomb.sigma
            )?;
        }
        Fit::Refused(why) => {
            write!(out, "calibrate: mechanics: refused: {why}\r\n")?;
            bad.note("mechanics", why);
        }
        Fit::NotRun => {}
    }
    write_points(out, rep)?;
    write!(
        out,
        "duration: {:.1} ms (PL time)\r\n",
        rep.cycles as f64 * 1e3 / f64::from(regmap::PL_CLOCK_HZ)
    )?;
    match bad.first {
        Some((what, why)) => {
            write!(
                out,
                "ERR {} {what}: {why}; configuration unchanged",
                ErrorCode::Calibration.as_str()
            )?;
            for (k, g) in bad.good[..bad.n_good].iter().enumerate() {
                let sep = if k == 0 {
                    " (fitted well, applied when run alone: calibrate "
                } else {
                    ", calibrate "
                };
                write!(out, "{sep}{g}")?;
            }
            if bad.n_good > 0 {
                out.write_str(")")?;
            }
            out.write_str("\r\n")?;
            Ok(Outcome::Final)
        }
        None => {
            if cfg != Config::from_servo(before) {
                try_drive!(out, "calibrate", drv.reconfigure(&cfg.apply(before)));
            }
            Ok(Outcome::Ok)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::{parse as parse_line, Command};
    use super::*;

    #[test]
    fn phases_are_parsed_and_bad_words_refused() {
        assert_eq!(parse_line("calibrate"), Ok(Command::Calibrate(Phases::ALL)));
        assert_eq!(
            parse_line("calibrate all"),
            Ok(Command::Calibrate(Phases::ALL))
        );
        for p in Phase::ALL {
            assert_eq!(
                parse_line(&std::format!("calibrate {}", p.name())),
                Ok(Command::Calibrate(Phases::only(p)))
            );
        }
        for bad in ["calibrate nothing", "calibrate all flux", "calibrate ALL"] {
            assert!(
                matches!(parse_line(bad), Err(ParseError::BadArgs("calibrate", _))),
                "{bad}"
            );
        }
    }
}
