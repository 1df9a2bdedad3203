//! `mpdcc_core` on the MPDCC page as `pl_top` wires it: an `MPDCC_START`
//! write while idle snapshots the page's input and constant words; the
//! decision is [`mpdcc_fixed::decide`] on that snapshot (the bit-exact model of the
//! core, not a copy of its arithmetic), and the core's busy time is
//! [`cycles::pipelined_core_cycles`] for the candidate set of `s(k-1)`,
//! plus the cycle of the snapshot. Timing, with the START write in cycle
//! `t` and the core's count `C`: `BUSY` reads 1 from `t + 1`, the result
//! registers change in `t + C + 1`, `BUSY` falls and `DONE` and the
//! counters change in `t + C + 2`.

use super::NEVER;
use models::mpdcc::controller::{candidates, DecisionKind};
use models::mpdcc::cycles;
use models::mpdcc::mpdcc_fixed::{self, Coeffs, Inputs};
use regmap::{self as rm, mpdcc_kind};

/// The page's input and constant words at a START (register values).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Words {
    /// `MPDCC_N_USE` (1..=6).
    pub n_use: u32,
    /// `MPDCC_S_PREV` (`{c, b, a}`, 3 bits each).
    pub s_prev: u32,
    /// `MPDCC_I_A` .. `MPDCC_OMEGA_S`, in page order.
    pub state: [u16; 12],
    /// `MPDCC_C_TAU` .. `MPDCC_LAMBDA_N`, in page order.
    pub consts: [u16; 27],
}

/// The result registers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Outputs {
    /// `MPDCC_DECISION`.
    pub decision: u32,
    /// `MPDCC_COST`.
    pub cost: u32,
    /// `MPDCC_J_DL`.
    pub j_dl: u32,
    /// `MPDCC_CYCLES`.
    pub cycles: u32,
}

/// The core's control state and the page's counters (the constants are
/// rebuilt from the words at each START: the ROM of `1/l` alone is 4 KiB,
/// more than the simulated PL may keep).
#[derive(Debug, Clone)]
pub struct MpdccBlock {
    left: u32,
    busy: bool,
    done: bool,
    count: u16,
    deadlocks: u16,
    pending: Outputs,
    /// The result registers.
    pub out: Outputs,
}

impl Default for MpdccBlock {
    fn default() -> Self {
        Self::new()
    }
}

/// The words of a register (two's complement in 16 bits).
fn w(v: u16) -> i16 {
    v as i16
}

/// The constants of the default build (`regmap::MPDCC_*`: `L`, `N_bar`,
/// nodes) with the page's constant words.
pub fn coeffs(words: &Words) -> Coeffs {
    let mut k = match Coeffs::core_shape(rm::MPDCC_LAMBDA, rm::MPDCC_M_BITS, rm::MPDCC_NODES) {
        Ok(k) => k,
        Err(_) => panic!("the register map's MPDCC build constants are a valid core"),
    };
    let c = &words.consts;
    k.c_tau = w(c[0]);
    k.c_r = w(c[1]);
    k.c_w = w(c[2]);
    k.c_p = w(c[3]);
    k.c_s = w(c[4]);
    k.c_3 = w(c[5]);
    k.c_d = w(c[6]);
    k.c_n = w(c[7]);
    k.c_ph = w(c[8]);
    k.s3h = w(c[9]);
    k.v_ph_ref = w(c[10]);
    k.c_tau1 = w(c[11]);
    k.c_r1 = w(c[12]);
    k.c_w1 = w(c[13]);
    k.c_s1 = w(c[14]);
    k.v_dc_half = w(c[15]);
    k.g3 = w(c[16]);
    k.gd = w(c[17]);
    k.g3_1 = w(c[18]);
    for j in 0..7 {
        k.bnd[j] = w(c[19 + j]);
    }
    k.lambda_n = c[26];
    k
}

impl MpdccBlock {
    /// After reset.
    pub fn new() -> Self {
        Self {
            left: 0,
            busy: false,
            done: false,
            count: 0,
            deadlocks: 0,
            pending: Outputs::default(),
            out: Outputs::default(),
        }
    }

    /// `MPDCC_STATUS`.
    pub fn status(&self) -> u32 {
        (u32::from(self.count) << 16) | (u32::from(self.done) << 1) | u32::from(self.busy)
    }

    /// `MPDCC_DEADLOCKS`.
    pub fn deadlocks(&self) -> u32 {
        u32::from(self.deadlocks)
    }

    /// The core's decision on `words` (what the result registers will show).
    pub fn evaluate(&self, words: &Words) -> Outputs {
        let k = coeffs(words);
        let s = &words.state;
        let s_prev = [0, 3, 6].map(|sh| ((words.s_prev >> sh) & 7) as u8);
        let x = Inputs {
            i_ab: [w(s[0]), w(s[1])],
            psi_ab: [w(s[2]), w(s[3])],
            v_n: w(s[4]),
            v_ph: [w(s[5]), w(s[6]), w(s[7])],
            i_ref_ab: [w(s[8]), w(s[9])],
            omega_r: w(s[10]),
            omega_s: w(s[11]),
            s_prev,
            saturated: false,
        };
        let n = words.n_use.clamp(1, rm::MPDCC_EXPLORERS);
        let out = mpdcc_fixed::decide(&k, &x, n);
        let d = out.decision;
        let (kind, cost, j_dl) = match (d.kind, out.results.iter().find(|r| r.s == d.s)) {
            (DecisionKind::Optimal, Some(r)) => (mpdcc_kind::OPTIMAL, r.cost, r.j_dl),
            (DecisionKind::Deadlock, Some(r)) => (mpdcc_kind::DEADLOCK, r.cost, r.j_dl),
            _ => (mpdcc_kind::KEPT, 0, 0),
        };
        let core_cycles =
            cycles::pipelined_core_cycles_ii(n, rm::MPDCC_II, candidates(s_prev).len() as u32);
        Outputs {
            decision: u32::from(d.s[0])
                | (u32::from(d.s[1]) << 3)
                | (u32::from(d.s[2]) << 6)
                | (kind << 12)
                | ((d.horizon_steps & 0xFF) << 16),
            cost,
            j_dl: j_dl as u32,
            cycles: (core_cycles & 0xFFFF) | ((d.candidates & 0xFF) << 16),
        }
    }

    /// One clock edge: `start` = an `MPDCC_START` write in this cycle, with
    /// the page's words as they are in it.
    pub fn step(&mut self, start: Option<&Words>) {
        if self.left > 0 {
            self.left -= 1;
            if self.left == 1 {
                self.out = self.pending;
            } else if self.left == 0 {
                self.busy = false;
                self.done = true;
                self.count = self.count.wrapping_add(1);
                if (self.out.decision >> 12) & 3 == mpdcc_kind::DEADLOCK {
                    self.deadlocks = self.deadlocks.wrapping_add(1);
                }
            }
        } else if let Some(words) = start {
            self.pending = self.evaluate(words);
            self.left = (self.pending.cycles & 0xFFFF) + rm::MPDCC_START_DELAY;
            self.busy = true;
            self.done = false;
        }
    }

    /// Cycles from now in which only the busy count runs.
    pub fn quiet(&self) -> u64 {
        if self.left == 0 {
            NEVER
        } else {
            u64::from(self.left.saturating_sub(2))
        }
    }

    /// Applies `k` quiet cycles.
    pub fn skip(&mut self, k: u64) {
        self.left -= k.min(u64::from(self.left)) as u32;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pl::SimPl;
    use drive::pl::mpdcc::Mpdcc;
    use models::mpdcc::controller::CtrlState;
    use models::mpdcc::mpdcc_fixed::{FpgaConfig, MpdccFixed};
    use models::mpdcc::params::DriveParams;
    use regmap::bus::{BusError, RegisterBus};
    use regmap::MPDCC;

    struct Bus(SimPl);

    impl RegisterBus for Bus {
        fn read(&mut self, addr: usize) -> core::result::Result<u32, BusError> {
            self.0.read(addr).0
        }
        fn write(&mut self, addr: usize, value: u32) -> core::result::Result<(), BusError> {
            self.0.write(addr, value).0
        }
    }

    fn core() -> MpdccFixed {
        let p = DriveParams::default();
        MpdccFixed::new(&p, FpgaConfig::core(&p.machine)).unwrap()
    }

    /// A state off the reference (the lazy check fails) from `s(k-1)`.
    fn state(s_prev: [u8; 3]) -> Inputs {
        let p = DriveParams::default();
        let st = CtrlState {
            x_m: [0.6, -0.2, 0.9, 0.3],
            v_n_pu: 0.01,
            v_ph_pu: [p.inverter.v_ph_ref_pu(); 3],
            omega_r_pu: p.operating_point.omega_r_pu,
            omega_s_pu: p.operating_point.omega_s_pu,
            i_ref_ab_pu: [0.8, 0.1],
            s_prev,
        };
        Inputs::quantize(&st).unwrap()
    }

    /// The words the driver writes give back the model's constants and its
    /// decision (the page adds nothing to the arithmetic).
    #[test]
    fn page_words_are_the_model_constants_and_decision() {
        let f = core();
        let x = state([4, 4, 3]);
        let mut pl = Bus(SimPl::new(10));
        Mpdcc(&mut pl).load_coeffs(f.coeffs()).unwrap();
        Mpdcc(&mut pl).write_inputs(&x).unwrap();
        let mut g = |r: usize| pl.read(MPDCC.addr(MPDCC.registers[r])).unwrap() as u16;
        let words = Words {
            n_use: u32::from(g(2)),
            s_prev: u32::from(g(4)),
            state: core::array::from_fn(|i| g(5 + i)),
            consts: core::array::from_fn(|i| g(17 + i)),
        };
        let out = MpdccBlock::new().evaluate(&words);
        assert_eq!(&coeffs(&words), f.coeffs());
        let want = f.decide_raw(&x).decision;
        let kind = match want.kind {
            DecisionKind::Kept => mpdcc_kind::KEPT,
            DecisionKind::Optimal => mpdcc_kind::OPTIMAL,
            DecisionKind::Deadlock => mpdcc_kind::DEADLOCK,
        };
        assert_ne!(want.kind, DecisionKind::Kept, "a state that searches");
        let s = want.s;
        assert_eq!(
            out.decision,
            u32::from(s[0])
                | u32::from(s[1]) << 3
                | u32::from(s[2]) << 6
                | kind << 12
                | want.horizon_steps << 16
        );
        // The search time of the core in pl_top's build (N = 1, II = 4):
        // common terms, the last of |S| candidates issued 4 (|S| - 1)
        // clocks after the first, the explorer latency 42, the arg-min
        // tree, the last fold.
        assert_eq!((rm::MPDCC_EXPLORERS, rm::MPDCC_II), (1, 4));
        let n = candidates(x.s_prev).len() as u32;
        assert_eq!(out.cycles & 0xFFFF, 20 + 4 * (n - 1) + 1 + 42 + 3 + 1);
        assert_eq!(out.cycles >> 16, want.candidates);
    }

    /// Timing of one decision through the simulated PL: BUSY from the cycle
    /// after the START write, the result after C + 1 cycles, DONE and the
    /// count one cycle later; a START while busy is ignored.
    #[test]
    fn start_busy_result_done_timing() {
        let f = core();
        let x = state([4, 4, 3]);
        let mut m = Mpdcc(Bus(SimPl::new(10)));
        m.load_coeffs(f.coeffs()).unwrap();
        m.write_inputs(&x).unwrap();
        let c = u64::from(cycles::pipelined_core_cycles_ii(
            rm::MPDCC_EXPLORERS,
            rm::MPDCC_II,
            candidates(x.s_prev).len() as u32,
        ));
        let a_status = MPDCC.addr(&rm::MPDCC_STATUS);
        let a_dec = MPDCC.addr(&rm::MPDCC_DECISION);
        assert_eq!(m.0 .0.peek(a_status), Some(0));
        m.start().unwrap();
        let t = m.0 .0.cycles(); // the START write was cycle t - 1
        let mut busy_from = None;
        let mut result_at = None;
        let mut done_at = None;
        for _ in 0..1200 {
            let now = m.0 .0.cycles();
            let st = m.0 .0.peek(a_status).unwrap();
            if st & 1 == 1 && busy_from.is_none() {
                busy_from = Some(now);
            }
            if m.0 .0.peek(a_dec).unwrap() != 0 && result_at.is_none() {
                result_at = Some(now);
            }
            if st == (1 << 16) | 2 {
                done_at = Some(now);
                break;
            }
            if now == t + 5 {
                // ignored while busy
                m.start().unwrap();
            } else {
                m.0 .0.run_cycle_by_cycle(1);
            }
        }
        assert_eq!(busy_from, Some(t));
        assert_eq!(result_at, Some(t + c));
        assert_eq!(done_at, Some(t + c + 1));
        let d = m.read_decision().unwrap();
        assert_eq!(d.decision, f.decide_raw(&x).decision);
        assert_eq!(u64::from(d.cycles), c);
        assert!(!m.status().unwrap().busy, "the second START was ignored");
    }
}
