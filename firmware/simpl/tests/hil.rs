//! The MPDCC hardware-in-the-loop run (`drive::hil`) on the simulated PL:
//! its decisions and statistics are the FPGA model's loop, one for one.
use drive::hil::{default_core, run, HilError, Paced, MAX_LATE_IN_A_ROW, MAX_PERIODS};
use drive::pl::mpdcc::{Mpdcc, MpdccError, PageDecision};
use models::mpdcc::closed_loop::{self, LoopConfig, LoopResult};
use models::mpdcc::mpdcc_fixed::Inputs;
use regmap::bus::{BusError, RegisterBus};
use simpl::pl::{Events, SimPl};

struct Bus(SimPl);

impl RegisterBus for Bus {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        self.0.read(addr).0
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        self.0.write(addr, value).0
    }
}

/// On the simulated PL the run is the FPGA-model loop: the same
/// statistics (so the same decisions and trajectory), the cycle counts
/// of the pipelined core in pl_top's configuration (one explorer, a
/// candidate every 4 clocks: at most 927 cycles, 216 candidates).
#[test]
fn simulated_pl_run_is_the_model_loop() {
    let (p, f) = default_core().unwrap();
    let mut model = f.clone();
    let want: LoopResult = closed_loop::run(
        &p,
        &LoopConfig {
            warmup_periods: 1,
            measure_periods: 1,
        },
        &mut model,
        None,
        &mut |_| {},
    )
    .unwrap();
    let mut m = Mpdcc(Bus(SimPl::new(10)));
    m.load_coeffs(f.coeffs()).unwrap();
    let r = run(&p, 1, &mut |x| m.decide(x, 1000)).unwrap();
    assert_eq!(r.fsw_hz, want.fsw_hz);
    assert_eq!(r.thd_percent, want.thd_percent);
    assert_eq!(r.max_i_err_pu, want.max_i_err_pu);
    assert_eq!(r.decisions, 2 * want.steps);
    assert!(r.kinds[1] > 10 && r.kinds[0] > 10, "{r:?}");
    // Common terms 20, the last of 216 candidates issued 4 x 215 clocks
    // after the first, explorer 42, arg-min tree 3, the last fold 1; the
    // smallest set (27 candidates) takes 20 + 4 x 26 + 1 + 42 + 3 + 1 = 171.
    assert_eq!(r.worst_cycles, 20 + 4 * 215 + 1 + 42 + 3 + 1);
    assert!(r.mean_cycles > 171.0 && r.mean_cycles < 927.0, "{r:?}");
    assert_eq!(m.deadlocks().unwrap() as u64, r.kinds[2]);
}

/// Paced by control periods (1,564 PL cycles between boundaries), the
/// loop is [`run`]'s: its first measured period has the model loop's
/// statistics exactly, and no decision was late (at most 927 cycles).
#[test]
fn paced_loop_is_the_model_loop() {
    let (p, f) = default_core().unwrap();
    let mut model = f.clone();
    let cfg = LoopConfig {
        warmup_periods: 1,
        measure_periods: 1,
    };
    let want = closed_loop::run(&p, &cfg, &mut model, None, &mut |_| {}).unwrap();
    let mut m = Mpdcc(Bus(SimPl::new(10)));
    m.load_coeffs(f.coeffs()).unwrap();
    let mut h = Paced::new(&p).unwrap();
    let mut ticks = 0u64;
    while h.status().report.periods == 0 {
        h.tick(&mut m).unwrap();
        m.0 .0.run(1564, &Events::default());
        ticks += 1;
    }
    let st = h.status();
    assert_eq!(st.report.fsw_hz, want.fsw_hz);
    assert_eq!(st.report.thd_percent, want.thd_percent);
    assert_eq!(st.report.max_i_err_pu, want.max_i_err_pu);
    assert_eq!(st.report.decisions, 2 * want.steps);
    assert_eq!(st.late, 0);
    // The tick that read the last decision also started the next one.
    assert_eq!(ticks, st.report.decisions + 1);
    assert_eq!(st.report.worst_cycles, 20 + 4 * 215 + 1 + 42 + 3 + 1);
    assert!((st.plant_time_s - 2.0 * want.steps as f64 * p.controller.ts_s).abs() < 1e-12);
    assert_eq!(st.stopped, None);
}

/// A decision not done at the next boundary waits (counted late); one
/// that never ends stops the loop with a timeout, and a stopped loop
/// stays stopped without touching the page.
#[test]
fn late_decisions_wait_then_time_out() {
    let (p, f) = default_core().unwrap();
    let mut m = Mpdcc(Bus(SimPl::new(10)));
    m.load_coeffs(f.coeffs()).unwrap();
    let mut h = Paced::new(&p).unwrap();
    h.tick(&mut m).unwrap();
    // The next boundary comes at once: the decision is still running.
    h.tick(&mut m).unwrap();
    assert_eq!((h.status().late, h.status().report.decisions), (1, 0));
    m.0 .0.run(1000, &Events::default());
    h.tick(&mut m).unwrap();
    assert_eq!((h.status().late, h.status().report.decisions), (1, 1));
    // A page that never finishes: STATUS reads busy.
    struct Busy;
    impl RegisterBus for Busy {
        fn read(&mut self, _: usize) -> Result<u32, BusError> {
            Ok(1)
        }
        fn write(&mut self, _: usize, _: u32) -> Result<(), BusError> {
            Ok(())
        }
    }
    let mut b = Mpdcc(Busy);
    let mut h = Paced::new(&p).unwrap();
    for _ in 0..MAX_LATE_IN_A_ROW {
        h.tick(&mut b).unwrap();
    }
    let e = Err(HilError::Page(MpdccError::Timeout));
    assert_eq!(h.tick(&mut b), e);
    assert_eq!(h.status().late, u64::from(MAX_LATE_IN_A_ROW));
    assert_eq!(
        h.status().stopped,
        Some(HilError::Page(MpdccError::Timeout))
    );
    let mut never = Mpdcc(Bus(SimPl::new(10)));
    assert_eq!(h.tick(&mut never), e);
}

#[test]
fn bad_periods_and_page_errors_stop_the_run() {
    let (p, _) = default_core().unwrap();
    let mut never = |_: &Inputs| -> Result<PageDecision, MpdccError> { unreachable!() };
    assert_eq!(run(&p, 0, &mut never), Err(HilError::Periods));
    assert_eq!(run(&p, MAX_PERIODS + 1, &mut never), Err(HilError::Periods));
    let mut fail = |_: &Inputs| Err(MpdccError::Timeout);
    assert_eq!(
        run(&p, 1, &mut fail),
        Err(HilError::Page(MpdccError::Timeout))
    );
}
