//! `calibrate` under QEMU on the simulated PL: random simulated motors
//! (`sim set`, seeded draws within +-40 % of the defaults, encoder offset
//! anywhere, both directions) measured by `calibrate all` and written into
//! the running configuration; the locked rotor; the gates on; a fault
//! during the calibration.
use drivectl::link::{Final, Reply, Session};
use models::testrng::Rng;
use std::time::Duration;
use system_tests::{assert_err, assert_ok, boot, cmd};

/// `calibrate all` takes about 1.3 s of PL time (docs/ARCHITECTURE.md,
/// "Tests and their budget"): 25 to 105 s of wall time under QEMU with
/// four in parallel, by the machine's load.
fn calibrate(s: &mut Session, line: &str) -> Reply {
    match s.command(line, Duration::from_secs(300)) {
        Ok(r) => r,
        Err(e) => panic!(
            "{line:?}: {e:#}\ntranscript:\n{}",
            String::from_utf8_lossy(&s.transcript)
        ),
    }
}

/// The value of `<name> = <value> ...` in a reply.
fn result(r: &Reply, name: &str) -> Option<f64> {
    r.lines.iter().find_map(|l| {
        l.strip_prefix(name)?
            .strip_prefix(" = ")?
            .split_whitespace()
            .next()?
            .parse()
            .ok()
    })
}

fn config(s: &mut Session, name: &str) -> f64 {
    let r = cmd(s, &format!("config get {name}"));
    assert_ok(&r);
    result(&r, name).unwrap_or_else(|| panic!("{r:?}"))
}

#[test]
fn gates_on_is_refused_and_changes_nothing() {
    let mut s = boot();
    assert_ok(&cmd(&mut s, "mode foc"));
    assert_ok(&cmd(&mut s, "enable"));
    let before = cmd(&mut s, "config list");
    assert_err(&cmd(&mut s, "calibrate"), "gates-on");
    assert_eq!(cmd(&mut s, "config list").lines, before.lines);
    assert_err(&cmd(&mut s, "calibrate nothing"), "bad-args");
}

/// A locked rotor: `calibrate all` measures R and L, refuses the phases
/// that need motion and, ending in `ERR`, applies nothing (the wrong R and
/// L configured before it stay); the phases it names as fitted well, run
/// alone, apply the paper's motor (0.555 ohm, 0.64 mH).
#[test]
fn a_locked_rotor_gets_r_and_l_and_refuses_the_rest() {
    let mut s = boot();
    // The default simulated motor is held (`locked 1`); the configured
    // model off the true one, so an applied result would show.
    assert_ok(&cmd(&mut s, "config set motor_r_s 0.7"));
    assert_ok(&cmd(&mut s, "config set motor_l 0.0008"));
    let before = cmd(&mut s, "config list");
    let r = calibrate(&mut s, "calibrate all");
    assert_err(&r, "calibration");
    for phase in ["encoder", "resistance", "inductance", "flux", "mechanics"] {
        assert!(
            r.lines
                .iter()
                .any(|l| l.starts_with(&format!("calibrate: {phase}: "))),
            "{phase}: {r:?}"
        );
    }
    for refused in ["encoder", "flux", "mechanics"] {
        assert!(
            r.lines
                .iter()
                .any(|l| l.starts_with(&format!("calibrate: {refused}: refused: rotor locked"))),
            "{refused}: {r:?}"
        );
    }
    // `ERR calibration <phase>: <why>; configuration unchanged (...)`:
    // the phase first (not the command's name again), then what to rerun.
    match &r.fin {
        Final::Err { message, .. } => {
            assert!(message.starts_with("encoder: rotor locked"), "{r:?}");
            assert!(
                message.ends_with(
                    "; configuration unchanged (fitted well, applied when run alone: \
                     calibrate resistance, calibrate inductance)"
                ),
                "{r:?}"
            );
        }
        Final::Ok => unreachable!(),
    }
    assert_eq!(cmd(&mut s, "config list").lines, before.lines);
    assert_eq!(config(&mut s, "motor_r_s"), 0.7);
    assert_ok(&calibrate(&mut s, "calibrate resistance"));
    assert_ok(&calibrate(&mut s, "calibrate inductance"));
    let r_s = config(&mut s, "motor_r_s");
    let l = config(&mut s, "motor_l");
    assert!((r_s / 0.555 - 1.0).abs() < 0.03, "{r_s}");
    assert!((l / 0.64e-3 - 1.0).abs() < 0.03, "{l}");
    assert_eq!(config(&mut s, "enc_zero"), 0.0);
    let st = cmd(&mut s, "status");
    assert!(st.lines.iter().any(|l| l.contains("gates: off")), "{st:?}");
}

#[test]
fn a_fault_during_calibration_leaves_the_gates_off_and_the_configuration_unchanged() {
    let mut s = boot();
    assert_ok(&cmd(&mut s, "sim set locked 0"));
    // Channel a inverted: the calibration's current loop runs away until
    // the over-current trip (14 A) latches.
    assert_ok(&cmd(&mut s, "debug fault adc-invert"));
    let before = cmd(&mut s, "config list");
    let r = calibrate(&mut s, "calibrate");
    assert_err(&r, "fault-latched");
    match &r.fin {
        Final::Err { message, .. } => {
            assert!(message.contains("configuration unchanged"), "{r:?}")
        }
        Final::Ok => unreachable!(),
    }
    assert_eq!(cmd(&mut s, "config list").lines, before.lines);
    let st = cmd(&mut s, "status");
    assert!(st.lines.iter().any(|l| l.contains("gates: off")), "{st:?}");
}

/// Three seeded motors, each in its own QEMU (in parallel): R and L within
/// 3 %, psi within 2 %, the encoder's zero within 1 electrical degree,
/// direction and pole pairs exact, J within 10 % (docs/calibration.md).
#[test]
fn calibrate_all_measures_three_random_motors() {
    let mut rng = Rng(2311);
    let draws: Vec<_> = (0..3)
        .map(|_| {
            let mut f = |x: f64| x * rng.uniform(0.6, 1.4);
            let m = [
                f(0.555),
                f(0.64e-3),
                f(0.009_287_9),
                f(7.0).round(),
                f(8.1e-5),
                f(2e-4),
                f(5e-3),
            ];
            let off = rng.range(0, 4095);
            let dir = if rng.range(0, 1) == 0 { 1 } else { -1 };
            (m, off, dir)
        })
        .collect();
    // The README's walk-through motor, beside the random ones.
    let walk = ([0.7, 0.9e-3, 0.012, 5.0, 1e-4, 2e-4, 5e-3], 1000, 1);
    std::thread::scope(|sc| {
        for (draw, d) in draws.iter().enumerate() {
            sc.spawn(move || one_draw(draw, d));
        }
        sc.spawn(move || one_draw(3, &walk));
    });
}

fn one_draw(draw: usize, &(m, off, dir): &([f64; 7], i32, i32)) {
    let [r_s, l, psi, p, j, b, c] = m;
    let mut s = boot();
    for (n, v) in [
        ("r_s", r_s),
        ("l", l),
        ("psi_pm", psi),
        ("pole_pairs", p),
        ("j", j),
        ("b", b),
        ("coulomb", c),
        ("enc_offset", f64::from(off)),
        ("enc_dir", f64::from(dir)),
        ("locked", 0.0),
    ] {
        assert_ok(&cmd(&mut s, &format!("sim set {n} {v}")));
    }
    let r = calibrate(&mut s, "calibrate all");
    // The transcript (draw 3: the README's walk-through).
    let mut t = format!("draw {draw}:\n");
    for (n, v) in [("r_s", r_s), ("l", l), ("psi_pm", psi), ("pole_pairs", p)] {
        t += &format!("drive> sim set {n} {v}\n");
    }
    t += &format!(
        "drive> sim set j {j}\ndrive> sim set b {b}\ndrive> sim set coulomb {c}\n\
         drive> sim set enc_offset {off}\ndrive> sim set enc_dir {dir}\n\
         drive> sim set locked 0\ndrive> calibrate all\n"
    );
    for l in &r.lines {
        t += &format!("{l}\n");
    }
    t += &format!("{:?}\n", r.fin);
    eprintln!("{t}");
    let rel = |est: f64, t: f64| (est / t - 1.0).abs();
    assert_eq!(
        result(&r, "encoder_direction"),
        Some(f64::from(dir)),
        "{r:?}"
    );
    assert_eq!(result(&r, "motor_pole_pairs"), Some(p), "{r:?}");
    let zero = result(&r, "enc_zero").unwrap();
    let d = (zero - f64::from(off)) * p * 360.0 / 4096.0;
    let d = d - 360.0 * (d / 360.0).round();
    assert!(d.abs() < 1.0, "offset {d} el deg: {r:?}");
    assert!(rel(result(&r, "motor_r_s").unwrap(), r_s) < 0.03, "{r:?}");
    assert!(rel(result(&r, "motor_l").unwrap(), l) < 0.03, "{r:?}");
    assert!(
        rel(result(&r, "motor_psi_pm").unwrap(), psi) < 0.02,
        "{r:?}"
    );
    assert!(rel(result(&r, "load_inertia").unwrap(), j) < 0.10, "{r:?}");
    if dir > 0 {
        // Everything applied.
        assert_ok(&r);
        assert_eq!(config(&mut s, "enc_zero"), zero);
        assert_eq!(config(&mut s, "motor_pole_pairs"), p);
        assert!(rel(config(&mut s, "motor_r_s"), r_s) < 0.03);
    } else {
        // An encoder counting backwards is reported and the run applies
        // nothing (the configured R stays the default, 0.555 ohm).
        assert_err(&r, "calibration");
        assert_eq!(config(&mut s, "enc_zero"), 0.0);
        assert_eq!(config(&mut s, "motor_r_s"), 0.555);
    }
}
