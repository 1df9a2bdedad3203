//! `mpdtc_frontend` as `pl_top` uses it (MPDTC_CTRL.AUTO = 1): one run per
//! averaged ADC sample, at most one in flight (`pl_top`'s busy counter), the
//! results [`regmap::MPDTC_FE_LATENCY_CYCLES`] cycles after the start. The
//! arithmetic is [`frontend_fixed::frontend`], the bit-exact model of the
//! RTL, evaluated on the inputs captured at the start.

use super::NEVER;
use models::pmsm::frontend_fixed::{self, FrontendInputs, FrontendOutputs, FrontendParams};

const LAT: u32 = regmap::MPDTC_FE_LATENCY_CYCLES;
const VLD_MASK: u32 = (1 << LAT) - 1;
/// `vld_q[LATENCY-1]`: `out_valid`.
const VALID_BIT: u32 = 1 << (LAT - 1);
/// The edge that raises `out_valid` also loads the last stage (i_d, i_q).
const DONE_BIT: u32 = 1 << (LAT - 2);

/// The front end's pipeline and results.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Frontend {
    vld: u32,
    busy: u32,
    pending: FrontendOutputs,
    /// The last completed run's outputs (held until the next completes).
    pub out: FrontendOutputs,
}

impl Frontend {
    /// `pl_top`'s start condition besides AUTO and the sample strobe: no run
    /// in flight.
    pub fn idle(&self) -> bool {
        self.busy == 0
    }

    /// `out_valid` in this cycle.
    pub fn valid(&self) -> bool {
        self.vld & VALID_BIT != 0
    }

    /// One clock edge; `start` = AUTO, the sample strobe and [`Self::idle`].
    pub fn step(&mut self, start: Option<(&FrontendInputs, &FrontendParams)>) {
        if self.vld & DONE_BIT != 0 {
            self.out = self.pending;
        }
        self.vld = (self.vld << 1) & VLD_MASK;
        if let Some((inp, p)) = start {
            self.pending = frontend_fixed::frontend(inp, p);
            self.vld |= 1;
            self.busy = LAT;
        } else if self.busy > 0 {
            self.busy -= 1;
        }
    }

    /// Cycles from now in which only the pipeline shifts and the busy
    /// counter counts (no start, no result).
    pub fn quiet(&self) -> u64 {
        if self.vld & (DONE_BIT | VALID_BIT) != 0 {
            return 0;
        }
        if self.vld == 0 {
            // The busy counter only gates a start, and a start comes with
            // the sample strobe, an event of the ADC.
            return NEVER;
        }
        let top = 31 - self.vld.leading_zeros();
        u64::from(LAT - 2 - top)
    }

    /// Applies `k` quiet cycles.
    pub fn skip(&mut self, k: u64) {
        self.vld = ((u64::from(self.vld) << k.min(32)) as u32) & VLD_MASK;
        self.busy = self.busy.saturating_sub(k.min(u64::from(u32::MAX)) as u32);
    }
}
