//! The drive under QEMU, through the console: the firmware's control code
//! (FOC on the PS, the MPDTC core's inputs) on the simulated PL and motor.
//! Figures: the host simulation's settling times (README, paper 000
//! results) plus 10 %: FOC <= 0.27 ms, MPDTC <= 0.19 ms for a 0.4 N m step.
use drivectl::link::Session;
use std::time::Duration;
use system_tests::{assert_err, assert_ok, boot, cmd, field, num};

/// `mode`, `enable`, `step 0.4`: settling within `limit_ms`, then `status`
/// shows the torque within 0.05 N m of 0.4 and `disable` turns the gates off.
fn step_in_mode(s: &mut Session, mode: &str, limit_ms: f64) {
    assert_ok(&cmd(s, &format!("mode {mode}")));
    assert_ok(&cmd(s, "enable"));
    let r = cmd(s, "step 0.4");
    assert_ok(&r);
    let settling = num(&r, "settling_time");
    assert!(
        settling <= limit_ms,
        "{mode}: settling {settling} ms > {limit_ms} ms: {r:?}"
    );
    assert!(num(&r, "overshoot") >= 0.0, "{r:?}");
    assert!(num(&r, "switching") > 0.0, "{r:?}");
    assert!((num(&r, "final") - 0.4).abs() < 0.05, "{r:?}");
    let st = cmd(s, "status");
    assert_eq!(field(&st, "mode"), Some(mode), "{st:?}");
    assert_eq!(field(&st, "gates"), Some("on"), "{st:?}");
    assert_eq!(field(&st, "fault"), Some("none"), "{st:?}");
    assert!((num(&st, "torque") - 0.4).abs() < 0.05, "{st:?}");
    assert!((num(&st, "torque_ref") - 0.4).abs() < 1e-9, "{st:?}");
    // A second `step 0.4` is a step of zero: refused, nothing changes.
    assert_err(&cmd(s, "step 0.4"), "bad-args");
    let st = cmd(s, "status");
    assert!((num(&st, "torque_ref") - 0.4).abs() < 1e-9, "{st:?}");
    assert_eq!(field(&st, "gates"), Some("on"), "{st:?}");
    assert_ok(&cmd(s, "disable"));
    let st = cmd(s, "status");
    assert_eq!(field(&st, "gates"), Some("off"), "{st:?}");
}

#[test]
fn foc_step_settles_within_the_host_figure() {
    let mut s = boot();
    step_in_mode(&mut s, "foc", 0.27);
    let st = cmd(&mut s, "status");
    let rate = num(&st, "control_rate");
    assert!((rate / 16_000.0 - 1.0).abs() < 0.002, "{st:?}");
}

#[test]
fn mpdtc_step_settles_within_the_host_figure() {
    let mut s = boot();
    step_in_mode(&mut s, "mpdtc", 0.19);
    let st = cmd(&mut s, "status");
    let rate = num(&st, "control_rate");
    assert!((rate / 64_000.0 - 1.0).abs() < 0.002, "{st:?}");
    assert!(num(&st, "periods") > 0.0, "{st:?}");
}

#[test]
fn status_reports_the_simulated_pl_and_its_time_scale() {
    let mut s = boot();
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "pl"), Some("simulated"), "{st:?}");
    assert!(num(&st, "sim_time_scale") > 0.0, "{st:?}");
    for key in [
        "mode",
        "gates",
        "fault",
        "torque",
        "torque_ref",
        "i_d",
        "i_q",
        "speed",
        "control_rate",
        "periods",
        "overruns",
    ] {
        assert!(field(&st, key).is_some(), "{key}: {st:?}");
    }
    assert_eq!(field(&st, "mode"), Some("off"));
    assert_eq!(field(&st, "gates"), Some("off"));
}

#[test]
fn bad_mode_and_torque_arguments_leave_the_state_unchanged() {
    let mut s = boot();
    assert_ok(&cmd(&mut s, "mode foc"));
    assert_ok(&cmd(&mut s, "torque 0.25"));
    // Refused in mode off and with the gates off.
    for bad in [
        "mode FOC",
        "mode 2",
        "mode on",
        "mode foc mpdtc",
        "torque nan",
        "torque NaN",
        "torque inf",
        "torque -inf",
        "torque infinity",
        "torque 1.01",
        "torque -5",
        "torque 1e9",
        "torque x",
        "torque 0.1Nm",
        "torque 0.1 0.2",
    ] {
        assert_err(&cmd(&mut s, bad), "bad-args");
    }
    let r = cmd(&mut s, "mode");
    assert_eq!(r.lines, ["mode: foc"], "{r:?}");
    let r = cmd(&mut s, "torque");
    assert_eq!(r.lines, ["torque_ref: 0.2500 Nm"], "{r:?}");
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "gates"), Some("off"), "{st:?}");
    // Gates are refused in mode off; step is refused with the gates off.
    assert_err(&cmd(&mut s, "step 0.4"), "gates-off");
    assert_ok(&cmd(&mut s, "mode off"));
    assert_err(&cmd(&mut s, "enable"), "mode-off");
}

/// The stall lasts 300 ms of PL time (the simulated PL's), far beyond the
/// 2 ms watchdog; in guest time it takes sim_time_scale times longer.
#[test]
fn a_stalled_control_loop_trips_the_watchdog() {
    let mut s = boot();
    assert_ok(&cmd(&mut s, "mode foc"));
    assert_ok(&cmd(&mut s, "enable"));
    let r = s
        .command("debug stall 300", Duration::from_secs(120))
        .expect("the stall ends");
    assert_eq!(r.lines, ["stalled: 300 ms"], "{r:?}");
    assert_ok(&r);
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "fault"), Some("WATCHDOG"), "{st:?}");
    assert_eq!(field(&st, "gates"), Some("off"), "{st:?}");
    assert_err(&cmd(&mut s, "enable"), "fault-latched");
    let r = cmd(&mut s, "fault");
    assert_eq!(r.lines, ["fault: WATCHDOG"], "{r:?}");
    assert_ok(&cmd(&mut s, "fault clear"));
    // Cleared, the gates stay off until `enable`.
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "fault"), Some("none"), "{st:?}");
    assert_eq!(field(&st, "gates"), Some("off"), "{st:?}");
    assert_ok(&cmd(&mut s, "enable"));
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "gates"), Some("on"), "{st:?}");
}

/// `mode mpdtc`, `enable`, `step 0.4`, then at once `mode foc`, `enable`,
/// `step 0.4`: the MPDTC run's current still decays when the FOC step is
/// armed; the step waits for it and is scored from rest (a settling time
/// above 0, within the FOC figure).
#[test]
fn a_foc_step_right_after_an_mpdtc_run_is_scored_from_rest() {
    let mut s = boot();
    assert_ok(&cmd(&mut s, "mode mpdtc"));
    assert_ok(&cmd(&mut s, "enable"));
    assert_ok(&cmd(&mut s, "step 0.4"));
    assert_ok(&cmd(&mut s, "mode foc"));
    assert_ok(&cmd(&mut s, "enable"));
    let r = cmd(&mut s, "step 0.4");
    assert_ok(&r);
    let settling = num(&r, "settling_time");
    assert!(settling > 0.0 && settling <= 0.27, "{r:?}");
    assert!((num(&r, "final") - 0.4).abs() < 0.05, "{r:?}");
}
