//! PWM/gates block: gate enable, dead time, centre-aligned PWM period and
//! duties, the manual switching state and the gate outputs.
//!
//! Each leg's duty register is an `embedded_hal::pwm::SetDutyCycle` channel
//! ([`Leg`]) whose full scale is `PWM_PERIOD` (duty = DUTY / PWM_PERIOD).
use regmap::bus::{BusError, RegisterBus};
use regmap::regs::pwm::{
    DeadTime, DeadTimeValue, DutyA, DutyAValue, DutyB, DutyBValue, DutyC, DutyCValue, GateCtrl,
    GateCtrlValue, GateStatus, PwmCount, PwmPeriod, PwmPeriodValue,
};

/// Writes `cycles` to the duty register of leg `i` (0 = a, 1 = b, 2 = c;
/// above 2 as c).
fn write_duty<B: RegisterBus + ?Sized>(bus: &mut B, i: usize, cycles: u32) -> Result<(), BusError> {
    match i {
        0 => DutyA::write(bus, DutyAValue::ZERO.with_value(cycles)),
        1 => DutyB::write(bus, DutyBValue::ZERO.with_value(cycles)),
        _ => DutyC::write(bus, DutyCValue::ZERO.with_value(cycles)),
    }
}

/// The PWM/gates block.
pub struct Pwm<B>(pub B);

impl<B: RegisterBus> Pwm<B> {
    /// Gates on (`true`: they follow the selected source) or off.
    pub fn set_gates(&mut self, on: bool) -> Result<(), BusError> {
        GateCtrl::write(&mut self.0, GateCtrlValue::ZERO.with_gate_en(on))
    }
    /// `GATE_CTRL.GATE_EN` as read back (held at 0 while a fault is latched).
    pub fn gates_enabled(&mut self) -> Result<bool, BusError> {
        Ok(GateCtrl::read(&mut self.0)?.gate_en())
    }
    /// Half period of the up-down counter, PL clock cycles (the PL clamps
    /// to 2..=65535); f_pwm = 100 MHz / (2 half_period).
    pub fn set_half_period(&mut self, cycles: u32) -> Result<(), BusError> {
        PwmPeriod::write(&mut self.0, PwmPeriodValue::ZERO.with_value(cycles))
    }
    /// Half period as stored, PL clock cycles.
    pub fn half_period(&mut self) -> Result<u32, BusError> {
        Ok(PwmPeriod::read(&mut self.0)?.value())
    }
    /// Dead time, PL clock cycles (the PL clamps to 1023).
    pub fn set_dead_time(&mut self, cycles: u32) -> Result<(), BusError> {
        DeadTime::write(&mut self.0, DeadTimeValue::ZERO.with_value(cycles))
    }
    /// The duty channel of leg `i` (0 = a, 1 = b, 2 = c); reads the period
    /// once for the channel's full scale.
    pub fn leg(&mut self, i: usize) -> Result<Leg<'_, B>, BusError> {
        let period = self.half_period()?.min(u32::from(u16::MAX)) as u16;
        Ok(Leg {
            bus: &mut self.0,
            leg: i.min(2),
            period,
        })
    }
    /// Writes the three duties (fractions of the period, clamped to
    /// `[0, 1]`, NaN as 0.5 = zero average voltage), rounded to cycles.
    /// Each goes through the leg's `SetDutyCycle` channel, whose full scale
    /// is `half_period` (the caller's `PWM_PERIOD`, so no read back).
    pub fn set_duties(&mut self, d: [f64; 3], half_period: u32) -> Result<(), BusError> {
        use embedded_hal::pwm::SetDutyCycle;
        // The PL clamps PWM_PERIOD to 2..=65535: a wider value is not a period.
        let period = half_period.min(u32::from(u16::MAX)) as u16;
        for (i, x) in d.into_iter().enumerate() {
            let mut leg = Leg {
                bus: &mut self.0,
                leg: i,
                period,
            };
            // duty_cycles <= half_period, so it fits the channel's u16.
            let c = duty_cycles(x, u32::from(period)) as u16;
            leg.set_duty_cycle(c).map_err(|e| e.0)?;
        }
        Ok(())
    }
    /// Cycles since the PWM counter's bottom (the period start), from
    /// `PWM_COUNT`, for a half period of `half_period` cycles.
    pub fn phase(&mut self, half_period: u32) -> Result<u32, BusError> {
        let c = PwmCount::read(&mut self.0)?;
        let count = c.count().min(half_period);
        Ok(if c.down() {
            2 * half_period - count
        } else {
            count
        })
    }
    /// `GATE_STATUS`: (upper gates, lower gates, requested state), bit 2 = leg a.
    pub fn gate_status(&mut self) -> Result<(u8, u8, u8), BusError> {
        let s = GateStatus::read(&mut self.0)?;
        Ok((s.hi() as u8, s.lo() as u8, s.state() as u8))
    }
}

/// Compare value for duty fraction `d` of a half period of `half_period`
/// cycles: `round(d half_period)`, `d` clamped to `[0, 1]`, NaN as 0.5.
pub fn duty_cycles(d: f64, half_period: u32) -> u32 {
    let d = if d.is_nan() { 0.5 } else { d.clamp(0.0, 1.0) };
    libm::round(d * f64::from(half_period)) as u32
}

/// One leg's duty register as an `embedded-hal` PWM channel.
pub struct Leg<'a, B> {
    bus: &'a mut B,
    leg: usize,
    period: u16,
}

/// A bus error seen through `embedded-hal`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PwmError(pub BusError);

impl embedded_hal::pwm::Error for PwmError {
    fn kind(&self) -> embedded_hal::pwm::ErrorKind {
        embedded_hal::pwm::ErrorKind::Other
    }
}

impl<B> embedded_hal::pwm::ErrorType for Leg<'_, B> {
    type Error = PwmError;
}

impl<B: RegisterBus> embedded_hal::pwm::SetDutyCycle for Leg<'_, B> {
    fn max_duty_cycle(&self) -> u16 {
        self.period
    }
    fn set_duty_cycle(&mut self, duty: u16) -> Result<(), PwmError> {
        write_duty(self.bus, self.leg, u32::from(duty.min(self.period))).map_err(PwmError)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pl::fake::FakePl;
    use embedded_hal::pwm::SetDutyCycle;
    use regmap::{self, Register, PWM};

    /// The duty registers of legs a, b, c.
    const DUTY: [&Register; 3] = [&regmap::DUTY_A, &regmap::DUTY_B, &regmap::DUTY_C];

    #[test]
    fn duty_rounding_and_clamping() {
        assert_eq!(duty_cycles(0.5, 3128), 1564);
        assert_eq!(duty_cycles(0.25, 3), 1); // 0.75 rounds to 1
        assert_eq!(duty_cycles(-0.1, 3128), 0);
        assert_eq!(duty_cycles(1.7, 3128), 3128);
        assert_eq!(duty_cycles(f64::NAN, 100), 50);
    }

    #[test]
    fn embedded_hal_channel_scales_to_the_period() {
        let mut pl = FakePl::new();
        let mut pwm = Pwm(&mut pl);
        pwm.set_half_period(3128).unwrap();
        let mut b = pwm.leg(1).unwrap();
        assert_eq!(b.max_duty_cycle(), 3128);
        b.set_duty_cycle_percent(25).unwrap();
        b.set_duty_cycle_fully_on().unwrap();
        let mut c = pwm.leg(2).unwrap();
        c.set_duty_cycle_fraction(1, 4).unwrap();
        assert_eq!(pl.get(PWM.addr(&regmap::DUTY_B)), 3128);
        assert_eq!(pl.get(PWM.addr(&regmap::DUTY_C)), 782);
        // A 25 % write happened before the 100 % one.
        assert!(pl.writes.contains(&(PWM.addr(&regmap::DUTY_B), 782)));
        // Leg a untouched: its reset value.
        assert_eq!(pl.get(PWM.addr(&regmap::DUTY_A)), regmap::DUTY_A.reset);
    }

    #[test]
    fn gates_and_duties() {
        let mut pl = FakePl::new();
        let mut pwm = Pwm(&mut pl);
        assert!(!pwm.gates_enabled().unwrap());
        pwm.set_gates(true).unwrap();
        assert!(pwm.gates_enabled().unwrap());
        pwm.set_duties([0.0, 0.5, 1.0], 1000).unwrap();
        pwm.set_gates(false).unwrap();
        assert_eq!(pl.get(regmap::GATE_CTRL_ADDR), 0);
        let duties: std::vec::Vec<u32> = DUTY.iter().map(|r| pl.get(PWM.addr(r))).collect();
        assert_eq!(duties, [0, 500, 1000]);
        pl.set(PWM.addr(&regmap::GATE_STATUS), 0b101_010_101);
        assert_eq!(Pwm(&mut pl).gate_status().unwrap(), (0b101, 0b010, 0b101));
    }
}
