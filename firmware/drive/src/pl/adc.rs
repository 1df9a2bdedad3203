//! ADC block: the averaged phase currents.
//!
//! `ADC_IA..IC` hold signed 12-bit counts (sign-extended to 16 bits), the
//! floor of the mean of 4 samples. The current per count is a fact of the
//! board's current sensing, not of the register map: [`AdcScale`].
use super::{rd, sext, wr};
use crate::bus::{BusError, RegisterBus};
use crate::regmap::{self, ADC};

/// Current sensing gain: amperes per ADC count.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdcScale {
    /// A per count (full scale +-2048 counts).
    pub amps_per_count: f64,
}

impl AdcScale {
    /// Counts to amperes.
    pub fn amps(&self, counts: i32) -> f64 {
        f64::from(counts) * self.amps_per_count
    }
}

/// The ADC block.
pub struct Adc<B>(pub B);

impl<B: RegisterBus> Adc<B> {
    /// Latest averaged phase currents a, b, c, counts.
    pub fn currents_counts(&mut self) -> Result<[i32; 3], BusError> {
        let mut c = [0; 3];
        for (x, r) in c
            .iter_mut()
            .zip([&regmap::ADC_IA, &regmap::ADC_IB, &regmap::ADC_IC])
        {
            *x = sext(rd(&mut self.0, &ADC, r)?, 16);
        }
        Ok(c)
    }
    /// Latest averaged phase currents a, b, c, A.
    pub fn currents_a(&mut self, scale: &AdcScale) -> Result<[f64; 3], BusError> {
        let c = self.currents_counts()?;
        Ok(c.map(|x| scale.amps(x)))
    }
    /// Averaged results since reset (wraps).
    pub fn count(&mut self) -> Result<u32, BusError> {
        rd(&mut self.0, &ADC, &regmap::ADC_COUNT)
    }
    /// Cycles between conversion starts (the PL clamps to 16..=65535).
    pub fn set_period(&mut self, cycles: u32) -> Result<(), BusError> {
        wr(&mut self.0, &ADC, &regmap::ADC_PERIOD, cycles)
    }
    /// Restarts the sample timer (`ADC_CTRL.ENABLE` 0 then 1): called right
    /// after a PWM period start, the conversions take a fixed phase to the
    /// PWM (the PL has no ADC trigger from the PWM counter).
    pub fn restart(&mut self) -> Result<(), BusError> {
        wr(&mut self.0, &ADC, &regmap::ADC_CTRL, 0)?;
        wr(&mut self.0, &ADC, &regmap::ADC_CTRL, 1)
    }
    /// Cycles between conversion starts, as stored.
    pub fn period(&mut self) -> Result<u32, BusError> {
        rd(&mut self.0, &ADC, &regmap::ADC_PERIOD)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pl::fake::FakePl;

    #[test]
    fn currents_are_sign_extended_and_scaled() {
        let mut pl = FakePl::new();
        pl.set(ADC.addr(&regmap::ADC_IA), 0xF800); // -2048
        pl.set(ADC.addr(&regmap::ADC_IB), 0x07FF); // 2047
        pl.set(ADC.addr(&regmap::ADC_IC), 0xFFFF); // -1
        assert_eq!(Adc(&mut pl).currents_counts().unwrap(), [-2048, 2047, -1]);
        let s = AdcScale {
            amps_per_count: 0.01,
        };
        let i = Adc(&mut pl).currents_a(&s).unwrap();
        assert!((i[0] + 20.48).abs() < 1e-12 && (i[1] - 20.47).abs() < 1e-12);
        Adc(&mut pl).set_period(5).unwrap();
        assert_eq!(Adc(&mut pl).period().unwrap(), 16, "the PL clamps");
    }
}
