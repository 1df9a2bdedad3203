//! Fault confinement of one CAN node: the transmit and receive error
//! counters and the state they give, by the rules of ISO 11898-1
//! (fault confinement; the same rules as section 8 of the Bosch CAN 2.0
//! specification for extended frames):
//!
//! - a transmitter that sends an error flag adds 8 to TEC, except an
//!   error-passive transmitter whose error is a missing acknowledge (a node
//!   alone on the bus stays error passive instead of going bus off);
//! - a receiver that detects an error adds 1 to REC;
//! - a successful transmission takes 1 from TEC; a successful reception
//!   takes 1 from REC, or sets a REC above 127 to a value from 119 to 127
//!   (this model: 127);
//! - error passive when TEC or REC is 128 or more; bus off when TEC is
//!   above 255; from bus off, error active with both counters 0 after 128
//!   occurrences of 11 consecutive recessive bits.

/// Fault confinement state.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum State {
    /// Both counters below 128.
    Active,
    /// A counter at 128 or more.
    Passive,
    /// TEC went above 255.
    BusOff,
}

/// Counter at which a node is error passive.
pub const PASSIVE_AT: u16 = 128;
/// TEC above which a node is bus off.
pub const BUS_OFF_ABOVE: u16 = 255;
/// Consecutive recessive bits that make one recovery occurrence.
pub const RECOVERY_RUN_BITS: u32 = 11;
/// Occurrences that end bus off.
pub const RECOVERY_RUNS: u32 = 128;
/// The error counter registers are 8 bits wide.
const COUNTER_REGISTER_MAX: u16 = 255;

/// The counters of one node.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Confinement {
    tec: u16,
    rec: u16,
    bus_off: bool,
    /// Recessive bits seen in bus off, toward the recovery.
    recessive_bits: u32,
}

impl Confinement {
    /// The state the counters give.
    pub fn state(&self) -> State {
        if self.bus_off {
            State::BusOff
        } else if self.tec >= PASSIVE_AT || self.rec >= PASSIVE_AT {
            State::Passive
        } else {
            State::Active
        }
    }

    /// TEC as `ECR` shows it (8 bits; 255 in bus off).
    pub fn tec(&self) -> u8 {
        self.tec.min(COUNTER_REGISTER_MAX) as u8
    }

    /// REC as `ECR` shows it.
    pub fn rec(&self) -> u8 {
        self.rec.min(COUNTER_REGISTER_MAX) as u8
    }

    /// This node, transmitting, sent an error flag; `ack` when the error
    /// was a missing acknowledge. True when this made the node bus off.
    pub fn transmit_error(&mut self, ack: bool) -> bool {
        if self.bus_off || (ack && self.state() == State::Passive) {
            return false;
        }
        self.tec += 8;
        if self.tec > BUS_OFF_ABOVE {
            self.bus_off = true;
            self.recessive_bits = 0;
        }
        self.bus_off
    }

    /// This node transmitted a frame without error.
    pub fn transmit_ok(&mut self) {
        self.tec = self.tec.saturating_sub(1);
    }

    /// This node, receiving, detected an error.
    pub fn receive_error(&mut self) {
        if !self.bus_off {
            self.rec = (self.rec + 1).min(COUNTER_REGISTER_MAX);
        }
    }

    /// This node received a frame without error.
    pub fn receive_ok(&mut self) {
        self.rec = if self.rec >= PASSIVE_AT {
            PASSIVE_AT - 1
        } else {
            self.rec.saturating_sub(1)
        };
    }

    /// `bits` consecutive recessive bits on the bus (an idle bus). True when
    /// they ended bus off.
    pub fn recessive(&mut self, bits: u32) -> bool {
        if !self.bus_off {
            return false;
        }
        self.recessive_bits = self.recessive_bits.saturating_add(bits);
        if self.recessive_bits / RECOVERY_RUN_BITS >= RECOVERY_RUNS {
            *self = Self::default();
            return true;
        }
        false
    }
}
