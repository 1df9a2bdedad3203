//! The outer loops under QEMU, through the console, on the simulated PL
//! with a free rotor (`sim set locked 0`): `move` in both torque loops
//! against the host simulation of the same code (`drivectl::motion`),
//! `imp` stiffness under a load, `vel`, refusals and the soft limit.
use drive::pl::top::Mode;
use drivectl::link::Session;
use std::time::{Duration, Instant};
use system_tests::{assert_err, assert_ok, boot, field, num};

/// Long enough for a move under QEMU.
const SLOW: Duration = Duration::from_secs(300);

fn cmd(s: &mut Session, line: &str) -> drivectl::link::Reply {
    match s.command(line, SLOW) {
        Ok(r) => r,
        Err(e) => panic!(
            "{line:?}: {e:#}\ntranscript:\n{}",
            String::from_utf8_lossy(&s.transcript)
        ),
    }
}

/// `move 1` in `mode`: the move figures, and the host simulation's
/// figures within a count.
fn move_one(mode: &str, m: Mode) {
    let mut s = boot();
    assert_ok(&cmd(&mut s, "sim set locked 0"));
    assert_ok(&cmd(&mut s, &format!("mode {mode}")));
    assert_ok(&cmd(&mut s, "enable"));
    let t0 = Instant::now();
    let r = cmd(&mut s, "move 1");
    assert_ok(&r);
    println!(
        "{mode}: move 1 under QEMU in {:.1} s wall: {:?}",
        t0.elapsed().as_secs_f64(),
        r.lines
    );
    let final_error = num(&r, "final_error");
    let settling = num(&r, "settling_time");
    assert!(final_error.abs() <= 1.0, "{r:?}");
    assert!(settling <= 5.0, "{r:?}");
    assert!(num(&r, "overshoot") <= 2.0, "{r:?}");
    // The default 100 rev/s^2: a 200 ms triangle.
    assert!((num(&r, "move_time") - 200.0).abs() < 1e-6, "{r:?}");
    let (h, _) = drivectl::motion::run_move(m, &[("locked", 0.0)], 1.0, 0.02).unwrap();
    println!("{mode}: move 1 on the host: {h:?}");
    assert!(
        (final_error - h.final_error_counts).abs() <= 1.0,
        "{r:?} vs {h:?}"
    );
    assert!(
        (num(&r, "max_following_error") - h.max_following_error_counts).abs() <= 1.0,
        "{r:?} vs {h:?}"
    );
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "loop"), Some("position"), "{st:?}");
    assert_eq!(field(&st, "fault"), Some("none"), "{st:?}");
    assert_eq!(num(&st, "overruns"), 0.0, "{st:?}");
}

#[test]
fn move_one_revolution_mpdtc() {
    move_one("mpdtc", Mode::Mpdtc);
}

#[test]
fn move_one_revolution_foc() {
    move_one("foc", Mode::Foc);
}

/// Control periods run (from `status`).
fn periods(s: &mut Session) -> u64 {
    num(&cmd(s, "status"), "periods") as u64
}

/// Waits until `n` more control periods have run; the `status` then.
fn run_periods(s: &mut Session, n: u64) -> drivectl::link::Reply {
    let p0 = periods(s);
    let end = Instant::now() + SLOW;
    loop {
        let st = cmd(s, "status");
        if num(&st, "periods") as u64 >= p0 + n {
            return st;
        }
        assert!(Instant::now() < end, "{st:?}");
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// FOC on a free rotor, gates on.
fn free_rotor_foc(s: &mut Session) {
    assert_ok(&cmd(s, "sim set locked 0"));
    assert_ok(&cmd(s, "mode foc"));
    assert_ok(&cmd(s, "enable"));
}

#[test]
fn impedance_stiffness_under_a_load_is_kp() {
    // kp = 2 N m/rev against 0.2 N m of load: 0.1 rev = 409.6 counts of
    // deflection; kd = 0.064 N m s/rev damps the 10 Hz spring-inertia
    // pair critically (2 sqrt(k J) per rad, x 2 pi per rev).
    let mut s = boot();
    assert_ok(&cmd(&mut s, "sim set load_torque 0.2"));
    free_rotor_foc(&mut s);
    let r = cmd(&mut s, "imp 0 0 2 0.064 0");
    assert_ok(&r);
    // 0.2 s: 12 time constants of the critically damped pair.
    let a = run_periods(&mut s, 3200);
    let b = run_periods(&mut s, 320);
    let (pa, pb) = (num(&a, "position"), num(&b, "position"));
    assert!((pa - pb).abs() <= 1.5 / 4096.0, "not at rest: {a:?} {b:?}");
    let stiffness = 0.2 / -pb;
    println!("imp kp 2 Nm/rev under 0.2 Nm: deflection {pb} rev, stiffness {stiffness} Nm/rev");
    assert!((stiffness / 2.0 - 1.0).abs() <= 0.02, "{b:?}");
    assert_eq!(field(&b, "loop"), Some("impedance"), "{b:?}");
    assert_eq!(field(&b, "fault"), Some("none"), "{b:?}");
}

#[test]
fn velocity_loop_reaches_10_rev_s() {
    let mut s = boot();
    free_rotor_foc(&mut s);
    assert_ok(&cmd(&mut s, "vel 10"));
    // The ramp takes 100 ms at the default 100 rev/s^2; 20 ms more to
    // settle (16 kHz FOC periods).
    let a = run_periods(&mut s, 1920);
    let b = run_periods(&mut s, 320);
    let dp = num(&b, "position") - num(&a, "position");
    let dt = (num(&b, "periods") - num(&a, "periods")) / num(&b, "control_rate");
    let v = dp / dt;
    println!(
        "vel 10: {v} rev/s from the position, {} rev/s estimated",
        num(&b, "velocity")
    );
    assert!((v / 10.0 - 1.0).abs() <= 0.02, "{v} rev/s: {a:?} {b:?}");
    assert!((num(&b, "velocity") / 10.0 - 1.0).abs() <= 0.02, "{b:?}");
    assert_eq!(field(&b, "loop"), Some("velocity"), "{b:?}");
}

#[test]
fn bad_arguments_are_refused_and_change_nothing() {
    let mut s = boot();
    let list = cmd(&mut s, "sim list");
    assert_ok(&list);
    assert!(
        list.lines
            .iter()
            .any(|l| l.starts_with("j = 0.000081 kg m^2  [")),
        "{list:?}"
    );
    for bad in [
        "sim set j -1",
        "sim set j nan",
        "sim set pole_pairs 2.5",
        "sim set enc_dir 0",
        "sim set locked 2",
        "sim set enc_offset 4096",
        "sim set no_such 1",
        "sim set load_torque",
    ] {
        assert_err(&cmd(&mut s, bad), "bad-args");
    }
    assert_eq!(cmd(&mut s, "sim list").lines, list.lines);
    assert_ok(&cmd(&mut s, "mode foc"));
    assert_ok(&cmd(&mut s, "enable"));
    assert_ok(&cmd(&mut s, "torque 0.1"));
    for bad in [
        "pos 5000",
        "pos inf",
        "pos",
        "vel 100",
        "vel -51",
        "vel x",
        "imp 0 0 -1 0 0",
        "imp 0 0 1 2 0",
        "imp 0 0 21 0 0",
        "imp 0 0 1 0 1.5",
        "imp 0 0 1 0",
        "imp 2000 0 1 0 0",
        "move 1 0",
        "move 1 501",
    ] {
        assert_err(&cmd(&mut s, bad), "bad-args");
    }
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "loop"), Some("torque"), "{st:?}");
    assert_eq!(num(&st, "torque_ref"), 0.1, "{st:?}");
    assert_eq!(field(&st, "gates"), Some("on"), "{st:?}");
}

#[test]
fn leaving_the_soft_limits_latches_position_limit_with_the_gates_off() {
    let mut s = boot();
    assert_ok(&cmd(&mut s, "config set pos_max 0.25"));
    free_rotor_foc(&mut s);
    // 0.5 N m on the bare rotor: about 980 rev/s^2, past 0.25 rev in 23 ms.
    assert_ok(&cmd(&mut s, "imp 0 0 0 0 0.5"));
    let end = Instant::now() + SLOW;
    let st = loop {
        let st = cmd(&mut s, "status");
        if field(&st, "fault") != Some("none") {
            break st;
        }
        assert!(Instant::now() < end, "{st:?}");
        std::thread::sleep(Duration::from_millis(20));
    };
    assert_eq!(field(&st, "fault"), Some("POSITION_LIMIT"), "{st:?}");
    assert_eq!(field(&st, "gates"), Some("off"), "{st:?}");
    assert_eq!(field(&st, "loop"), Some("torque"), "{st:?}");
    assert!(num(&st, "position") > 0.25, "{st:?}");
    let h = cmd(&mut s, "fault history");
    assert!(
        h.lines
            .iter()
            .any(|l| l.contains(" code 7 POSITION_LIMIT: ")),
        "{h:?}"
    );
    assert_err(&cmd(&mut s, "enable"), "fault-latched");
}

/// `sim set locked 0`, `mode mpdtc`, `enable`, `move 1 5` sent in one
/// write (the move is armed during the rotor alignment and starts at its
/// end on both PLs); the move's reply.
fn move_in_one_write(s: &mut Session) -> drivectl::link::Reply {
    s.send(b"sim set locked 0\rmode mpdtc\renable\rmove 1 5\r")
        .unwrap();
    let mut last = None;
    for _ in 0..4 {
        let text = s
            .read_until(drivectl::link::PROMPT.as_bytes(), SLOW)
            .unwrap_or_else(|e| panic!("{e:#}: {}", String::from_utf8_lossy(&s.transcript)));
        let r = drivectl::link::parse_reply(&String::from_utf8_lossy(&text)).unwrap();
        assert_ok(&r);
        last = Some(r);
    }
    last.unwrap()
}

/// The same move on the Verilated `pl_top` (co-simulation) as on the
/// simulated PL: the figures within 5 % (a count where they are counts
/// near 0). Its PL time is the alignment, the 90 ms move and a 5 ms
/// window: the longest co-simulation test (about 100 ms of PL time, 10^7
/// PL cycles; 23 s of CPU time, docs/speed.md).
/// A 2 ms alignment (the default 0.2 s is most of a minute of wall time
/// in co-simulation): a fresh boot's rotor starts on the d axis (angle 0).
/// The configuration write costs no control step (no overrun, no fault).
/// The bare rotor's tuned gains (the README's gain rule for its known
/// inertia, rounded): a 90 ms move instead of the default 200 ms, less PL
/// time to co-simulate.
fn short_align(s: &mut Session) {
    assert_ok(&cmd(s, "config set mpdtc_align_time 200000"));
    for (name, v) in [
        ("traj_accel_limit", 500.0),
        ("vel_kp", 0.25),
        ("vel_ki", 30.0),
        ("pos_kp", 100.0),
    ] {
        assert_ok(&cmd(s, &format!("config set {name} {v}")));
    }
    let st = cmd(s, "status");
    assert_eq!(num(&st, "overruns"), 0.0, "{st:?}");
    assert_eq!(field(&st, "fault"), Some("none"), "{st:?}");
}

#[test]
fn move_one_revolution_on_the_rtl_matches_the_simulated_pl() {
    let mut rtl = system_tests::boot_rtl();
    short_align(&mut rtl);
    let t0 = Instant::now();
    let r_rtl = move_in_one_write(&mut rtl);
    let wall = t0.elapsed().as_secs_f64();
    let mut sim = boot();
    short_align(&mut sim);
    let r_sim = move_in_one_write(&mut sim);
    println!("move 1 on the RTL in {wall:.1} s wall: {:?}", r_rtl.lines);
    println!("move 1 on the simulated PL: {:?}", r_sim.lines);
    assert!(num(&r_rtl, "final_error").abs() <= 1.0, "{r_rtl:?}");
    assert!(num(&r_rtl, "settling_time") <= 5.0, "{r_rtl:?}");
    assert_eq!(num(&r_rtl, "move_time"), num(&r_sim, "move_time"));
    for key in [
        "max_following_error",
        "final_error",
        "overshoot",
        "settling_time",
    ] {
        let (a, b) = (num(&r_rtl, key), num(&r_sim, key));
        assert!(
            (a - b).abs() <= 0.05 * b.abs() || (a - b).abs() <= 1.0,
            "{key}: RTL {a}, simulated PL {b}"
        );
    }
    // The figures agree within a count (the loop above), not closer: the
    // control step's position is ENC_POS_SAMPLE, latched at the boundary on
    // both PLs, but the step's torque-reference write still lands at a
    // guest-time latency, which host load moves (QEMU without -icount on
    // the simulated PL): the maximum following error measured 1.0..1.1
    // counts on the simulated PL and 1.1..1.2 on the RTL on an idle
    // machine, 1.4 and 1.7 in one run beside two busy loops (`scripts/bench
    // flaky`: a bound of 0.2 count failed one loaded run in 14). The PL's
    // own arithmetic is held bit-exact by the RTL tests, not here.
    let st = cmd(&mut rtl, "status");
    assert_eq!(field(&st, "fault"), Some("none"), "{st:?}");
    assert_eq!(num(&st, "overruns"), 0.0, "{st:?}");
    let stats = rtl
        .finish_bridge()
        .expect("a bridge")
        .expect("its statistics");
    assert!(stats.contains("\"mismatches\":0"), "{stats}");
}

/// `pos zero` right after `enable` in MPDTC (one write: the firmware takes
/// it within the alignment, however busy the host) answers `ERR aligning`
/// and zeroes nothing; once `status` no longer shows the alignment it is
/// taken, and `move 1` then holds the rotor at 1 rev: `status`, the move's
/// target and its final error agree (a zero taken during the alignment,
/// which still turned the rotor, left the hold 108 counts short of 1 rev).
#[test]
fn pos_zero_during_the_mpdtc_alignment_is_refused_until_it_ends() {
    let mut s = boot();
    s.send(b"sim set locked 0\rmode mpdtc\renable\rpos zero\r")
        .unwrap();
    let mut replies = Vec::new();
    for _ in 0..4 {
        let text = s
            .read_until(drivectl::link::PROMPT.as_bytes(), SLOW)
            .unwrap_or_else(|e| panic!("{e:#}: {}", String::from_utf8_lossy(&s.transcript)));
        replies.push(drivectl::link::parse_reply(&String::from_utf8_lossy(&text)).unwrap());
    }
    for r in &replies[..3] {
        assert_ok(r);
    }
    assert_err(&replies[3], "aligning");
    let end = Instant::now() + SLOW;
    loop {
        let st = cmd(&mut s, "status");
        if !st.lines.iter().any(|l| l.starts_with("alignment: running")) {
            break;
        }
        assert!(Instant::now() < end, "{st:?}");
    }
    assert_ok(&cmd(&mut s, "pos zero"));
    let st = cmd(&mut s, "status");
    assert!(num(&st, "position").abs() <= 1.0 / 4096.0, "{st:?}");
    let r = cmd(&mut s, "move 1");
    assert_ok(&r);
    assert!(num(&r, "final_error").abs() <= 2.0, "{r:?}");
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "loop"), Some("position"), "{st:?}");
    assert_eq!(num(&st, "position_ref"), 1.0, "{st:?}");
    assert!((num(&st, "position") - 1.0).abs() <= 2.0 / 4096.0, "{st:?}");
}

/// A load the drive was not told about, with the default gains (the
/// corners of `drivectl`'s `motion::tests::robustness_table` under QEMU):
/// the true inertia 10 times `load_inertia` in MPDTC and 0.3 times in FOC,
/// each with Coulomb friction of 5 % of the 1 N m torque limit; `move 1`
/// with a 300 ms window settles into +-2 counts and ends there, within a
/// count of the host simulation's final error.
#[test]
fn a_move_on_a_load_it_was_not_told_about_ends_within_two_counts() {
    for (jm, mode, m) in [(10.0, "mpdtc", Mode::Mpdtc), (0.3, "foc", Mode::Foc)] {
        let j = 8.1e-5 * jm;
        let mut s = boot();
        for c in [
            "sim set locked 0".to_string(),
            format!("sim set j {j}"),
            "sim set coulomb 0.05".to_string(),
            format!("mode {mode}"),
            "enable".to_string(),
        ] {
            assert_ok(&cmd(&mut s, &c));
        }
        let end = Instant::now() + SLOW;
        while cmd(&mut s, "status")
            .lines
            .iter()
            .any(|l| l.starts_with("alignment: running"))
        {
            assert!(Instant::now() < end, "alignment");
        }
        let r = cmd(&mut s, "move 1 300");
        if r.fin != drivectl::link::Final::Ok {
            let st = cmd(&mut s, "status");
            let h = cmd(&mut s, "fault history");
            panic!("{jm}x, {mode}: {r:?}\n{st:?}\n{h:?}");
        }
        println!("{jm}x, {mode}: {:?}", r.lines);
        assert!(num(&r, "settling_time") < 300.0, "{r:?}");
        let fe = num(&r, "final_error");
        assert!(fe.abs() <= 2.0, "{r:?}");
        let sim = [("locked", 0.0), ("j", j), ("coulomb", 0.05)];
        let (h, _) = drivectl::motion::run_move(m, &sim, 1.0, 0.3).unwrap();
        assert!((fe - h.final_error_counts).abs() <= 1.0, "{r:?} vs {h:?}");
        let st = cmd(&mut s, "status");
        assert_eq!(field(&st, "fault"), Some("none"), "{st:?}");
    }
}
