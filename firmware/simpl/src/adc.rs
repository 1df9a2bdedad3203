//! `adc_frontend` (sample-rate timer, data-ready synchroniser and edge
//! detector, raw sample register, average of 1, 2 or 4 = 2^`ADC_AVG_LOG2`)
//! and the converter behind it ([`Converter`]: data-ready after each convert
//! pulse, optionally with a random delay and width), with their closed form
//! between events.
//!
//! Formats: raw samples are 12-bit two's complement ADC counts; the sum of
//! n = 2^`ADC_AVG_LOG2` samples is kept in 14 bits (two's complement, wraps as the
//! RTL's adder); the average is `sum[11+k:k]` (k = `ADC_AVG_LOG2`), i.e.
//! floor(sum / n), 12 bits, read sign-extended to 16 bits.

use super::enc::Sync2;
use super::NEVER;

/// The converter on the ADC bus: after the convert pulse (the edge that
/// shows `adc_cnv_o` high) its data-ready goes high `conv + j` edges later
/// and stays high for `w` cycles, where `j` in `0..=jitter` and `w` in
/// `1..=width_max` are drawn per conversion from a seeded generator
/// (xorshift64). In a cycle-level model a data-ready edge of any phase
/// against the PL clock is first seen by the synchroniser at one of two
/// clock edges (a metastable first flop resolves either way): a random
/// whole-cycle delay covers every outcome, and a random width every
/// pulse the converter's timing allows (high and low >= 1 clock period).
/// `jitter` 0 and `width_max` 1 is the converter of a synchronous bus:
/// a one-cycle strobe `conv + 1` cycles after the pulse. A convert pulse
/// during a conversion restarts it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Converter {
    conv: u32,
    jitter: u32,
    width_max: u32,
    rng: u64,
    /// Edges since the convert pulse of the conversion under way.
    since: Option<u32>,
    delay: u32,
    width: u32,
    /// No converter on the bus (no card fitted): no conversion starts and
    /// data-ready stays low (the board's pull-down).
    absent: bool,
}

impl Converter {
    /// A converter whose one-cycle data-ready follows `conv + 1` cycles after
    /// each convert pulse.
    pub const fn new(conv: u32) -> Self {
        Self::jittered(conv, 0, 1, 0)
    }

    /// Data-ready `conv + (0..=jitter)` edges after the pulse, high for
    /// `1..=width_max` cycles (`width_max` 0 counts as 1), drawn from `seed`.
    pub const fn jittered(conv: u32, jitter: u32, width_max: u32, seed: u64) -> Self {
        Self {
            conv,
            jitter,
            width_max: if width_max == 0 { 1 } else { width_max },
            // xorshift64 must not start at 0.
            rng: seed ^ 0x9E37_79B9_7F4A_7C15,
            since: None,
            delay: 0,
            width: 0,
            absent: false,
        }
    }

    /// Fits (`true`) or removes the converter. Removed, a conversion under
    /// way is lost and data-ready goes low from this cycle on; fitted
    /// again, it converts from the next convert pulse.
    pub fn set_fitted(&mut self, fitted: bool) {
        self.absent = !fitted;
        if self.absent {
            self.since = None;
        }
    }

    /// Whether a converter is fitted.
    pub fn fitted(&self) -> bool {
        !self.absent
    }

    fn draw(&mut self, n: u32) -> u32 {
        if n <= 1 {
            return 0;
        }
        let mut x = self.rng;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        self.rng = x;
        (x % u64::from(n)) as u32
    }

    /// The data-ready level in this cycle.
    pub fn drdy(&self) -> bool {
        matches!(self.since, Some(s) if s >= self.delay && s < self.delay + self.width)
    }

    /// One clock edge; `cnv` is `adc_cnv_o` as that edge sees it.
    pub fn edge(&mut self, cnv: bool) {
        self.since = match self.since {
            Some(s) if s + 1 < self.delay + self.width => Some(s + 1),
            _ => None,
        };
        if cnv && !self.absent {
            self.delay = self.conv + self.draw(self.jitter.saturating_add(1));
            self.width = 1 + self.draw(self.width_max);
            self.since = Some(0);
        }
    }

    /// Edges from now before the data-ready level changes.
    pub fn quiet(&self) -> u64 {
        match self.since {
            None => NEVER,
            Some(s) if s < self.delay => u64::from(self.delay - s),
            Some(s) => u64::from(self.delay + self.width - s),
        }
    }

    /// Applies `k` <= [`Self::quiet`] edges without a convert pulse.
    pub fn skip(&mut self, k: u64) {
        if let Some(s) = &mut self.since {
            *s += k as u32;
            if *s >= self.delay + self.width {
                self.since = None;
            }
        }
    }
}

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
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
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
    /// Data-ready synchroniser (`sync2`, reset 1) and the edge register.
    drdy_sync: Sync2,
    drdy_prev: bool,
    /// The converter.
    pub conv: Converter,
}

impl Adc {
    /// Out of reset, with converter `conv`.
    pub const fn new(conv: Converter) -> Self {
        Self {
            tmr: 0,
            cnv: false,
            sv: false,
            sample: [0; 3],
            acc: [0; 3],
            n: 0,
            av: false,
            avg: [0; 3],
            count: 0,
            drdy_sync: Sync2::new(true),
            drdy_prev: true,
            conv,
        }
    }

    /// `ADC_IA..IC` as read (sign-extended to 16 bits).
    pub fn avg_reg(&self, phase: usize) -> u32 {
        u32::from(sext16(self.avg[phase]))
    }

    /// The converter's data-ready level in this cycle.
    pub fn drdy(&self) -> bool {
        self.conv.drdy()
    }

    /// One clock edge: `en`, `period`, `avg_log2` (`ADC_AVG_LOG2`, 0..=2) from
    /// the registers, `word` the converter's data bus (captured at the edge
    /// after the synchronised data-ready rises). Returns `true` when the
    /// edge raises `adc_cnv_o`.
    pub fn step(&mut self, en: bool, period: u16, avg_log2: u32, word: u64) -> bool {
        let drdy = self.drdy();
        let rise = self.drdy_sync.q && !self.drdy_prev;
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
        if rise {
            self.sample = [field(word, 24), field(word, 12), field(word, 0)];
        }
        self.sv = rise;
        self.drdy_prev = self.drdy_sync.q;
        self.drdy_sync.step(drdy);
        self.av = av;
        self.cnv = cnv;
        self.conv.edge(cnv_now);
        cnv
    }

    /// Cycles from now in which only the timer and the converter count down.
    pub fn quiet(&self, en: bool) -> u64 {
        let drdy = self.drdy();
        if self.cnv || self.sv || self.av || !self.drdy_sync.settled(drdy) || self.drdy_prev != drdy
        {
            return 0;
        }
        let k = if en { u64::from(self.tmr) } else { NEVER };
        k.min(self.conv.quiet())
    }

    /// Applies `k` quiet cycles.
    pub fn skip(&mut self, en: bool, k: u64) {
        if en {
            self.tmr -= k as u16;
        }
        self.conv.skip(k);
    }
}
