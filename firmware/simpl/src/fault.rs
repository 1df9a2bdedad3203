//! `fault_block`: over-current on raw samples, external input, watchdog on
//! HEARTBEAT writes / WDG_TIMEOUT; latched, W1C with set winning.

use super::NEVER;

/// Fault bits (as `FAULT_STATUS`).
pub const OVERCURRENT: u8 = 1;
/// External fault input.
pub const EXTERNAL: u8 = 2;
/// Watchdog.
pub const WATCHDOG: u8 = 4;

/// |x| of a 12-bit two's complement value as 12-bit unsigned (|-2048| = 2048).
fn mag(x: u16) -> u16 {
    if x & 0x800 != 0 {
        (!x).wrapping_add(1) & 0xFFF
    } else {
        x
    }
}

/// Registers of `fault_block`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Fault {
    /// Latched faults (`FAULT_STATUS`).
    pub status: u8,
    oc_last: bool,
    wdg: u32,
}

/// Inputs of one cycle.
#[derive(Debug, Clone, Copy)]
pub struct FaultIn {
    /// Raw-sample strobe.
    pub sample_valid: bool,
    /// Raw samples (12 bits).
    pub sample: [u16; 3],
    /// OC_LIMIT, counts.
    pub oc_limit: u16,
    /// Synchronised external fault, active high.
    pub ext: bool,
    /// WDG_TIMEOUT, cycles.
    pub wdg_timeout: u32,
}

impl Fault {
    fn oc_sample(i: &FaultIn) -> bool {
        i.sample.iter().any(|&s| mag(s) > i.oc_limit)
    }

    /// Fault conditions of this cycle `{watchdog, external, overcurrent}`.
    pub fn cond(&self, i: &FaultIn) -> u8 {
        let oc = i.sample_valid && Self::oc_sample(i);
        let wdg = self.wdg >= i.wdg_timeout;
        (u8::from(wdg) << 2) | (u8::from(i.ext) << 1) | u8::from(oc)
    }

    /// Gate-driver fault input: latched or raised this cycle.
    pub fn trip(&self, i: &FaultIn) -> bool {
        self.status != 0 || self.cond(i) != 0
    }

    /// `FAULT_RAW`.
    pub fn raw(&self, i: &FaultIn) -> u8 {
        (u8::from(self.wdg >= i.wdg_timeout) << 2) | (u8::from(i.ext) << 1) | u8::from(self.oc_last)
    }

    /// One clock edge. `status_after_clear` is `FAULT_STATUS` after this
    /// cycle's W1C write (the table's rule), `heartbeat` a HEARTBEAT write.
    pub fn step(&mut self, i: &FaultIn, status_after_clear: u8, heartbeat: bool) {
        let cond = self.cond(i);
        self.status = status_after_clear | cond;
        if i.sample_valid {
            self.oc_last = Self::oc_sample(i);
        }
        if heartbeat {
            self.wdg = 0;
        } else {
            self.wdg = self.wdg.saturating_add(1);
        }
    }

    /// Cycles from now without a new latched bit or a watchdog expiry
    /// (no raw sample in them).
    pub fn quiet(&self, i: &FaultIn) -> u64 {
        if self.status | self.cond(i) != self.status {
            return 0;
        }
        if self.wdg >= i.wdg_timeout {
            NEVER
        } else {
            u64::from(i.wdg_timeout - self.wdg)
        }
    }

    /// Applies `k` quiet cycles.
    pub fn skip(&mut self, k: u64) {
        self.wdg = self.wdg.saturating_add(k.min(u64::from(u32::MAX)) as u32);
    }
}
