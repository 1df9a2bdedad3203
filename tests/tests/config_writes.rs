//! A configuration write costs no control step: `config set` (accepted,
//! refused with the gates on, refused as malformed) and `config save` (a
//! flash sector erase and program) while the drive runs FOC and MPDTC with
//! the gates on, and while it is idle, on the simulated PL and on the
//! co-simulated `pl_top`. The control loop must see every boundary: no
//! overrun, no fault, one control interrupt per period, and the step's
//! start latency no worse than the loop's own.
use drivectl::link::{Reply, Session};
use system_tests::{assert_err, assert_ok, boot, boot_rtl, cmd, field, num};

/// The figures of `status` a configuration write must not move.
#[derive(Debug, Clone, Copy)]
struct Loop {
    periods: f64,
    overruns: f64,
    control_irq: f64,
    latency_mean: f64,
    latency_max: f64,
}

fn loop_figures(s: &mut Session) -> (Loop, Reply) {
    let st = cmd(s, "status");
    assert_ok(&st);
    // `control_latency: min <a> mean <b> max <c> PL cycles ...`
    let latency = |key: &str| {
        st.lines
            .iter()
            .find_map(|l| l.strip_prefix("control_latency: "))
            .and_then(|l| l.split_whitespace().skip_while(|w| *w != key).nth(1))
            .and_then(|v| v.parse().ok())
            .unwrap_or(0.0)
    };
    let (latency_mean, latency_max) = (latency("mean"), latency("max"));
    let f = Loop {
        periods: num(&st, "periods"),
        overruns: num(&st, "overruns"),
        control_irq: num(&st, "control_irq"),
        latency_mean,
        latency_max,
    };
    (f, st)
}

/// `n` rounds of configuration writes in the drive's present state:
/// accepted ones (`accepted`, each a `config set` line), one refused for
/// its value, and a `config save` every other round.
fn writes(s: &mut Session, n: usize, accepted: &[&str], refused_gates_on: bool) {
    for i in 0..n {
        for line in accepted {
            assert_ok(&cmd(s, line));
        }
        // Out of range: refused, nothing changes.
        assert_err(&cmd(s, "config set mpdtc_t_tol 0.51"), "bad-args");
        if refused_gates_on {
            // A valid value that may not change with the gates on.
            assert_err(&cmd(s, "config set mpdtc_t_tol 0.06"), "gates-on");
        }
        if i % 2 == 0 {
            let r = cmd(s, "config save");
            assert_ok(&r);
        }
    }
}

/// Checks that the writes between `a` and `b` cost nothing: no overrun in
/// the window, no fault, every period served by one control interrupt, and the start
/// latency's maximum raised by the window to at most `latency_bound`
/// PL cycles.
fn assert_no_step_lost(what: &str, a: Loop, b: Loop, st: &Reply, latency_bound: f64) {
    // The window's mean from the running means (one sample per control
    // interrupt).
    let window_mean = (b.latency_mean * b.control_irq - a.latency_mean * a.control_irq)
        / (b.control_irq - a.control_irq);
    println!(
        "{what}: {} periods, overruns {} -> {}, control_irq +{}, latency mean {window_mean:.0} \
         in the window, max {} -> {} PL cycles since boot",
        b.periods - a.periods,
        a.overruns,
        b.overruns,
        b.control_irq - a.control_irq,
        a.latency_max,
        b.latency_max
    );
    assert!(b.periods > a.periods, "{what}: the loop ran: {st:?}");
    assert_eq!(b.overruns, a.overruns, "{what}: {st:?}");
    assert_eq!(field(st, "fault"), Some("none"), "{what}: {st:?}");
    // One control interrupt per period: none of the boundaries was
    // merged into a later step.
    assert_eq!(
        b.control_irq - a.control_irq,
        b.periods - a.periods,
        "{what}: {st:?}"
    );
    // `status` keeps the maximum since boot (the sensor check at the first
    // `enable` holds the loop off by design): the window may only raise it
    // up to the bound.
    assert!(
        b.latency_max <= a.latency_max.max(latency_bound),
        "{what}: start latency {} PL cycles: {st:?}",
        b.latency_max
    );
}

/// Idle (mode off, gates off), then FOC and MPDTC with the gates on.
fn config_writes_cost_no_step(s: &mut Session, rounds: usize, latency_bound: f64) {
    // Idle: writes that rebuild the controllers and rewrite the PL's
    // configuration registers.
    let (a, _) = loop_figures(s);
    writes(
        s,
        rounds,
        &[
            "config set mpdtc_align_time 200000",
            "config set mpdtc_t_tol 0.05",
            "config set dead_time 70",
        ],
        false,
    );
    let (b, st) = loop_figures(s);
    assert_no_step_lost("idle", a, b, &st, latency_bound);
    assert_eq!(b.overruns, 0.0, "{st:?}");
    for mode in ["foc", "mpdtc"] {
        assert_ok(&cmd(s, &format!("mode {mode}")));
        assert_ok(&cmd(s, "enable"));
        assert_ok(&cmd(s, "torque 0.2"));
        let (a, _) = loop_figures(s);
        writes(
            s,
            rounds,
            &["config set torque_limit 0.5", "config set torque_limit 0.6"],
            true,
        );
        let (b, st) = loop_figures(s);
        assert_eq!(field(&st, "gates"), Some("on"), "{st:?}");
        assert_no_step_lost(mode, a, b, &st, latency_bound);
        assert_ok(&cmd(s, "disable"));
    }
}

/// One MPDTC control period, PL cycles: a step that starts later has let
/// a boundary pass (the simulated PL's steps start at their boundary, its
/// latency is 0; the co-simulated `pl_top`'s in the windows averaged 45 to
/// 77 cycles).
const LATENCY_BOUND_CYCLES: f64 = 1_564.0;

#[test]
fn config_writes_and_saves_cost_no_control_step_on_the_simulated_pl() {
    let mut s = boot();
    config_writes_cost_no_step(&mut s, 10, LATENCY_BOUND_CYCLES);
}

#[test]
fn config_writes_and_saves_cost_no_control_step_on_the_rtl() {
    let mut s = boot_rtl();
    config_writes_cost_no_step(&mut s, 3, LATENCY_BOUND_CYCLES);
}
