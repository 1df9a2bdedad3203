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

/// `move 1` in `mode`: the acceptance figures, and the host simulation's
/// figures within a count.
fn move_one(mode: &str, m: Mode) {
    let mut s = boot();
    assert_ok(&cmd(&mut s, "sim set locked 0"));
    assert_ok(&cmd(&mut s, &format!("mode {mode}")));
    assert_ok(&cmd(&mut s, "enable"));
    let t0 = Instant::now();
    let r = cmd(&mut s, "move 1");
    assert_ok(&r);
    println!("{mode}: move 1 under QEMU in {:.1} s wall: {:?}", t0.elapsed().as_secs_f64(), r.lines);
    let final_error = num(&r, "final_error");
    let settling = num(&r, "settling_time");
    assert!(final_error.abs() <= 1.0, "{r:?}");
    assert!(settling <= 5.0, "{r:?}");
    assert!(num(&r, "overshoot") <= 2.0, "{r:?}");
    assert!((num(&r, "move_time") - 90.0).abs() < 1e-6, "{r:?}");
    let (h, _) = drivectl::motion::run_move(m, &[("locked", 0.0)], 1.0, 0.02).unwrap();
    println!("{mode}: move 1 on the host: {h:?}");
    assert!((final_error - h.final_error_counts).abs() <= 1.0, "{r:?} vs {h:?}");
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
