//! `mpdtc_seq`: the control sequence of paper 000 (IDLE, INITIAL with the
//! chopped rotor alignment, SAMPLE, MPDTC, PWM), with its closed form
//! between events. State encoding = `regmap::seq_state`.

use super::NEVER;
use regmap::seq_state::{IDLE, INITIAL, MPDTC, PWM, SAMPLE};

/// Inputs of one cycle.
#[derive(Debug, Clone, Copy)]
pub struct SeqIn {
    /// Run condition (mode MPDTC, GATE_EN, not MANUAL, not STATE_CLR, no fault, no trip).
    pub run: bool,
    /// Averaged-sample strobe (control-period boundary).
    pub sample: bool,
    /// MPDTC_CTRL.AUTO: `start` is the front end's result.
    pub auto: bool,
    /// Inputs ready: MPDTC_START write, or the front end's `out_valid`.
    pub start: bool,
    /// Core ready.
    pub core_ready: bool,
    /// Core result valid.
    pub core_valid: bool,
    /// Core result S[k+1].
    pub core_s: u8,
    /// MPDTC_ALIGN_VEC.
    pub align_vec: u8,
    /// MPDTC_ALIGN_PERIOD, cycles.
    pub align_period: u16,
    /// MPDTC_ALIGN_ON, cycles.
    pub align_on: u16,
    /// MPDTC_ALIGN_TIME, cycles.
    pub align_time: u32,
    /// ENC_POS.
    pub enc_pos: u16,
}

/// Registers of `mpdtc_seq`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Seq {
    /// State (`regmap::seq_state`).
    pub state: u32,
    tmr: u32,
    chop: u16,
    /// SAMPLE holds this period's sample.
    pub sampled: bool,
    /// The alignment of this run finished.
    pub aligned: bool,
    s_pend: u8,
    s_apply: u8,
    /// Overrun counter (wraps).
    pub overruns: u8,
    /// Completed periods (wraps).
    pub periods: u16,
    /// ENC_POS latched at the end of INITIAL.
    pub align_pos: u16,
}

impl Seq {
    fn align_on(&self, i: &SeqIn) -> bool {
        self.state == INITIAL && self.chop < i.align_on && self.chop < i.align_period >> 1
    }

    fn go(&self, i: &SeqIn) -> bool {
        self.state == SAMPLE && self.sampled && i.start && i.core_ready
    }

    /// Core start (`in_valid` before the STATE_CLR gate).
    pub fn core_start(&self, i: &SeqIn) -> bool {
        if self.state == IDLE {
            i.start && !i.auto
        } else {
            self.go(i)
        }
    }

    /// The core's state is held at zero (INITIAL).
    pub fn core_clr(&self) -> bool {
        self.state == INITIAL
    }

    /// Gate-driver enable from the sequence.
    pub fn drive(&self, run: bool) -> bool {
        run && self.state != IDLE
    }

    /// Requested switching state.
    pub fn s(&self, i: &SeqIn) -> u8 {
        if self.state == INITIAL {
            if self.align_on(i) {
                i.align_vec
            } else {
                0
            }
        } else {
            self.s_apply
        }
    }

    /// `MPDTC_SEQ_STATUS`.
    pub fn status(&self) -> u32 {
        (u32::from(self.periods) << 16)
            | (u32::from(self.overruns) << 8)
            | (u32::from(self.aligned) << 4)
            | (u32::from(self.sampled) << 3)
            | self.state
    }

    /// One clock edge.
    pub fn step(&mut self, i: &SeqIn) {
        if !i.run {
            self.state = IDLE;
            self.sampled = false;
            return;
        }
        match self.state {
            IDLE => {
                self.state = INITIAL;
                self.tmr = 0;
                self.chop = 0;
                self.aligned = false;
            }
            INITIAL => {
                let done = self.tmr.wrapping_add(1) >= i.align_time && i.core_ready;
                let wrap = self.chop.wrapping_add(1) >= i.align_period;
                self.tmr = self.tmr.wrapping_add(1);
                self.chop = if wrap { 0 } else { self.chop + 1 };
                if done {
                    self.state = SAMPLE;
                    self.aligned = true;
                    self.align_pos = i.enc_pos;
                    self.s_apply = 0;
                    self.sampled = false;
                }
            }
            SAMPLE => {
                let go = self.go(i);
                if i.sample {
                    if self.sampled {
                        self.overruns = self.overruns.wrapping_add(1);
                    }
                    self.sampled = true;
                }
                if go {
                    self.state = MPDTC;
                    self.sampled = false;
                }
            }
            MPDTC => {
                if i.sample {
                    self.overruns = self.overruns.wrapping_add(1);
                }
                if i.core_valid {
                    self.state = PWM;
                    self.s_pend = i.core_s;
                }
            }
            PWM => {
                if i.sample {
                    self.state = SAMPLE;
                    self.s_apply = self.s_pend;
                    self.sampled = true;
                    self.periods = self.periods.wrapping_add(1);
                }
            }
            _ => self.state = IDLE,
        }
    }

    /// Cycles from now in which only the alignment timers count, with
    /// inputs that stay as they are (no sample, start or core event).
    pub fn quiet(&self, i: &SeqIn) -> u64 {
        if !i.run {
            return if self.state != IDLE || self.sampled {
                0
            } else {
                NEVER
            };
        }
        match self.state {
            INITIAL => {
                let next = self.tmr.wrapping_add(1);
                let k_done = if next >= i.align_time {
                    if i.core_ready {
                        return 0;
                    }
                    // Waits for the core; the condition holds until tmr wraps.
                    u64::from(u32::MAX - self.tmr)
                } else {
                    u64::from(i.align_time - next)
                };
                let cnext = self.chop.wrapping_add(1);
                if cnext >= i.align_period {
                    return 0;
                }
                let mut k = k_done.min(u64::from(i.align_period - cnext));
                let thr = i.align_on.min(i.align_period >> 1);
                if self.chop < thr {
                    k = k.min(u64::from(thr - self.chop));
                }
                k
            }
            SAMPLE | MPDTC | PWM => NEVER,
            _ => 0,
        }
    }

    /// Applies `k` quiet cycles.
    pub fn skip(&mut self, k: u64) {
        if self.state == INITIAL {
            self.tmr = self.tmr.wrapping_add(k as u32);
            self.chop += k as u16;
        }
    }
}
