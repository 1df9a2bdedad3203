//! The telemetry stream under QEMU: `tel` on the console and `drivectl`'s
//! recording over the same link, with `status` commands in between.
//! Expectations: the stream's own definition (1 sample per ms of drive time,
//! consecutive sequence numbers) and the drive's physics (the FOC holds the
//! measured torque at its reference).
use drivectl::link::{Final, Reply};
use drivectl::tel::{record, RecordOptions};
use std::time::Duration;
use system_tests::{boot, cmd, TIMEOUT};

fn assert_ok(r: &Reply) {
    assert!(r.is_ok(), "{r:?}");
}

/// Torque, i_q and torque_ref at 1 kHz for 0.5 s of
/// drive time with the FOC holding 0.2 N m, `status` every 50 ms of wall
/// time over the same link.
#[test]
fn one_khz_for_half_a_second_loses_nothing_while_status_replies_come_whole() {
    let mut s = boot();
    for l in ["mode foc", "enable", "torque 0.2"] {
        assert_ok(&cmd(&mut s, l));
    }
    let ch: Vec<String> = ["torque", "i_q", "torque_ref"].map(String::from).to_vec();
    let opts = RecordOptions {
        status_every: Some(Duration::from_millis(50)),
        timeout: TIMEOUT,
    };
    let rec = record(&mut s, 1000, &ch, 0.5, opts, &mut |_| {}).expect("recording");
    eprintln!(
        "samples {}, lost {}, bad {}, status replies {}, wall {:?}, {} B/s",
        rec.rows.len(),
        rec.lost,
        rec.bad,
        rec.status_replies,
        rec.wall,
        rec.bytes_per_s
    );
    assert!(rec.rows.len() >= 490, "{} samples", rec.rows.len());
    assert_eq!(rec.lost, 0);
    assert_eq!(rec.bad, 0);
    assert!(rec.status_replies >= 1, "no status during the recording");
    // One sample per ms of drive time, give or take one FOC period (62.6 us).
    for w in rec.rows.windows(2) {
        let d = w[1].time_s - w[0].time_s;
        assert!((d - 1e-3).abs() < 70e-6, "spacing {d} s");
    }
    let n = rec.rows.len() as f64;
    let mean = |k: usize| rec.rows.iter().map(|r| f64::from(r.values[k])).sum::<f64>() / n;
    assert!(rec.rows.iter().all(|r| r.values[2] == 0.2), "torque_ref");
    assert!((mean(0) - 0.2).abs() < 0.02, "mean torque {}", mean(0));
    assert!(mean(1) > 0.0, "i_q carries the torque");
    // The firmware's own count agrees: nothing dropped.
    let st = cmd(&mut s, "tel status");
    assert!(st.lines.iter().any(|l| l.ends_with(" 0 dropped")), "{st:?}");
    assert!(st.lines.iter().any(|l| l.contains("stopped")), "{st:?}");
    // The console's text holds no frame byte.
    assert!(!s.transcript.contains(&0), "a frame byte in the text");
}

#[test]
fn tel_list_names_the_channels_and_bad_starts_change_nothing() {
    let mut s = boot();
    let r = cmd(&mut s, "tel list");
    assert_ok(&r);
    for want in [
        "i_d [A]",
        "i_q [A]",
        "torque [Nm]",
        "torque_ref [Nm]",
        "position [rev]",
        "velocity [rev/s]",
        "speed [rad/s]",
        "duty_a [1]",
        "switching [bits]",
        "faults [bits]",
        "step_time [us]",
    ] {
        assert!(r.lines.iter().any(|l| l.starts_with(want)), "{want}: {r:?}");
    }
    // The max rates from the baud rate, by hand: 73,728 B/s for telemetry
    // over 17-byte frames (one channel) and 45-byte frames (eight).
    assert!(
        r.lines.iter().any(
            |l| l.starts_with("max rate: 1 channel 4336 Hz, 2 channels 3510 Hz, ")
                && l.contains(", 8 channels 1638 Hz ")
        ),
        "{r:?}"
    );
    assert_ok(&cmd(&mut s, "tel start 4336 i_d"));
    assert_ok(&cmd(&mut s, "tel start 100 i_d,step_time"));
    let r = cmd(&mut s, "tel start 4337 i_d");
    match &r.fin {
        Final::Err { message, .. } => {
            assert!(message.contains("max rate of 1 channel, 4336 Hz"), "{r:?}")
        }
        Final::Ok => panic!("4337 Hz accepted: {r:?}"),
    }
    for bad in [
        "tel start 0 i_d",
        "tel start 100 nope",
        "tel start 100 i_d,i_d",
        "tel start 10000 i_d,i_q,torque,torque_ref,position,velocity,speed,duty_a",
        "tel start 100 i_d,i_q,torque,torque_ref,position,velocity,speed,duty_a,duty_b",
        "tel start",
    ] {
        let r = cmd(&mut s, bad);
        match &r.fin {
            Final::Err { code, .. } => assert_eq!(code, "bad-args", "{bad}: {r:?}"),
            Final::Ok => panic!("{bad} accepted"),
        }
    }
    let st = cmd(&mut s, "tel status");
    // The second start above (the first was the max rate's).
    assert!(st.lines.iter().any(|l| l == "stream: 2 running"), "{st:?}");
    assert!(
        st.lines.iter().any(|l| l == "channels: i_d,step_time"),
        "{st:?}"
    );
    // Frames of the running stream arrive, with the step time measured.
    // (Frames of the first stream, sent before it was replaced, come first.)
    let f = loop {
        let f = s.frames.next(TIMEOUT).expect("a frame");
        if f.stream != 1 {
            break f;
        }
    };
    assert_eq!((f.stream, f.n), (2, 2));
    assert!(f.values[1] > 0.0, "step_time {}", f.values[1]);
    assert_ok(&cmd(&mut s, "tel stop"));
}
