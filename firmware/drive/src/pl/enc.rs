//! Encoder block: position and speed, and their electrical equivalents.
use core::f64::consts::TAU;
use regmap::bus::{BusError, RegisterBus};
use regmap::regs::enc::{
    EncCpr, EncCprValue, EncPos, EncPosSample, EncPosSampleValue, EncPosValue, EncSpeed,
    EncSpeedValue, EncWindow, EncWindowValue,
};
use regmap::regs::top::{BoundaryAge, BoundaryAgeValue};

/// The live count read late in a control period ([`Encoder::live_pos_aged`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LivePos {
    /// `ENC_POS`, counts in `0..cpr`.
    pub pos: u32,
    /// `BOUNDARY_AGE` read just after it: PL cycles since the boundary,
    /// at least the count's own age.
    pub age: u32,
}

/// Encoder readings.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct EncReading {
    /// `ENC_POS` (live, [`Encoder::read`]) or `ENC_POS_SAMPLE` (at the
    /// control-period boundary, [`Encoder::read_sampled`]), counts in
    /// `0..cpr`.
    pub pos: u32,
    /// `ENC_CPR`, counts per mechanical revolution.
    pub cpr: u32,
    /// `ENC_SPEED`, counts per window.
    pub speed: i32,
    /// `ENC_WINDOW`, PL clock cycles.
    pub window: u32,
}

impl EncReading {
    /// Electrical angle, rad in `[0, 2 pi)`, for `pole_pairs` and the
    /// position `zero` (counts) where the rotor d axis is on phase a.
    pub fn theta_e_rad(&self, pole_pairs: u32, zero: u32) -> f64 {
        let cpr = self.cpr.max(1);
        let rel = (self.pos + cpr - zero % cpr) % cpr;
        let turns = f64::from(rel) / f64::from(cpr) * f64::from(pole_pairs);
        (turns - libm::floor(turns)) * TAU
    }
    /// Electrical speed, rad/s.
    pub fn omega_e_rad_s(&self, pole_pairs: u32) -> f64 {
        let window_s = f64::from(self.window.max(1)) / f64::from(regmap::PL_CLOCK_HZ);
        f64::from(self.speed) / f64::from(self.cpr.max(1)) * TAU * f64::from(pole_pairs) / window_s
    }
}

/// The encoder block.
pub struct Encoder<B>(pub B);

impl<B: RegisterBus> Encoder<B> {
    /// Live position, resolution, speed and window in one go.
    pub fn read(&mut self) -> Result<EncReading, BusError> {
        self.read_with(EncPos::ADDR, |w| EncPosValue::from_bits(w).value())
    }
    /// As [`Encoder::read`], with the position latched at the last
    /// control-period boundary: the control step's position, of the same
    /// instant as its sample whenever in the period the step reads it.
    pub fn read_sampled(&mut self) -> Result<EncReading, BusError> {
        self.read_with(EncPosSample::ADDR, |w| {
            EncPosSampleValue::from_bits(w).value()
        })
    }
    /// The live position `ENC_POS` and, read just after it (in one
    /// group), `BOUNDARY_AGE`: the count's age after the last boundary is
    /// at most that.
    pub fn live_pos_aged(&mut self) -> Result<LivePos, BusError> {
        let mut w = [0; 2];
        self.0
            .read_many(&[EncPos::ADDR, BoundaryAge::ADDR], &mut w)?;
        Ok(LivePos {
            pos: EncPosValue::from_bits(w[0]).value(),
            age: BoundaryAgeValue::from_bits(w[1]).bits(),
        })
    }
    /// The position register at `pos_addr` (decoded by `pos`), then the
    /// rest, back to back.
    fn read_with(&mut self, pos_addr: usize, pos: fn(u32) -> u32) -> Result<EncReading, BusError> {
        let a = [pos_addr, EncCpr::ADDR, EncSpeed::ADDR, EncWindow::ADDR];
        let mut w = [0; 4];
        self.0.read_many(&a, &mut w)?;
        Ok(EncReading {
            pos: pos(w[0]),
            cpr: EncCprValue::from_bits(w[1]).value(),
            speed: EncSpeedValue::from_bits(w[2]).value_i32(),
            window: EncWindowValue::from_bits(w[3]).value(),
        })
    }
    /// Counts per mechanical revolution (the PL clamps to 4..=65535).
    pub fn set_cpr(&mut self, cpr: u32) -> Result<(), BusError> {
        EncCpr::write(
            &mut self.0,
            regmap::regs::enc::EncCprValue::ZERO.with_value(cpr),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pl::fake::FakePl;
    use regmap::{self, ENC};

    #[test]
    fn electrical_angle_and_speed() {
        let mut pl = FakePl::new();
        pl.set(ENC.addr(&regmap::ENC_POS), 1024);
        pl.set(ENC.addr(&regmap::ENC_SPEED), 0xFFF6); // -10 counts
        let r = Encoder(&mut pl).read().unwrap();
        assert_eq!(
            (r.pos, r.cpr, r.speed, r.window),
            (1024, 4096, -10, 100_000)
        );
        // A quarter turn with 7 pole pairs = 1.75 electrical turns.
        assert!((r.theta_e_rad(7, 0) - 0.75 * TAU).abs() < 1e-12);
        // Relative to a zero at 3072: half a turn = 3.5 electrical turns.
        assert!((r.theta_e_rad(7, 3072) - 0.5 * TAU).abs() < 1e-12);
        // -10 counts per ms = -10/4096 rev per ms.
        let w = -10.0 / 4096.0 * TAU * 7.0 / 1e-3;
        assert!((r.omega_e_rad_s(7) - w).abs() < 1e-9);
    }

    #[test]
    fn the_sampled_read_takes_the_boundary_position() {
        let mut pl = FakePl::new();
        pl.set(ENC.addr(&regmap::ENC_POS), 1024);
        pl.set(ENC.addr(&regmap::ENC_POS_SAMPLE), 1020);
        assert_eq!(Encoder(&mut pl).read().unwrap().pos, 1024);
        assert_eq!(Encoder(&mut pl).read_sampled().unwrap().pos, 1020);
    }
}
