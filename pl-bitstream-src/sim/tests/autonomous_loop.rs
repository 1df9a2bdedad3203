//! The autonomous MPDTC loop (`MPDTC_CTRL.AUTO = 1`) in closed loop: the
//! Verilated `pl_top` (front end -> core -> gates every period, paced by its
//! own ADC) coupled to the Rust plant and measurement chain
//! (`SimDrive<RtlPl>`), where the PS side writes the parameters once and
//! then only the torque reference: a 0.4 N m step after the rotor
//! alignment. The same harness on the simulated PL (`SimDrive<SimPl>`, i.e.
//! `frontend_fixed` + `mpdtc_fixed` in the pure-Rust model of `pl_top`) must
//! take the same decision in every control period, and the torque must
//! settle at the reference (plant truth, 10 % band). Run at the paper's
//! 64 kHz and at a 1 us control period.
use drive::pl::adc::Adc;
use drive::pl::enc::Encoder;
use drive::pl::mpdtc::{frontend_params, torque_ref_word, FrontendSetup, Mpdtc};
use drive::pl::pwm::Pwm;
use drive::pl::top::{Mode, Top};
use models::pmsm::metrics;
use models::pmsm::mpdtc_fixed::FixedParams;
use models::pmsm::mpdtc_ref::{MpdtcConfig, MpdtcParams};
use regmap::bus::RegisterBus;
use regmap::{self as rm};
use rtl_sim::cosim::RtlPl;
use rtl_sim::rtl_timed::RtlTimedSimPl;
use simpl::pl::SimPl;
use simpl::{PlModel, SimConfig, SimDrive};

/// One operating point: PL timing and the controller's model of it.
#[derive(Clone, Copy)]
struct Rate {
    adc_period: u32,
    avg_log2: u32,
    /// Converter time (result `conv + 1` cycles after the convert pulse).
    conv: u32,
    /// Periods of the step window.
    periods: usize,
}

impl Rate {
    fn period_cycles(&self) -> u32 {
        self.adc_period << self.avg_log2
    }
    /// Age of the averaged measurement at the boundary, periods: the
    /// newest sample is `conv + 2` cycles old, the mean of n samples
    /// (n - 1) / 2 ADC periods older.
    fn meas_age(&self) -> f64 {
        let n = f64::from(1u32 << self.avg_log2);
        (f64::from(self.conv + 2) + (n - 1.0) / 2.0 * f64::from(self.adc_period))
            / f64::from(self.period_cycles())
    }
}

/// What one run recorded: the decision (`MPDTC_STATUS`: S_NEXT and
/// DONE_COUNT) at every boundary after the step, and the plant torque.
struct Run {
    decisions: Vec<u32>,
    torque: Vec<f64>,
    overruns: u32,
}

const ALIGN_CYCLES: u32 = 20_000;
const STEP_NM: f64 = 0.4;

fn run<P: PlModel>(sim: &mut SimDrive<P>, r: Rate) -> Run {
    let motor = sim.config().motor;
    let ts = f64::from(r.period_cycles()) / f64::from(rm::PL_CLOCK_HZ);
    let mp = MpdtcParams {
        control_period_s: ts,
        meas_age_periods: r.meas_age(),
        ..MpdtcParams::default()
    };
    let cfg = MpdtcConfig::new(motor, mp).expect("MPDTC configuration");
    let p = FixedParams::from_config(&cfg).expect("core registers");
    let fe = frontend_params(&FrontendSetup {
        pole_pairs: motor.pole_pairs,
        enc_cpr: sim.config().encoder_cpr,
        period_cycles: r.period_cycles(),
        window_cycles: rm::ENC_WINDOW.reset,
        meas_age_periods: r.meas_age(),
        amps_per_count: sim.config().adc_amps_per_count,
        adc_offset: [0; 3],
    })
    .expect("front-end registers");
    // The parameters, once.
    Adc(&mut *sim).set_period(r.adc_period).unwrap();
    // The conversions restart at the new period at once (the PL's ADC
    // result timer would see the old period's countdown as a gap).
    Adc(&mut *sim).restart().unwrap();
    sim.write(rm::ADC.addr(&rm::ADC_AVG_LOG2), r.avg_log2)
        .unwrap();
    // 100 ns dead time (the reset 500 ns would be half of a 1 us period).
    Pwm(&mut *sim).set_dead_time(10).unwrap();
    let cpr = sim.config().encoder_cpr;
    Encoder(&mut *sim).set_cpr(cpr).unwrap();
    let mut m = Mpdtc(&mut *sim);
    m.load_params(&p).unwrap();
    m.load_frontend(&fe).unwrap();
    m.set_align_time(ALIGN_CYCLES).unwrap();
    m.set_ctrl_path(false, false, true).unwrap();
    Top(&mut *sim).set_mode(Mode::Mpdtc).unwrap();
    Pwm(&mut *sim).set_gates(true).unwrap();
    // The alignment, then one more boundary (the first decision's sample).
    let mut guard = 0;
    while !Mpdtc(&mut *sim).seq_status().unwrap().aligned {
        sim.advance_to_boundary(100_000);
        guard += 1;
        assert!(guard < 10_000, "no alignment");
    }
    sim.advance_to_boundary(100_000);
    let ov0 = Mpdtc(&mut *sim).seq_status().unwrap().overruns;
    // The step: the only write of the loop.
    Mpdtc(&mut *sim)
        .write_torque_ref(torque_ref_word(STEP_NM))
        .unwrap();
    let mut out = Run {
        decisions: Vec::new(),
        torque: Vec::new(),
        overruns: 0,
    };
    for _ in 0..r.periods {
        let a = sim.advance_to_boundary(100_000);
        assert_eq!(a.control_periods, 1);
        out.decisions
            .push(sim.read(rm::MPDTC.addr(&rm::MPDTC_STATUS)).unwrap() >> 1);
        out.torque.push(sim.truth().torque_nm);
    }
    out.overruns = Mpdtc(&mut *sim).seq_status().unwrap().overruns - ov0;
    assert!(Pwm(&mut *sim).gates_enabled().unwrap(), "a fault tripped");
    out
}

fn compare(r: Rate, name: &str) {
    let cfg = SimConfig {
        adc_conversion_cycles: r.conv,
        ..SimConfig::default()
    };
    let mut model = SimDrive::with_pl(&cfg, RtlTimedSimPl(SimPl::new(r.conv))).unwrap();
    let rust = run(&mut model, r);
    let mut rtl = SimDrive::with_pl(&cfg, RtlPl::new(r.conv)).unwrap();
    let ver = run(&mut rtl, r);
    assert_eq!(rtl.pl().mismatches(), 0, "{:?}", rtl.pl().first_mismatch());
    let diff = rust
        .decisions
        .iter()
        .zip(&ver.decisions)
        .filter(|(a, b)| a != b)
        .count();
    let ts = f64::from(r.period_cycles()) / f64::from(rm::PL_CLOCK_HZ);
    let n = ver.torque.len();
    let samples = || {
        ver.torque
            .iter()
            .enumerate()
            .map(|(k, &y)| (k as f64 * ts, y))
    };
    let band = metrics::settling_band(0.0, STEP_NM);
    let settling = metrics::settling_time_s(samples(), 0.0, n as f64 * ts, STEP_NM, band);
    let last = &ver.torque[n - n / 4..];
    let final_nm = last.iter().sum::<f64>() / last.len() as f64;
    println!(
        "{name}: {n} periods of {} cycles, {} decisions compared, {diff} differences; \
         settling {settling:?} s, final {final_nm:.4} N m, overruns {}",
        r.period_cycles(),
        ver.decisions.len(),
        ver.overruns
    );
    if let Some(k) = rust
        .torque
        .iter()
        .zip(&ver.torque)
        .position(|(a, b)| a != b)
    {
        println!(
            "torque differs first at period {k}: {} vs {}",
            rust.torque[k], ver.torque[k]
        );
    }
    for (k, (a, b)) in rust.decisions.iter().zip(&ver.decisions).enumerate() {
        if a != b {
            println!("period {k}: rust {a:#x} rtl {b:#x}");
        }
    }
    assert_eq!(rust.decisions.len(), ver.decisions.len());
    assert_eq!(diff, 0, "decisions differ");
    assert_eq!(rust.torque, ver.torque, "plant torque differs");
    // The decisions are the core's (DONE_COUNT moves every period) and
    // switch (not a stuck state).
    let done: Vec<u32> = ver.decisions.iter().map(|d| d >> 15).collect();
    assert!(
        done.windows(2).all(|w| w[1] == (w[0] + 1) & 0xFFFF),
        "{done:?}"
    );
    let s: Vec<u32> = ver.decisions.iter().map(|d| d & 7).collect();
    assert!(s.windows(2).filter(|w| w[0] != w[1]).count() > 5, "{s:?}");
    assert_eq!(ver.overruns, 0);
    // The loop does its job: torque at the reference.
    assert!(settling.is_some(), "no settling");
    assert!((final_nm - STEP_NM).abs() < 0.04, "final {final_nm}");
}

#[test]
fn autonomous_loop_at_64_khz_equals_the_simulated_pl() {
    // The paper's rate: 391 x 4 cycles (63.94 kHz), 3 ms window.
    compare(
        Rate {
            adc_period: 391,
            avg_log2: 2,
            conv: 50,
            periods: 192,
        },
        "64 kHz",
    );
}

#[test]
fn autonomous_loop_at_1_us_equals_the_simulated_pl() {
    // 1 MHz: one conversion per period (a 1 MSPS simultaneous-sampling ADC
    // with a 100 ns result), 2 ms window.
    compare(
        Rate {
            adc_period: 100,
            avg_log2: 0,
            conv: 10,
            periods: 2000,
        },
        "1 us",
    );
}
