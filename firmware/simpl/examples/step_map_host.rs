//! The torque step-response map on the host: the product's servo against
//! the simulated PL and motor, one control step per boundary, the way the
//! firmware runs them under QEMU but without the console (fast, for tuning
//! the MPDTC). The map the README quotes comes from the console
//! (`drivectl experiment step-map`); this is its quick twin.
//!
//! `cargo run --release -p simpl --example step_map_host [nominal|all]`
//! Environment (all optional):
//! - `SET="mpdtc_aw=1,mpdtc_k_auto=1"`: `config set` keys for the MPDTC runs;
//! - `CASES=0,3`: the steps to run (indices into the six);
//! - `MOTOR=0.65,1,1.35`: one motor (R, L, psi factors) instead;
//! - `PHASES=12`: runs per cell, each starting 7 periods later (the MPDTC's
//!   limit-cycle phase at the step);
//! - `KAUTO=10000`: K = this x (L / L_nom) / (psi / psi_nom), 1/s;
//! - `TOLAUTO=0.6`: T_tol = this x one period's torque step;
//! - `FOC=0`: skip the FOC runs; `TRACE=1` (`T0=n`): print 40 samples.
//!
//! A cell is `MISS` when the MPDTC misses a target of the map, `BOUND` when
//! it misses one but one period's torque step is wider than the band
//! (`models::pmsm::mpdtc_tuning::band_holds_one_period`).
use drive::config::Config;
use drive::pl::top::Mode;
use drive::servo::{Servo, ServoConfig, StepResult};
use models::pmsm::mpdtc_tuning::{
    band_holds_one_period, period_torque_step_nm, Q_SHARE_MIDWAY, STEP_CASES_NM as CASES,
};
use models::pmsm::params::MotorParams;
use simpl::{SimConfig, SimDrive};

/// Share of `current_limit` a cell's torque may need (the console map's
/// `drivectl::step_map::CURRENT_HEADROOM`).
const CURRENT_HEADROOM: f64 = 0.8;

/// The nominal motor with its R, L, psi scaled by `f`.
fn corner(f: (f64, f64, f64)) -> MotorParams {
    let mut m = MotorParams::default();
    m.r_s_ohm *= f.0;
    m.l_d_h *= f.1;
    m.l_q_h *= f.1;
    m.psi_pm_wb *= f.2;
    m
}

fn run(s: &mut Servo, sim: &mut SimDrive, n: u32, mut done: impl FnMut(&Servo) -> bool) -> bool {
    for _ in 0..n {
        let a = sim.advance_to_boundary(20_000);
        assert!(a.control_periods >= 1, "no boundary in 200 us");
        if s.control_step(sim).is_err() {
            return false;
        }
        if done(s) {
            return true;
        }
    }
    true
}

fn one(
    mode: Mode,
    f: (f64, f64, f64),
    case: (f64, f64),
    set: &[(String, f64)],
    phase: u32,
) -> Result<StepResult, String> {
    let mut sim = SimDrive::new(&SimConfig::default()).unwrap();
    let nom = sim.config().motor;
    for (k, v) in [
        ("r_s", nom.r_s_ohm * f.0),
        ("l", nom.l_d_h * f.1),
        ("psi_pm", nom.psi_pm_wb * f.2),
    ] {
        sim.sim_set(k, v).map_err(|e| format!("{e:?}"))?;
    }
    let base = ServoConfig::for_plant(nom, sim.config().adc_amps_per_count);
    let mut c = Config::from_servo(&base);
    for (k, v) in [
        ("motor_r_s", nom.r_s_ohm * f.0),
        ("motor_l", nom.l_d_h * f.1),
        ("motor_psi_pm", nom.psi_pm_wb * f.2),
        ("torque_limit", 1.0),
    ]
    .into_iter()
    .chain(set.iter().map(|(k, v)| (k.as_str(), *v)))
    {
        c.set(&base, k, v).map_err(|e| format!("{k}: {e:?}"))?;
    }
    let cfg = c.apply(&base);
    let mut s = Servo::new(&cfg).map_err(|e| format!("{e:?}"))?;
    s.init(&mut sim).map_err(|e| format!("{e:?}"))?;
    s.set_mode(&mut sim, mode).map_err(|e| format!("{e:?}"))?;
    s.enable(&mut sim).map_err(|e| format!("{e:?}"))?;
    run(&mut s, &mut sim, 200_000, |s| s.controlling());
    s.set_torque_ref(case.0).map_err(|e| format!("{e:?}"))?;
    let n = (20e-3 * s.control_rate_hz()) as u32 + phase;
    if !run(&mut s, &mut sim, n, |_| false) {
        return Err("fault in dwell".into());
    }
    s.begin_step(&mut sim, case.1, 10e-3)
        .map_err(|e| format!("{e:?}"))?;
    if !run(&mut s, &mut sim, 10_000, |s| !s.step_pending()) {
        return Err(format!("fault in step {:?}", s.faults_recorded()));
    }
    if std::env::var("TRACE").is_ok() {
        let rec = s.step_recording().expect("done");
        let v: Vec<String> = rec.samples()[std::env::var("T0").map_or(0, |v| v.parse().unwrap())..]
            [..40]
            .iter()
            .map(|x| format!("{x:.3}"))
            .collect();
        println!("{mode:?} {}", v.join(" "));
    }
    s.step_result().ok_or_else(|| "no result".into())
}

fn main() {
    let all = std::env::args().nth(1).as_deref() == Some("all");
    let set: Vec<(String, f64)> = std::env::var("SET")
        .unwrap_or_default()
        .split(',')
        .filter(|s| !s.is_empty())
        .map(|kv| {
            let (k, v) = kv.split_once('=').expect("key=value");
            (k.to_string(), v.parse().expect("number"))
        })
        .collect();
    let cases: Vec<usize> = std::env::var("CASES")
        .map(|s| s.split(',').map(|x| x.parse().unwrap()).collect())
        .unwrap_or((0..6).collect());
    let phases: u32 = std::env::var("PHASES")
        .map(|s| s.parse().unwrap())
        .unwrap_or(1);
    let foc = std::env::var("FOC").map(|s| s == "1").unwrap_or(true);
    let fs = [0.65, 1.0, 1.35];
    let mut corners = match std::env::var("MOTOR") {
        Ok(m) => {
            let v: Vec<f64> = m.split(",").map(|x| x.parse().unwrap()).collect();
            vec![(v[0], v[1], v[2])]
        }
        _ => vec![(1.0, 1.0, 1.0)],
    };
    if all {
        for r in fs {
            for l in fs {
                for p in fs {
                    if (r, l, p) != (1.0, 1.0, 1.0) {
                        corners.push((r, l, p));
                    }
                }
            }
        }
    }
    let (mut bad, mut n) = (0, 0);
    for f in corners {
        for &ci in &cases {
            let case = CASES[ci];
            let motor = corner(f);
            let servo = ServoConfig::default();
            let ts = servo.mpdtc_period_s();
            if case.0.abs().max(case.1.abs()) / motor.k_t_nm_per_a()
                > CURRENT_HEADROOM * servo.current_limit_a
            {
                continue;
            }
            for ph in 0..phases {
                let mut set = set.clone();
                if let Ok(c) = std::env::var("KAUTO") {
                    let c: f64 = c.parse().unwrap();
                    set.push(("mpdtc_k_auto".into(), 0.0));
                    set.push(("mpdtc_k".into(), c * f.1 / f.2));
                }
                if let Ok(a) = std::env::var("TOLAUTO") {
                    let a: f64 = a.parse().unwrap();
                    let hop = period_torque_step_nm(&motor, ts, Q_SHARE_MIDWAY);
                    set.push(("mpdtc_t_tol".into(), a * hop));
                }
                let m = one(Mode::Mpdtc, f, case, &set, ph * 7);
                let fo = if foc {
                    Some(one(Mode::Foc, f, case, &[], ph * 7))
                } else {
                    None
                };
                let fmt = |r: &Result<StepResult, String>| match r {
                    Ok(r) => format!(
                        "{:>6} ms {:5.1} % fin {:5.1} % sw {:4.1} kHz",
                        r.settling_s
                            .map_or("none".into(), |t| format!("{:.3}", t * 1e3)),
                        r.overshoot_percent,
                        100.0 * (r.final_nm - r.to_nm).abs() / (r.to_nm - r.from_nm).abs(),
                        r.switching_per_leg_per_s * 1e-3
                    ),
                    Err(e) => format!("ERR {e}"),
                };
                let miss = match (&m, &fo) {
                    (Ok(r), fo) => {
                        let fe = 100.0 * (r.final_nm - r.to_nm).abs() / (r.to_nm - r.from_nm).abs();
                        let t = r.settling_s.unwrap_or(1.0);
                        let tf = match fo {
                            Some(Ok(x)) => x.settling_s.unwrap_or(1.0),
                            _ => 1.0,
                        };
                        r.overshoot_percent > 10.0 || fe > 2.0 || t > tf + 1e-9
                    }
                    _ => true,
                };
                let bound = !band_holds_one_period(&motor, ts, case.0, case.1);
                let miss = miss && !bound;
                n += 1;
                if miss {
                    bad += 1;
                }
                println!(
                    "{:>4}x{:>4}x{:>4} {:>4}->{:>4}  MPDTC {}  | FOC {} {}",
                    f.0,
                    f.1,
                    f.2,
                    case.0,
                    case.1,
                    fmt(&m),
                    fo.as_ref().map_or(String::new(), fmt),
                    if miss {
                        "MISS"
                    } else if bound {
                        "BOUND"
                    } else {
                        ""
                    }
                );
            }
        }
    }
    println!("cells {n}, missing {bad}");
}
