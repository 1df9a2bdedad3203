//! Cycle-exact model of the PL gate driver (`pl-bitstream-src/rtl/gate_leg.v`
//! and `gate_driver.v`): per-leg interlock and dead time, 3 legs.
//!
//! It is the oracle of the Verilator harness (`rtl-sim`): every output bit of
//! every clock cycle must match. Firmware can use it as the mocked gate stage
//! under QEMU (which has no PL).
//!
//! Conventions (ARCHITECTURE.md): switching state bits `SaSbSc`, `Sx = 1` =
//! upper switch of leg x on, index `4 Sa + 2 Sb + Sc`; so bit 2 is leg a.
//! The gate output vectors use the same bit order.
//!
//! Dead time: an unsigned count of PL clock cycles, [`DEAD_TIME_BITS`] wide
//! (0..=1023 cycles, 10 ns..10.23 us at 100 MHz). 0 is treated as 1, so a
//! gate never turns on in the cycle right after the other one turned off.

/// Width of the dead-time input of the RTL (`DT_W`).
pub const DEAD_TIME_BITS: u32 = 10;
/// Largest dead time the RTL input can hold, in clock cycles.
pub const DEAD_TIME_MAX_CYCLES: u16 = (1 << DEAD_TIME_BITS) - 1;

/// Invalid input to the gate-driver model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GateError {
    /// Dead time above [`DEAD_TIME_MAX_CYCLES`] (does not fit the register).
    DeadTimeTooLarge(u16),
    /// Switching state above 7 (only 3 bits `SaSbSc`).
    InvalidSwitchState(u8),
}

/// Dead time in PL clock cycles, validated to fit [`DEAD_TIME_BITS`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DeadTime(u16);

impl DeadTime {
    /// `cycles` as written to the register; 0 behaves as 1.
    pub const fn new(cycles: u16) -> Result<Self, GateError> {
        if cycles > DEAD_TIME_MAX_CYCLES {
            Err(GateError::DeadTimeTooLarge(cycles))
        } else {
            Ok(Self(cycles))
        }
    }
    /// The register value.
    pub const fn cycles(self) -> u16 {
        self.0
    }
    /// Cycles with both gates off before a gate may turn on: max(value, 1).
    pub const fn effective_cycles(self) -> u16 {
        if self.0 == 0 {
            1
        } else {
            self.0
        }
    }
}

/// One leg: registered gate outputs and the both-off cycle counter.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct GateLeg {
    /// Upper gate on.
    pub hi: bool,
    /// Lower gate on.
    pub lo: bool,
    /// Consecutive cycles, including the current one, with both gates off;
    /// saturates at [`DEAD_TIME_MAX_CYCLES`] (RTL `off_cnt_q`).
    pub off_cycles: u16,
}

impl GateLeg {
    /// One rising clock edge. `upper` is the desired switch state (`Sx`).
    pub fn step(&mut self, rst: bool, en: bool, fault: bool, upper: bool, dt: DeadTime) {
        let dead_done = self.off_cycles >= dt.effective_cycles();
        let (hi, lo) = if rst || fault || !en {
            (false, false)
        } else if upper {
            (self.hi || (!self.lo && dead_done), false)
        } else {
            (false, self.lo || (!self.hi && dead_done))
        };
        self.off_cycles = if rst || hi || lo {
            0
        } else if self.off_cycles < DEAD_TIME_MAX_CYCLES {
            self.off_cycles + 1
        } else {
            self.off_cycles
        };
        self.hi = hi;
        self.lo = lo;
    }
}

/// Inputs of the gate driver for one clock cycle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct GateInputs {
    /// Synchronous reset.
    pub rst: bool,
    /// 1 = follow `state`; 0 = all gates off.
    pub en: bool,
    /// 1 = all gates off at the next edge.
    pub fault: bool,
    /// Desired switching state `SaSbSc` (0..=7).
    pub state: u8,
    /// Dead time.
    pub dead_time: DeadTime,
}

/// Gate outputs: bit 2 = leg a, bit 1 = leg b, bit 0 = leg c.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct GateOutputs {
    /// Upper gates.
    pub hi: u8,
    /// Lower gates.
    pub lo: u8,
}

/// The three legs (RTL `gate_driver`). The reset state is `Default`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct GateDriver {
    /// Legs c, b, a (index = bit position).
    pub legs: [GateLeg; 3],
}

impl GateDriver {
    /// One rising clock edge; returns the outputs after it. An invalid switch
    /// state is rejected and changes nothing.
    pub fn step(&mut self, inp: &GateInputs) -> Result<GateOutputs, GateError> {
        if inp.state > 7 {
            return Err(GateError::InvalidSwitchState(inp.state));
        }
        for (bit, leg) in self.legs.iter_mut().enumerate() {
            let upper = (inp.state >> bit) & 1 == 1;
            leg.step(inp.rst, inp.en, inp.fault, upper, inp.dead_time);
        }
        Ok(self.outputs())
    }

    /// Current (registered) outputs.
    pub fn outputs(&self) -> GateOutputs {
        let mut out = GateOutputs::default();
        for (bit, leg) in self.legs.iter().enumerate() {
            out.hi |= u8::from(leg.hi) << bit;
            out.lo |= u8::from(leg.lo) << bit;
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn inp(en: bool, fault: bool, state: u8, dt: u16) -> GateInputs {
        GateInputs {
            rst: false,
            en,
            fault,
            state,
            dead_time: DeadTime::new(dt).unwrap(),
        }
    }

    #[test]
    fn rejects_bad_input_without_change() {
        assert_eq!(DeadTime::new(1024), Err(GateError::DeadTimeTooLarge(1024)));
        assert!(DeadTime::new(1023).is_ok());
        let mut gd = GateDriver::default();
        let before = gd;
        assert_eq!(
            gd.step(&inp(true, false, 8, 3)),
            Err(GateError::InvalidSwitchState(8))
        );
        assert_eq!(gd, before);
    }

    /// Hand-computed: from reset, dt = 3: the counter reaches 3 after three
    /// edges, so the upper gate of leg a turns on at the 4th edge. Then a
    /// switch to lower: upper off at the next edge, 3 both-off cycles, lower
    /// on at the 4th edge after the command.
    #[test]
    fn dead_time_sequence_by_hand() {
        let mut gd = GateDriver::default();
        let hi_a: Vec<bool> = (0..5)
            .map(|_| gd.step(&inp(true, false, 0b100, 3)).unwrap().hi & 4 != 0)
            .collect();
        assert_eq!(hi_a, [false, false, false, true, true]);
        // Legs b, c asked for lower since the start: same timing.
        assert_eq!(gd.outputs().lo, 0b011);
        let seq: Vec<(u8, u8)> = (0..5)
            .map(|_| {
                let o = gd.step(&inp(true, false, 0b000, 3)).unwrap();
                (o.hi, o.lo)
            })
            .collect();
        assert_eq!(
            seq,
            [(0, 0b011), (0, 0b011), (0, 0b011), (0, 0b111), (0, 0b111)]
        );
    }

    #[test]
    fn zero_dead_time_is_one_cycle() {
        let mut gd = GateDriver::default();
        for _ in 0..3 {
            gd.step(&inp(true, false, 0b111, 0)).unwrap();
        }
        assert_eq!(gd.outputs(), GateOutputs { hi: 7, lo: 0 });
        let o1 = gd.step(&inp(true, false, 0, 0)).unwrap();
        let o2 = gd.step(&inp(true, false, 0, 0)).unwrap();
        assert_eq!((o1.hi, o1.lo), (0, 0));
        assert_eq!((o2.hi, o2.lo), (0, 7));
    }

    #[test]
    fn fault_and_disable_turn_everything_off_next_edge() {
        let mut gd = GateDriver::default();
        for _ in 0..4 {
            gd.step(&inp(true, false, 0b101, 1)).unwrap();
        }
        assert_eq!(
            gd.outputs(),
            GateOutputs {
                hi: 0b101,
                lo: 0b010
            }
        );
        assert_eq!(
            gd.step(&inp(true, true, 0b101, 1)).unwrap(),
            GateOutputs::default()
        );
        for _ in 0..4 {
            gd.step(&inp(true, false, 0b101, 1)).unwrap();
        }
        assert_eq!(
            gd.step(&inp(false, false, 0b101, 1)).unwrap(),
            GateOutputs::default()
        );
    }

    #[test]
    fn counter_saturates() {
        let mut gd = GateDriver::default();
        for _ in 0..2000 {
            gd.step(&inp(false, false, 0, 1023)).unwrap();
        }
        assert_eq!(gd.legs[0].off_cycles, DEAD_TIME_MAX_CYCLES);
        assert_eq!(gd.step(&inp(true, false, 1, 1023)).unwrap().hi, 1);
    }
}
