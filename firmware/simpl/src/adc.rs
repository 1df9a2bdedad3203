//! `adc_frontend` (sample-rate timer, raw sample register, average of 1, 2
//! or 4 = 2^`ADC_AVG_LOG2`)
//! and the converter behind it (a result `conv + 1` cycles after each
//! convert pulse), with their closed form between events.
//!
//! Formats: raw samples are 12-bit two's complement ADC counts; the sum of
//! n = 2^`ADC_AVG_LOG2` samples is kept in 14 bits (two's complement, wraps as the
//! RTL's adder); the average is `sum[11+k:k]` (k = `ADC_AVG_LOG2`), i.e.
//! floor(sum / n), 12 bits, read sign-extended to 16 bits.

use super::NEVER;

/// A 12-bit two's complement field of the ADC data word.
fn field(word: u64, lsb: u32) -> u16 {
    ((word >> lsb) & 0xFFF) as u16
}

/// 12-bit two's complement to 14 bits.
fn sext14(x: u16) -> u16 {
    if x & 0x800 != 0 {
        x | 0x3000
    } else {
        x
    }
}

/// 12 bits sign-extended to 16.
pub fn sext16(x: u16) -> u16 {
    if x & 0x800 != 0 {
        x | 0xF000
    } else {
        x
    }
}

/// ADC data word `{ia, ib, ic}` (12 bits each, ia in bits 35..24) from
/// three signed counts, each saturated to -2048..=2047.
pub fn adc_word(counts: [i32; 3]) -> u64 {
    let f = |c: i32| u64::from((c.clamp(-2048, 2047) as u32) & 0xFFF);
    (f(counts[0]) << 24) | (f(counts[1]) << 12) | f(counts[2])
}

/// Registers of `adc_frontend` and the converter model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Adc {
    tmr: u16,
    /// Convert-start pulse (`adc_cnv_o`).
    pub cnv: bool,
    /// Raw-sample strobe (`sample_valid_o`, to the fault block).
    pub sv: bool,
    /// Raw samples a, b, c (12 bits).
    pub sample: [u16; 3],
    acc: [u16; 3],
    n: u8,
    /// Averaged-sample strobe (`adc_avg_valid_o`): the control-period boundary.
    pub av: bool,
    avg: [u16; 3],
    /// Averages produced (`ADC_COUNT`).
    pub count: u32,
    /// Cycles until the converter's `drdy` (`Some(0)`: in this cycle).
    conv_left: Option<u32>,
}

impl Adc {
    /// `ADC_IA..IC` as read (sign-extended to 16 bits).
    pub fn avg_reg(&self, phase: usize) -> u32 {
        u32::from(sext16(self.avg[phase]))
    }

    /// The converter's data-ready strobe in this cycle.
    pub fn drdy(&self) -> bool {
        self.conv_left == Some(0)
    }

    /// One clock edge: `en`, `period`, `avg_log2` (`ADC_AVG_LOG2`, 0..=2) from
    /// the registers, `word` the converter's data (latched when `drdy`),
    /// `conv` its conversion time in cycles. Returns `true` when the edge
    /// raises `adc_cnv_o`.
    pub fn step(&mut self, en: bool, period: u16, avg_log2: u32, word: u64, conv: u32) -> bool {
        let drdy = self.drdy();
        let cnv_now = self.cnv;
        // Sample-rate timer.
        let mut cnv = false;
        if !en {
            self.tmr = 0;
        } else if self.tmr == 0 {
            self.tmr = period.wrapping_sub(1);
            cnv = true;
        } else {
            self.tmr -= 1;
        }
        // Average of n = 2^avg_log2 over the raw sample register; a sum
        // already past a smaller n ends with this sample.
        let mut av = false;
        if self.sv {
            let sum = core::array::from_fn::<u16, 3, _>(|x| {
                (self.acc[x].wrapping_add(sext14(self.sample[x]))) & 0x3FFF
            });
            let k = avg_log2.min(2);
            let last = (1u8 << k) - 1;
            if self.n >= last {
                self.avg = sum.map(|s| (s >> k) & 0xFFF);
                self.acc = [0; 3];
                av = true;
                self.count = self.count.wrapping_add(1);
                self.n = 0;
            } else {
                self.acc = sum;
                self.n += 1;
            }
        }
        if drdy {
            self.sample = [field(word, 24), field(word, 12), field(word, 0)];
        }
        self.sv = drdy;
        self.av = av;
        self.cnv = cnv;
        // Converter: the result follows `conv + 1` cycles after the pulse.
        self.conv_left = match self.conv_left {
            Some(0) | None => None,
            Some(c) => Some(c - 1),
        };
        if cnv_now {
            self.conv_left = Some(conv);
        }
        cnv
    }

    /// Cycles from now in which only the timer and the converter count down.
    pub fn quiet(&self, en: bool) -> u64 {
        if self.cnv || self.sv || self.av || self.drdy() {
            return 0;
        }
        let mut k = if en { u64::from(self.tmr) } else { NEVER };
        if let Some(c) = self.conv_left {
            k = k.min(u64::from(c));
        }
        k
    }

    /// Applies `k` quiet cycles.
    pub fn skip(&mut self, en: bool, k: u64) {
        if en {
            self.tmr -= k as u16;
        }
        if let Some(c) = &mut self.conv_left {
            *c -= k as u32;
        }
    }
}
