//! `mpdtc_core` as the PL sees it: a fixed latency of
//! [`regmap::MPDTC_LATENCY_CYCLES`] cycles from the input strobe to
//! `out_valid`, one decision in flight, the state registers updated at the
//! edge that raises `out_valid`, a state load (to zero) while idle. The
//! decision itself is [`mpdtc_fixed::decide`], the bit-exact model of the
//! core's arithmetic; the register words are read as the core's ports do
//! (two's complement in the port width).

use super::NEVER;
use models::pmsm::mpdtc_fixed::{self, FixedInputs, FixedParams, FixedState};

const LAT: u32 = regmap::MPDTC_LATENCY_CYCLES;
const VLD_MASK: u64 = (1 << LAT) - 1;
/// `vld_q[LATENCY-2]`: the state registers load at this cycle's edge.
const DONE_BIT: u64 = 1 << (LAT - 2);
/// `vld_q[LATENCY-1]`: `out_valid`.
const VALID_BIT: u64 = 1 << (LAT - 1);

/// Sign-extends the low `bits` of a register word.
pub fn sext(word: u32, bits: u32) -> i32 {
    let sh = 32 - bits;
    ((word << sh) as i32) >> sh
}

/// Result of a decision kept until `out_valid`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Pending {
    /// S[k+1].
    pub s_next: u8,
    /// i_q* (CUR, two's complement).
    pub iq_ref: i32,
    next: FixedState,
}

/// The core's control and state registers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Core {
    vld: u64,
    busy: bool,
    /// State registers (S[k], S[k-1], observers, integrator).
    pub state: FixedState,
    /// The decision in flight (or the last one).
    pub pending: Pending,
}

impl Core {
    /// `in_ready`.
    pub fn ready(&self) -> bool {
        !self.busy
    }

    /// `out_valid` in this cycle.
    pub fn valid(&self) -> bool {
        self.vld & VALID_BIT != 0
    }

    /// One clock edge: `in_valid` with `inputs`/`params`, `load` = state
    /// load (to zero).
    pub fn step(&mut self, in_valid: bool, load: bool, inputs: &FixedInputs, params: &FixedParams) {
        let start = in_valid && !self.busy;
        let done = self.vld & DONE_BIT != 0;
        if start {
            let out = mpdtc_fixed::decide(&self.state, inputs, params);
            self.pending = Pending {
                s_next: out.s_next,
                iq_ref: out.iq_ref,
                next: out.next,
            };
        }
        if done {
            self.state = self.pending.next;
        } else if load && !self.busy {
            self.state = FixedState::default();
        }
        self.vld = ((self.vld << 1) | u64::from(start)) & VLD_MASK;
        if start {
            self.busy = true;
        } else if done {
            self.busy = false;
        }
    }

    /// Cycles from now in which the pipeline only shifts.
    pub fn quiet(&self, load: bool) -> u64 {
        if load && !self.busy && self.state != FixedState::default() {
            return 0;
        }
        if self.vld & (DONE_BIT | VALID_BIT) != 0 {
            return 0;
        }
        if self.vld == 0 {
            return NEVER;
        }
        let top = 63 - self.vld.leading_zeros();
        u64::from(LAT - 2 - top)
    }

    /// Applies `k` quiet cycles.
    pub fn skip(&mut self, k: u64) {
        if self.vld != 0 {
            self.vld = (self.vld << k.min(63)) & VLD_MASK;
        }
    }
}
