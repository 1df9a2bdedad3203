//! The control interrupt (`IRQ_EN`, `IRQ_STATUS`, `BOUNDARY_AGE`; the PL's
//! `irq_o` on `IRQ_F2P[0]`, GIC SPI 61): enabling it, taking it at the
//! start of the control step, and the step's start latency after the
//! control-period boundary.
use regmap::bus::{BusError, RegisterBus};
use regmap::regs::top::{BoundaryAge, IrqEn, IrqEnValue, IrqStatus, IrqStatusValue};

/// Enables the boundary interrupt and clears stale flags.
pub fn enable<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<(), BusError> {
    clear(bus)?;
    IrqEn::write(bus, IrqEnValue::from_bits(0).with_boundary(true))
}

/// Clears every flag (W1C): boundaries crossed before the control loop
/// starts are no steps it owes.
pub fn clear<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<(), BusError> {
    IrqStatus::write(bus, IrqStatusValue::from_bits(0b111))
}

/// What the handler found when it took the interrupt.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Taken {
    /// `IRQ_STATUS` before the acknowledge.
    pub status: IrqStatusValue,
    /// `BOUNDARY_AGE`: PL cycles since the boundary.
    pub age: u32,
}

/// Reads the flags and the age, then acknowledges the flags read (the
/// line drops; a boundary in the same cycle still sets its flag).
pub fn take<B: RegisterBus + ?Sized>(bus: &mut B) -> Result<Taken, BusError> {
    let mut w = [0; 2];
    bus.read_many(&[BoundaryAge::ADDR, IrqStatus::ADDR], &mut w)?;
    let (age, status) = (w[0], IrqStatusValue::from_bits(w[1]));
    if status.bits() != 0 {
        IrqStatus::write(bus, status)?;
    }
    Ok(Taken { status, age })
}

/// Start latency of the control step after the boundary, PL cycles.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Latency {
    /// Samples.
    pub n: u64,
    /// Smallest, PL cycles.
    pub min: u32,
    /// Largest, PL cycles.
    pub max: u32,
    /// Sum, PL cycles.
    pub sum: u64,
}

impl Latency {
    /// Adds one sample.
    pub fn add(&mut self, cycles: u32) {
        self.min = if self.n == 0 {
            cycles
        } else {
            self.min.min(cycles)
        };
        self.max = self.max.max(cycles);
        self.sum += u64::from(cycles);
        self.n += 1;
    }

    /// Mean, PL cycles (0 without samples).
    pub fn mean(&self) -> f64 {
        if self.n == 0 {
            0.0
        } else {
            self.sum as f64 / self.n as f64
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::pl::fake::FakePl;

    #[test]
    fn take_reads_age_and_acknowledges_what_it_read() {
        let mut pl = FakePl::new();
        enable(&mut pl).unwrap();
        assert_eq!(IrqEn::read(&mut pl).unwrap().bits(), 1);
        pl.set(IrqStatus::ADDR, 0b101);
        pl.set(BoundaryAge::ADDR, 37);
        let t = take(&mut pl).unwrap();
        assert!(t.status.boundary() && t.status.missed() && !t.status.fault());
        assert_eq!(t.age, 37);
        // W1C of what was read: nothing left.
        assert_eq!(IrqStatus::read(&mut pl).unwrap().bits(), 0);
    }

    #[test]
    fn latency_min_mean_max() {
        let mut l = Latency::default();
        assert_eq!(l.mean(), 0.0);
        for c in [12, 4, 20] {
            l.add(c);
        }
        assert_eq!((l.n, l.min, l.max), (3, 4, 20));
        assert_eq!(l.mean(), 12.0);
    }
}
