//! `capture_buf`: the triggered capture ring of the CAPTURE page, cycle
//! exact (`pl-bitstream-src/rtl/capture_buf.v` documents the behaviour; the
//! equivalence test in `rtl-sim` checks every read against the Verilog).
//!
//! Channel formats (register table): i_d, i_q in mA, torque and its
//! reference in 0.1 mN m, 16-bit two's complement; the selectable channel is
//! the low 16 bits of its register; the switching state 3 bits; position in
//! counts (32-bit two's complement, wraps), velocity Q16.16 rev/s (32 bits),
//! following error Q12.4 counts (16 bits). The ring only stores them.

use regmap::{cap_source, cap_state, CAPTURE_DEPTH};

/// Samples in the ring.
pub const DEPTH: usize = CAPTURE_DEPTH as usize;
const MASK: u16 = (DEPTH - 1) as u16;
const DEPTH16: u16 = DEPTH as u16;

/// One sample of the nine channels (raw register bits).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Sample {
    /// i_d, mA (two's complement).
    pub i_d: u16,
    /// i_q, mA.
    pub i_q: u16,
    /// Torque, 0.1 mN m.
    pub torque: u16,
    /// Torque reference, 0.1 mN m.
    pub tref: u16,
    /// Selectable channel.
    pub sel: u16,
    /// Switching state at the gate driver.
    pub sw: u8,
    /// Multi-turn position, counts (`CAP_IN_POS`).
    pub pos: u32,
    /// Velocity, Q16.16 rev/s (`CAP_IN_VEL`).
    pub vel: u32,
    /// Following error, Q12.4 counts (`CAP_IN_FERR`).
    pub ferr: u16,
}

impl Sample {
    /// The channel `CAP_THR_CH` selects (values above 4: the selectable one).
    fn channel(&self, ch: u32) -> u16 {
        match ch {
            0 => self.i_d,
            1 => self.i_q,
            2 => self.torque,
            3 => self.tref,
            _ => self.sel,
        }
    }
}

/// Inputs of one cycle.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct CapIn {
    /// `CAP_ARM` write strobe.
    pub arm: bool,
    /// `CAP_TRIG` write strobe.
    pub trig: bool,
    /// `CAP_SOURCE`.
    pub source: u32,
    /// `CAP_PRE` (clamped below the depth by the register file).
    pub pre: u32,
    /// `CAP_DECIM`.
    pub decim: u32,
    /// `CAP_STEP`.
    pub step: u32,
    /// `CAP_THR_CH`.
    pub thr_ch: u32,
    /// `CAP_THR_LEVEL`.
    pub thr_level: u16,
    /// `CAP_THR_EDGE` (true: falling).
    pub falling: bool,
    /// Averaged-ADC strobe.
    pub sample: bool,
    /// A fault is latched.
    pub fault: bool,
    /// The channels now.
    pub ch: Sample,
    /// `CAP_RD_INDEX`.
    pub rd_index: u32,
}

/// `capture_buf` state.
#[derive(Debug, Clone)]
pub struct Capture {
    mem: [Sample; DEPTH],
    state: u32,
    wr_ptr: u16,
    count: u16,
    post: u16,
    pre: u16,
    decim: u32,
    trig_pend: bool,
    prev_valid: bool,
    tref_prev: u16,
    thr_prev: u16,
    /// `CAP_STEP` of the cycle before: the step in force (the RTL keeps
    /// `tref_prev` +- it in registers, so a write takes effect one clock
    /// later).
    step_prev: u32,
    /// The read port's output register (`CAP_DATA0..2`).
    pub rd: Sample,
}

impl Default for Capture {
    fn default() -> Self {
        Self {
            mem: [Sample::default(); DEPTH],
            state: cap_state::IDLE,
            wr_ptr: 0,
            count: 0,
            post: 0,
            pre: 0,
            decim: 0,
            trig_pend: false,
            prev_valid: false,
            tref_prev: 0,
            thr_prev: 0,
            step_prev: 0,
            rd: Sample::default(),
        }
    }
}

impl Capture {
    fn running(&self) -> bool {
        self.state == cap_state::ARMED || self.state == cap_state::TRIGGERED
    }

    fn post_len(&self) -> u16 {
        DEPTH16 - self.pre
    }

    fn rd_ptr(&self, rd_index: u32) -> usize {
        let start = self.wr_ptr.wrapping_sub(self.count) & MASK;
        usize::from(start.wrapping_add(rd_index as u16) & MASK)
    }

    /// `CAP_STATUS`.
    pub fn status(&self) -> u32 {
        let trig_index = if self.state == cap_state::DONE {
            self.count - self.post_len()
        } else {
            0
        };
        (u32::from(self.count) << 16) | (u32::from(trig_index) << 4) | self.state
    }

    fn trigger(&self, i: &CapIn) -> bool {
        let d = (i32::from(i.ch.tref as i16) - i32::from(self.tref_prev as i16)).unsigned_abs();
        let step_hit = self.prev_valid && d >= self.step_prev;
        let now = i.ch.channel(i.thr_ch) as i16;
        let prev = self.thr_prev as i16;
        let lvl = i.thr_level as i16;
        let crossed = if i.falling {
            prev > lvl && now <= lvl
        } else {
            prev < lvl && now >= lvl
        };
        let thr_hit = self.prev_valid && crossed;
        self.trig_pend
            || (i.source == cap_source::REF_STEP && step_hit)
            || (i.source == cap_source::THRESHOLD && thr_hit)
            || (i.source == cap_source::FAULT && i.fault)
    }

    /// One clock cycle.
    pub fn step(&mut self, i: &CapIn) {
        self.rd = self.mem[self.rd_ptr(i.rd_index)];
        let take = self.running() && i.sample && self.decim >= i.decim;
        if i.arm {
            let pre = (i.pre as u16).min(DEPTH16 - 1);
            *self = Self {
                mem: self.mem,
                rd: self.rd,
                state: cap_state::ARMED,
                pre,
                step_prev: i.step,
                ..Self::default()
            };
            return;
        }
        // The trigger sees the pending flag as it was before this cycle.
        let trigger = self.trigger(i);
        self.step_prev = i.step;
        if i.trig && self.state == cap_state::ARMED {
            self.trig_pend = true;
        }
        if self.running() && i.sample {
            self.decim = if take { 0 } else { (self.decim + 1) & 0xFF };
        }
        if !take {
            return;
        }
        self.mem[usize::from(self.wr_ptr)] = i.ch;
        self.wr_ptr = (self.wr_ptr + 1) & MASK;
        self.count = (self.count + 1).min(DEPTH16);
        self.prev_valid = true;
        self.tref_prev = i.ch.tref;
        self.thr_prev = i.ch.channel(i.thr_ch);
        if self.state == cap_state::ARMED {
            if trigger {
                self.trig_pend = false;
                self.post = self.post_len() - 1;
                self.state = if self.post == 0 {
                    cap_state::DONE
                } else {
                    cap_state::TRIGGERED
                };
            }
        } else {
            self.post -= 1;
            if self.post == 0 {
                self.state = cap_state::DONE;
            }
        }
    }

    /// `n` >= 1 cycles without a sample strobe or a write: only the read
    /// port and the step in force (`step`, `CAP_STEP`) settle.
    pub fn skip(&mut self, rd_index: u32, step: u32) {
        self.rd = self.mem[self.rd_ptr(rd_index)];
        self.step_prev = step;
    }
}
