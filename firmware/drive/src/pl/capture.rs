//! Capture buffer (`capture_buf`, the CAPTURE page): arm with a trigger and
//! a pre-trigger length, feed the PS-computed channels each control period,
//! read the record back in physical units.
//!
//! Channel formats (the register table's): currents in mA, torques in
//! 0.1 mN m, 16-bit two's complement, saturated at the ends when written
//! (+-32.767 A, +-3.2767 N m), rounded to nearest. Position: the
//! multi-turn count since the last `pos zero` (an `i64` on the PS) modulo
//! 2^32, 32-bit two's complement; a reader unwraps it by the difference of
//! consecutive samples (less than 2^31 counts apart at any speed the
//! estimator reads). Velocity: Q16.16 rev/s (32-bit two's complement, LSB
//! 2^-16 rev/s, +-32768 rev/s), following error: Q12.4 counts (16-bit, LSB
//! 1/16 count, -2048..+2047.9375 counts); both rounded to nearest and
//! saturated at the ends, NaN written as 0.
use regmap::bus::{BusError, RegisterBus};
use regmap::regs::capture::{
    self as r, CapArm, CapArmValue, CapData0, CapData1, CapData2, CapDecim, CapDecimValue,
    CapInFerr, CapInFerrValue, CapInId, CapInIdValue, CapInIq, CapInIqValue, CapInPos,
    CapInPosValue, CapInTorque, CapInTorqueValue, CapInTref, CapInTrefValue, CapInVel,
    CapInVelValue, CapPre, CapPreValue, CapRdIndex, CapRdIndexValue, CapSource, CapSourceValue,
    CapStep, CapStepValue, CapThrCh, CapThrChValue, CapThrEdge, CapThrEdgeValue, CapThrLevel,
    CapThrLevelValue, CapTrig, CapTrigValue,
};
use regmap::{cap_source, cap_state, CAPTURE_DEPTH};

/// Current channel resolution, A per LSB.
pub const CURRENT_LSB_A: f64 = 1e-3;
/// Torque channel resolution, N m per LSB.
pub const TORQUE_LSB_NM: f64 = 1e-4;
/// Velocity channel resolution (Q16.16), rev/s per LSB.
pub const VELOCITY_LSB_REV_S: f64 = 1.0 / 65536.0;
/// Following-error channel resolution (Q12.4), counts per LSB.
pub const FERR_LSB_COUNTS: f64 = 1.0 / 16.0;
/// Samples in the ring.
pub const DEPTH: u32 = CAPTURE_DEPTH;

/// A 16-bit channel of a sample.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Channel {
    /// Measured d current, A.
    Id,
    /// Measured q current, A.
    Iq,
    /// Torque from the measured currents, N m.
    Torque,
    /// Torque reference, N m.
    TorqueRef,
}

impl Channel {
    /// `CAP_THR_CH` value.
    fn code(self) -> u32 {
        match self {
            Channel::Id => 0,
            Channel::Iq => 1,
            Channel::Torque => 2,
            Channel::TorqueRef => 3,
        }
    }
    /// Physical value to the channel's register bits.
    pub fn encode(self, x: f64) -> u16 {
        let lsb = match self {
            Channel::Id | Channel::Iq => CURRENT_LSB_A,
            Channel::Torque | Channel::TorqueRef => TORQUE_LSB_NM,
        };
        quantize(x, lsb)
    }
    /// Console name (unit in [`Channel::unit`]).
    pub fn name(self) -> &'static str {
        match self {
            Channel::Id => "i_d",
            Channel::Iq => "i_q",
            Channel::Torque => "torque",
            Channel::TorqueRef => "torque_ref",
        }
    }
    /// Unit of the channel.
    pub fn unit(self) -> &'static str {
        match self {
            Channel::Id | Channel::Iq => "A",
            Channel::Torque | Channel::TorqueRef => "Nm",
        }
    }
    /// By console name.
    pub fn from_name(s: &str) -> Option<Self> {
        [
            Channel::Id,
            Channel::Iq,
            Channel::Torque,
            Channel::TorqueRef,
        ]
        .into_iter()
        .find(|c| c.name() == s)
    }
}

/// `x / lsb` rounded to nearest and saturated to 16-bit two's complement;
/// NaN gives 0.
fn quantize(x: f64, lsb: f64) -> u16 {
    quantize32(x, lsb).clamp(i32::from(i16::MIN), i32::from(i16::MAX)) as i16 as u16
}

/// `x / lsb` rounded to nearest (half away from zero) and saturated to
/// 32-bit two's complement; NaN gives 0.
fn quantize32(x: f64, lsb: f64) -> i32 {
    // `as` saturates and maps NaN to 0.
    libm::round(x / lsb) as i32
}

/// Velocity, rev/s, to the `CAP_IN_VEL` word (Q16.16).
pub fn encode_velocity(v_rev_s: f64) -> u32 {
    quantize32(v_rev_s, VELOCITY_LSB_REV_S) as u32
}

/// Following error, counts, to the `CAP_IN_FERR` bits (Q12.4).
pub fn encode_following_error(e_counts: f64) -> u16 {
    quantize(e_counts, FERR_LSB_COUNTS)
}

/// Multi-turn count to the `CAP_IN_POS` word (its low 32 bits).
pub fn encode_position(counts: i64) -> u32 {
    counts as u32
}

/// What starts the post-trigger part of a record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Trigger {
    /// Only [`Capture::trigger`].
    Manual,
    /// A torque-reference step of at least this many N m between two samples.
    RefStep(f64),
    /// The channel crosses the level (in its unit); `falling` or rising.
    Threshold {
        /// Channel compared.
        channel: Channel,
        /// Level, A or N m.
        level: f64,
        /// Falling edge (else rising).
        falling: bool,
    },
    /// Any latched fault.
    Fault,
}

/// Capture state (`CAP_STATUS`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CapState {
    /// Never armed since reset.
    Idle,
    /// Waiting for the trigger.
    Armed,
    /// Taking the post-trigger samples.
    Triggered,
    /// The record is complete.
    Done,
}

impl CapState {
    /// Console name.
    pub fn name(self) -> &'static str {
        match self {
            CapState::Idle => "idle",
            CapState::Armed => "armed",
            CapState::Triggered => "triggered",
            CapState::Done => "done",
        }
    }
}

/// `CAP_STATUS` decoded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CapStatus {
    /// State.
    pub state: CapState,
    /// Samples in the record.
    pub count: u32,
    /// Record index of the trigger sample (valid when done).
    pub trig_index: u32,
}

/// One recorded sample in physical units.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct CapSample {
    /// i_d, A.
    pub i_d_a: f64,
    /// i_q, A.
    pub i_q_a: f64,
    /// Torque, N m.
    pub torque_nm: f64,
    /// Torque reference, N m.
    pub torque_ref_nm: f64,
    /// Switching state at the gate driver (bits SaSbSc).
    pub sw: u8,
    /// Selectable channel, raw 16 bits (`CAP_SEL`, reset: `ADC_IA`).
    pub sel: u16,
    /// Multi-turn position modulo 2^32, counts.
    pub position_counts: i32,
    /// Velocity, rev/s.
    pub velocity_rev_s: f64,
    /// Position reference minus position, counts.
    pub following_error_counts: f64,
}

fn signed(bits: u32) -> f64 {
    f64::from(bits as u16 as i16)
}

/// The capture block.
pub struct Capture<B>(pub B);

impl<B: RegisterBus> Capture<B> {
    /// Starts a new record: trigger, `pre` samples before it (at most
    /// [`DEPTH`] - 1, the PL clamps), one sample every `decim + 1` averaged
    /// ADC results.
    pub fn arm(&mut self, trigger: Trigger, pre: u32, decim: u8) -> Result<(), BusError> {
        let b = &mut self.0;
        let source = match trigger {
            Trigger::Manual => cap_source::MANUAL,
            Trigger::RefStep(nm) => {
                let step = libm::round(libm::fabs(nm) / TORQUE_LSB_NM).min(65535.0) as u32;
                CapStep::write(b, CapStepValue::ZERO.with_value(step))?;
                cap_source::REF_STEP
            }
            Trigger::Threshold {
                channel,
                level,
                falling,
            } => {
                CapThrCh::write(b, CapThrChValue::ZERO.with_value(channel.code()))?;
                CapThrLevel::write(
                    b,
                    CapThrLevelValue::ZERO.with_value(u32::from(channel.encode(level))),
                )?;
                CapThrEdge::write(b, CapThrEdgeValue::ZERO.with_value(falling))?;
                cap_source::THRESHOLD
            }
            Trigger::Fault => cap_source::FAULT,
        };
        CapSource::write(b, CapSourceValue::ZERO.with_value(source))?;
        CapPre::write(b, CapPreValue::ZERO.with_value(pre.min(DEPTH - 1)))?;
        CapDecim::write(b, CapDecimValue::ZERO.with_value(u32::from(decim)))?;
        CapArm::write(b, CapArmValue::ZERO.with_value(true))?;
        self.taken()
    }

    /// Starts the armed record again with the latched settings (a
    /// `CAP_ARM` write: the ring empties, `CAP_PRE` is latched again).
    pub fn restart(&mut self) -> Result<(), BusError> {
        CapArm::write(&mut self.0, CapArmValue::ZERO.with_value(true))?;
        self.taken()
    }

    /// `pl_top` registers the buffer's inputs, so an arm takes effect one
    /// clock after its write, and `CAP_STATUS` read in that clock still
    /// shows the record before it. One read after the write spends that
    /// clock: a later read sees the new record. A bus whose PL runs only
    /// while it is accessed (the simulated PL between two PL ticks) needs
    /// it, else a `capture status` right after `capture arm` answered
    /// `idle`; on GP0 the next access is later than that anyway.
    fn taken(&mut self) -> Result<(), BusError> {
        r::CapStatus::read(&mut self.0).map(|_| ())
    }

    /// Manual trigger (taken at the next sample while armed).
    pub fn trigger(&mut self) -> Result<(), BusError> {
        CapTrig::write(&mut self.0, CapTrigValue::ZERO.with_value(true))
    }

    /// State and counters.
    pub fn status(&mut self) -> Result<CapStatus, BusError> {
        let v = r::CapStatus::read(&mut self.0)?;
        let state = match v.state() {
            cap_state::IDLE => CapState::Idle,
            cap_state::ARMED => CapState::Armed,
            cap_state::TRIGGERED => CapState::Triggered,
            _ => CapState::Done,
        };
        Ok(CapStatus {
            state,
            count: v.count(),
            trig_index: v.trig_index(),
        })
    }

    /// The channels of this control period.
    pub fn write_channels(
        &mut self,
        i_d_a: f64,
        i_q_a: f64,
        torque_nm: f64,
        torque_ref_nm: f64,
    ) -> Result<(), BusError> {
        let b = &mut self.0;
        let v = |c: Channel, x: f64| u32::from(c.encode(x));
        CapInId::write(b, CapInIdValue::ZERO.with_value(v(Channel::Id, i_d_a)))?;
        CapInIq::write(b, CapInIqValue::ZERO.with_value(v(Channel::Iq, i_q_a)))?;
        CapInTorque::write(
            b,
            CapInTorqueValue::ZERO.with_value(v(Channel::Torque, torque_nm)),
        )?;
        CapInTref::write(
            b,
            CapInTrefValue::ZERO.with_value(v(Channel::TorqueRef, torque_ref_nm)),
        )
    }

    /// The outer loops' channels of this control period: multi-turn
    /// count, velocity (rev/s), following error (counts).
    pub fn write_motion(
        &mut self,
        counts: i64,
        velocity_rev_s: f64,
        following_error_counts: f64,
    ) -> Result<(), BusError> {
        let b = &mut self.0;
        CapInPos::write(b, CapInPosValue::ZERO.with_value(encode_position(counts)))?;
        CapInVel::write(
            b,
            CapInVelValue::ZERO.with_value(encode_velocity(velocity_rev_s)),
        )?;
        CapInFerr::write(
            b,
            CapInFerrValue::ZERO
                .with_value(u32::from(encode_following_error(following_error_counts))),
        )
    }

    /// Sample `index` of the record (0 = oldest).
    pub fn sample(&mut self, index: u32) -> Result<CapSample, BusError> {
        let b = &mut self.0;
        CapRdIndex::write(b, CapRdIndexValue::ZERO.with_value(index))?;
        // The BRAM read takes the clock after the index write: one access
        // in between (back-to-back accesses are one clock apart in the
        // simulated PL).
        r::CapDepth::read(b)?;
        let d0 = CapData0::read(b)?;
        let d1 = CapData1::read(b)?;
        let d2 = CapData2::read(b)?;
        let d3 = r::CapData3::read(b)?;
        let d4 = r::CapData4::read(b)?;
        let d5 = r::CapData5::read(b)?;
        Ok(CapSample {
            i_d_a: signed(d0.i_d()) * CURRENT_LSB_A,
            i_q_a: signed(d0.i_q()) * CURRENT_LSB_A,
            torque_nm: signed(d1.torque()) * TORQUE_LSB_NM,
            torque_ref_nm: signed(d1.tref()) * TORQUE_LSB_NM,
            sw: d2.sw() as u8,
            sel: d2.sel() as u16,
            position_counts: d3.value() as i32,
            velocity_rev_s: f64::from(d4.value() as i32) * VELOCITY_LSB_REV_S,
            following_error_counts: signed(d5.value()) * FERR_LSB_COUNTS,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn channels_round_and_saturate() {
        assert_eq!(Channel::Iq.encode(1.2345), 1235);
        assert_eq!(Channel::Iq.encode(-0.0004), 0);
        assert_eq!(Channel::Id.encode(-1.0), (-1000i16) as u16);
        assert_eq!(Channel::Torque.encode(0.4), 4000);
        assert_eq!(Channel::Torque.encode(10.0), 32767);
        assert_eq!(Channel::TorqueRef.encode(-10.0), 0x8000);
        assert_eq!(Channel::Torque.encode(f64::NAN), 0);
        assert_eq!(Channel::from_name("i_q"), Some(Channel::Iq));
        assert_eq!(Channel::from_name("iq"), None);
    }

    #[test]
    fn motion_channels_round_saturate_and_wrap() {
        // Q16.16: 1.5 rev/s is 0x18000; half an LSB rounds away from 0.
        assert_eq!(encode_velocity(1.5), 0x0001_8000);
        assert_eq!(encode_velocity(-1.0), 0xFFFF_0000);
        assert_eq!(encode_velocity(0.5 / 65536.0), 1);
        assert_eq!(encode_velocity(1e9), 0x7FFF_FFFF);
        assert_eq!(encode_velocity(-1e9), 0x8000_0000);
        assert_eq!(encode_velocity(f64::NAN), 0);
        // Q12.4 counts.
        assert_eq!(encode_following_error(2.5), 40);
        assert_eq!(encode_following_error(-0.03), 0);
        assert_eq!(encode_following_error(-0.04), 0xFFFF);
        assert_eq!(encode_following_error(5000.0), 0x7FFF);
        assert_eq!(encode_following_error(-5000.0), 0x8000);
        // Position: the low 32 bits of the multi-turn count.
        assert_eq!(encode_position(-1), 0xFFFF_FFFF);
        assert_eq!(encode_position((1 << 32) + 7), 7);
    }
}
