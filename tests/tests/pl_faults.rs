//! The PL's own encoder-loss and ADC-stuck faults, on the simulated PL and
//! on the co-simulated `pl_top`: `debug fault encoder-loss` (the simulated
//! encoder's A and B lines change in the same instant, an illegal
//! quadrature step) and `debug fault adc-stuck` (`ADC_CTRL.ENABLE` = 0),
//! each caused right after a control step with the gates on. Checked: the
//! fault latches under its name, the gates are off within one control
//! period of the cause (`debug fault-time`, PL cycles), `fault history`
//! has the entry, `enable` is refused until `fault clear`.
use drivectl::link::Session;
use std::time::{Duration, Instant};
use system_tests::{assert_err, assert_ok, boot, boot_rtl, cmd, field, num};

/// PL cycles of one control period: FOC (one PWM period), MPDTC (one
/// averaged ADC result).
fn period(mode: &str) -> i64 {
    if mode == "foc" {
        6256
    } else {
        1564
    }
}

/// The PL's own bound of the encoder loss, cycles from the pins' change to
/// the gates off: 2 synchroniser flops, the decoder's step, the gate
/// driver's edge.
const ENC_LOSS_CYCLES: i64 = 4;

/// The PL's own bound of the stuck ADC, cycles from `ADC_CTRL.ENABLE` = 0:
/// a conversion under way still ends in a sample (50 cycles of conversion,
/// 5 of convert pulse, data-ready and synchroniser), then ADC_PERIOD (391)
/// + the margin (16) without one, then the gate edge.
const ADC_STUCK_CYCLES: i64 = 55 + 391 + 16 + 1;

fn periods(s: &mut Session) -> u64 {
    num(&cmd(s, "status"), "periods") as u64
}

fn history_len(s: &mut Session) -> usize {
    let r = cmd(s, "fault history");
    assert_ok(&r);
    r.lines.len() - 1
}

/// Injects `inject` in `mode` with the gates on; returns the gates-off time
/// in PL cycles from the cause, after checking the latch (`name`, code
/// `code`), the history entry, the refusal of `enable` and `fault clear`.
fn pl_fault(s: &mut Session, mode: &str, inject: &str, name: &str, code: u32) -> i64 {
    assert_ok(&cmd(s, "sim reset"));
    assert_ok(&cmd(s, "fault clear"));
    assert_ok(&cmd(s, &format!("mode {mode}")));
    assert_ok(&cmd(s, "enable"));
    assert_ok(&cmd(s, "torque 0.2"));
    let p0 = periods(s);
    let end = Instant::now() + Duration::from_secs(60);
    while periods(s) < p0 + 10 {
        assert!(Instant::now() < end, "the control loop does not run");
        std::thread::sleep(Duration::from_millis(5));
    }
    let st = cmd(s, "status");
    assert_eq!(field(&st, "fault"), Some("none"), "{mode}: {st:?}");
    assert_eq!(field(&st, "gates"), Some("on"), "{mode}: {st:?}");
    let before = history_len(s);
    let r = s
        .command(&format!("debug fault {inject}"), Duration::from_secs(60))
        .expect("debug fault");
    assert_eq!(r.lines, ["injected"], "{name} {mode}: {r:?}");
    let end = Instant::now() + Duration::from_secs(30);
    let st = loop {
        let st = cmd(s, "status");
        let line = st.lines.iter().find(|l| l.starts_with("fault: ")).unwrap();
        if line.split_whitespace().any(|w| w == name) {
            break st;
        }
        assert!(Instant::now() < end, "no {name} in {mode}: {st:?}");
        std::thread::sleep(Duration::from_millis(10));
    };
    assert_eq!(field(&st, "gates"), Some("off"), "{st:?}");
    assert_err(&cmd(s, "enable"), "fault-latched");
    let end = Instant::now() + Duration::from_secs(30);
    loop {
        let h = cmd(s, "fault history");
        let new = &h.lines[before.min(h.lines.len() - 1)..h.lines.len() - 1];
        if new
            .iter()
            .any(|l| l.contains(&format!(" code {code} {name}: ")))
        {
            break;
        }
        assert!(Instant::now() < end, "{name} not in the history: {h:?}");
        std::thread::sleep(Duration::from_millis(10));
    }
    let t = cmd(s, "debug fault-time");
    assert_ok(&t);
    let lat = num(&t, "latency") as i64;
    assert_err(&cmd(s, "enable"), "fault-latched");
    let r = cmd(s, "fault clear");
    assert_ok(&r);
    assert_eq!(r.lines[0], "fault: none", "{r:?}");
    assert_ok(&cmd(s, "disable"));
    println!("{name} {mode}: gates off {lat} PL cycles after the cause");
    lat
}

fn check(lat: i64, mode: &str, own: i64, name: &str) {
    assert!(
        (0..=own).contains(&lat) && lat <= period(mode),
        "{name} {mode}: {lat} cycles (PL bound {own}, period {})",
        period(mode)
    );
}

#[test]
fn encoder_loss_and_adc_stuck_are_the_simulated_pls_own_within_a_period() {
    let mut s = boot();
    for mode in ["foc", "mpdtc"] {
        let lat = pl_fault(&mut s, mode, "encoder-loss", "ENCODER_LOSS", 4);
        check(lat, mode, ENC_LOSS_CYCLES, "ENCODER_LOSS");
        let lat = pl_fault(&mut s, mode, "adc-stuck", "ADC_STUCK", 5);
        check(lat, mode, ADC_STUCK_CYCLES, "ADC_STUCK");
    }
}

/// A few ms of PL time each in co-simulation (MPDTC: the ADC's results
/// pace its period, so a stuck ADC stops its boundaries).
#[test]
fn encoder_loss_and_adc_stuck_on_the_rtl_within_a_period() {
    let mut s = boot_rtl();
    // A 2 ms alignment (the default 0.2 s is minutes of co-simulation): a
    // fresh boot's rotor is held on the d axis, where no alignment moves
    // it. `pl_fault` clears what the reconfiguration may latch.
    assert_ok(&cmd(&mut s, "config set mpdtc_align_time 200000"));
    let lat = pl_fault(&mut s, "mpdtc", "encoder-loss", "ENCODER_LOSS", 4);
    check(lat, "mpdtc", ENC_LOSS_CYCLES, "ENCODER_LOSS");
    let lat = pl_fault(&mut s, "mpdtc", "adc-stuck", "ADC_STUCK", 5);
    check(lat, "mpdtc", ADC_STUCK_CYCLES, "ADC_STUCK");
    let lat = pl_fault(&mut s, "foc", "encoder-loss", "ENCODER_LOSS", 4);
    check(lat, "foc", ENC_LOSS_CYCLES, "ENCODER_LOSS");
    let lat = pl_fault(&mut s, "foc", "adc-stuck", "ADC_STUCK", 5);
    check(lat, "foc", ADC_STUCK_CYCLES, "ADC_STUCK");
    let stats = s
        .finish_bridge()
        .expect("a bridge")
        .expect("its statistics");
    assert!(stats.contains("\"mismatches\":0"), "{stats}");
}
