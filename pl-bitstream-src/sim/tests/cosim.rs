//! The co-simulation bridge on the host, without QEMU:
//! - the firmware's drive code (`Servo`) on the Verilated `pl_top` coupled to
//!   the plant (`SimDrive<RtlPl>`) takes the same MPDTC decisions over a
//!   0.4 N m step window as on the simulated PL (`SimDrive<SimPl>`), and the
//!   settling times agree within 5 %, also with an asynchronous converter
//!   (random data-ready delay and width);
//! - the `pl-cosim` binary answers the wire protocol over its FIFOs: ID,
//!   a read-only write refused, a scratch register round trip, the time
//!   mapping (one guest count = one PL cycle) and the control-period
//!   boundaries of the ADC average (1564 cycles after reset).
use drive::pl::mpdtc::Mpdtc;
use drive::pl::top::Mode;
use drive::servo::{Servo, ServoConfig, StepResult};
use regmap::bus::RegisterBus;
use regmap::{self as rm};
use rtl_sim::cosim::{Bridge, RtlPl};
use rtl_sim::rtl_timed::RtlTimedSimPl;
use simpl::cosim::{Op, Reply, Request, Status, REPLY_LEN};
use simpl::pl::SimPl;
use simpl::{PlModel, SimConfig, SimDrive};
use std::io::{BufRead, BufReader, Read, Write};
use std::process::{Command, Stdio};

/// The simulated drive with the Verilated `pl_top`'s bus timing.
fn rtl_timed_model(cfg: &SimConfig) -> SimDrive<RtlTimedSimPl> {
    SimDrive::with_pl(cfg, RtlTimedSimPl(SimPl::with_converter(cfg.converter()))).unwrap()
}

/// `mode mpdtc`, `enable`, `step 0.4` armed at once (it starts after the
/// 2 ms alignment): the step's result and the decision of every period of
/// its window. On the PS-fed path, with the simulated PL on the RTL's bus
/// timing (`RtlTimedSimPl`): the PS-fed loop's decisions depend on the
/// cycle each access lands on (with 1-cycle accesses on the simulated PL
/// one of the 128 differed once the RTL's took 3 and 4 cycles); with the
/// autonomous loop the last of the 128 decisions differed between 2-cycle
/// and 1-cycle accesses, not yet understood; the autonomous loop's
/// RTL-vs-model equality is `tests/autonomous_loop.rs` (equal bus timing).
fn mpdtc_step<P: PlModel>(sim: &mut SimDrive<P>) -> (StepResult, Vec<u8>) {
    let cfg = ServoConfig {
        mpdtc_ps_fed: true,
        // 2 ms of alignment (the default 0.2 s would be 12,800 periods of
        // RTL): the simulated motor is held on the d axis, where no
        // alignment moves it.
        align_cycles: 200_000,
        ..ServoConfig::for_plant(sim.config().motor, sim.config().adc_amps_per_count)
    };
    let mut s = Servo::new(&cfg).unwrap();
    s.init(sim).unwrap();
    s.set_mode(sim, Mode::Mpdtc).unwrap();
    s.enable(sim).unwrap();
    s.begin_step(sim, 0.4, 2e-3).unwrap();
    let mut decisions = Vec::new();
    // A step's decision is read at the next boundary, when the core has
    // surely finished it: read within the step, it would depend on how
    // many bus cycles the step's other accesses took, which differ
    // between the two PLs' bus models.
    let mut decided = false;
    for _ in 0..1000 {
        let a = sim.advance_to_boundary(20_000);
        assert!(a.control_periods >= 1, "no boundary in 200 us");
        if decided {
            decisions.push(Mpdtc(&mut *sim).last_decision().unwrap());
        }
        s.control_step(&mut *sim).unwrap();
        decided = s.torque_ref_nm() != 0.0;
        if !s.step_pending() {
            break;
        }
    }
    if decided {
        sim.advance_to_boundary(20_000);
        decisions.push(Mpdtc(&mut *sim).last_decision().unwrap());
    }
    assert_eq!(s.overruns(), 0);
    (s.step_result().expect("step completed"), decisions)
}

#[test]
fn the_servo_takes_the_same_mpdtc_decisions_on_the_rtl_as_on_the_simulated_pl() {
    let cfg = SimConfig::default();
    let mut model = rtl_timed_model(&cfg);
    let (r_model, d_model) = mpdtc_step(&mut model);
    let mut bridge = Bridge::new();
    let (r_rtl, d_rtl) = mpdtc_step(bridge.drive_mut());
    println!("simulated PL: {r_model:?}\nRTL: {r_rtl:?}");
    let pl = bridge.drive().pl();
    assert_eq!(pl.mismatches(), 0, "{:?}", pl.first_mismatch());
    assert!(d_rtl.len() >= 128, "{} periods recorded", d_rtl.len());
    let changes = d_rtl.windows(2).filter(|w| w[0] != w[1]).count();
    assert!(changes > 5, "only {changes} state changes: {d_rtl:?}");
    assert_eq!(d_rtl, d_model, "decisions over the step window");
    let (t_rtl, t_model) = (r_rtl.settling_s.unwrap(), r_model.settling_s.unwrap());
    assert!(
        (t_rtl / t_model - 1.0).abs() <= 0.05,
        "{t_rtl} vs {t_model}"
    );
    assert!((r_rtl.final_nm - 0.4).abs() < 0.05, "{r_rtl:?}");
}

/// An asynchronous converter (data-ready 0 to 8 cycles late and 1 to 4
/// cycles wide, random per conversion): the servo on the Verilated `pl_top`
/// takes the same decisions as on the simulated PL with the same converter,
/// and the 0.4 N m step settles within 5 % of the run with a one-cycle
/// data-ready at a fixed delay.
#[test]
fn an_asynchronous_converter_keeps_the_closed_loop() {
    let cfg = SimConfig {
        adc_drdy_jitter_cycles: 8,
        adc_drdy_width_cycles: 4,
        ..SimConfig::default()
    };
    let mut model = rtl_timed_model(&cfg);
    let (r_model, d_model) = mpdtc_step(&mut model);
    let mut rtl = SimDrive::with_pl(&cfg, RtlPl::with_converter(cfg.converter())).unwrap();
    let (r_rtl, d_rtl) = mpdtc_step(&mut rtl);
    let mut fixed = SimDrive::new(&SimConfig::default()).unwrap();
    let (r_fixed, _) = mpdtc_step(&mut fixed);
    println!(
        "asynchronous converter: simulated PL {r_model:?}\nRTL {r_rtl:?}\nfixed delay {r_fixed:?}"
    );
    let pl = rtl.pl();
    assert_eq!(pl.mismatches(), 0, "{:?}", pl.first_mismatch());
    assert!(d_rtl.len() >= 128, "{} periods recorded", d_rtl.len());
    assert_eq!(d_rtl, d_model, "decisions over the step window");
    let (t_async, t_fixed) = (r_rtl.settling_s.unwrap(), r_fixed.settling_s.unwrap());
    assert!(
        (t_async / t_fixed - 1.0).abs() <= 0.05,
        "{t_async} vs {t_fixed}"
    );
    assert!((r_rtl.final_nm - 0.4).abs() < 0.05, "{r_rtl:?}");
}

fn req(op: Op, addr: usize, data: u32, guest: u64) -> Request {
    Request {
        op,
        addr: addr as u32,
        data,
        guest,
    }
}

#[test]
fn pl_cosim_serves_the_protocol_over_its_fifos() {
    let dir = std::env::temp_dir().join(format!("pl-cosim-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let stats = dir.join("stats.json");
    let mut child = Command::new(env!("CARGO_BIN_EXE_pl-cosim"))
        .arg("--dir")
        .arg(&dir)
        .arg("--stats")
        .arg(&stats)
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let mut line = String::new();
    BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut line)
        .unwrap();
    assert_eq!(line.trim(), "ready");
    let mut tx = std::fs::OpenOptions::new()
        .write(true)
        .open(dir.join("req"))
        .unwrap();
    let mut rx = std::fs::File::open(dir.join("rep")).unwrap();
    let mut ask = |r: Request| -> Reply {
        tx.write_all(&r.encode()).unwrap();
        let mut b = [0u8; REPLY_LEN];
        rx.read_exact(&mut b).unwrap();
        Reply::decode(&b).unwrap()
    };
    let g0 = 5_000_000; // any origin: only differences count
    let id = ask(req(Op::Read, rm::TOP.addr(&rm::ID), 0, g0));
    assert_eq!(
        (id.status, id.data),
        (Status::Ok, u32::from_be_bytes(*b"PSDR"))
    );
    let first_cycle = id.pl_cycles;
    let ro = ask(req(Op::Write, rm::TOP.addr(&rm::ID), 1, g0 + 10));
    assert_eq!(ro.status, Status::SlaveError);
    let scratch = rm::TOP.addr(&rm::SCRATCH);
    assert_eq!(
        ask(req(Op::Write, scratch, 0x1234_5678, g0 + 20)).status,
        Status::Ok
    );
    let r = ask(req(Op::Read, scratch, 0, g0 + 30));
    assert_eq!((r.status, r.data), (Status::Ok, 0x1234_5678));
    let bad = ask(req(Op::Read, rm::BASE_ADDR + 0x7FFC, 0, g0 + 40));
    assert_eq!(bad.status, Status::SlaveError);
    // The ID read started at the origin and took 3 cycles. 100,000 guest
    // counts later the PL is 100,000 cycles on, and the ADC averages at
    // 4 x 391 cycles crossed in between are the control-period boundaries
    // (mode off).
    let s = ask(req(Op::Sync, 0, 0, g0 + 100_000));
    assert_eq!(s.pl_cycles, first_cycle - 3 + 100_000, "{s:?}");
    let expect = (s.pl_cycles as f64 / 1564.0) as u32;
    assert!(
        s.boundaries.abs_diff(expect) <= 1,
        "{s:?}, expected {expect}"
    );
    assert!(s.since_boundary < 1564, "{s:?}");
    let s2 = ask(req(Op::Sync, 0, 0, g0 + 100_000 + 3128));
    assert_eq!(s2.boundaries, 2, "{s2:?}");
    // A garbled record changes nothing and is answered as such.
    let mut raw = req(Op::Read, scratch, 0, g0 + 200_000).encode();
    raw[0] = 77;
    tx.write_all(&raw).unwrap();
    let mut b = [0u8; REPLY_LEN];
    rx.read_exact(&mut b).unwrap();
    assert_eq!(Reply::decode(&b).unwrap().status, Status::BadRequest);
    drop(tx);
    assert!(child.wait().unwrap().success());
    let st = std::fs::read_to_string(&stats).unwrap();
    assert!(st.contains("\"mismatches\":0"), "{st}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn rtl_pl_counts_a_read_as_three_cycles() {
    let mut pl = RtlPl::new(50);
    let c0 = pl.cycles();
    let (r, _) = pl.read(rm::TOP.addr(&rm::ID));
    assert_eq!(r, Ok(rm::ID_VALUE));
    assert_eq!(pl.cycles() - c0, 3);
    let mut sim = SimDrive::with_pl(&SimConfig::default(), pl).unwrap();
    assert_eq!(sim.read(rm::TOP.addr(&rm::ID)), Ok(rm::ID_VALUE));
}

#[test]
fn rtl_pl_counts_a_write_as_write_cycles() {
    let mut pl = RtlPl::new(50);
    let c0 = pl.cycles();
    let (r, _) = pl.write(rm::TOP.addr(&rm::SCRATCH), 7);
    assert_eq!(r, Ok(()));
    assert_eq!(pl.cycles() - c0, simpl::cosim::WRITE_CYCLES);
}

/// A posted write is served like a waiting one (same register, same PL
/// cycles) but answered with nothing; `Op::State` then gives the reply a
/// waiting write would have had, at the cycle the guest computes; a posted
/// write the PL refuses (read-only register) is counted.
#[test]
fn bridge_serves_posted_writes_without_a_reply() {
    let scratch = rm::TOP.addr(&rm::SCRATCH);
    let g0 = 1_000;
    let mut waits = Bridge::new();
    let mut posts = Bridge::new();
    let first = waits.handle(&req(Op::Sync, 0, 0, g0).encode()).unwrap();
    assert_eq!(posts.handle(&req(Op::Sync, 0, 0, g0).encode()), Some(first));
    let origin = (g0, first.pl_cycles);
    let w = waits
        .handle(&req(Op::Write, scratch, 0xABCD, g0 + 500).encode())
        .unwrap();
    assert_eq!(
        posts.handle(&req(Op::PostedWrite, scratch, 0xABCD, g0 + 500).encode()),
        None
    );
    let s = posts
        .handle(&req(Op::State, 0, 0, g0 + 900).encode())
        .unwrap();
    assert_eq!(
        s, w,
        "the state after the posted write is the waiting write's reply"
    );
    assert_eq!(
        s.pl_cycles,
        simpl::cosim::cycle_after_write(origin, g0 + 500, first.pl_cycles)
    );
    // Two posted writes closer than a write's cycles: the second is served
    // when the first ends, as a waiting one would be.
    posts.handle(&req(Op::PostedWrite, scratch, 1, g0 + 1000).encode());
    posts.handle(&req(Op::PostedWrite, scratch, 2, g0 + 1001).encode());
    let s = posts
        .handle(&req(Op::State, 0, 0, g0 + 2000).encode())
        .unwrap();
    assert_eq!(s.pl_cycles, first.pl_cycles + 1000 + 2 * 4);
    let r = posts
        .handle(&req(Op::Read, scratch, 0, g0 + 2000).encode())
        .unwrap();
    assert_eq!((r.status, r.data), (Status::Ok, 2));
    assert_eq!((posts.posted, posts.posted_errors), (3, 0));
    posts.handle(&req(Op::PostedWrite, rm::TOP.addr(&rm::ID), 1, g0 + 3000).encode());
    assert_eq!((posts.posted, posts.posted_errors), (4, 1));
    assert_eq!(posts.drive().pl().mismatches(), 0);
}
