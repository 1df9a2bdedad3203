//! The control step paced by the PL's interrupt (GIC SPI 61, `IRQ_F2P[0]`)
//! under QEMU: the PL model's line pends it through the distributor, the
//! handler acknowledges `IRQ_STATUS` and reads `BOUNDARY_AGE`. Every
//! control-period boundary gets its interrupt and its step (no overrun,
//! every step from an interrupt): FOC and MPDTC for 1 s of PL time each on
//! the simulated PL; on the co-simulated RTL FOC for 0.1 s and MPDTC for
//! 1,600 periods.
use drivectl::link::{Reply, Session};
use std::time::{Duration, Instant};
use system_tests::{assert_ok, boot, boot_rtl, cmd, field, num};

/// `control_latency: min <a> mean <b> max <c> PL cycles ...` as (a, b, c).
fn latency(r: &Reply) -> (f64, f64, f64) {
    let line = r
        .lines
        .iter()
        .find_map(|l| l.strip_prefix("control_latency: "))
        .unwrap_or_else(|| panic!("no control_latency: {r:?}"));
    let w: Vec<&str> = line.split_whitespace().collect();
    assert_eq!(
        (w[0], w[2], w[4], w[6]),
        ("min", "mean", "max", "PL"),
        "{line}"
    );
    let n = |i: usize| w[i].parse::<f64>().unwrap();
    (n(1), n(3), n(5))
}

/// Runs `mode` with the gates on and 0.2 N m until `periods` control
/// periods passed (at most `wall` of wall time); returns the last status.
fn run_periods(s: &mut Session, mode: &str, periods: f64, wall: Duration) -> Reply {
    assert_ok(&cmd(s, &format!("mode {mode}")));
    assert_ok(&cmd(s, "enable"));
    assert_ok(&cmd(s, "torque 0.2"));
    let start = Instant::now();
    loop {
        std::thread::sleep(Duration::from_secs(2));
        let st = cmd(s, "status");
        assert_eq!(field(&st, "fault"), Some("none"), "{st:?}");
        assert_eq!(num(&st, "overruns"), 0.0, "{mode}: {st:?}");
        if num(&st, "periods") >= periods {
            return st;
        }
        assert!(start.elapsed() < wall, "{mode}: too slow: {st:?}");
    }
}

/// Every step came from an interrupt (`control_irq` >= `periods`; an
/// interrupt whose `IRQ_STATUS` holds no boundary runs no step, at most
/// `spurious` of them), and each step started within `max_lat` PL cycles
/// of its boundary.
fn check(st: &Reply, max_lat: f64, spurious: f64) {
    let (irq, periods) = (num(st, "control_irq"), num(st, "periods"));
    assert!(irq >= periods && irq - periods <= spurious, "{st:?}");
    let (min, mean, max) = latency(st);
    assert!(min <= mean && mean <= max && max <= max_lat, "{st:?}");
}

/// A fresh boot on the simulated PL: every period so far had its
/// interrupt (it pends SPI 61 only on its line: no spurious one); returns
/// the session and the periods counted since the boot.
fn boot_simulated() -> (Session, f64) {
    let mut s = boot();
    let st = cmd(&mut s, "status");
    assert_eq!(num(&st, "control_irq"), num(&st, "periods"), "{st:?}");
    let periods = num(&st, "periods");
    (s, periods)
}

// FOC at 16 kHz and MPDTC at 64 kHz, 1 s of PL time each, in two tests
// (two QEMUs) so the runner runs them side by side. The simulated PL's
// time stands while the guest handles the interrupt: every step starts in
// its boundary's cycle.
#[test]
fn simulated_pl_paces_foc_for_one_second_of_pl_time() {
    let (mut s, _) = boot_simulated();
    let foc = run_periods(&mut s, "foc", 16_000.0, Duration::from_secs(240));
    check(&foc, 0.0, 0.0);
}

#[test]
fn simulated_pl_paces_mpdtc_for_one_second_of_pl_time() {
    let (mut s, before) = boot_simulated();
    let mpdtc = run_periods(&mut s, "mpdtc", before + 64_000.0, Duration::from_secs(400));
    check(&mpdtc, 0.0, 0.0);
}

#[test]
fn cosimulated_rtl_paces_foc_and_mpdtc() {
    let mut s = boot_rtl();
    // FOC: 0.1 s of PL time (1,600 periods of 6,256 cycles).
    let foc = run_periods(&mut s, "foc", 1_600.0, Duration::from_secs(900));
    // The RTL runs in guest time: the latency is the PS's interrupt entry
    // and the bridge's register reads (about 45 cycles), or a console
    // critical section that held the interrupt off; always inside the
    // period, or the next boundary would count as an overrun. No
    // interrupt without a step: a boundary that a late step served is not
    // raised again.
    check(&foc, 6_256.0, 0.0);
    // MPDTC: 0.1 s of PL time too (6,400 periods of 1,564 cycles).
    let before = num(&foc, "periods");
    let mpdtc = run_periods(&mut s, "mpdtc", before + 6_400.0, Duration::from_secs(900));
    // The latency figures are since boot (FOC's included); that every
    // MPDTC step started before the next boundary is the overrun count.
    check(&mpdtc, 6_256.0, 0.0);
    let stats = s
        .finish_bridge()
        .expect("a bridge")
        .expect("its statistics");
    assert!(stats.contains("\"mismatches\":0"), "{stats}");
}

/// Waits (at most 60 s of wall time) until `periods` has grown by `n`
/// since `st`; returns the new status.
fn wait_periods(s: &mut Session, st: &Reply, n: f64) -> Reply {
    let until = num(st, "periods") + n;
    let start = Instant::now();
    loop {
        let st = cmd(s, "status");
        if num(&st, "periods") >= until {
            return st;
        }
        assert!(start.elapsed() < Duration::from_secs(60), "{st:?}");
        std::thread::sleep(Duration::from_millis(5));
    }
}

/// Co-simulation: the boundaries the PL crosses while the firmware sets
/// up (interrupts masked) are no steps owed, and the first step serves the
/// first boundary after the loop starts with the loop's own latency (it
/// used to serve a boundary of the set-up up to a period late, or the
/// next one twice: one control interrupt without a step). After a mode
/// change the next boundary is of the new kind (the PWM period start in
/// FOC, the ADC average otherwise) at a phase of its own: the first step
/// after it starts within an eighth of the new period plus the handler,
/// not up to a period late as when the tick was planned from the old
/// kind's boundary. Both hold in every run by construction: the latencies
/// are PL cycles in guest time (`-icount`), whatever the host's load.
#[test]
fn cosimulated_rtl_serves_the_first_boundary_after_boot_and_after_mode_changes() {
    let mut s = boot_rtl();
    let st = cmd(&mut s, "status");
    let st = wait_periods(&mut s, &st, 5.0);
    assert_eq!(num(&st, "control_irq"), num(&st, "periods"), "{st:?}");
    assert_eq!(num(&st, "overruns"), 0.0, "{st:?}");
    let (_, _, max) = latency(&st);
    // The step starts a handler's entry and two bridge reads after its
    // boundary (about 60 cycles; a console section of the polling
    // `status` may hold it off a few hundred more): half an MPDTC period.
    assert!(max <= 782.0, "boot: {st:?}");
    let mut st = st;
    for _ in 0..6 {
        for mode in ["foc", "off"] {
            assert_ok(&cmd(&mut s, &format!("mode {mode}")));
            st = wait_periods(&mut s, &st, 3.0);
        }
    }
    assert_eq!(num(&st, "control_irq"), num(&st, "periods"), "{st:?}");
    assert_eq!(num(&st, "overruns"), 0.0, "{st:?}");
    assert_eq!(field(&st, "fault"), Some("none"), "{st:?}");
    // FOC: 6,256 / 8 = 782 cycles of polling, the handler and a console
    // section on top.
    let (_, _, max) = latency(&st);
    assert!(max <= 1_200.0, "mode changes: {st:?}");
}
