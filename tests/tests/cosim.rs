//! The firmware under QEMU against the Verilog itself: the PL is the
//! Verilated `pl_top` with the simulated motor in the co-simulation bridge
//! (`pl-cosim`), reached over semihosting (`drivectl --pl rtl`). A subset
//! of the drive tests runs here (the co-simulation runs about 200 control
//! periods per wall second): status, the MPDTC step against the
//! simulated-PL run, torque, the FOC step, the watchdog trip and its
//! recovery. That the MPDTC takes the same decisions on both PLs is checked
//! on the host (`pl-bitstream-src/sim/tests/cosim.rs`), where the decisions
//! are visible.
use drivectl::link::{parse_reply, Reply, Session, PROMPT};
use std::time::Duration;
use system_tests::{assert_err, assert_ok, boot, boot_rtl, cmd, field, num};

/// A 2 ms MPDTC rotor alignment (the default 0.2 s is 64 s of wall time
/// in co-simulation) where the rotor starts on the d axis: a fresh boot's
/// rotor is at angle 0, and held there.
const SHORT_ALIGN: &str = "config set mpdtc_align_time 200000";

/// `SHORT_ALIGN`: a configuration write costs no control step (no
/// overrun, no fault).
fn short_align(s: &mut Session) {
    assert_ok(&cmd(s, SHORT_ALIGN));
    let st = cmd(s, "status");
    assert_eq!(num(&st, "overruns"), 0.0, "{st:?}");
    assert_eq!(field(&st, "fault"), Some("none"), "{st:?}");
}

/// `mode mpdtc`, `enable`, `step 0.4` sent in one write: the step is
/// armed during the rotor alignment (however slow the host) and starts at
/// its end, so both PLs start it from the same state. The alignment is
/// 2 ms (`short_align` first), not the default 0.2 s: the rotor is held.
fn mpdtc_step(s: &mut Session) -> Reply {
    s.send(b"mode mpdtc\renable\rstep 0.4\r").unwrap();
    let mut replies = (0..3).map(|_| {
        let text = s
            .read_until(PROMPT.as_bytes(), Duration::from_secs(60))
            .unwrap_or_else(|e| panic!("{e:#}: {}", String::from_utf8_lossy(&s.transcript)));
        parse_reply(&String::from_utf8_lossy(&text)).unwrap()
    });
    let (mode, enable, step) = (
        replies.next().unwrap(),
        replies.next().unwrap(),
        replies.next().unwrap(),
    );
    assert_eq!(mode.lines[0], "mode: mpdtc", "{mode:?}");
    assert_eq!(enable.lines, ["gates: on"], "{enable:?}");
    assert_ok(&step);
    step
}

#[test]
fn mpdtc_step_on_the_rtl_settles_within_5_percent_of_the_simulated_pl() {
    let mut rtl = boot_rtl();
    let st = cmd(&mut rtl, "status");
    assert_eq!(field(&st, "pl"), Some("rtl"), "{st:?}");
    assert!(
        st.lines.iter().any(|l| l == "pl: rtl co-simulation"),
        "{st:?}"
    );
    assert!(field(&st, "sim_time_scale").is_none(), "{st:?}");
    short_align(&mut rtl);
    let r_rtl = mpdtc_step(&mut rtl);
    let mut sim = boot();
    short_align(&mut sim);
    let r_sim = mpdtc_step(&mut sim);
    let (t_rtl, t_sim) = (num(&r_rtl, "settling_time"), num(&r_sim, "settling_time"));
    assert!(t_rtl > 0.0 && t_sim > 0.0, "{r_rtl:?} {r_sim:?}");
    assert!(
        (t_rtl / t_sim - 1.0).abs() <= 0.05,
        "settling on the RTL {t_rtl} ms, on the simulated PL {t_sim} ms"
    );
    assert!(t_rtl <= 0.19, "{r_rtl:?}");
    assert!((num(&r_rtl, "final") - 0.4).abs() < 0.05, "{r_rtl:?}");
    // Same commanded switching within one transition per leg in the window.
    let (f_rtl, f_sim) = (num(&r_rtl, "switching"), num(&r_sim, "switching"));
    assert!((f_rtl - f_sim).abs() <= 0.6, "{r_rtl:?} {r_sim:?}");
    let st = cmd(&mut rtl, "status");
    assert_eq!(field(&st, "gates"), Some("on"), "{st:?}");
    assert_eq!(field(&st, "fault"), Some("none"), "{st:?}");
    assert_eq!(num(&st, "overruns"), 0.0, "{st:?}");
    assert!((num(&st, "torque") - 0.4).abs() < 0.05, "{st:?}");
    let stats = rtl
        .finish_bridge()
        .expect("a bridge")
        .expect("its statistics");
    assert!(stats.contains("\"mismatches\":0"), "{stats}");
}

#[test]
fn foc_torque_and_watchdog_on_the_rtl() {
    let mut s = boot_rtl();
    // Refusals read the RTL's state and change nothing.
    assert_err(&cmd(&mut s, "enable"), "mode-off");
    assert_ok(&cmd(&mut s, "mode foc"));
    assert_err(&cmd(&mut s, "step 0.4"), "gates-off");
    assert_err(&cmd(&mut s, "torque 1.01"), "bad-args");
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "gates"), Some("off"), "{st:?}");
    assert_eq!(field(&st, "mode"), Some("foc"), "{st:?}");
    assert_ok(&cmd(&mut s, "enable"));
    let r = cmd(&mut s, "step 0.4");
    assert_ok(&r);
    let t = num(&r, "settling_time");
    assert!(t > 0.0 && t <= 0.27, "{r:?}");
    assert!((num(&r, "final") - 0.4).abs() < 0.05, "{r:?}");
    // 3 ms of PL time without a heartbeat: the RTL's 2 ms watchdog trips.
    // The reference is steady here: the duties held through a stall right
    // after a reference change drive the current up and trip the
    // over-current protection as well.
    let r = s
        .command("debug stall 3", Duration::from_secs(60))
        .expect("the stall ends");
    assert_eq!(r.lines, ["stalled: 3 ms"], "{r:?}");
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "fault"), Some("WATCHDOG"), "{st:?}");
    assert_eq!(field(&st, "gates"), Some("off"), "{st:?}");
    assert_err(&cmd(&mut s, "enable"), "fault-latched");
    assert_ok(&cmd(&mut s, "fault clear"));
    assert_ok(&cmd(&mut s, "enable"));
    let r = cmd(&mut s, "torque 0.2");
    assert_eq!(r.lines, ["torque_ref: 0.2000 Nm"], "{r:?}");
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "gates"), Some("on"), "{st:?}");
    assert!((num(&st, "torque_ref") - 0.2).abs() < 1e-9, "{st:?}");
    assert_eq!(field(&st, "fault"), Some("none"), "{st:?}");
    let stats = s
        .finish_bridge()
        .expect("a bridge")
        .expect("its statistics");
    assert!(stats.contains("\"mismatches\":0"), "{stats}");
}
