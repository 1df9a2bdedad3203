//! The drive's CANopen device in one value: the node, the dictionary, the
//! CiA 402 axis and the counters `status` shows. A transport (socketcand
//! over TCP, the PS CAN controller) hands it every received frame and
//! sends what it returns; the control loop calls [`Link::boundary`] after
//! each step.

use super::axis::Axis;
use super::eds::node_config;
use super::objects::{ConfigPort, DriveObjects};
use crate::servo::sensors::PlTime;
use crate::servo::Servo;
use canopen::cia402::{mode, State};
use canopen::nmt::NmtState;
use canopen::node::Node;
use canopen::pdo::Pdos;
use canopen::{CanFrame, Frames};
use core::fmt;
use regmap::bus::{BusError, RegisterBus};

/// EMCY error code of a heartbeat the consumer lost (CiA 301: "life guard
/// error or heartbeat error").
pub const HEARTBEAT_LOST: u16 = canopen::emcy::code::HEARTBEAT;

/// Frames the link has seen and sent, by kind, since power-on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Counters {
    /// SYNC frames received (COB-ID 0x080).
    pub syncs: u32,
    /// RPDOs received (COB-IDs 0x200..=0x5FF).
    pub rpdos: u32,
    /// TPDOs sent (COB-IDs 0x180..=0x4FF).
    pub tpdos: u32,
    /// SDO requests received for this node.
    pub sdos: u32,
    /// SDO aborts and EMCY frames sent: the refusals and faults a master
    /// saw.
    pub errors: u32,
}

/// The `canopen:` line of `status`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LinkStatus {
    pub node_id: u8,
    pub nmt: NmtState,
    pub state: State,
    /// 0x6061.
    pub mode: i8,
    pub counters: Counters,
    /// The master owns the motor ([`Link::owns`]).
    pub owns: bool,
}

fn nmt_name(s: NmtState) -> &'static str {
    match s {
        NmtState::Initialising => "initialising",
        NmtState::PreOperational => "pre-operational",
        NmtState::Operational => "operational",
        NmtState::Stopped => "stopped",
    }
}

fn state_name(s: State) -> &'static str {
    match s {
        State::NotReadyToSwitchOn => "not-ready-to-switch-on",
        State::SwitchOnDisabled => "switch-on-disabled",
        State::ReadyToSwitchOn => "ready-to-switch-on",
        State::SwitchedOn => "switched-on",
        State::OperationEnabled => "operation-enabled",
        State::QuickStopActive => "quick-stop-active",
        State::FaultReactionActive => "fault-reaction-active",
        State::Fault => "fault",
    }
}

fn mode_name(m: i8) -> &'static str {
    match m {
        mode::CYCLIC_SYNC_TORQUE => "cst",
        mode::CYCLIC_SYNC_VELOCITY => "csv",
        mode::CYCLIC_SYNC_POSITION => "csp",
        mode::HOMING => "hm",
        mode::VENDOR => "impedance",
        _ => "none",
    }
}

impl fmt::Display for LinkStatus {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let c = &self.counters;
        write!(
            f,
            "node {}, nmt {}, cia402 {}, mode {} ({}), syncs {}, rpdos {}, tpdos {}, sdos {}, \
             errors {}{}",
            self.node_id,
            nmt_name(self.nmt),
            state_name(self.state),
            self.mode,
            mode_name(self.mode),
            c.syncs,
            c.rpdos,
            c.tpdos,
            c.sdos,
            c.errors,
            if self.owns { ", owns the motor" } else { "" }
        )
    }
}

/// The node, its dictionary and the axis behind it.
pub struct Link<C> {
    pub node: Node,
    pub obj: DriveObjects<C>,
    pub axis: Axis,
    pub counters: Counters,
}

impl<C: ConfigPort> Link<C> {
    /// A device with node-ID `node_id` (1..=127, else `None`) over the
    /// configuration `config`.
    pub fn new(node_id: u8, config: C) -> Option<Self> {
        Some(Self {
            node: Node::new(node_config(node_id), Pdos::new(node_id))?,
            obj: DriveObjects::new(config),
            axis: Axis::new(),
            counters: Counters::default(),
        })
    }

    /// Power-on: the boot-up frame, and the drive's own initialisation
    /// ended (CiA 402 transition 1, to Switch on disabled).
    pub fn boot(&mut self) -> Frames {
        let f = self.node.boot();
        self.node.drive_initialised(&mut self.obj);
        self.count_out(&f);
        f
    }

    /// The master owns the motor: NMT operational and the drive enabled
    /// or quick-stopping. The console then refuses the commands that move
    /// it.
    pub fn owns(&self) -> bool {
        self.node.nmt_state() == NmtState::Operational
            && matches!(
                self.node.drive().state(),
                State::OperationEnabled | State::QuickStopActive
            )
    }

    pub fn status(&self) -> LinkStatus {
        LinkStatus {
            node_id: self.node.id(),
            nmt: self.node.nmt_state(),
            state: self.node.drive().state(),
            mode: self.node.drive().mode_display(),
            counters: self.counters,
            owns: self.owns(),
        }
    }

    /// Counts what the node sends: its SDO answers, EMCYs and heartbeats
    /// have fixed COB-IDs, everything else it sends is a TPDO.
    fn count_out(&mut self, out: &Frames) {
        let id = u16::from(self.node.id());
        for f in out.iter() {
            let cob = f.id();
            let c = &mut self.counters;
            if cob == 0x580 + id {
                if f.data().first() == Some(&0x80) {
                    c.errors = c.errors.wrapping_add(1);
                }
            } else if cob == 0x080 + id {
                c.errors = c.errors.wrapping_add(1);
            } else if cob != 0x700 + id {
                c.tpdos = c.tpdos.wrapping_add(1);
            }
        }
    }

    fn count_in(&mut self, f: &CanFrame) {
        let id = u16::from(self.node.id());
        let rpdo = self.node.pdos().rpdo_for(f.id()).is_some();
        let c = &mut self.counters;
        match f.id() {
            0x080 => c.syncs = c.syncs.wrapping_add(1),
            cob if cob == 0x600 + id => c.sdos = c.sdos.wrapping_add(1),
            _ if rpdo => c.rpdos = c.rpdos.wrapping_add(1),
            _ => {}
        }
    }

    /// A received frame: the node's answer, then what its transitions
    /// asked of the servo. Returns the frames to send, in order.
    pub fn on_frame<B: PlTime>(
        &mut self,
        f: &CanFrame,
        servo: &mut Servo,
        bus: &mut B,
    ) -> Result<Frames, BusError> {
        self.count_in(f);
        let mut out = self.node.on_frame(f, &mut self.obj);
        let more = self
            .axis
            .carry_out(servo, bus, &mut self.obj, &mut self.node)?;
        out.append(&more);
        self.count_out(&out);
        Ok(out)
    }

    /// Time passes (monotonic microseconds): heartbeat, event-driven
    /// TPDOs and the heartbeat consumer. A master whose heartbeat stops
    /// (0x1016) gets its EMCY 0x8130 from the node, and the drive reacts
    /// as 0x6007 says: 1 a fault (gates off, Fault), 2 disable voltage, 3
    /// (the default) a quick stop, 0 nothing.
    pub fn tick<B: PlTime>(
        &mut self,
        now_us: u64,
        servo: &mut Servo,
        bus: &mut B,
    ) -> Result<Frames, BusError> {
        let mut out = self.node.tick(now_us, &mut self.obj);
        let emcy = 0x080 + u16::from(self.node.id());
        let lost = out.iter().any(|f| {
            f.id() == emcy && f.data().get(..2) == Some(&HEARTBEAT_LOST.to_le_bytes()[..])
        });
        if lost {
            match self.obj.image.abort_connection_option {
                1 => {
                    self.obj.image.error_code = HEARTBEAT_LOST;
                    let f = self.node.drive_fault(
                        &mut self.obj,
                        HEARTBEAT_LOST,
                        canopen::emcy::register::COMMUNICATION,
                        [0; 5],
                    );
                    out.append(&f);
                }
                2 => self.node.controlword(&mut self.obj, 0x0000),
                3 => self.node.controlword(&mut self.obj, 0x0002),
                _ => {}
            }
            let more = self
                .axis
                .carry_out(servo, bus, &mut self.obj, &mut self.node)?;
            out.append(&more);
        }
        self.count_out(&out);
        Ok(out)
    }

    /// After a control step: faults to the node, set-points to the servo,
    /// actual values back, and what the transitions this caused asked.
    /// `dt_s` is the time since the last call.
    pub fn boundary<B: PlTime + RegisterBus>(
        &mut self,
        servo: &mut Servo,
        bus: &mut B,
        dt_s: f64,
    ) -> Result<Frames, BusError> {
        let mut out = self
            .axis
            .exchange(servo, bus, &mut self.obj, &mut self.node, dt_s)?;
        let more = self
            .axis
            .carry_out(servo, bus, &mut self.obj, &mut self.node)?;
        out.append(&more);
        self.count_out(&out);
        Ok(out)
    }
}
