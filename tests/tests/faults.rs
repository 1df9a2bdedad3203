//! Faults under QEMU: each PS- and PL-detected fault latched with its name,
//! the gates off, `fault history` with drive time, code and the samples
//! before, `fault clear`, and the history's length.
use drivectl::link::{Reply, Session};
use std::time::{Duration, Instant};
use system_tests::{assert_err, assert_ok, boot, cmd, field};

/// The `fault:` line of `status` once it names `name` (the control step
/// that sees a PS fault runs a few control periods after the command).
fn wait_fault(s: &mut Session, name: &str) -> Reply {
    let end = Instant::now() + Duration::from_secs(10);
    loop {
        let st = cmd(s, "status");
        let line = st.lines.iter().find(|l| l.starts_with("fault: ")).unwrap();
        if line.split_whitespace().any(|w| w == name) {
            return st;
        }
        assert!(Instant::now() < end, "no {name}: {st:?}");
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// `fault history` lines (without the summary line) and the summary.
fn history(s: &mut Session) -> (Vec<String>, String) {
    let r = cmd(s, "fault history");
    assert_ok(&r);
    let (last, recs) = r.lines.split_last().unwrap();
    (recs.to_vec(), last.clone())
}

/// Injects `what` with the gates on in `mode`; the fault `name` (code
/// `code`) latches, the gates are off, the history's newest entry names it
/// with a snapshot, and `fault clear` lets `enable` work again.
fn fault_cycle(s: &mut Session, mode: &str, what: &str, name: &str, code: u32) {
    assert_ok(&cmd(s, &format!("mode {mode}")));
    assert_ok(&cmd(s, "enable"));
    assert_ok(&cmd(s, "torque 0.2"));
    // Let the control loop run a few periods first (the FOC's first step
    // restarts the ADC to sync it to the PWM).
    let periods = |s: &mut Session| -> u64 {
        field(&cmd(s, "status"), "periods")
            .unwrap()
            .parse()
            .unwrap()
    };
    let p0 = periods(s);
    let end = Instant::now() + Duration::from_secs(10);
    while periods(s) < p0 + 10 {
        assert!(Instant::now() < end);
        std::thread::sleep(Duration::from_millis(5));
    }
    let (before, _) = history(s);
    let r = cmd(s, &format!("debug fault {what}"));
    assert_eq!(r.lines[0], "injected", "{r:?}");
    // A fault the PL latches at once is waited for and named (with
    // whatever else latched in the same control period).
    if drive::console::Injection::from_name(what)
        .and_then(|i| i.prompt_fault())
        .is_some()
    {
        assert_eq!(r.lines.len(), 2, "{r:?}");
        let named = r.lines[1]
            .strip_prefix("fault: ")
            .is_some_and(|l| l.split_whitespace().any(|w| w == name));
        assert!(named, "{r:?}");
    } else {
        assert_eq!(r.lines.len(), 1, "{r:?}");
    }
    let st = wait_fault(s, name);
    assert_eq!(field(&st, "gates"), Some("off"), "{st:?}");
    assert_err(&cmd(s, "enable"), "fault-latched");
    // The PL latches EXTERNAL itself; the history entry is the control
    // step's, at the next boundary.
    let end = Instant::now() + Duration::from_secs(10);
    let recs = loop {
        let (recs, _) = history(s);
        if recs.len() > before.len() {
            break recs;
        }
        assert!(Instant::now() < end, "{recs:?}");
        std::thread::sleep(Duration::from_millis(20));
    };
    let rec = recs
        .iter()
        .rev()
        .find(|l| l.contains(&format!(" code {code} {name}: ")))
        .unwrap_or_else(|| panic!("{name} not in {recs:?}"));
    // `#<n> t=<s> s code <c> <NAME>: 8 samples, i_d .. A, i_q .. A, ...`
    let t: f64 = rec
        .split_once("t=")
        .and_then(|(_, r)| r.split_whitespace().next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("{rec}"));
    assert!(t > 0.0, "{rec}");
    assert!(rec.contains(": 8 samples, i_d "), "{rec}");
    assert!(
        rec.contains(" A, i_q ") && rec.contains(" Nm (ref "),
        "{rec}"
    );
    // The reference the drive was following, not the 0 N m the fault's
    // gates-off set.
    assert!(rec.ends_with("(ref 0.2000 Nm)"), "{rec}");
    let r = cmd(s, "fault clear");
    assert_ok(&r);
    assert_eq!(r.lines[0], "fault: none", "{r:?}");
    assert_ok(&cmd(s, "enable"));
    let st = cmd(s, "status");
    assert_eq!(field(&st, "fault"), Some("none"), "{st:?}");
    assert_eq!(field(&st, "gates"), Some("on"), "{st:?}");
    assert_ok(&cmd(s, "disable"));
}

/// `debug fault overcurrent` with the gates on answers once `OC_LIMIT` 0
/// has tripped: the reply names the fault, and `fault` right after it (no
/// wait in between) shows it latched with the gates off.
#[test]
fn overcurrent_is_latched_when_debug_fault_answers() {
    let mut s = boot();
    for mode in ["foc", "mpdtc"] {
        assert_ok(&cmd(&mut s, &format!("mode {mode}")));
        assert_ok(&cmd(&mut s, "enable"));
        assert_ok(&cmd(&mut s, "torque 0.2"));
        let r = s
            .command("debug fault overcurrent", Duration::from_secs(90))
            .expect("debug fault");
        assert_ok(&r);
        assert_eq!(r.lines[0], "injected", "{mode}: {r:?}");
        assert!(
            r.lines.len() == 2
                && r.lines[1].starts_with("fault: ")
                && r.lines[1].split_whitespace().any(|w| w == "OVERCURRENT"),
            "{mode}: {r:?}"
        );
        // `fault` right after says what the reply said.
        let f = cmd(&mut s, "fault");
        assert_eq!(f.lines, r.lines[1..], "{mode}: {f:?}");
        assert_eq!(field(&cmd(&mut s, "status"), "gates"), Some("off"));
        assert_ok(&cmd(&mut s, "fault clear"));
    }
}

#[test]
fn external_fault_in_foc_and_mpdtc() {
    let mut s = boot();
    let (recs, sum) = history(&mut s);
    assert!(recs.is_empty(), "{recs:?}");
    assert_eq!(sum, "history: 0 shown, 0 since boot");
    fault_cycle(&mut s, "foc", "external", "EXTERNAL", 2);
    fault_cycle(&mut s, "mpdtc", "external", "EXTERNAL", 2);
}

/// The ADC stops: in FOC the control step sees no new result; in MPDTC the
/// control period itself (one averaged result) stops coming.
#[test]
fn adc_stuck_in_foc_and_mpdtc() {
    let mut s = boot();
    fault_cycle(&mut s, "foc", "adc-stuck", "ADC_STUCK", 5);
    fault_cycle(&mut s, "mpdtc", "adc-stuck", "ADC_STUCK", 5);
}

#[test]
fn control_overrun() {
    let mut s = boot();
    fault_cycle(&mut s, "foc", "overrun", "CONTROL_OVERRUN", 6);
    let st = cmd(&mut s, "status");
    let overruns: u64 = field(&st, "overruns").unwrap().parse().unwrap();
    assert!(overruns >= 2, "{st:?}");
}

#[test]
fn bad_fault_arguments_change_nothing() {
    let mut s = boot();
    for bad in [
        "fault history 1",
        "fault hist",
        "fault clear now",
        "debug fault",
        "debug fault fire",
        "debug fault external 1",
    ] {
        assert_err(&cmd(&mut s, bad), "bad-args");
    }
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "fault"), Some("none"), "{st:?}");
    assert_eq!(history(&mut s).1, "history: 0 shown, 0 since boot");
}

/// 18 faults: the history shows the last 16, oldest first, and counts all.
#[test]
fn history_keeps_the_last_16() {
    let mut s = boot();
    assert_ok(&cmd(&mut s, "mode foc"));
    for k in 0..18 {
        let r = cmd(&mut s, "debug fault external");
        assert_ok(&r);
        wait_fault(&mut s, "EXTERNAL");
        // The control step records it at the next boundary.
        let end = Instant::now() + Duration::from_secs(10);
        while history(&mut s).1
            != format!("history: {} shown, {} since boot", (k + 1).min(16), k + 1)
        {
            assert!(Instant::now() < end, "{:?}", history(&mut s));
            std::thread::sleep(Duration::from_millis(20));
        }
        assert_ok(&cmd(&mut s, "fault clear"));
    }
    let (recs, sum) = history(&mut s);
    assert_eq!(sum, "history: 16 shown, 18 since boot");
    assert_eq!(recs.len(), 16);
    let times: Vec<f64> = recs
        .iter()
        .enumerate()
        .map(|(i, l)| {
            assert!(l.starts_with(&format!("#{} t=", i + 1)), "{l}");
            l.split_once("t=")
                .unwrap()
                .1
                .split_whitespace()
                .next()
                .unwrap()
                .parse()
                .unwrap()
        })
        .collect();
    assert!(times.windows(2).all(|w| w[0] < w[1]), "{times:?}");
}

/// PL time now, s: guest uptime over `sim_time_scale` (the simulated PL's
/// clock; the offset of its start cancels in a difference).
fn pl_time_s(st: &Reply) -> f64 {
    system_tests::num(st, "uptime") / system_tests::num(st, "sim_time_scale")
}

/// A board without its ADC card (`sim set adc_card 0`: data-ready held
/// low, no ADC result, so no control-period boundary in mode off): with
/// the gates off the firmware's tick feeds the 2 ms watchdog, so no
/// WATCHDOG latches over 25 of its timeouts, after boot or after `fault
/// clear`; the first `enable` then names the ADC (the sensor check's
/// ADC_STUCK), and with the card fitted it works.
#[test]
fn without_the_adc_card_the_watchdog_stays_quiet_and_enable_names_the_adc() {
    let mut s = boot();
    assert_ok(&cmd(&mut s, "sim set adc_card 0"));
    let quiet_for_50_ms = |s: &mut Session| {
        let first = cmd(s, "status");
        let t0 = pl_time_s(&first);
        let end = Instant::now() + Duration::from_secs(60);
        loop {
            let st = cmd(s, "status");
            assert_eq!(field(&st, "fault"), Some("none"), "{st:?}");
            // No boundary: no control step ran.
            assert_eq!(field(&st, "periods"), field(&first, "periods"), "{st:?}");
            if pl_time_s(&st) - t0 >= 0.05 {
                break;
            }
            assert!(
                Instant::now() < end,
                "50 ms of PL time did not pass: {st:?}"
            );
            std::thread::sleep(Duration::from_millis(20));
        }
    };
    quiet_for_50_ms(&mut s);
    assert_ok(&cmd(&mut s, "mode foc"));
    let r = cmd(&mut s, "enable");
    assert_err(&r, "sensor-check");
    match &r.fin {
        drivectl::link::Final::Err { message, .. } => {
            assert!(message.contains("ADC_STUCK"), "{r:?}");
            assert!(message.contains("converter card"), "{r:?}");
        }
        drivectl::link::Final::Ok => unreachable!(),
    }
    assert_ok(&cmd(&mut s, "mode off"));
    assert_ok(&cmd(&mut s, "fault clear"));
    quiet_for_50_ms(&mut s);
    assert_ok(&cmd(&mut s, "sim set adc_card 1"));
    assert_ok(&cmd(&mut s, "mode foc"));
    assert_ok(&cmd(&mut s, "enable"));
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "gates"), Some("on"), "{st:?}");
}
