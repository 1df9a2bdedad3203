//! A console storm under QEMU: 10,000 valid and invalid lines back to back
//! (the host keeps up to 16 KiB of them queued ahead of the firmware, so
//! its receive ring stays full and the UART's flow control holds the rest)
//! while the FOC holds a torque with the gates on and telemetry streams.
//! Expectations: every line is answered in order (its own echo, then `OK`
//! or `ERR` as the grammar says), the control loop never overruns, the
//! refused lines change nothing (mode, gates, torque reference,
//! configuration, faults), and `periods` advance with the drive time the
//! telemetry sampler counts.
use drivectl::link::{parse_reply, Final, PROMPT};
use models::testrng::Rng;
use std::time::{Duration, Instant};
use system_tests::{assert_ok, boot, cmd, field, num};

const LINES: usize = 10_000;
/// Bytes of lines sent and not yet answered, at most.
const AHEAD: usize = 16 * 1024;

/// A line of the storm and whether the firmware must accept it.
fn storm_line(rng: &mut Rng) -> (String, bool) {
    let r = rng.next_u64();
    let valid = [
        "status",
        "version",
        "fault",
        "fault history",
        "config get mpdtc_t_tol",
        "config get dead_time",
        "torque 0.2",
        "tel status",
        "help fault",
        "mode",
        "torque",
    ];
    let invalid = [
        "bogus",
        "torque 99",
        "torque nan",
        "torque inf",
        "torque 0.2 0.3",
        "mode turbo",
        "enable now",
        "config set mpdtc_t_tol -1",
        "config set dead_time nan",
        "config set nosuch 1",
        "config get",
        "debug stall 0",
        "debug fault nothing",
        "fault now",
        "status extra",
        "tel start 0 torque",
        "tel start 1000 nosuch",
        "capture arm nosuch",
    ];
    match r % 8 {
        0..=3 => (valid[(r >> 8) as usize % valid.len()].to_string(), true),
        4..=6 => (
            invalid[(r >> 8) as usize % invalid.len()].to_string(),
            false,
        ),
        _ => {
            // Garbage: an unknown word of printable bytes, sometimes past
            // the line length.
            let len = 1 + (r >> 8) as usize % 150;
            let mut s = String::from("zz");
            for _ in 0..len {
                s.push(char::from(b'!' + (rng.next_u64() >> 58) as u8 % 94));
            }
            (s, false)
        }
    }
}

#[test]
fn ten_thousand_lines_back_to_back_while_the_foc_runs_and_telemetry_streams() {
    let mut s = boot();
    for l in ["mode foc", "enable", "torque 0.2"] {
        assert_ok(&cmd(&mut s, l));
    }
    assert_ok(&cmd(&mut s, "tel start 200 torque,i_q"));
    let config_before = cmd(&mut s, "config list");
    assert_ok(&config_before);
    let history_before = cmd(&mut s, "fault history");
    assert_ok(&history_before);
    let st0 = cmd(&mut s, "status");
    let (periods0, lines0, errors0) = (
        num(&st0, "periods"),
        console_counts(&st0).0,
        console_counts(&st0).1,
    );
    let taken0 = samples_taken(&mut s);

    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let storm: Vec<(String, bool)> = (0..LINES).map(|_| storm_line(&mut rng)).collect();
    // The console's `errors` count every `ERR` reply: the lines refused
    // before execution (too long, not parsed) and those the drive refused.
    let refused = storm.iter().filter(|(_, ok)| !ok).count();
    let t0 = Instant::now();
    let (mut sent, mut answered, mut ahead) = (0, 0, 0usize);
    let mut last_periods = periods0;
    let mut status_seen = 0;
    while answered < LINES {
        // Queue lines while fewer than AHEAD bytes wait for an answer.
        let mut chunk = Vec::new();
        while sent < LINES && ahead + storm[sent].0.len() < AHEAD {
            chunk.extend_from_slice(storm[sent].0.as_bytes());
            chunk.push(b'\r');
            ahead += storm[sent].0.len() + 1;
            sent += 1;
        }
        if !chunk.is_empty() {
            s.send(&chunk).unwrap();
        }
        let (line, valid) = &storm[answered];
        let text = s
            .read_until(PROMPT.as_bytes(), Duration::from_secs(20))
            .unwrap_or_else(|e| panic!("line {answered} {line:?} not answered: {e:#}"));
        let text = String::from_utf8_lossy(&text);
        let r = parse_reply(&text).unwrap_or_else(|e| panic!("line {answered}: {e:#}"));
        if line.len() <= drive::console::LINE_MAX {
            assert_eq!(
                text.split("\r\n").next(),
                Some(line.as_str()),
                "echo of line {answered}"
            );
        }
        assert_eq!(r.is_ok(), *valid, "line {answered} {line:?}: {r:?}");
        if line == "status" {
            // Mid-storm: gates on, no fault, no overrun, periods never back.
            assert_eq!(field(&r, "gates"), Some("on"), "{r:?}");
            assert_eq!(field(&r, "fault"), Some("none"), "{r:?}");
            assert_eq!(num(&r, "overruns"), 0.0, "{r:?}");
            let p = num(&r, "periods");
            assert!(p >= last_periods, "periods {p} after {last_periods}");
            last_periods = p;
            status_seen += 1;
        }
        if let Final::Err { code, .. } = &r.fin {
            assert!(!code.is_empty(), "{r:?}");
        }
        ahead -= line.len() + 1;
        answered += 1;
    }
    let wall = t0.elapsed();

    let st1 = cmd(&mut s, "status");
    let taken1 = samples_taken(&mut s);
    let frames = s.frames.drain();
    let (lines1, errors1, rx_overruns) = console_counts(&st1);
    assert_eq!(field(&st1, "mode"), Some("foc"), "{st1:?}");
    assert_eq!(field(&st1, "gates"), Some("on"), "{st1:?}");
    assert_eq!(field(&st1, "fault"), Some("none"), "{st1:?}");
    assert_eq!(num(&st1, "torque_ref"), 0.2, "{st1:?}");
    assert_eq!(num(&st1, "overruns"), 0.0, "{st1:?}");
    assert_eq!(rx_overruns, 0, "{st1:?}");
    // Every storm line counted (`tel status` before the storm and `status`
    // itself are the +2), each refused one as an error.
    assert_eq!(lines1 - lines0, LINES as u64 + 2, "{st1:?}");
    assert_eq!(errors1 - errors0, refused as u64, "{st1:?}");
    let config_after = cmd(&mut s, "config list");
    assert_eq!(config_after, config_before, "configuration changed");
    assert_eq!(
        cmd(&mut s, "fault history"),
        history_before,
        "fault history changed"
    );
    // Periods against the drive time the telemetry sampler counted: one
    // sample per 5 ms of drive time (200 Hz), one control period per period
    // at the FOC's rate, give or take a sample interval at each end (the
    // `status` and `tel status` replies are a line apart).
    let rate = num(&st1, "control_rate");
    let periods1 = num(&st1, "periods");
    let drive_s = (taken1 - taken0) / 200.0;
    assert!(taken1 > taken0, "no telemetry samples during the storm");
    let expect = drive_s * rate;
    let got = periods1 - periods0;
    let slack = 2.0 * rate / 200.0 + 10.0;
    assert!(
        (got - expect).abs() <= slack,
        "periods {got} over {drive_s} s of drive time at {rate} Hz"
    );
    println!(
        "storm: {LINES} lines ({refused} refused) in {wall:?}, {status_seen} status \
         mid-storm, {got} control periods over {drive_s:.3} s of drive time, \
         {} telemetry frames",
        frames.len()
    );
}

/// `samples: <taken> taken, ...` of `tel status`.
fn samples_taken(s: &mut drivectl::link::Session) -> f64 {
    let r = cmd(s, "tel status");
    assert_ok(&r);
    num(&r, "samples")
}

/// `console: <lines> lines, <errors> errors, <rx> rx overruns`.
fn console_counts(r: &drivectl::link::Reply) -> (u64, u64, u64) {
    let l = r
        .lines
        .iter()
        .find_map(|l| l.strip_prefix("console: "))
        .unwrap_or_else(|| panic!("{r:?}"));
    let n: Vec<u64> = l
        .split(|c: char| !c.is_ascii_digit())
        .filter_map(|w| w.parse().ok())
        .collect();
    (n[0], n[1], n[2])
}
