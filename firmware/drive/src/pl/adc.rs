//! ADC block: the averaged phase currents.
//!
//! `ADC_IA..IC` hold signed 12-bit counts (sign-extended to 16 bits), the
//! floor of the mean of 4 samples. The current per count is a fact of the
//! board's current sensing, not of the register map: [`AdcScale`].
use regmap::bus::{BusError, RegisterBus};
use regmap::regs::adc::{
    AdcCount, AdcCountValue, AdcCtrl, AdcCtrlValue, AdcIa, AdcIaValue, AdcIb, AdcIbValue, AdcIc,
    AdcIcValue, AdcPeriod, AdcPeriodValue,
};

/// `ADC_IA..IC` words to signed counts.
fn counts(w: &[u32; 3]) -> [i32; 3] {
    [
        AdcIaValue::from_bits(w[0]).value_i32(),
        AdcIbValue::from_bits(w[1]).value_i32(),
        AdcIcValue::from_bits(w[2]).value_i32(),
    ]
}

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
        let mut w = [0; 3];
        self.0
            .read_many(&[AdcIa::ADDR, AdcIb::ADDR, AdcIc::ADDR], &mut w)?;
        Ok(counts(&w))
    }
    /// Latest averaged phase currents a, b, c, A.
    pub fn currents_a(&mut self, scale: &AdcScale) -> Result<[f64; 3], BusError> {
        let c = self.currents_counts()?;
        Ok(c.map(|x| scale.amps(x)))
    }
    /// [`Adc::count`], then [`Adc::currents_a`], read back to back.
    pub fn count_and_currents_a(&mut self, scale: &AdcScale) -> Result<(u32, [f64; 3]), BusError> {
        let a = [AdcCount::ADDR, AdcIa::ADDR, AdcIb::ADDR, AdcIc::ADDR];
        let mut w = [0; 4];
        self.0.read_many(&a, &mut w)?;
        let c = counts(&[w[1], w[2], w[3]]);
        Ok((
            AdcCountValue::from_bits(w[0]).value(),
            c.map(|x| scale.amps(x)),
        ))
    }
    /// Averaged results since reset (wraps).
    pub fn count(&mut self) -> Result<u32, BusError> {
        Ok(AdcCount::read(&mut self.0)?.value())
    }
    /// Cycles between conversion starts (the PL clamps to 16..=65535). A
    /// changed period is written with the conversions stopped and restarts
    /// them (`ADC_CTRL.ENABLE` 0, the period, 1): the sample timer would
    /// otherwise run out its countdown of the old period first, longer
    /// than the PL's ADC result timer allows with a shorter one
    /// (`ADC_STUCK` as soon as the gates go on); each change of `ENABLE`
    /// restarts that timer. An unchanged period is not written.
    pub fn set_period(&mut self, cycles: u32) -> Result<(), BusError> {
        let old = self.period()?;
        let new = regmap::ADC_PERIOD.apply_write(old, cycles).unwrap_or(old);
        if new == old {
            return Ok(());
        }
        AdcCtrl::write(&mut self.0, AdcCtrlValue::ZERO.with_enable(false))?;
        AdcPeriod::write(&mut self.0, AdcPeriodValue::ZERO.with_value(cycles))?;
        AdcCtrl::write(&mut self.0, AdcCtrlValue::ZERO.with_enable(true))
    }
    /// Restarts the sample timer (`ADC_CTRL.ENABLE` 0 then 1): called right
    /// after a PWM period start, the conversions take a fixed phase to the
    /// PWM (the PL has no ADC trigger from the PWM counter).
    pub fn restart(&mut self) -> Result<(), BusError> {
        AdcCtrl::write(&mut self.0, AdcCtrlValue::ZERO.with_enable(false))?;
        AdcCtrl::write(&mut self.0, AdcCtrlValue::ZERO.with_enable(true))
    }
    /// Starts (`true`) or stops the conversions (`ADC_CTRL.ENABLE`).
    pub fn set_enabled(&mut self, on: bool) -> Result<(), BusError> {
        AdcCtrl::write(&mut self.0, AdcCtrlValue::ZERO.with_enable(on))
    }
    /// Cycles between conversion starts, as stored.
    pub fn period(&mut self) -> Result<u32, BusError> {
        Ok(AdcPeriod::read(&mut self.0)?.value())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pl::fake::FakePl;
    use regmap::{self, ADC};

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
