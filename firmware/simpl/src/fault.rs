//! `fault_block`: over-current on raw samples, external input, watchdog on
//! HEARTBEAT writes / WDG_TIMEOUT, illegal encoder steps and the ADC result
//! timer while GATE_EN = 1; latched, W1C with set winning.

use super::NEVER;

/// Fault bits (as `FAULT_STATUS`).
pub const OVERCURRENT: u8 = 1;
/// External fault input.
pub const EXTERNAL: u8 = 2;
/// Watchdog.
pub const WATCHDOG: u8 = 4;
/// Illegal quadrature step while running.
pub const ENCODER_LOSS: u8 = 8;
/// No raw ADC sample for `ADC_PERIOD` + [`ADC_MARGIN`] cycles while running.
pub const ADC_STUCK: u8 = 16;
/// `fault_block`'s `ADC_MARGIN`, cycles.
pub const ADC_MARGIN: u32 = regmap::ADC_STUCK_MARGIN_CYCLES;
/// The result timer's saturation (17 bits).
const AGE_MAX: u32 = 0x1_FFFF;

/// |x| of a 12-bit two's complement value as 12-bit unsigned (|-2048| = 2048).
fn mag(x: u16) -> u16 {
    if x & 0x800 != 0 {
        (!x).wrapping_add(1) & 0xFFF
    } else {
        x
    }
}

/// Registers of `fault_block`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Fault {
    /// Latched faults (`FAULT_STATUS`).
    pub status: u8,
    oc_last: bool,
    /// Over-current on the sample of the cycle before (`oc_hit_q`): the
    /// comparison is registered, so over-current trips one clock after its
    /// sample strobe.
    oc_hit: bool,
    wdg: u32,
    /// Cycles since the last raw sample, ADC_CTRL.ENABLE change or cycle
    /// with GATE_EN = 0 (`adc_age_q`, saturating at 17 bits).
    adc_age: u32,
    /// ADC_CTRL.ENABLE of the cycle before (`adc_en_q`, reset 1).
    adc_en: bool,
    /// The timer's trip level, ADC_PERIOD of the cycle before + the margin
    /// (reset 0: a register, so a new period counts one clock after its
    /// write; the RTL compares with it a clock ahead, in `adc_early_q`).
    adc_limit: u32,
    /// The watchdog's comparison of the cycle before (`wdg_exp_q`: the
    /// watchdog trips one clock after its counter reaches WDG_TIMEOUT).
    wdg_exp: bool,
}

impl Default for Fault {
    fn default() -> Self {
        Self {
            status: 0,
            oc_last: false,
            oc_hit: false,
            wdg: 0,
            adc_age: 0,
            adc_en: true,
            adc_limit: 0,
            wdg_exp: false,
        }
    }
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
    /// GATE_EN: the drive runs.
    pub run: bool,
    /// `encoder_qei`'s illegal step this cycle.
    pub enc_illegal: bool,
    /// ADC_CTRL.ENABLE.
    pub adc_en: bool,
    /// ADC_PERIOD, cycles.
    pub adc_period: u16,
}

impl Fault {
    fn oc_sample(i: &FaultIn) -> bool {
        i.sample.iter().any(|&s| mag(s) > i.oc_limit)
    }

    /// The timer's trip level after this cycle: ADC_PERIOD + the margin.
    fn adc_limit(i: &FaultIn) -> u32 {
        u32::from(i.adc_period) + ADC_MARGIN
    }

    /// Live conditions of encoder loss and ADC stuck (bits 3, 4).
    fn run_cond(&self, i: &FaultIn) -> u8 {
        let enc = i.run && i.enc_illegal;
        let adc = i.run && self.adc_age >= self.adc_limit;
        (u8::from(adc) << 4) | (u8::from(enc) << 3)
    }

    /// Fault conditions of this cycle `{adc stuck, encoder loss, watchdog,
    /// external, overcurrent}`.
    pub fn cond(&self, i: &FaultIn) -> u8 {
        let oc = self.oc_hit;
        let wdg = self.wdg_exp;
        self.run_cond(i) | (u8::from(wdg) << 2) | (u8::from(i.ext) << 1) | u8::from(oc)
    }

    /// Gate-driver fault input: latched or raised this cycle.
    pub fn trip(&self, i: &FaultIn) -> bool {
        self.status != 0 || self.cond(i) != 0
    }

    /// `FAULT_RAW`.
    pub fn raw(&self, i: &FaultIn) -> u8 {
        self.run_cond(i)
            | (u8::from(self.wdg_exp) << 2)
            | (u8::from(i.ext) << 1)
            | u8::from(self.oc_last)
    }

    /// One clock edge. `status_after_clear` is `FAULT_STATUS` after this
    /// cycle's W1C write (the table's rule), `heartbeat` a HEARTBEAT write.
    pub fn step(&mut self, i: &FaultIn, status_after_clear: u8, heartbeat: bool) {
        let cond = self.cond(i);
        self.status = status_after_clear | cond;
        if i.sample_valid {
            self.oc_last = Self::oc_sample(i);
        }
        self.oc_hit = i.sample_valid && Self::oc_sample(i);
        self.wdg_exp = self.wdg >= i.wdg_timeout;
        if heartbeat {
            self.wdg = 0;
        } else {
            self.wdg = self.wdg.saturating_add(1);
        }
        let restart = !i.run || i.sample_valid || i.adc_en != self.adc_en;
        self.adc_en = i.adc_en;
        self.adc_limit = Self::adc_limit(i);
        self.adc_age = if restart {
            0
        } else {
            (self.adc_age + 1).min(AGE_MAX)
        };
    }

    /// Cycles from now without a new latched bit, a watchdog expiry or an
    /// ADC result overdue (no raw sample, no encoder step, no change of the
    /// registers in them).
    pub fn quiet(&self, i: &FaultIn) -> u64 {
        if self.status | self.cond(i) != self.status
            || i.adc_en != self.adc_en
            || self.oc_hit
            || self.adc_limit != Self::adc_limit(i)
            || self.wdg_exp != (self.wdg >= i.wdg_timeout)
        {
            return 0;
        }
        let wdg = if self.wdg >= i.wdg_timeout {
            NEVER
        } else {
            u64::from(i.wdg_timeout - self.wdg)
        };
        let limit = self.adc_limit;
        let adc = if !i.run {
            // The timer holds at 0.
            if self.adc_age == 0 {
                NEVER
            } else {
                0
            }
        } else if self.adc_age >= limit {
            NEVER
        } else {
            u64::from(limit - self.adc_age)
        };
        wdg.min(adc)
    }

    /// Applies `k` quiet cycles with the drive running (`run`) or not.
    pub fn skip(&mut self, k: u64, run: bool) {
        self.wdg = self.wdg.saturating_add(k.min(u64::from(u32::MAX)) as u32);
        if run {
            self.adc_age = (u64::from(self.adc_age) + k).min(u64::from(AGE_MAX)) as u32;
        }
    }
}
