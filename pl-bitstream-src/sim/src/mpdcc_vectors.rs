//! Test vectors for the MPDCC RTL against `models::mpdcc::mpdcc_fixed` (the frozen
//! core, `FpgaConfig::core`), and the comparison loop used by the tests and
//! `scripts/rtl-check mpdcc-lane`.
//!
//! Lane vectors (`mpdcc_lane` against `mpdcc_fixed::lane`), three classes cycled by
//! index:
//! - closed loop: the states an FPGA-model-driven loop of the default drive
//!   passes through (start-up transient, steady state, deadlocks), every
//!   candidate of every step whose lazy check fails, all seven outputs;
//! - random states: random currents, fluxes, capacitor voltages and `s(k-1)`
//!   through the model's common terms and node changes;
//! - raw: every word random over its range (nodes up to the 18-bit
//!   saturation, bounds 0..=32767), with bends between the pieces, and
//!   corners (zero slope, zero bound, `|e0|` at the bound).
//!
//! Inputs are offered back to back, with a random idle gap before one in
//! eight, so the pipeline is checked at one input per clock and with gaps.
use models::mpdcc::closed_loop::{self, LoopConfig};
use models::mpdcc::controller::{candidates, Controller, CtrlState, Decision, StateError};
use models::mpdcc::mpdcc_fixed::{self, Coeffs, FpgaConfig, Inputs, MpdccFixed, NODE_MAX};
use models::mpdcc::params::DriveParams;

use crate::mpdcc_lane::{LaneInput, MpdccLaneSim};
pub use crate::mpdtc_vectors::Rng;

/// The frozen core with the default drive parameters.
pub fn core() -> MpdccFixed {
    let p = DriveParams::default();
    MpdccFixed::new(&p, FpgaConfig::core(&p.machine)).expect("default MPDCC core")
}

/// The lane's constants (L = 8, N_bar = 128, four nodes) are those of `k`.
pub fn lane_constants_match(k: &Coeffs) -> bool {
    k.lambda == 3 && k.m_bits == 7 && k.n_bar == 128 && k.nodes == 4
}

/// One lane vector and the model's `l_j`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LaneCase {
    /// What the RTL is given.
    pub input: LaneInput,
    /// `mpdcc_fixed::lane` of it.
    pub want: u32,
}

fn lane_case(k: &mut Coeffs, e0: i16, nodes: [i32; 4], bnd: i16) -> LaneCase {
    k.bnd[0] = bnd;
    let mut n: mpdcc_fixed::Nodes = [[0; 7]; mpdcc_fixed::MAX_NODES];
    for i in 0..4 {
        n[i][0] = nodes[i];
    }
    let (want, _) = mpdcc_fixed::lane(k, i32::from(e0), &n, 0);
    LaneCase {
        input: LaneInput {
            e0,
            nodes,
            bnd,
            idle_before: 0,
        },
        want,
    }
}

/// Every candidate's seven lanes for the quantized state `x`.
fn cases_of_state(f: &MpdccFixed, x: &Inputs, out: &mut Vec<LaneCase>) {
    let k = f.coeffs();
    let c = mpdcc_fixed::common_terms(k, x);
    for s in candidates(x.s_prev) {
        let n: mpdcc_fixed::Nodes = core::array::from_fn(|i| mpdcc_fixed::node_deltas(k, &c, s, i));
        for j in 0..7 {
            let input = LaneInput {
                e0: c.e0[j],
                nodes: core::array::from_fn(|i| n[i][j]),
                bnd: k.bnd[j],
                idle_before: 0,
            };
            let (want, _) = mpdcc_fixed::lane(k, i32::from(c.e0[j]), &n, j);
            out.push(LaneCase { input, want });
        }
    }
}

/// Records the quantized states of the steps (all, or those that search).
struct Recorder {
    f: MpdccFixed,
    states: Vec<Inputs>,
    all: bool,
}

impl Controller for Recorder {
    fn name(&self) -> &'static str {
        "fpga-recorder"
    }
    fn step(&mut self, st: &CtrlState) -> Result<Decision, StateError> {
        let d = self.f.step(st)?;
        if let (Some(o), Ok(x)) = (self.f.last_outcome(), Inputs::quantize(st)) {
            if self.all || !o.results.is_empty() {
                self.states.push(x);
            }
        }
        Ok(d)
    }
}

/// Quantized states of the FPGA-model-driven loop that searched: two
/// fundamental periods from start-up.
pub fn closed_loop_states() -> Vec<Inputs> {
    record_loop(false)
}

/// Every quantized state of the same loop (kept steps included).
pub fn closed_loop_all_states() -> Vec<Inputs> {
    record_loop(true)
}

fn record_loop(all: bool) -> Vec<Inputs> {
    let p = DriveParams::default();
    let mut r = Recorder {
        f: core(),
        states: Vec::new(),
        all,
    };
    let cfg = LoopConfig {
        warmup_periods: 1,
        measure_periods: 1,
    };
    closed_loop::run(&p, &cfg, &mut r, None, &mut |_| {}).expect("default closed loop");
    r.states
}

fn random_state(rng: &mut Rng, p: &DriveParams) -> CtrlState {
    let u = |rng: &mut Rng, a: f64| (rng.unit() * 2.0 - 1.0) * a;
    let op = p.operating_point;
    CtrlState {
        x_m: [u(rng, 1.3), u(rng, 1.3), u(rng, 1.1), u(rng, 1.1)],
        v_n_pu: u(rng, 0.08),
        v_ph_pu: core::array::from_fn(|_| p.inverter.v_ph_ref_pu() + u(rng, 0.08)),
        omega_r_pu: op.omega_r_pu * (1.0 + u(rng, 0.05)),
        omega_s_pu: op.omega_s_pu,
        i_ref_ab_pu: [u(rng, 1.0), u(rng, 1.0)],
        s_prev: core::array::from_fn(|_| rng.range(0, 7) as u8),
    }
}

fn raw_case(rng: &mut Rng, k: &mut Coeffs, idx: u64) -> LaneCase {
    let nmax = NODE_MAX as i32;
    let bnd = match idx % 5 {
        0 => rng.range(0, 32767) as i16,
        1 => 0,
        _ => rng.range(1, 2000) as i16,
    };
    let e0 = match idx % 7 {
        0 => bnd,
        1 => -bnd,
        2 => rng.range(-32768, 32767) as i16,
        _ => rng
            .range(-(i32::from(bnd)) - 50, i32::from(bnd) + 50)
            .clamp(-32768, 32767) as i16,
    };
    let mut nodes = [0i32; 4];
    let mut d = rng.range(-1500, 1500);
    for node in nodes.iter_mut() {
        *node = d.clamp(-nmax, nmax);
        d = 2 * d + rng.range(-600, 600);
    }
    match idx % 11 {
        0 => nodes = [0; 4],
        1 => nodes = core::array::from_fn(|_| rng.range(-nmax, nmax)),
        2 => nodes = [nmax, -nmax, nmax, -nmax],
        _ => {}
    }
    lane_case(k, e0, nodes, bnd)
}

/// `n` lane vectors of seed `seed`, the three classes cycled by index.
pub fn lane_cases(seed: u64, n: u64) -> Vec<LaneCase> {
    let f = core();
    assert!(
        lane_constants_match(f.coeffs()),
        "lane RTL constants differ"
    );
    let p = DriveParams::default();
    let mut rng = Rng(seed);
    let mut k = f.coeffs().clone();
    let mut pool_cl = Vec::new();
    let states = closed_loop_states();
    // Start at a seed-dependent step so seeds see different states.
    let first = (seed as usize * 7919) % states.len().max(1);
    for x in states.iter().cycle().skip(first).take(states.len()) {
        if pool_cl.len() as u64 > n / 3 {
            break;
        }
        cases_of_state(&f, x, &mut pool_cl);
    }
    let mut pool_rs = Vec::new();
    while (pool_rs.len() as u64) < n / 3 + 1 {
        if let Ok(x) = Inputs::quantize(&random_state(&mut rng, &p)) {
            cases_of_state(&f, &x, &mut pool_rs);
        }
    }
    let mut out = Vec::with_capacity(n as usize);
    for idx in 0..n {
        let mut c = match idx % 3 {
            0 if !pool_cl.is_empty() => pool_cl[(idx / 3) as usize % pool_cl.len()],
            1 => pool_rs[(idx / 3) as usize % pool_rs.len()],
            _ => raw_case(&mut rng, &mut k, idx),
        };
        if rng.range(0, 7) == 0 {
            c.input.idle_before = rng.range(1, 15) as u32;
        }
        out.push(c);
    }
    out
}

/// Summary of a lane run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LaneSummary {
    /// Vectors run.
    pub vectors: u64,
    /// Outputs that differ from the model (a lost output counts).
    pub mismatches: u64,
    /// Index of the first mismatch.
    pub first_mismatch: Option<u64>,
    /// The latency, if every output had the same.
    pub latency_cycles: Option<u32>,
    /// Vectors with `l_j = 0`, `0 < l_j < 128`, `l_j = 128` (coverage).
    pub classes: [u64; 3],
}

/// Runs `n` vectors of seed `seed` through the RTL and the model.
pub fn check_lane(seed: u64, n: u64) -> LaneSummary {
    let cases = lane_cases(seed, n);
    let mut sim = MpdccLaneSim::new();
    let mut s = LaneSummary {
        vectors: n,
        mismatches: 0,
        first_mismatch: None,
        latency_cycles: None,
        classes: [0; 3],
    };
    let mut lat: Option<Option<u32>> = None;
    for (b, chunk) in cases.chunks(65_536).enumerate() {
        let inputs: Vec<LaneInput> = chunk.iter().map(|c| c.input).collect();
        let got = sim.run(&inputs);
        for (i, c) in chunk.iter().enumerate() {
            let idx = (b * 65_536 + i) as u64;
            s.classes[match c.want {
                0 => 0,
                128 => 2,
                _ => 1,
            }] += 1;
            let ok = got.get(i).is_some_and(|g| g.lj == c.want);
            if !ok {
                s.mismatches += 1;
                s.first_mismatch.get_or_insert(idx);
            }
            if let Some(g) = got.get(i) {
                lat = Some(match lat {
                    None => Some(g.latency_cycles),
                    Some(Some(l)) if l == g.latency_cycles => Some(l),
                    _ => None,
                });
            }
        }
    }
    s.latency_cycles = lat.flatten();
    s
}

/// Summary of an explorer run (one result per candidate).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ExplorerSummary {
    /// States (decisions) run.
    pub states: u64,
    /// Candidates evaluated.
    pub candidates: u64,
    /// Candidates whose result differs in any field (a lost one counts).
    pub mismatches: u64,
    /// Index (candidate count before it) of the first mismatch.
    pub first_mismatch: Option<u64>,
    /// The latency, if every result had the same.
    pub latency_cycles: Option<u32>,
    /// Candidates with `L* = 0`, `0 < L* < 128`, `L* = 128`.
    pub classes: [u64; 3],
}

/// `n` states (closed-loop and random, alternating; seed `seed`), every
/// candidate through the RTL explorer and `mpdcc_fixed::explore`, compared on
/// `s`, `L*`, `J`, `J_dl`, `f_s` and `Delta_j`.
pub fn check_explorer(seed: u64, n: u64) -> ExplorerSummary {
    use crate::mpdcc_explorer::MpdccExplorerSim;
    let f = core();
    let k = f.coeffs();
    let p = DriveParams::default();
    let mut rng = Rng(seed);
    let cl = closed_loop_states();
    let first = (seed as usize * 7919) % cl.len().max(1);
    let mut sim = MpdccExplorerSim::new();
    let mut s = ExplorerSummary {
        states: 0,
        candidates: 0,
        mismatches: 0,
        first_mismatch: None,
        latency_cycles: None,
        classes: [0; 3],
    };
    let mut lat: Option<Option<u32>> = None;
    for idx in 0..n {
        let x = if idx % 2 == 0 && !cl.is_empty() {
            cl[(first + idx as usize / 2) % cl.len()]
        } else {
            match Inputs::quantize(&random_state(&mut rng, &p)) {
                Ok(x) => x,
                Err(_) => continue,
            }
        };
        let c = mpdcc_fixed::common_terms(k, &x);
        let cands: Vec<[u8; 3]> = candidates(x.s_prev).iter().copied().collect();
        let got = sim.run(k, &c, x.s_prev, &cands);
        s.states += 1;
        for (i, &cand) in cands.iter().enumerate() {
            let want = mpdcc_fixed::explore(k, &c, x.s_prev, cand);
            s.classes[match want.l_star {
                0 => 0,
                128 => 2,
                _ => 1,
            }] += 1;
            let ok = got.get(i).is_some_and(|g| {
                g.s == want.s
                    && g.l_star == want.l_star
                    && g.cost == want.cost
                    && g.j_dl == want.j_dl
                    && g.fs == want.fs
                    && g.deltas == want.deltas
            });
            if !ok {
                s.mismatches += 1;
                s.first_mismatch.get_or_insert(s.candidates);
            }
            if let Some(g) = got.get(i) {
                lat = Some(match lat {
                    None => Some(g.latency_cycles),
                    Some(Some(l)) if l == g.latency_cycles => Some(l),
                    _ => None,
                });
            }
            s.candidates += 1;
        }
    }
    s.latency_cycles = lat.flatten();
    s
}

/// Summary of a core run (one decision per vector).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoreSummary {
    /// Decisions run.
    pub vectors: u64,
    /// Explorers used.
    pub explorers: u32,
    /// Decisions that differ in any field (position, kind, `L*`, candidate
    /// count, `J` and `J_dl` of the chosen candidate, cycle count).
    pub mismatches: u64,
    /// Index of the first mismatch.
    pub first_mismatch: Option<u64>,
    /// Largest measured cycle count, start strobe to `done_o`.
    pub worst_case_cycles: u32,
    /// Mean measured cycle count.
    pub mean_cycles: f64,
    /// Kept, optimal, deadlock decisions.
    pub kinds: [u64; 3],
}

/// `n` decisions (seed `seed`), a third each: the states of the
/// FPGA-model-driven loop (kept steps included), its steps that search, and
/// random states, some of them the constructed worst case
/// (`s(k-1)` with six admissible positions per phase, 216 candidates),
/// through `mpdcc_core` of datapath `config` with `explorers` explorers and
/// `MpdccFixed::decide_raw`; the cycle count against
/// `cycles::pipelined_core_cycles_ii` of the datapath's `II`.
pub fn check_core(
    seed: u64,
    n: u64,
    explorers: u32,
    config: crate::mpdcc_core::CoreConfig,
) -> CoreSummary {
    use crate::mpdcc_core::MpdccCoreSim;
    use models::mpdcc::controller::DecisionKind;
    use models::mpdcc::cycles;
    let f = core();
    let k = f.coeffs();
    let p = DriveParams::default();
    let mut rng = Rng(seed);
    let cl = closed_loop_all_states();
    let searched = closed_loop_states();
    let first = (seed as usize * 7919) % cl.len().max(1);
    let mut sim = MpdccCoreSim::with_config(config);
    let mut s = CoreSummary {
        vectors: 0,
        explorers,
        mismatches: 0,
        first_mismatch: None,
        worst_case_cycles: 0,
        mean_cycles: 0.0,
        kinds: [0; 3],
    };
    let mut sum = 0u64;
    for idx in 0..n {
        let x = match idx % 3 {
            0 if !cl.is_empty() => cl[(first + idx as usize) % cl.len()],
            1 if !searched.is_empty() => searched[(first + idx as usize) % searched.len()],
            _ => {
                let mut st = random_state(&mut rng, &p);
                if idx % 9 == 2 {
                    // six admissible positions in every phase: 216 candidates
                    st.s_prev = [3 + rng.range(0, 1) as u8, 3 + rng.range(0, 1) as u8, 3];
                }
                match Inputs::quantize(&st) {
                    Ok(x) => x,
                    Err(_) => continue,
                }
            }
        };
        let want = f.decide_raw(&x);
        let got = sim.decide(k, &x, explorers);
        let d = want.decision;
        let winner = want.results.iter().find(|r| r.s == d.s);
        let (cost, j_dl) = match (d.kind, winner) {
            (DecisionKind::Kept, _) | (_, None) => (0, 0),
            (_, Some(r)) => (r.cost, r.j_dl),
        };
        let cands = models::mpdcc::controller::candidates(x.s_prev).len() as u32;
        let model_cycles =
            cycles::pipelined_core_cycles_ii(explorers.clamp(1, 6), config.ii(), cands);
        let ok = got.s == d.s
            && got.kind == Some(d.kind)
            && got.horizon_steps == d.horizon_steps
            && got.candidates == d.candidates
            && got.cost == cost
            && got.j_dl == j_dl
            && got.measured_cycles == Some(got.cycles)
            && got.cycles == model_cycles;
        if !ok {
            s.mismatches += 1;
            s.first_mismatch.get_or_insert(s.vectors);
        }
        s.kinds[match d.kind {
            DecisionKind::Kept => 0,
            DecisionKind::Optimal => 1,
            DecisionKind::Deadlock => 2,
        }] += 1;
        let m = got.measured_cycles.unwrap_or(u32::MAX);
        s.worst_case_cycles = s.worst_case_cycles.max(m);
        sum += u64::from(m);
        s.vectors += 1;
    }
    s.mean_cycles = sum as f64 / s.vectors.max(1) as f64;
    s
}
