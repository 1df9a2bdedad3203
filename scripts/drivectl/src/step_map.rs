//! The torque step-response map (`drivectl experiment step-map`): which
//! motors and steps it runs, which cells a motor cannot make, how a cell is
//! judged against the torque loop's targets, and the CSV and Markdown it
//! writes. The console I/O lives in the binary; this part is pure.
//!
//! Motors: the nominal one and the 26 corners of (R, L, psi) in
//! {0.65, 1, 1.35} x nominal, the simulated motor's true values and the
//! controllers' model set alike. Steps: six torque steps of the 1 N m
//! limit, each after a 20 ms dwell at its start value, on a locked rotor.
use anyhow::{bail, Result};
use models::pmsm::params::MotorParams;
use std::fmt::Write as _;

/// The six steps `(from, to)`, N m (the ones the MPDTC's tuning was
/// measured on).
pub use models::pmsm::mpdtc_tuning::STEP_CASES_NM as CASES;

/// Factors of the corners, per parameter.
pub const CORNER_FACTORS: [f64; 3] = [0.65, 1.0, 1.35];

/// Share of `current_limit` a step's final current may take: the rest is
/// left to the current ripple (MPDTC) and the overshoot, so a cell never
/// measures the over-current trip instead of the torque loop.
pub const CURRENT_HEADROOM: f64 = 0.8;

/// Largest overshoot, percent of the step.
pub const TARGET_OVERSHOOT_PERCENT: f64 = 10.0;
/// Largest final error, percent of the step.
pub const TARGET_FINAL_PERCENT: f64 = 2.0;
/// Settling time the MPDTC must reach on the nominal motor for 0 -> 0.4
/// and -0.4 -> 0.4, s (the paper's 0.19 ms).
pub const TARGET_NOMINAL_SETTLING_S: f64 = 0.19e-3;

/// A motor of the map: factors on the nominal R, L, psi, and whether the
/// controllers get the motor's true values or what `calibrate all`
/// measured on it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Corner {
    pub r: f64,
    pub l: f64,
    pub psi: f64,
    pub calibrated: bool,
}

/// The motors the map also runs with the controllers' model from
/// `calibrate all` (`--calibrated`): the nominal one, the two extreme
/// corners and two with R and L apart.
pub const CALIBRATED_CORNERS: [(f64, f64, f64); 5] = [
    (1.0, 1.0, 1.0),
    (0.65, 0.65, 0.65),
    (1.35, 1.35, 1.35),
    (0.65, 1.35, 1.35),
    (1.35, 0.65, 0.65),
];

impl Corner {
    pub const NOMINAL: Corner = Corner {
        r: 1.0,
        l: 1.0,
        psi: 1.0,
        calibrated: false,
    };

    /// The nominal motor, with either model.
    pub fn is_nominal(&self) -> bool {
        (self.r, self.l, self.psi) == (1.0, 1.0, 1.0)
    }

    /// The motor's parameters (nominal ones scaled).
    pub fn motor(&self) -> MotorParams {
        let m = MotorParams::default();
        MotorParams {
            r_s_ohm: m.r_s_ohm * self.r,
            l_d_h: m.l_d_h * self.l,
            l_q_h: m.l_q_h * self.l,
            psi_pm_wb: m.psi_pm_wb * self.psi,
            ..m
        }
    }

    /// `r x l x psi`, e.g. `0.65 x 1 x 1.35`, and ` (calibrated)` when
    /// the model is `calibrate all`'s.
    pub fn label(&self) -> String {
        let cal = if self.calibrated { " (calibrated)" } else { "" };
        format!("{} x {} x {}{cal}", self.r, self.l, self.psi)
    }
}

/// Which motors: `nominal`, or `all` (nominal, then the 26 other corners),
/// each with its true values in the model; with `calibrated`, then the
/// [`CALIBRATED_CORNERS`] among them with `calibrate all`'s model.
pub fn corners(all: bool, calibrated: bool) -> Vec<Corner> {
    let mut v = vec![Corner::NOMINAL];
    if all {
        for r in CORNER_FACTORS {
            for l in CORNER_FACTORS {
                for psi in CORNER_FACTORS {
                    let c = Corner {
                        r,
                        l,
                        psi,
                        calibrated: false,
                    };
                    if !c.is_nominal() {
                        v.push(c);
                    }
                }
            }
        }
    }
    if calibrated {
        let present: Vec<Corner> = v.clone();
        for (r, l, psi) in CALIBRATED_CORNERS {
            if present.iter().any(|c| (c.r, c.l, c.psi) == (r, l, psi)) {
                v.push(Corner {
                    r,
                    l,
                    psi,
                    calibrated: true,
                });
            }
        }
    }
    v
}

/// Torque constant of a surface PMSM, N m per A of peak phase current:
/// `1.5 p psi`.
pub fn torque_constant_nm_per_a(m: &MotorParams) -> f64 {
    m.k_t_nm_per_a()
}

/// Peak phase current a torque needs on the motor, A.
pub fn current_for_a(m: &MotorParams, torque_nm: f64) -> f64 {
    torque_nm.abs() / torque_constant_nm_per_a(m)
}

/// Why a cell is not run: its larger torque needs more than
/// [`CURRENT_HEADROOM`] of `current_limit_a`.
pub fn infeasible(m: &MotorParams, (from, to): (f64, f64), current_limit_a: f64) -> Option<String> {
    let need = current_for_a(m, from.abs().max(to.abs()));
    let room = CURRENT_HEADROOM * current_limit_a;
    (need > room).then(|| {
        format!(
            "needs {need:.1} A, over {:.0} % of current_limit {current_limit_a} A",
            CURRENT_HEADROOM * 100.0
        )
    })
}

/// The MPDTC's control period on the drive with its default
/// configuration, s (4 ADC periods of 391 PL cycles at 100 MHz).
pub fn mpdtc_period_s() -> f64 {
    drive::servo::ServoConfig::default().mpdtc_period_s()
}

/// Why no one-vector-per-period loop can meet the cell's settling band:
/// one period of an active vector moves the torque further than the band
/// is wide (`models::pmsm::mpdtc_tuning`: `k_T sqrt(3)/2 (Ts / L) 2/3
/// U_dc` with the rotor locked as the map has it). `None`: it can.
pub fn beyond_one_period(m: &MotorParams, (from, to): (f64, f64)) -> Option<String> {
    use models::pmsm::mpdtc_tuning::{
        band_holds_one_period, period_torque_step_nm, Q_SHARE_MIDWAY,
    };
    if band_holds_one_period(m, mpdtc_period_s(), from, to) {
        return None;
    }
    Some(format!(
        "one period moves the torque {:.3} N m, the 10 % band is {:.3} N m wide",
        period_torque_step_nm(m, mpdtc_period_s(), Q_SHARE_MIDWAY),
        2.0 * models::pmsm::metrics::settling_band(from, to)
    ))
}

/// What one mode's step on one cell gave.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// The `step` reply: settling (None: not within the window), s;
    /// overshoot, %; switching per leg, Hz; final torque, N m.
    Measured {
        settling_s: Option<f64>,
        overshoot_percent: f64,
        switching_hz: f64,
        final_nm: f64,
    },
    /// The drive refused or tripped (its message).
    Failed(String),
    /// Not run (why).
    Skipped(String),
}

impl Outcome {
    /// Final error, percent of the step.
    pub fn final_error_percent(&self, (from, to): (f64, f64)) -> Option<f64> {
        match self {
            Outcome::Measured { final_nm, .. } => {
                Some(100.0 * (final_nm - to).abs() / (to - from).abs())
            }
            _ => None,
        }
    }
}

/// One cell: a motor, a step, both modes.
#[derive(Debug, Clone, PartialEq)]
pub struct Cell {
    pub corner: Corner,
    pub case: (f64, f64),
    pub mpdtc: Outcome,
    pub foc: Outcome,
}

/// The targets a cell's MPDTC step misses (empty: it meets them all).
/// Skipped cells miss nothing; a failed step misses everything.
pub fn misses(c: &Cell) -> Vec<String> {
    let mut v = Vec::new();
    let (settling_s, overshoot) = match &c.mpdtc {
        Outcome::Skipped(_) => return v,
        Outcome::Failed(e) => return vec![format!("failed: {e}")],
        Outcome::Measured {
            settling_s,
            overshoot_percent,
            ..
        } => (*settling_s, *overshoot_percent),
    };
    if overshoot > TARGET_OVERSHOOT_PERCENT {
        v.push(format!(
            "overshoot {overshoot:.1} % > {TARGET_OVERSHOOT_PERCENT} %"
        ));
    }
    let fe = c.mpdtc.final_error_percent(c.case).unwrap_or(f64::INFINITY);
    if fe > TARGET_FINAL_PERCENT {
        v.push(format!("final error {fe:.1} % > {TARGET_FINAL_PERCENT} %"));
    }
    let Some(t) = settling_s else {
        v.push("not settled in the window".into());
        return v;
    };
    if let Outcome::Measured {
        settling_s: Some(t_foc),
        ..
    } = c.foc
    {
        if t > t_foc {
            v.push(format!(
                "settling {:.3} ms > FOC {:.3} ms",
                t * 1e3,
                t_foc * 1e3
            ));
        }
    }
    let nominal_case = c.case == (0.0, 0.4) || c.case == (-0.4, 0.4);
    if c.corner.is_nominal() && nominal_case && t > TARGET_NOMINAL_SETTLING_S {
        v.push(format!(
            "settling {:.3} ms > {:.2} ms",
            t * 1e3,
            TARGET_NOMINAL_SETTLING_S * 1e3
        ));
    }
    v
}

/// Parses a step reply's fields (`settling_time: 0.1406 ms` or `none (...)`,
/// `overshoot: 7.1 %`, `switching: 6.2 kHz`, `final: 0.4012 Nm`).
pub fn parse_step(field: impl Fn(&str) -> Option<String>) -> Result<Outcome> {
    let num = |k: &str| -> Result<f64> {
        let v = field(k).ok_or_else(|| anyhow::anyhow!("no `{k}` in the step reply"))?;
        v.parse::<f64>()
            .map_err(|_| anyhow::anyhow!("`{k}: {v}` is not a number"))
    };
    let settling_s = match field("settling_time").as_deref() {
        Some("none") => None,
        Some(_) => Some(num("settling_time")? * 1e-3),
        None => bail!("no `settling_time` in the step reply"),
    };
    Ok(Outcome::Measured {
        settling_s,
        overshoot_percent: num("overshoot")?,
        switching_hz: num("switching")? * 1e3,
        final_nm: num("final")?,
    })
}

fn csv_outcome(o: &Outcome, case: (f64, f64)) -> String {
    match o {
        Outcome::Measured {
            settling_s,
            overshoot_percent,
            switching_hz,
            ..
        } => format!(
            "measured,{},{overshoot_percent:.2},{:.3},{:.0},",
            settling_s.map_or(String::new(), |t| format!("{:.4}", t * 1e3)),
            o.final_error_percent(case).unwrap_or(f64::NAN),
            switching_hz
        ),
        Outcome::Failed(e) => format!("failed,,,,,{}", e.replace(',', ";")),
        Outcome::Skipped(e) => format!("skipped,,,,,{}", e.replace(',', ";")),
    }
}

/// CSV: one row per cell and mode.
pub fn csv(cells: &[Cell]) -> String {
    let mut s = String::from(
        "r_factor,l_factor,psi_factor,from_Nm,to_Nm,mode,outcome,settling_ms,overshoot_percent,\
         final_error_percent,switching_per_leg_Hz,note,model\n",
    );
    for c in cells {
        for (mode, o) in [("mpdtc", &c.mpdtc), ("foc", &c.foc)] {
            let _ = writeln!(
                s,
                "{},{},{},{},{},{mode},{},{}",
                c.corner.r,
                c.corner.l,
                c.corner.psi,
                c.case.0,
                c.case.1,
                csv_outcome(o, c.case),
                if c.corner.calibrated {
                    "calibrated"
                } else {
                    "true"
                }
            );
        }
    }
    s
}

fn md_outcome(o: &Outcome, case: (f64, f64)) -> String {
    match o {
        Outcome::Measured {
            settling_s,
            overshoot_percent,
            switching_hz,
            ..
        } => format!(
            "{} / {overshoot_percent:.1} % / {:.1} % / {:.1} kHz",
            settling_s.map_or("none".to_string(), |t| format!("{:.3} ms", t * 1e3)),
            o.final_error_percent(case).unwrap_or(f64::NAN),
            switching_hz * 1e-3
        ),
        Outcome::Failed(e) => format!("failed: {e}"),
        Outcome::Skipped(e) => format!("not run: {e}"),
    }
}

/// Summary of a map: cells run, cells meeting every target, and the worst
/// cell by MPDTC-to-FOC settling ratio among the measured ones.
#[derive(Debug, Clone, PartialEq)]
pub struct Summary {
    pub run: usize,
    pub skipped: usize,
    pub meeting: usize,
    /// Cells run that miss a target and are beyond one period's torque
    /// step ([`beyond_one_period`]).
    pub missing_beyond: usize,
    pub worst_overshoot_percent: f64,
    pub worst_settling_ratio: f64,
    pub worst_final_percent: f64,
    /// Index of the cell furthest from its targets ([`badness`]).
    pub worst: Option<usize>,
}

/// How far a cell's MPDTC step is from its targets, as the largest of its
/// ratios to them: overshoot / 10 %, final error / 2 %, settling / the
/// FOC's and, on the nominal motor's 0 -> 0.4 and -0.4 -> 0.4, settling /
/// 0.19 ms. At most 1 meets every target; a step that failed or did not
/// settle is infinite; a skipped cell is 0.
pub fn badness(c: &Cell) -> f64 {
    let (settling_s, overshoot) = match &c.mpdtc {
        Outcome::Skipped(_) => return 0.0,
        Outcome::Failed(_) => return f64::INFINITY,
        Outcome::Measured {
            settling_s,
            overshoot_percent,
            ..
        } => (*settling_s, *overshoot_percent),
    };
    let Some(t) = settling_s else {
        return f64::INFINITY;
    };
    let fe = c.mpdtc.final_error_percent(c.case).unwrap_or(f64::INFINITY);
    let mut b = (overshoot / TARGET_OVERSHOOT_PERCENT).max(fe / TARGET_FINAL_PERCENT);
    if let Outcome::Measured {
        settling_s: Some(t_foc),
        ..
    } = c.foc
    {
        if t_foc > 0.0 {
            b = b.max(t / t_foc);
        }
    }
    let nominal_case = c.case == (0.0, 0.4) || c.case == (-0.4, 0.4);
    if c.corner.is_nominal() && nominal_case {
        b = b.max(t / TARGET_NOMINAL_SETTLING_S);
    }
    b
}

pub fn summary(cells: &[Cell]) -> Summary {
    let mut s = Summary {
        run: 0,
        skipped: 0,
        meeting: 0,
        missing_beyond: 0,
        worst_overshoot_percent: 0.0,
        worst_settling_ratio: 0.0,
        worst_final_percent: 0.0,
        worst: None,
    };
    for (i, c) in cells.iter().enumerate() {
        if matches!(c.mpdtc, Outcome::Skipped(_)) {
            s.skipped += 1;
            continue;
        }
        s.run += 1;
        if misses(c).is_empty() {
            s.meeting += 1;
        } else if beyond_one_period(&c.corner.motor(), c.case).is_some() {
            s.missing_beyond += 1;
        }
        if let Outcome::Measured {
            settling_s,
            overshoot_percent,
            ..
        } = c.mpdtc
        {
            s.worst_overshoot_percent = s.worst_overshoot_percent.max(overshoot_percent);
            s.worst_final_percent = s
                .worst_final_percent
                .max(c.mpdtc.final_error_percent(c.case).unwrap_or(0.0));
            let ratio = match (settling_s, &c.foc) {
                (
                    Some(t),
                    Outcome::Measured {
                        settling_s: Some(tf),
                        ..
                    },
                ) if *tf > 0.0 => t / tf,
                (None, _) => f64::INFINITY,
                _ => continue,
            };
            s.worst_settling_ratio = s.worst_settling_ratio.max(ratio);
        } else {
            // A refused or tripped step is the worst there is.
            s.worst_settling_ratio = f64::INFINITY;
        }
        if s.worst.is_none_or(|w| badness(c) > badness(&cells[w])) {
            s.worst = Some(i);
        }
    }
    s
}

/// Markdown: the summary, then one row per cell.
pub fn markdown(cells: &[Cell], how: &str) -> String {
    let sm = summary(cells);
    let mut s = String::new();
    let _ = writeln!(s, "{how}\n");
    let _ = writeln!(
        s,
        "Targets of the MPDTC on every cell: overshoot <= {TARGET_OVERSHOOT_PERCENT} % of the \
         step, settling (10 % band) no slower than the FOC on the same cell and <= {:.2} ms on \
         the nominal motor for 0 -> 0.4 and -0.4 -> 0.4 N m, final error (mean of the window's \
         last quarter) <= {TARGET_FINAL_PERCENT} % of the step.\n",
        TARGET_NOMINAL_SETTLING_S * 1e3
    );
    let _ = writeln!(
        s,
        "Cells run: {}; meeting every target: {}; missing one where one control period's \
         torque step is wider than the 10 % band (no one-vector-per-period loop can meet it): \
         {}; not run (beyond the current): {}. Worst MPDTC overshoot {:.1} %, worst settling \
         ratio MPDTC / FOC {:.2}, worst final error {:.1} %.\n",
        sm.run,
        sm.meeting,
        sm.missing_beyond,
        sm.skipped,
        sm.worst_overshoot_percent,
        sm.worst_settling_ratio,
        sm.worst_final_percent
    );
    if let Some(i) = sm.worst {
        let c = &cells[i];
        let _ = writeln!(
            s,
            "Worst cell: motor {} (R x L x psi), {} -> {} N m: MPDTC {}, FOC {}.\n",
            c.corner.label(),
            c.case.0,
            c.case.1,
            md_outcome(&c.mpdtc, c.case),
            md_outcome(&c.foc, c.case)
        );
    }
    s += "| motor R x L x psi | step, N m | MPDTC settling / overshoot / final error / switching | FOC settling / overshoot / final error / switching | MPDTC misses |\n";
    s += "|---|---|---|---|---|\n";
    for c in cells {
        let m = misses(c);
        let _ = writeln!(
            s,
            "| {} | {} -> {} | {} | {} | {} |",
            c.corner.label(),
            c.case.0,
            c.case.1,
            md_outcome(&c.mpdtc, c.case),
            md_outcome(&c.foc, c.case),
            if matches!(c.mpdtc, Outcome::Skipped(_)) {
                "-".to_string()
            } else if m.is_empty() {
                "none".to_string()
            } else if let Some(b) = beyond_one_period(&c.corner.motor(), c.case) {
                format!("{} (beyond one period: {b})", m.join("; "))
            } else {
                m.join("; ")
            }
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    fn meas(t_ms: Option<f64>, os: f64, fin: f64) -> Outcome {
        Outcome::Measured {
            settling_s: t_ms.map(|t| t * 1e-3),
            overshoot_percent: os,
            switching_hz: 5e3,
            final_nm: fin,
        }
    }

    #[test]
    fn the_map_has_the_nominal_motor_and_26_corners() {
        let c = corners(true, false);
        assert_eq!(c.len(), 27);
        assert!(c[0].is_nominal());
        assert_eq!(c.iter().filter(|c| c.is_nominal()).count(), 1);
        assert_eq!(corners(false, false), vec![Corner::NOMINAL]);
        // Five more with the calibrated model, each a corner of the 27.
        let cal = corners(true, true);
        assert_eq!(cal.len(), 32);
        assert!(cal[27..].iter().all(|c| c.calibrated
            && c.label().ends_with(" (calibrated)")
            && cal[..27]
                .iter()
                .any(|t| (t.r, t.l, t.psi) == (c.r, c.l, c.psi))));
        assert!(cal[27].is_nominal());
        // The nominal map alone gets the nominal motor's calibrated twin.
        assert_eq!(corners(false, true).len(), 2);
    }

    #[test]
    fn cells_beyond_the_current_are_the_weak_magnet_ones_at_high_torque() {
        // 1.5 * 7 * 0.0092879 = 0.09752 N m/A nominal; 0.65 x: 0.06339 N m/A.
        let weak = Corner {
            r: 1.0,
            l: 1.0,
            psi: 0.65,
            calibrated: false,
        }
        .motor();
        assert!((torque_constant_nm_per_a(&weak) - 0.063_39).abs() < 1e-4);
        // 0.9 N m / 0.06339 = 14.2 A > 11.2 A; 0.4 N m: 6.3 A.
        assert!(infeasible(&weak, (0.1, 0.9), 14.0).is_some());
        assert!(infeasible(&weak, (-0.8, 0.8), 14.0).is_some());
        assert!(infeasible(&weak, (0.0, 0.4), 14.0).is_none());
        let nominal = Corner::NOMINAL.motor();
        for case in CASES {
            assert!(infeasible(&nominal, case, 14.0).is_none(), "{case:?}");
        }
    }

    /// One period's torque step against the band, by hand: nominal
    /// 0.0975 N m/A x 0.866 x (15.64 us / 0.64 mH) x 32 V = 0.0660 N m,
    /// inside a 0.4 N m step's 0.08 N m band; L x 0.65: 0.1016 N m, not;
    /// an 0.8 N m step's 0.16 N m band holds both.
    #[test]
    fn cells_beyond_one_periods_torque_step() {
        let low_l = Corner {
            r: 1.0,
            l: 0.65,
            psi: 1.0,
            calibrated: false,
        }
        .motor();
        let nominal = Corner::NOMINAL.motor();
        assert_eq!(beyond_one_period(&nominal, (0.0, 0.4)), None);
        let why = beyond_one_period(&low_l, (0.0, 0.4)).expect("beyond");
        assert!(
            why.contains("0.102 N m") && why.contains("0.080 N m"),
            "{why}"
        );
        assert_eq!(beyond_one_period(&low_l, (-0.4, 0.4)), None);
        assert_eq!(beyond_one_period(&low_l, (0.1, 0.9)), None);
    }

    #[test]
    fn a_cell_is_judged_against_each_target() {
        let cell = |corner, case, mpdtc, foc| Cell {
            corner,
            case,
            mpdtc,
            foc,
        };
        let low_l = Corner {
            r: 1.0,
            l: 0.65,
            psi: 1.0,
            calibrated: false,
        };
        // Meets all: faster than the FOC, 5 % overshoot, 1 % final error.
        let ok = cell(
            low_l,
            (0.0, 0.8),
            meas(Some(0.2), 5.0, 0.808),
            meas(Some(0.3), 1.0, 0.8),
        );
        assert!(misses(&ok).is_empty());
        // Each target missed alone.
        let os = cell(
            low_l,
            (0.0, 0.8),
            meas(Some(0.2), 10.5, 0.8),
            meas(Some(0.3), 0.0, 0.8),
        );
        assert_eq!(misses(&os).len(), 1, "{:?}", misses(&os));
        let fin = cell(
            low_l,
            (0.0, 0.8),
            meas(Some(0.2), 0.0, 0.8 - 0.017),
            meas(Some(0.3), 0.0, 0.8),
        );
        assert_eq!(misses(&fin).len(), 1, "{:?}", misses(&fin));
        let slow = cell(
            low_l,
            (0.0, 0.8),
            meas(Some(0.31), 0.0, 0.8),
            meas(Some(0.3), 0.0, 0.8),
        );
        assert_eq!(misses(&slow).len(), 1, "{:?}", misses(&slow));
        // The 0.19 ms target binds on the nominal motor's two cases only.
        let nom = cell(
            Corner::NOMINAL,
            (-0.4, 0.4),
            meas(Some(0.2), 0.0, 0.4),
            meas(Some(0.25), 0.0, 0.4),
        );
        assert_eq!(misses(&nom).len(), 1, "{:?}", misses(&nom));
        let nom_big = cell(
            Corner::NOMINAL,
            (0.0, 0.8),
            meas(Some(0.2), 0.0, 0.8),
            meas(Some(0.25), 0.0, 0.8),
        );
        assert!(misses(&nom_big).is_empty());
        // Not settled, tripped: missed; not run: nothing to judge.
        let none = cell(
            low_l,
            (0.0, 0.4),
            meas(None, 0.0, 0.4),
            meas(Some(0.3), 0.0, 0.4),
        );
        assert!(!misses(&none).is_empty());
        let trip = cell(
            low_l,
            (0.0, 0.4),
            Outcome::Failed("OVERCURRENT".into()),
            meas(Some(0.3), 0.0, 0.4),
        );
        assert!(!misses(&trip).is_empty());
        let skip = cell(
            low_l,
            (0.0, 0.4),
            Outcome::Skipped("x".into()),
            Outcome::Skipped("x".into()),
        );
        assert!(misses(&skip).is_empty());
        let s = summary(&[ok.clone(), slow.clone(), skip]);
        assert_eq!((s.run, s.meeting, s.skipped, s.worst), (2, 1, 1, Some(1)));
        assert!((s.worst_settling_ratio - 0.31 / 0.3).abs() < 1e-9);
        // Badness by hand: the largest ratio to a target.
        let near = |a: f64, b: f64| (a - b).abs() < 1e-9;
        assert!(near(badness(&ok), 0.2 / 0.3));
        assert!(near(badness(&os), 10.5 / 10.0));
        assert!(near(badness(&fin), (0.017 / 0.8 * 100.0) / 2.0));
        assert!(near(badness(&slow), 0.31 / 0.3));
        assert!(near(badness(&nom), 0.2 / 0.19));
        assert_eq!(badness(&none), f64::INFINITY);
        assert_eq!(badness(&trip), f64::INFINITY);
        // The worst cell is the one furthest from a target: the final
        // error's 1.0625, not the slowest settling's 1.033.
        let s = summary(&[ok.clone(), os, fin, slow, nom]);
        assert_eq!(s.worst, Some(2));
    }

    #[test]
    fn step_replies_parse_with_units_and_none() {
        let reply = |settling: &'static str| {
            move |k: &str| {
                match k {
                    "settling_time" => Some(settling),
                    "overshoot" => Some("7.1"),
                    "switching" => Some("6.2"),
                    "final" => Some("0.4012"),
                    _ => None,
                }
                .map(str::to_string)
            }
        };
        assert_eq!(
            parse_step(reply("0.1406")).unwrap(),
            Outcome::Measured {
                settling_s: Some(0.1406e-3),
                overshoot_percent: 7.1,
                switching_hz: 6200.0,
                final_nm: 0.4012
            }
        );
        assert!(matches!(
            parse_step(reply("none")).unwrap(),
            Outcome::Measured {
                settling_s: None,
                ..
            }
        ));
        assert!(parse_step(reply("x")).is_err());
        assert!(parse_step(|_| None).is_err());
    }

    #[test]
    fn csv_has_a_row_per_cell_and_mode_with_units_in_the_header() {
        let c = Cell {
            corner: Corner::NOMINAL,
            case: (0.0, 0.4),
            mpdtc: meas(Some(0.14), 7.1, 0.404),
            foc: Outcome::Failed("ERR fault, OVERCURRENT".into()),
        };
        let s = csv(&[c]);
        let lines: Vec<&str> = s.lines().collect();
        assert_eq!(lines.len(), 3);
        let cols = lines[0].split(',').count();
        assert!(lines.iter().all(|l| l.split(',').count() == cols), "{s}");
        assert!(
            lines[1].starts_with("1,1,1,0,0.4,mpdtc,measured,0.1400,7.10,1.000,5000,"),
            "{}",
            lines[1]
        );
        assert!(lines[2].contains("failed") && lines[2].contains("ERR fault; OVERCURRENT"));
    }
}
