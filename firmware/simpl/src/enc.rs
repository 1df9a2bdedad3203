//! `sync2` and `encoder_qei`: quadrature decoding (4 counts per line),
//! position wrapping at ENC_CPR, index pulses, speed window; closed form
//! between events.

/// Two-flip-flop synchroniser (`sync2`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Sync2 {
    meta: bool,
    /// Synchronised output.
    pub q: bool,
}

impl Sync2 {
    /// Reset state: both flops at `v`.
    pub const fn new(v: bool) -> Self {
        Self { meta: v, q: v }
    }
    /// One clock edge with pin level `d`.
    pub fn step(&mut self, d: bool) {
        self.q = self.meta;
        self.meta = d;
    }
    /// Both flops hold the pin level: nothing moves until the pin changes.
    pub fn settled(&self, d: bool) -> bool {
        self.meta == d && self.q == d
    }
}

const SMAX: i16 = i16::MAX;
const SMIN: i16 = i16::MIN;
const WIN_MASK: u32 = 0x00FF_FFFF;

/// Registers of `encoder_qei`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Encoder {
    ph: u8,
    primed: bool,
    z: bool,
    /// Position, counts (`ENC_POS`).
    pub pos: u16,
    /// Index pulses (`ENC_INDEX`).
    pub index: u16,
    win: u32,
    acc: i16,
    /// Counts in the last window (`ENC_SPEED`).
    pub speed: i16,
    /// `pos` of the last control-period boundary's cycle (`ENC_POS_SAMPLE`).
    pub pos_sample: u16,
}

impl Default for Encoder {
    fn default() -> Self {
        Self {
            ph: 0,
            primed: false,
            // No index edge right out of reset.
            z: true,
            pos: 0,
            index: 0,
            win: 0,
            acc: 0,
            speed: 0,
            pos_sample: 0,
        }
    }
}

/// Quadrature phase 0..3 of the levels (a, b) = 00, 10, 11, 01.
fn phase(a: bool, b: bool) -> u8 {
    (u8::from(b) << 1) | u8::from(a ^ b)
}

impl Encoder {
    /// `illegal_o`: the synchronised levels make an illegal quadrature
    /// step this cycle (A and B changed in one clock; not counted).
    pub fn illegal(&self, a: bool, b: bool) -> bool {
        self.primed && phase(a, b).wrapping_sub(self.ph) & 3 == 2
    }

    /// One clock edge with the synchronised levels, the registers and the
    /// control-period boundary strobe `sample`.
    pub fn step(&mut self, a: bool, b: bool, z: bool, cpr: u16, window: u32, sample: bool) {
        if sample {
            self.pos_sample = self.pos;
        }
        let ph = phase(a, b);
        let step = ph.wrapping_sub(self.ph) & 3;
        let up = self.primed && step == 1;
        let down = self.primed && step == 3;
        let index = z && !self.z;
        let acc_next = if up && self.acc != SMAX {
            self.acc + 1
        } else if down && self.acc != SMIN {
            self.acc - 1
        } else {
            self.acc
        };
        self.ph = ph;
        self.primed = true;
        self.z = z;
        if index {
            self.pos = 0;
            self.index = self.index.wrapping_add(1);
        } else if up {
            self.pos = if self.pos >= cpr.wrapping_sub(1) {
                0
            } else {
                self.pos + 1
            };
        } else if down {
            self.pos = if self.pos == 0 {
                cpr.wrapping_sub(1)
            } else {
                self.pos - 1
            };
        }
        if (self.win + 1) & WIN_MASK >= window {
            self.win = 0;
            self.speed = acc_next;
            self.acc = 0;
        } else {
            self.win += 1;
            self.acc = acc_next;
        }
    }

    /// Cycles from now without a count, an index edge or a window end,
    /// given synchronised levels that stay as they are.
    pub fn quiet(&self, a: bool, b: bool, z: bool, window: u32) -> u64 {
        if !self.primed || self.ph != phase(a, b) || self.z != z {
            return 0;
        }
        let next = (self.win + 1) & WIN_MASK;
        if next >= window {
            0
        } else {
            u64::from(window - next)
        }
    }

    /// Applies `k` quiet cycles.
    pub fn skip(&mut self, k: u64) {
        self.win += k as u32;
    }
}
