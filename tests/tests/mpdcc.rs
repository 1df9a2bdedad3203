//! Paper 001's hardware-in-the-loop run under QEMU: `mpdcc run` on the
//! simulated PL (the plant on the PS, the core's model behind the MPDCC
//! page) must give the numbers of the host's FPGA-model loop
//! (`drive::mpdcc::closed_loop` with `FpgaMpdcc`): decision counts by kind,
//! the worst core cycle count, f_sw and THD, without faults or overruns of
//! the PMSM drive's loop. Also the command's errors (bad arguments, gates
//! on).
use std::time::{Duration, Instant};

use drive::mpdcc::closed_loop::{self, LoopConfig};
use drive::mpdcc::controller::{CtrlState, Decision, DecisionKind, MpdccController, StateError};
use drive::mpdcc::fpga::FpgaMpdcc;
use drive::mpdcc::hil;
use drivectl::link::{Final, Reply};
use system_tests::{boot, cmd, field};

/// The model, counting its decisions by kind.
struct Counting(FpgaMpdcc, [u64; 3]);

impl MpdccController for Counting {
    fn name(&self) -> &'static str {
        "fpga"
    }
    fn decide(&mut self, st: &CtrlState) -> Result<Decision, StateError> {
        let d = self.0.decide(st)?;
        self.1[match d.kind {
            DecisionKind::Kept => 0,
            DecisionKind::Optimal => 1,
            DecisionKind::Deadlock => 2,
        }] += 1;
        Ok(d)
    }
}

fn num(r: &Reply, key: &str) -> f64 {
    field(r, key)
        .and_then(|v| v.trim_end_matches(',').parse().ok())
        .unwrap_or_else(|| panic!("no number for {key}: {r:?}"))
}

#[test]
fn mpdcc_run_on_the_simulated_pl_is_the_host_model_loop() {
    let (p, f) = hil::default_core().unwrap();
    let mut host = Counting(f, [0; 3]);
    let cfg = LoopConfig {
        warmup_periods: 1,
        measure_periods: 1,
    };
    let want = closed_loop::run(&p, &cfg, &mut host, None, &mut |_| {}).unwrap();

    let mut s = boot();
    let r = cmd(&mut s, "mpdcc");
    assert!(r.lines.iter().any(|l| l.contains("no run yet")), "{r:?}");
    let t0 = Instant::now();
    let r = s
        .command("mpdcc run 1", Duration::from_secs(240))
        .expect("mpdcc run");
    let secs = t0.elapsed().as_secs_f64();
    assert!(r.is_ok(), "{r:?}");
    println!("{:#?}\n({secs:.1} s under QEMU)", r.lines);
    let line = |k: &str| {
        r.lines
            .iter()
            .find(|l| l.starts_with(k))
            .cloned()
            .unwrap_or_else(|| panic!("no {k}: {r:?}"))
    };
    let [kept, opt, dl] = host.1;
    assert_eq!(
        line("decisions:"),
        format!(
            "decisions: {} (kept {kept}, optimal {opt}, deadlock {dl})",
            kept + opt + dl
        )
    );
    assert!(line("core_cycles:").ends_with("worst 173 (PL clock cycles)"));
    assert!(
        (num(&r, "f_sw") - want.fsw_hz).abs() < 0.05,
        "{r:?} {want:?}"
    );
    assert!(
        (num(&r, "thd") - want.thd_percent).abs() < 0.005,
        "{r:?} {want:?}"
    );
    // The report stays for `mpdcc`.
    let again = cmd(&mut s, "mpdcc");
    assert_eq!(again.lines, r.lines);
    // Bad arguments change nothing.
    for bad in ["mpdcc run 0", "mpdcc run 21", "mpdcc stop"] {
        let e = cmd(&mut s, bad);
        assert!(
            matches!(&e.fin, Final::Err { code, .. } if code == "bad-args"),
            "{bad}: {e:?}"
        );
    }
    assert_eq!(cmd(&mut s, "mpdcc").lines, r.lines);
    // The run left the PMSM drive's loop alone (simulated PL).
    let st = cmd(&mut s, "status");
    assert_eq!(field(&st, "fault"), Some("none"), "{st:?}");
    assert_eq!(field(&st, "overruns"), Some("0"), "{st:?}");
    // Refused while the gates are on, and nothing runs.
    assert!(cmd(&mut s, "mode foc").is_ok());
    assert!(cmd(&mut s, "enable").is_ok());
    let e = cmd(&mut s, "mpdcc run 1");
    assert!(
        matches!(&e.fin, Final::Err { code, .. } if code == "gates-on"),
        "{e:?}"
    );
    assert!(cmd(&mut s, "disable").is_ok());
    assert_eq!(cmd(&mut s, "mpdcc").lines, r.lines);
}
