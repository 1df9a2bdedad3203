//! The simulated PL (`simpl::pl::SimPl`, event-driven) against the
//! Verilated `pl_top`: the same random sequence of register accesses (every
//! register of the map, valid and invalid values, unmapped and unaligned
//! addresses), ADC converter data, encoder and fault pin levels and idle
//! PL cycles goes into both, with an asynchronous converter (data-ready of
//! random delay and width, the same seeded `simpl::adc::Converter` in both); every read must return the same data and
//! response, every write the same response, and the gate outputs must
//! change at the same PL cycles to the same levels. Fails on the first
//! mismatch and prints the seed (`SIMPL_SEED=<n>` replays one).
//!
//! Timing correspondence: an AXI read of the harness takes 3 cycles with
//! the register-bus strobe in the first, a write 4 with the register file's
//! decoded write in the third; a `SimPl` access is that cycle, with idle
//! cycles around it here (as `rtl_sim::rtl_timed`). The Verilated model
//! leaves reset at cycle 4; `SimPl` counts from 0 there.
use drive::pl::mpdcc::Mpdcc;
use models::mpdcc::mpdcc_fixed::{self, Coeffs, Inputs};
use regmap::bus::{BusError, RegisterBus};
use regmap::{self as rm, Access, Register, BASE_ADDR, BLOCKS};
use rtl_sim::mpdtc_vectors::Rng;
use rtl_sim::pl_top::{PlTopSim, PtOut, OKAY, SLVERR};
use simpl::adc::{adc_word, Converter};
use simpl::pl::{Events, SimPl};

/// Converter time of both models: `drdy` rises 10 to 10 + `JITTER` edges
/// after `adc_cnv` and stays high 1 to `WIDTH` cycles (random per
/// conversion): the synchroniser sees every phase of an asynchronous edge.
const CONV: u32 = 10;
const JITTER: u32 = 5;
const WIDTH: u32 = 4;
/// Cycles the harness spends in reset before `SimPl`'s cycle 0.
const RESET_CYCLES: u64 = 4;

const GATES: Events = Events {
    gates: true,
    adc_convert: false,
    adc_average: false,
    pwm_period: false,
    control_boundary: false,
};

/// Both models and the gate edges each has produced: (cycle, hi, lo).
struct Pair {
    rtl: PlTopSim,
    sim: SimPl,
    rtl_gates: (u8, u8),
    rtl_edges: Vec<(u64, u8, u8)>,
    sim_edges: Vec<(u64, u8, u8)>,
    reads: u64,
    writes: u64,
    hist: [u64; 16],
    log: Vec<String>,
    /// Reads of CAP_DATA0..2 that returned a nonzero sample.
    cap_data: u64,
    /// Reads of CAP_STATUS in state DONE.
    cap_done: u64,
    /// Reads of CAP_DATA3..5 (position, velocity, following error) that
    /// returned a nonzero sample.
    cap_motion: u64,
    /// Reads of ENC_POS_SAMPLE that returned a nonzero position.
    pos_samples: u64,
    /// The simulated PL's answer to the last read.
    last_read: Result<u32, BusError>,
    /// MPDCC decisions read through the driver, by kind (kept, optimal,
    /// deadlock).
    mc_kinds: [u64; 3],
    /// Idle cycles with MPDTC_CTRL.AUTO set and the sequence out of IDLE.
    auto_cycles: u64,
    /// Reads of MPDTC_FE_ID/IQ that returned a nonzero current.
    fe_data: u64,
    /// FAULT_STATUS reads with ENCODER_LOSS, ADC_STUCK set.
    run_faults: [u64; 2],
}

impl Pair {
    fn new(seed: u64) -> Self {
        let conv = Converter::jittered(CONV, JITTER, WIDTH, seed);
        let mut rtl = PlTopSim::new();
        rtl.adc = Some(conv);
        assert_eq!(rtl.cycles, RESET_CYCLES);
        Self {
            rtl,
            sim: SimPl::with_converter(conv),
            rtl_gates: (0, 0),
            rtl_edges: Vec::new(),
            sim_edges: Vec::new(),
            reads: 0,
            writes: 0,
            hist: [0; 16],
            log: Vec::new(),
            cap_data: 0,
            cap_done: 0,
            cap_motion: 0,
            pos_samples: 0,
            last_read: Ok(0),
            mc_kinds: [0; 3],
            auto_cycles: 0,
            fe_data: 0,
            run_faults: [0; 2],
        }
    }

    /// One cycle of the Verilated model; a gate change at its edge is
    /// recorded at the cycle that first shows it (as `SimPl` does).
    fn rtl_step(&mut self) -> PtOut {
        let o = self.rtl.step();
        let after = self.rtl.peek();
        if (after.gate_hi, after.gate_lo) != self.rtl_gates {
            self.rtl_gates = (after.gate_hi, after.gate_lo);
            let cycle = self.rtl.cycles - RESET_CYCLES;
            self.rtl_edges.push((cycle, after.gate_hi, after.gate_lo));
        }
        o
    }

    fn sim_event(&mut self, ev: &Events) {
        if ev.gates {
            let g = self.sim.gates();
            self.sim_edges.push((self.sim.cycles(), g.hi, g.lo));
        }
    }

    fn sim_idle(&mut self, n: u64) {
        if std::env::var("SIMPL_CYCLE").is_ok() {
            for _ in 0..n {
                let g0 = self.sim.gates();
                self.sim.run_cycle_by_cycle(1);
                let g = self.sim.gates();
                if g != g0 {
                    self.sim_edges.push((self.sim.cycles(), g.hi, g.lo));
                }
            }
            return;
        }
        let mut left = n;
        while left > 0 {
            let (k, ev) = self.sim.run(left, &GATES);
            left -= k;
            self.sim_event(&ev);
        }
    }

    fn idle(&mut self, n: u64) {
        let st = self
            .sim
            .peek(BASE_ADDR + rel(&rm::TOP, &rm::STATUS) as usize);
        self.hist[st.unwrap_or(0) as usize & 15] += n;
        let peek = |r: &Register| self.sim.peek(rm::MPDTC.addr(r)).unwrap_or(0);
        if peek(&rm::MPDTC_CTRL) & 4 != 0 && peek(&rm::MPDTC_SEQ_STATUS) & 7 != 0 {
            self.auto_cycles += n;
        }
        for _ in 0..n {
            self.rtl_step();
        }
        self.sim_idle(n);
        self.check("idle");
    }

    fn read(&mut self, rel: u16) {
        self.rtl.inp.araddr = rel;
        self.rtl.inp.arvalid = 1;
        self.rtl.inp.rready = 1;
        // AR and the register-bus read in the first cycle, the register
        // file's second read stage in the next, R in the third.
        let o1 = self.rtl_step();
        assert_eq!(o1.arready, 1);
        self.rtl.inp.arvalid = 0;
        assert_eq!(self.rtl_step().rvalid, 0);
        let o2 = self.rtl_step();
        assert_eq!(o2.rvalid, 1);
        let (got, ev) = self.sim.read(BASE_ADDR + rel as usize);
        self.last_read = got;
        self.sim_event(&ev);
        self.sim_idle(2);
        let want = if o2.rresp == OKAY {
            Ok(o2.rdata)
        } else {
            assert_eq!(o2.rresp, SLVERR);
            Err(regmap::bus::BusError::SlaveError)
        };
        self.reads += 1;
        if let Ok(v) = want {
            let n = name(rel);
            if n.starts_with("CAP_DATA") && v != 0 {
                self.cap_data += 1;
                if matches!(n, "CAP_DATA3" | "CAP_DATA4" | "CAP_DATA5") {
                    self.cap_motion += 1;
                }
            }
            if n == "ENC_POS_SAMPLE" && v != 0 {
                self.pos_samples += 1;
            }
            if n == "CAP_STATUS" && v & 3 == rm::cap_state::DONE {
                self.cap_done += 1;
            }
            if n == "FAULT_STATUS" {
                self.run_faults[0] += u64::from(v >> 3 & 1);
                self.run_faults[1] += u64::from(v >> 4 & 1);
            }
            if n.starts_with("MPDTC_FE_I") && v != 0 {
                self.fe_data += 1;
            }
        }
        if got != want {
            self.fail(&format!(
                "read {rel:#06x} ({}): simpl {got:x?}, rtl {want:x?}",
                name(rel)
            ));
        }
        self.check("read");
    }

    fn write(&mut self, rel: u16, v: u32) {
        self.log.push(format!(
            "{:>9} write {rel:#06x} ({}) = {v:#x}",
            self.sim.cycles(),
            name(rel)
        ));
        self.rtl.inp.awaddr = rel;
        self.rtl.inp.wdata = v;
        self.rtl.inp.wstrb = 0xF;
        self.rtl.inp.awvalid = 1;
        self.rtl.inp.wvalid = 1;
        self.rtl.inp.bready = 1;
        // AW and W in the first cycle, the register-bus write in the next,
        // the register file's decoded write in the third (the simulated
        // PL's write cycle), B in the fourth.
        let o1 = self.rtl_step();
        assert_eq!((o1.awready, o1.wready), (1, 1));
        self.rtl.inp.awvalid = 0;
        self.rtl.inp.wvalid = 0;
        assert_eq!(self.rtl_step().bvalid, 0);
        assert_eq!(self.rtl_step().bvalid, 0);
        let o2 = self.rtl_step();
        assert_eq!(o2.bvalid, 1);
        self.sim_idle(2);
        let (got, ev) = self.sim.write(BASE_ADDR + rel as usize, v);
        self.sim_event(&ev);
        self.sim_idle(1);
        self.writes += 1;
        let want_ok = o2.bresp == OKAY;
        if got.is_ok() != want_ok {
            self.fail(&format!(
                "write {rel:#06x} ({}) = {v:#x}: simpl {got:?}, rtl bresp {}",
                name(rel),
                o2.bresp
            ));
        }
        self.check("write");
    }

    fn set_adc(&mut self, word: u64) {
        self.rtl.adc_data = word;
        self.sim.pins.adc_word = word;
    }

    fn set_pins(&mut self, a: bool, b: bool, z: bool, fault_n: bool) {
        self.rtl.inp.enc_a = u8::from(a);
        self.rtl.inp.enc_b = u8::from(b);
        self.rtl.inp.enc_z = u8::from(z);
        self.rtl.inp.fault_ext_n = u8::from(fault_n);
        self.sim.pins.enc_a = a;
        self.sim.pins.enc_b = b;
        self.sim.pins.enc_z = z;
        self.sim.pins.fault_ext_n = fault_n;
    }

    fn check(&mut self, what: &str) {
        assert_eq!(
            self.rtl.cycles - RESET_CYCLES,
            self.sim.cycles(),
            "cycle counts"
        );
        if self.rtl_edges != self.sim_edges {
            let n = self
                .rtl_edges
                .iter()
                .zip(&self.sim_edges)
                .position(|(a, b)| a != b)
                .unwrap_or(self.rtl_edges.len().min(self.sim_edges.len()));
            let msg = format!(
                "after {what}: gate edges differ from #{n}: rtl {:?}, simpl {:?}",
                &self.rtl_edges[n.saturating_sub(3)..self.rtl_edges.len().min(n + 4)],
                &self.sim_edges[n.saturating_sub(3)..self.sim_edges.len().min(n + 4)]
            );
            self.fail(&msg);
        }
    }

    fn fail(&mut self, msg: &str) -> ! {
        let tail = self.log[self.log.len().saturating_sub(25)..].join("\n");
        let mut regs = String::new();
        for (b, r) in all_registers() {
            let a = rel(b, r);
            let x = self.rtl.read(a);
            let (y, _) = self.sim.read(BASE_ADDR + a as usize);
            regs += &format!("  {:<20} rtl {:>10x?} simpl {:x?}\n", r.name, x, y);
        }
        panic!(
            "{msg}\nat PL cycle {}; last writes:\n{tail}\nregisters now (rtl, simpl):\n{regs}",
            self.sim.cycles(),
        );
    }
}

/// The pair as a register bus (both models see every access; the value is
/// the simulated PL's, equal to the RTL's or the test has failed).
struct PairBus<'a>(&'a mut Pair);

impl RegisterBus for PairBus<'_> {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        self.0.read((addr - BASE_ADDR) as u16);
        self.0.last_read
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        self.0.write((addr - BASE_ADDR) as u16, value);
        Ok(())
    }
}

/// One MPDCC-page operation (own random stream): arbitrary words to a page
/// register, the core's constants, or a decision through the driver on a
/// closed-loop state (its `s(k-1)` sometimes replaced), whose result must
/// also be the model's (`mpdcc_fixed::decide`).
fn mpdcc_op(p: &mut Pair, rng: &mut Rng, states: &[Inputs], k: &Coeffs) {
    match rng.next_u64() % 8 {
        0 => {
            let regs = rm::MPDCC.registers;
            let r = regs[(rng.next_u64() % regs.len() as u64) as usize];
            let v = value_for(rng, r);
            p.write(rel(&rm::MPDCC, r), v);
        }
        1 => Mpdcc(PairBus(p)).load_coeffs(k).expect("load constants"),
        _ => {
            let mut x = states[(rng.next_u64() % states.len() as u64) as usize];
            if rng.next_u64() % 3 == 0 {
                x.s_prev = core::array::from_fn(|_| (rng.next_u64() % 8) as u8);
            }
            if rng.next_u64() % 4 == 0 {
                let n = 1 + (rng.next_u64() % 6) as u32;
                Mpdcc(PairBus(p)).set_explorers(n).expect("n_use");
            }
            let mut m = Mpdcc(PairBus(p));
            // The constants again (arbitrary words may have changed them),
            // and no decision of an earlier arbitrary START in flight.
            m.load_coeffs(k).expect("load constants");
            for _ in 0..2000 {
                if !m.status().expect("status").busy {
                    break;
                }
            }
            m.write_inputs(&x).expect("inputs");
            m.start().expect("start");
            // Either poll at once or after a random pause.
            let pause = rng.next_u64() % 200;
            m.0 .0.idle(pause);
            let (got, _) = m.wait(2000).expect("MPDCC decision");
            let _ = m.deadlocks();
            let _ = m.config();
            let idx = match got.decision.kind {
                models::mpdcc::controller::DecisionKind::Kept => 0,
                models::mpdcc::controller::DecisionKind::Optimal => 1,
                models::mpdcc::controller::DecisionKind::Deadlock => 2,
            };
            let want = mpdcc_fixed::decide(k, &x, 2).decision;
            assert_eq!(got.decision, want, "MPDCC page vs model on {x:?}");
            p.mc_kinds[idx] += 1;
        }
    }
}

fn name(rel: u16) -> &'static str {
    rm::lookup(BASE_ADDR + rel as usize).map_or("unmapped", |(_, r)| r.name)
}

fn rel(b: &rm::Block, r: &Register) -> u16 {
    (b.addr(r) - BASE_ADDR) as u16
}

/// Every register of the map with its block.
fn all_registers() -> Vec<(&'static rm::Block, &'static Register)> {
    BLOCKS
        .iter()
        .flat_map(|b| b.registers.iter().map(move |r| (*b, *r)))
        .collect()
}

/// A value for a write to `r`: random bits, in range, at the limits, or one
/// of the values that make the blocks do something within a short test.
fn value_for(rng: &mut Rng, r: &Register) -> u32 {
    let useful: &[u32] = match r.name {
        "CTRL" => &[0, 1, 2, 2, 2, 3],
        "GATE_CTRL" => &[1, 1, 1, 0],
        "MPDTC_CTRL" => &[0, 0, 0, 1, 2, 3, 4, 4, 4, 6],
        "ADC_AVG_LOG2" => &[0, 1, 2, 2, 3],
        "MPDTC_FE_ANG_SCALE" => &[7 << 20, 1 << 20, 0x1234_5678],
        "MPDTC_FE_SPD_SCALE" => &[29_388_314, 1_000_000, 0],
        "MPDTC_FE_GAIN_A" | "MPDTC_FE_GAIN_B" | "MPDTC_FE_GAIN_C" => &[8192, 8192, 0x3_E000],
        "DEAD_TIME" => &[0, 1, 2, 3, 5, 17, 1023, 5000],
        "PWM_PERIOD" => &[0, 1, 2, 3, 7, 40, 40, 150, 150, 400],
        "DUTY_A" | "DUTY_B" | "DUTY_C" => &[0, 1, 2, 5, 20, 75, 200, 0xFFFF],
        "ADC_CTRL" => &[1, 1, 1, 0],
        "ADC_PERIOD" => &[0, 16, 17, 25, 40, 100],
        "ENC_CPR" => &[0, 4, 5, 16, 4096],
        "ENC_WINDOW" => &[0, 100, 101, 157, 1000],
        "OC_LIMIT" => &[1000, 1800, 2047, 3000, 1800, 250],
        "WDG_TIMEOUT" => &[0, 1000, 30_000, 100_000, 1_000_000],
        "FAULT_STATUS" => &[31, 1, 2, 4, 3, 8, 16, 24],
        "ERR" => &[7, 1, 2, 4, 3],
        "MPDTC_ALIGN_TIME" => &[0, 1, 2, 50, 300, 2000],
        "MPDTC_ALIGN_PERIOD" => &[0, 2, 3, 9, 40, 200],
        "MPDTC_ALIGN_ON" => &[0, 1, 3, 10, 100, 40000],
        "MPDTC_ALIGN_VEC" | "SW_STATE" => &[0, 1, 2, 3, 4, 5, 6, 7],
        "CAP_PRE" => &[0, 1, 2, 7, 512, 1019, 1022, 1023, 1023, 5000],
        "CAP_DECIM" => &[0, 0, 0, 1, 3],
        "CAP_SOURCE" => &[0, 1, 2, 3],
        "CAP_STEP" => &[0, 1, 40, 500],
        "CAP_THR_CH" => &[0, 1, 2, 3, 4, 5],
        "CAP_THR_LEVEL" => &[0, 1, 0xFFFF, 100, 0xFF00],
        "CAP_SEL" => &[0, 1, 2, 3, 4, 5],
        "CAP_RD_INDEX" => &[0, 1, 2, 3, 1020, 1023, 1024, 5000],
        _ => &[],
    };
    let roll = rng.next_u64() % 10;
    if !useful.is_empty() && roll < 6 {
        return useful[(rng.next_u64() % useful.len() as u64) as usize];
    }
    match roll {
        6 | 7 => rng.next_u64() as u32 & r.mask(),
        8 => match r.invalid {
            rm::Invalid::Clamp { min, max } => {
                [min.wrapping_sub(1), min, max, max.wrapping_add(1)][(rng.next_u64() % 4) as usize]
            }
            rm::Invalid::Reject { max } => max + (rng.next_u64() % 3) as u32,
            rm::Invalid::AllValid => r.mask().wrapping_add(rng.next_u64() as u32 % 3),
        },
        _ => rng.next_u64() as u32,
    }
}

/// ADC data: mostly small currents, sometimes beyond the over-current limit.
fn adc_data(rng: &mut Rng) -> u64 {
    let mut c = [0i32; 3];
    for x in &mut c {
        *x = if rng.next_u64() % 40 == 0 {
            rng.range(-2048, 2047)
        } else {
            rng.range(-300, 300)
        };
    }
    adc_word(c)
}

fn run(seed: u64, ops: usize) -> Pair {
    let mut rng = Rng(seed);
    let mut p = Pair::new(seed);
    // The MPDCC page has its own operation and random stream (below).
    let mut mc_rng = Rng(seed ^ 0x4D50_4443);
    let mc_states = rtl_sim::mpdcc_vectors::closed_loop_states();
    let mc_k = rtl_sim::mpdcc_vectors::core().coeffs().clone();
    let regs: Vec<_> = all_registers()
        .into_iter()
        .filter(|(b, _)| b.name != rm::MPDCC.name)
        .collect();
    let control: Vec<_> = regs
        .iter()
        .copied()
        .filter(|(_, r)| {
            r.access != Access::Ro
                && !r.name.starts_with("MPDTC_IN_")
                && !r.name.starts_with("MPDTC_P_")
        })
        .collect();
    // Quadrature phase of the encoder pins and their levels.
    let mut qph = 0u8;
    let mut z = false;
    // A short, active start: fast ADC and PWM, short alignment, watchdog fed.
    for (b, r, v) in [
        (&rm::ADC, &rm::ADC_PERIOD, 20),
        (&rm::PWM, &rm::PWM_PERIOD, 60),
        (&rm::PWM, &rm::DUTY_A, 20),
        (&rm::PWM, &rm::DEAD_TIME, 3),
        (&rm::MPDTC, &rm::MPDTC_ALIGN_TIME, 200),
        (&rm::MPDTC, &rm::MPDTC_ALIGN_PERIOD, 30),
        (&rm::MPDTC, &rm::MPDTC_ALIGN_ON, 7),
        (&rm::ENC, &rm::ENC_WINDOW, 300),
        (&rm::FAULT, &rm::WDG_TIMEOUT, 30_000),
    ] {
        p.write(rel(b, r), v);
    }
    for op in 0..ops {
        if op % 16 == 0 {
            mpdcc_op(&mut p, &mut mc_rng, &mc_states, &mc_k);
        }
        match rng.next_u64() % 100 {
            0..=29 => {
                let (b, r) = control[(rng.next_u64() % control.len() as u64) as usize];
                let v = value_for(&mut rng, r);
                p.write(rel(b, r), v);
            }
            30..=37 => {
                let (b, r) = regs[(rng.next_u64() % regs.len() as u64) as usize];
                let v = value_for(&mut rng, r);
                p.write(rel(b, r), v);
            }
            38..=39 => {
                // Unmapped, unaligned or MPDCC/CAPTURE page.
                let a = (rng.next_u64() & 0x7FFF) as u16;
                if rng.next_u64() % 2 == 0 {
                    p.write(a, rng.next_u64() as u32);
                } else {
                    p.read(a);
                }
            }
            40..=44 => {
                // A few control periods of the PS.
                for _ in 0..1 + rng.next_u64() % 8 {
                    // The PS's side of a control period: wait for SAMPLE with
                    // the sample, then START (with the watchdog fed).
                    let seq = rel(&rm::MPDTC, &rm::MPDTC_SEQ_STATUS);
                    for _ in 0..200 {
                        let st = p.sim.peek(BASE_ADDR + seq as usize).unwrap_or(0);
                        if st & 0xF == rm::seq_state::SAMPLE | 8 || st & 7 <= 1 {
                            break;
                        }
                        p.read(seq);
                    }
                    p.write(rel(&rm::TOP, &rm::HEARTBEAT), rng.next_u64() as u32);
                    // The capture channels of this period, as the PS writes
                    // them (small values around zero, sometimes large).
                    for r in [
                        &rm::CAP_IN_ID,
                        &rm::CAP_IN_IQ,
                        &rm::CAP_IN_TORQUE,
                        &rm::CAP_IN_TREF,
                    ] {
                        let v = rng.range(-200, 200) * (1 + (rng.next_u64() % 2) as i32 * 100);
                        p.write(rel(&rm::CAPTURE, r), v as u32 & 0xFFFF);
                    }
                    // Position, velocity, following error: full-width
                    // words (the register file masks the 16-bit one).
                    for r in [&rm::CAP_IN_POS, &rm::CAP_IN_VEL, &rm::CAP_IN_FERR] {
                        p.write(rel(&rm::CAPTURE, r), rng.next_u64() as u32);
                    }
                    p.write(rel(&rm::MPDTC, &rm::MPDTC_START), rng.next_u64() as u32);
                }
            }
            45..=64 => {
                let (b, r) = regs[(rng.next_u64() % regs.len() as u64) as usize];
                p.read(rel(b, r));
            }
            65..=69 => {
                let w = adc_data(&mut rng);
                p.set_adc(w);
            }
            70..=74 => {
                // Encoder: one quadrature step either way, a glitch (two
                // steps at once), or the index pin.
                match rng.next_u64() % 8 {
                    0..=2 => qph = (qph + 1) & 3,
                    3..=5 => qph = (qph + 3) & 3,
                    6 => qph = (qph + 2) & 3,
                    _ => z = !z,
                }
                let (a, b) =
                    [(false, false), (true, false), (true, true), (false, true)][qph as usize];
                // A short external fault pulse now and then.
                let pulse = rng.next_u64() % 40 == 0;
                p.set_pins(a, b, z, !pulse);
                let n = rng.next_u64() % 4;
                p.idle(n);
                if pulse {
                    p.set_pins(a, b, z, true);
                }
            }
            75..=84 => {
                // Re-arm: watchdog fed, faults cleared, a mode, gates on.
                p.write(rel(&rm::TOP, &rm::HEARTBEAT), 0);
                p.write(rel(&rm::FAULT, &rm::FAULT_STATUS), 31);
                let m = [1, 2, 2][(rng.next_u64() % 3) as usize];
                p.write(rel(&rm::TOP, &rm::CTRL), m);
                if m == 2 && rng.next_u64() % 4 != 0 {
                    // The PS-fed path or the autonomous loop.
                    let ctrl = [0, 0, 4][(rng.next_u64() % 3) as usize];
                    p.write(rel(&rm::MPDTC, &rm::MPDTC_CTRL), ctrl);
                    if rng.next_u64() % 2 == 0 {
                        p.write(rel(&rm::MPDTC, &rm::MPDTC_ALIGN_TIME), 100);
                    }
                }
                p.write(rel(&rm::PWM, &rm::GATE_CTRL), 1);
                // A new capture record now and then: short ones (most of
                // the ring before the trigger) so that some complete.
                if rng.next_u64() % 3 == 0 {
                    let pre = [1023, 1020, 1000, 3][(rng.next_u64() % 4) as usize];
                    p.write(rel(&rm::CAPTURE, &rm::CAP_PRE), pre);
                    p.write(rel(&rm::CAPTURE, &rm::CAP_ARM), 1);
                }
            }
            85..=86 => {
                // Every register once.
                for (b, r) in &regs {
                    p.read(rel(b, r));
                }
            }
            _ => {
                if rng.next_u64() % 8 != 0 {
                    p.write(rel(&rm::TOP, &rm::HEARTBEAT), 1);
                }
                let n = match rng.next_u64() % 10 {
                    0..=5 => rng.next_u64() % 64,
                    6..=8 => rng.next_u64() % 1500,
                    _ => rng.next_u64() % 25_000,
                };
                p.idle(n);
            }
        }
    }
    p
}

#[test]
fn simulated_pl_equals_verilated_pl_top() {
    let seed = std::env::var("SIMPL_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0x5EED_0009);
    println!("simpl_equiv seed {seed} (SIMPL_SEED={seed} replays it)");
    let p = run(seed, 12_000);
    println!(
        "{} PL cycles, {} reads, {} writes, {} gate edges",
        p.sim.cycles(),
        p.reads,
        p.writes,
        p.sim_edges.len()
    );
    println!(
        "idle cycles by STATUS (mode | gates active << 2 | fault << 3): {:?}",
        p.hist
    );
    // The run exercised the blocks (not a trivial pass): gate edges, MPDTC
    // decisions and sequence periods.
    let st = |r: &Register| p.sim.peek(rm::MPDTC.addr(r)).unwrap_or(0) >> 16;
    let (decisions, periods) = (st(&rm::MPDTC_STATUS), st(&rm::MPDTC_SEQ_STATUS));
    println!("{decisions} MPDTC decisions (mod 2^16), {periods} sequence periods (mod 2^16)");
    assert!(
        decisions > 200 && periods > 100,
        "{decisions} decisions, {periods} periods"
    );
    assert!(
        p.sim_edges.len() > 3000,
        "only {} gate edges",
        p.sim_edges.len()
    );
    assert!(p.reads > 1000 && p.writes > 1000);
    // The capture buffer completed records and its data was read.
    println!(
        "capture: {} CAP_STATUS reads in DONE, {} nonzero CAP_DATA reads ({} of position, \
         velocity, following error)",
        p.cap_done, p.cap_data, p.cap_motion
    );
    assert!(
        p.cap_done > 5 && p.cap_data > 100 && p.cap_motion > 20,
        "capture: {} done, {} data, {} motion data",
        p.cap_done,
        p.cap_data,
        p.cap_motion
    );
    // The boundary's encoder sample was read while the encoder had moved.
    println!("{} nonzero ENC_POS_SAMPLE reads", p.pos_samples);
    assert!(p.pos_samples > 5, "{} ENC_POS_SAMPLE reads", p.pos_samples);
    // The PL's encoder-loss and ADC-stuck latches were seen.
    println!(
        "FAULT_STATUS reads with ENCODER_LOSS, ADC_STUCK: {:?}",
        p.run_faults
    );
    assert!(p.run_faults.iter().all(|&n| n >= 3), "{:?}", p.run_faults);
    // MPDCC decisions of every kind went through the page.
    println!(
        "MPDCC decisions (kept, optimal, deadlock): {:?}",
        p.mc_kinds
    );
    assert!(p.mc_kinds.iter().all(|&n| n > 5), "{:?}", p.mc_kinds);
    // The autonomous loop ran (front end -> core -> gates) and its
    // currents were read.
    println!(
        "autonomous loop: {} idle cycles with AUTO and the sequence running, {} nonzero MPDTC_FE_ID/IQ reads",
        p.auto_cycles, p.fe_data
    );
    assert!(
        p.auto_cycles > 100_000 && p.fe_data > 50,
        "autonomous loop: {} cycles, {} front-end reads",
        p.auto_cycles,
        p.fe_data
    );
}
