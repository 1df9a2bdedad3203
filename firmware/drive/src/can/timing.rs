//! Bit timing of the PS CAN controller from its reference clock and the
//! wanted bit rate (UG585 appendix B, `BRPR` and `BTR`).
//!
//! One time quantum is `BRP + 1` reference-clock cycles; a bit is
//! `1 + (TS1 + 1) + (TS2 + 1)` quanta (the synchronisation segment, then
//! propagation plus phase segment 1, then phase segment 2) and the bus is
//! sampled at the end of segment 1. The search takes only settings that
//! give the bit rate exactly (CAN allows about 0.5 % between nodes at
//! 1 Mbit/s, so a rounded divisor is refused rather than chosen), a sample
//! point from 75 % to 87.5 % (CiA 301 recommends 87.5 %), and of those the
//! one closest to 87.5 %, with more quanta per bit on a tie.

use regmap::ps_can::{BTR_SJW_SHIFT, BTR_TS2_SHIFT};

/// Fewest quanta per bit the search takes: below 8 the sample point cannot
/// be placed within the 75-87.5 % window with `TS2 + 1 >= 2`.
const MIN_QUANTA_PER_BIT: u32 = 8;
/// Most quanta per bit the register fields allow: 1 + 16 + 8.
const MAX_QUANTA_PER_BIT: u32 = 25;
/// Largest prescaler (`BRPR.BRP` is 8 bits, the prescaler `BRP + 1`).
const MAX_PRESCALER: u32 = 256;
/// Phase segment 1 (with propagation) limits, quanta (`BTR.TS1`, 4 bits).
const TSEG1_QUANTA: core::ops::RangeInclusive<u32> = 1..=16;
/// Phase segment 2 limits, quanta: the field allows 1..=8; ISO 11898-1
/// wants at least the information processing time, 2 quanta.
const TSEG2_QUANTA: core::ops::RangeInclusive<u32> = 2..=8;
/// Sample point window, per mille of the bit time.
const SAMPLE_POINT_MIN_PERMILLE: u32 = 750;
/// Upper end of the window and the target.
const SAMPLE_POINT_TARGET_PERMILLE: u32 = 875;
/// Largest synchronisation jump width, quanta (`BTR.SJW`, 2 bits).
const MAX_SJW_QUANTA: u32 = 4;

/// A bit timing, in quanta and reference-clock cycles (not register codes).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BitTiming {
    /// Reference-clock cycles per time quantum (1..=256).
    pub prescaler: u32,
    /// Propagation plus phase segment 1, quanta (1..=16).
    pub tseg1_quanta: u32,
    /// Phase segment 2, quanta (2..=8).
    pub tseg2_quanta: u32,
    /// Synchronisation jump width, quanta (1..=4, at most `tseg2_quanta`).
    pub sjw_quanta: u32,
}

impl BitTiming {
    /// Quanta per bit: the synchronisation segment and both segments.
    pub fn quanta_per_bit(&self) -> u32 {
        1 + self.tseg1_quanta + self.tseg2_quanta
    }

    /// Sample point, per mille of the bit time.
    pub fn sample_point_permille(&self) -> u32 {
        (1 + self.tseg1_quanta) * 1000 / self.quanta_per_bit()
    }

    /// `BRPR`: the prescaler minus one.
    pub fn brpr(&self) -> u32 {
        self.prescaler - 1
    }

    /// `BTR`: each segment minus one in its field.
    pub fn btr(&self) -> u32 {
        (self.tseg1_quanta - 1)
            | (self.tseg2_quanta - 1) << BTR_TS2_SHIFT
            | (self.sjw_quanta - 1) << BTR_SJW_SHIFT
    }
}

/// Why no bit timing was found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BitTimingError {
    /// The bit rate or the reference clock is zero.
    Zero,
    /// No prescaler and segments give the bit rate exactly with the sample
    /// point in 75-87.5 %.
    NoExactSetting,
}

/// The bit timing for `bit_rate_bps` from a reference clock of
/// `ref_clock_hz` (see the module doc for the rules).
pub fn bit_timing(ref_clock_hz: u32, bit_rate_bps: u32) -> Result<BitTiming, BitTimingError> {
    if ref_clock_hz == 0 || bit_rate_bps == 0 {
        return Err(BitTimingError::Zero);
    }
    let mut best: Option<(u32, BitTiming)> = None;
    for quanta in MIN_QUANTA_PER_BIT..=MAX_QUANTA_PER_BIT {
        let cycles_per_bit = u64::from(bit_rate_bps) * u64::from(quanta);
        if u64::from(ref_clock_hz) % cycles_per_bit != 0 {
            continue;
        }
        let prescaler = u64::from(ref_clock_hz) / cycles_per_bit;
        if prescaler > u64::from(MAX_PRESCALER) {
            continue;
        }
        let Some(t) = segments(prescaler as u32, quanta) else {
            continue;
        };
        let miss = SAMPLE_POINT_TARGET_PERMILLE - t.sample_point_permille();
        // `<=`: a tie goes to more quanta per bit, a finer division.
        if best.is_none_or(|(m, _)| miss <= m) {
            best = Some((miss, t));
        }
    }
    best.map(|(_, t)| t).ok_or(BitTimingError::NoExactSetting)
}

/// The segments of a `quanta`-quantum bit with the sample point closest
/// to the target from below, within the window; `None` when none fits.
fn segments(prescaler: u32, quanta: u32) -> Option<BitTiming> {
    TSEG2_QUANTA
        .filter_map(|tseg2| {
            let tseg1 = quanta.checked_sub(1 + tseg2)?;
            let t = BitTiming {
                prescaler,
                tseg1_quanta: tseg1,
                tseg2_quanta: tseg2,
                sjw_quanta: tseg2.min(MAX_SJW_QUANTA),
            };
            let sp = t.sample_point_permille();
            (TSEG1_QUANTA.contains(&tseg1)
                && (SAMPLE_POINT_MIN_PERMILLE..=SAMPLE_POINT_TARGET_PERMILLE).contains(&sp))
            .then_some(t)
        })
        // The shortest segment 2 that fits has the latest sample point.
        .next()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 100 MHz to 1 Mbit/s: 100 cycles per bit. 25 quanta (prescaler 4)
    /// needs TS2 >= 8 (TS1 <= 16): sample point 17/25 = 68 %, out.
    /// 20 quanta (prescaler 5): TS2 = 3, TS1 = 16, 17/20 = 85 %.
    /// 10 quanta (prescaler 10): TS2 = 2, TS1 = 7, 8/10 = 80 %. 85 % wins.
    #[test]
    fn one_mbit_from_100_mhz() {
        let t = bit_timing(100_000_000, 1_000_000).unwrap();
        assert_eq!(
            t,
            BitTiming {
                prescaler: 5,
                tseg1_quanta: 16,
                tseg2_quanta: 3,
                sjw_quanta: 3
            }
        );
        assert_eq!(t.sample_point_permille(), 850);
        // BRPR = 4; BTR = TS1 15 | TS2 2 << 4 | SJW 2 << 7 = 0x12F.
        assert_eq!((t.brpr(), t.btr()), (4, 0x12F));
    }

    /// 24 MHz to 1 Mbit/s: 24 cycles per bit; 8, 12 or 24 quanta.
    /// 24 (prescaler 1): TS2 >= 7, 17/24 = 70.8 %, out. 12 (prescaler 2):
    /// TS2 = 2, TS1 = 9, 10/12 = 83.3 %. 8 (prescaler 3): 6/8 = 75 %.
    #[test]
    fn one_mbit_from_24_mhz() {
        let t = bit_timing(24_000_000, 1_000_000).unwrap();
        assert_eq!(
            t,
            BitTiming {
                prescaler: 2,
                tseg1_quanta: 9,
                tseg2_quanta: 2,
                sjw_quanta: 2
            }
        );
        assert_eq!(t.sample_point_permille(), 833);
        // BRPR = 1; BTR = 8 | 1 << 4 | 1 << 7 = 0x98.
        assert_eq!((t.brpr(), t.btr()), (1, 0x98));
    }

    /// 100 MHz to 125 kbit/s: 800 cycles per bit; 16 quanta (prescaler
    /// 50): TS2 = 2, TS1 = 13, 14/16 = 87.5 %, the target itself.
    #[test]
    fn the_target_sample_point_when_reachable() {
        let t = bit_timing(100_000_000, 125_000).unwrap();
        assert_eq!((t.prescaler, t.quanta_per_bit()), (50, 16));
        assert_eq!(t.sample_point_permille(), 875);
        assert_eq!((t.brpr(), t.btr()), (49, 0x9C));
    }

    #[test]
    fn impossible_rates_are_refused() {
        assert_eq!(bit_timing(0, 1_000_000), Err(BitTimingError::Zero));
        assert_eq!(bit_timing(100_000_000, 0), Err(BitTimingError::Zero));
        // 24 MHz / 1.1 Mbit/s is not a whole number of cycles.
        assert_eq!(
            bit_timing(24_000_000, 1_100_000),
            Err(BitTimingError::NoExactSetting)
        );
        // 10 kbit/s from 100 MHz: 10,000 cycles per bit, > 256 x 25.
        assert_eq!(
            bit_timing(100_000_000, 10_000),
            Err(BitTimingError::NoExactSetting)
        );
        // Faster than 8 reference cycles per bit.
        assert_eq!(
            bit_timing(24_000_000, 4_000_000),
            Err(BitTimingError::NoExactSetting)
        );
        assert_eq!(
            bit_timing(u32::MAX, u32::MAX),
            Err(BitTimingError::NoExactSetting)
        );
    }
}
