//! The PL capture buffer and the frequency response under QEMU, through the
//! console: `capture arm|trigger|status|dump` and `sweep` on the simulated
//! PL, bad arguments included.
use drivectl::link::{Reply, Session};
use std::time::Duration;
use system_tests::{assert_err, assert_ok, boot, cmd, field, num};

/// Polls `capture status` until the record is complete.
fn wait_done(s: &mut Session) -> Reply {
    for _ in 0..200 {
        let st = cmd(s, "capture status");
        if field(&st, "capture") == Some("done") {
            return st;
        }
        std::thread::sleep(std::time::Duration::from_millis(100));
    }
    panic!("capture did not complete");
}

#[test]
fn bad_capture_and_sweep_arguments_change_nothing() {
    let mut s = boot();
    let st = cmd(&mut s, "capture status");
    assert_ok(&st);
    assert_eq!(field(&st, "capture"), Some("idle"), "{st:?}");
    for bad in [
        "capture",
        "capture arm",
        "capture arm bogus",
        "capture arm torque>abc",
        "capture arm torque>nan",
        "capture arm speed>1",
        "capture arm torque>0.1<0.2",
        "capture arm manual 1024",
        "capture arm manual -1",
        "capture arm manual 10 0",
        "capture arm manual 10 257",
        "capture arm manual 10 2.5",
        "capture arm manual 10 2 3",
        "capture dumpp",
        "sweep",
        "sweep 100",
        "sweep 100 50 0.1",
        "sweep 0 100 0.1",
        "sweep 100 1000 nan",
        "sweep 100 1000 0.1 1",
        "sweep 100 1000 0.1 33",
        "sweep 100 inf 0.1",
    ] {
        assert_err(&cmd(&mut s, bad), "bad-args");
    }
    // Nothing was armed by the refused lines; no record to dump.
    let st = cmd(&mut s, "capture status");
    assert_eq!(field(&st, "capture"), Some("idle"), "{st:?}");
    assert_err(&cmd(&mut s, "capture dump"), "bad-args");
    // A sweep needs a mode and the gates.
    assert_err(&cmd(&mut s, "sweep 100 1000 0.1 2"), "mode-off");
    assert_ok(&cmd(&mut s, "mode mpdtc"));
    assert_err(&cmd(&mut s, "sweep 100 1000 0.1 2"), "gates-off");
    assert_ok(&cmd(&mut s, "enable"));
    // Beyond the torque limit, and above a quarter of the control rate.
    assert_err(&cmd(&mut s, "sweep 100 1000 1.5 2"), "bad-args");
    assert_err(&cmd(&mut s, "sweep 100 20000 0.1 2"), "bad-args");
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "gates"), Some("on"), "{st:?}");
    assert!(num(&st, "torque_ref").abs() < 1e-9, "{st:?}");
}

/// A step captured with its pre-trigger part: the record's trigger sample
/// is at t = 0 with the new reference, the samples before it hold the old
/// one, and the torque settles at the reference.
#[test]
fn capture_dump_shows_an_mpdtc_step_with_pre_trigger() {
    let mut s = boot();
    assert_ok(&cmd(&mut s, "mode mpdtc"));
    assert_ok(&cmd(&mut s, "enable"));
    assert_ok(&cmd(&mut s, "capture arm step 100"));
    let st = cmd(&mut s, "capture status");
    assert_eq!(field(&st, "capture"), Some("armed"), "{st:?}");
    let ts_us = num(&st, "sample_period");
    assert!((ts_us - 15.64).abs() < 0.01, "{st:?}");
    // The step waits for the MPDTC's alignment (0.2 s of PL time, up to
    // 150 times that under QEMU on a loaded host).
    let r = s.command("step 0.4", Duration::from_secs(60)).unwrap();
    assert_ok(&r);
    let st = wait_done(&mut s);
    assert_eq!(num(&st, "samples"), 1024.0, "{st:?}");
    assert_eq!(num(&st, "trigger_index"), 100.0, "{st:?}");
    let d = cmd(&mut s, "capture dump");
    assert_ok(&d);
    assert_eq!(
        d.lines[0],
        "t_ms,i_d_A,i_q_A,torque_Nm,torque_ref_Nm,sw_state,adc_ia_raw,position_counts,\
         velocity_rev_s,following_error_counts"
    );
    let rows: Vec<Vec<f64>> = d.lines[1..]
        .iter()
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 1024);
    assert!(rows.iter().all(|r| r.len() == 10));
    // Locked rotor, torque loop: the position does not change, and the
    // following error is 0.
    assert!(
        rows.iter().all(|r| r[7] == rows[0][7] && r[9] == 0.0),
        "{:?}",
        rows.iter().find(|r| r[7] != rows[0][7] || r[9] != 0.0)
    );
    // t = 0 at the trigger sample; sample period 15.64 us.
    assert_eq!(rows[100][0], 0.0);
    assert!(
        (rows[101][0] - ts_us * 1e-3).abs() < 1e-4,
        "{:?}",
        rows[101]
    );
    assert_eq!((rows[99][4], rows[100][4]), (0.0, 0.4));
    assert!(rows[99][3].abs() < 0.05, "{:?}", rows[99]);
    // Settled after 1 ms: the mean of the last 500 samples is 0.4 N m.
    let tail = &rows[524..];
    let mean = tail.iter().map(|r| r[3]).sum::<f64>() / tail.len() as f64;
    assert!((mean - 0.4).abs() < 0.02, "{mean}");
    // Switching states 0..=7 only, and the drive switched.
    assert!(rows.iter().all(|r| (0.0..=7.0).contains(&r[5])));
    assert!(rows[100..].windows(2).any(|w| w[0][5] != w[1][5]));
}

/// A manual trigger in FOC: the sample period is one PWM period.
#[test]
fn manual_capture_in_foc_at_the_pwm_rate() {
    let mut s = boot();
    assert_ok(&cmd(&mut s, "mode foc"));
    assert_ok(&cmd(&mut s, "capture arm manual 0"));
    let st = cmd(&mut s, "capture status");
    assert!((num(&st, "sample_period") - 62.56).abs() < 0.01, "{st:?}");
    assert_ok(&cmd(&mut s, "capture trigger"));
    let st = wait_done(&mut s);
    assert_eq!(num(&st, "trigger_index"), 0.0, "{st:?}");
}

/// `sweep` in both modes: one `f_hz gain_db phase_deg` line per point and
/// the bandwidth; at the lowest frequency the torque follows the reference
/// (near 0 dB, little lag).
#[test]
fn sweep_prints_the_frequency_response_in_both_modes() {
    let mut s = boot();
    for (mode, line) in [
        ("mpdtc", "sweep 300 12000 0.2 3"),
        ("foc", "sweep 200 3000 0.2 3"),
    ] {
        if mode == "mpdtc" {
            // The PS-fed path: the autonomous loop takes the reference one
            // period later and gives -1.51 dB at 300 Hz (the bound below is
            // this path's).
            assert_ok(&cmd(&mut s, "config set mpdtc_ps_fed 1"));
        }
        assert_ok(&cmd(&mut s, &format!("mode {mode}")));
        assert_ok(&cmd(&mut s, "enable"));
        let r = cmd(&mut s, line);
        assert_ok(&r);
        assert_eq!(r.lines[0], "f_hz gain_db phase_deg", "{r:?}");
        let pts: Vec<Vec<f64>> = r.lines[1..4]
            .iter()
            .map(|l| l.split(' ').map(|x| x.parse().unwrap()).collect())
            .collect();
        assert!(
            pts[0][1].abs() < 1.5 && pts[0][2].abs() < 30.0,
            "{mode}: {r:?}"
        );
        assert!(pts[2][1] < pts[0][1], "{mode}: {r:?}");
        assert!(r.lines[4].starts_with("bandwidth: "), "{r:?}");
        // The reference is back at 0 after the sweep.
        let st = cmd(&mut s, "status");
        assert!(num(&st, "torque_ref").abs() < 1e-9, "{st:?}");
    }
}

/// A `move` recorded by the capture buffer: `capture arm manual 0 16` (one
/// sample every 16 control periods: 256 ms of record for the default
/// gains' 200 ms move), then `move 1` restarts and triggers the record. The
/// position channel travels the revolution (4096 counts) and ends within a
/// count of it, the velocity channel peaks at the trajectory's 10 rev/s
/// (a triangle at 100 rev/s^2 over 1 rev: sqrt(100 x 1)), the following
/// error stays within the move's figure.
#[test]
fn capture_records_a_move_with_position_velocity_and_following_error() {
    let mut s = boot();
    assert_ok(&cmd(&mut s, "sim set locked 0"));
    assert_ok(&cmd(&mut s, "mode mpdtc"));
    assert_ok(&cmd(&mut s, "enable"));
    let a = cmd(&mut s, "capture arm manual 0 16");
    assert_ok(&a);
    let ts_us = num(&a, "sample_period");
    assert!((ts_us - 16.0 * 15.64).abs() < 0.1, "{a:?}");
    // The move waits for the MPDTC's alignment (as `step 0.4` above).
    let r = s.command("move 1", Duration::from_secs(60)).unwrap();
    assert_ok(&r);
    let st = wait_done(&mut s);
    assert_eq!(num(&st, "trigger_index"), 0.0, "{st:?}");
    let d = cmd(&mut s, "capture dump");
    let rows: Vec<Vec<f64>> = d.lines[1..]
        .iter()
        .map(|l| l.split(',').map(|x| x.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 1024);
    let (p0, p1) = (rows[0][7], rows[1023][7]);
    let vmax = rows.iter().map(|r| r[8]).fold(f64::MIN, f64::max);
    let fe = rows.iter().map(|r| r[9].abs()).fold(0.0, f64::max);
    let first = rows.iter().position(|r| r[4] != 0.0).unwrap();
    println!(
        "move record: {p0} -> {p1} counts, peak {vmax} rev/s, |following error| <= {fe} counts, \
         torque reference from sample {first}; move: {:?}",
        r.lines
    );
    assert!((p1 - p0 - 4096.0).abs() <= 1.0, "{p0} -> {p1}");
    assert!((vmax - 10.0).abs() < 0.5, "{vmax}");
    // The record's following error (1/16 count, every 8th period) within
    // the move's own maximum (every period, printed to a count).
    assert!(fe <= num(&r, "max_following_error") + 0.5, "{fe} vs {r:?}");
}
