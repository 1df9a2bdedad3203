//! The NMT slave (CiA 301 v4.2 NMT state machine): the node's communication state,
//! driven by NMT commands on COB-ID 0, and which services each state
//! allows (CiA 301's table of services per NMT state).
//!
//! An NMT command frame has two data bytes: the command specifier and the
//! addressed node-ID, 0 addressing all nodes. Specifiers: 0x01 start
//! remote node, 0x02 stop remote node, 0x80 enter pre-operational, 0x81
//! reset node, 0x82 reset communication. After initialisation the node
//! sends its boot-up message (COB-ID 0x700 + node, one byte 0x00) and
//! enters pre-operational by itself.

use crate::frame::CanFrame;

/// COB-ID of NMT commands.
pub const NMT_COB_ID: u16 = 0x000;

/// NMT states.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NmtState {
    /// Initialisation (reset application / communication under way).
    Initialising,
    PreOperational,
    Operational,
    Stopped,
}

impl NmtState {
    /// The state byte of heartbeat and boot-up messages (CiA 301 §7.2.8:
    /// 0 boot-up, 4 stopped, 5 operational, 127 pre-operational).
    pub fn heartbeat_byte(self) -> u8 {
        match self {
            NmtState::Initialising => 0x00,
            NmtState::Stopped => 0x04,
            NmtState::Operational => 0x05,
            NmtState::PreOperational => 0x7F,
        }
    }

    /// SDO is served in pre-operational and operational.
    pub fn sdo_allowed(self) -> bool {
        matches!(self, NmtState::PreOperational | NmtState::Operational)
    }

    /// PDOs are received and sent in operational only.
    pub fn pdo_allowed(self) -> bool {
        self == NmtState::Operational
    }

    /// SYNC and EMCY are active in pre-operational and operational.
    pub fn sync_emcy_allowed(self) -> bool {
        matches!(self, NmtState::PreOperational | NmtState::Operational)
    }
}

/// What a received NMT command asks of the node.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NmtEvent {
    /// The state changed (start, stop, enter pre-operational).
    StateChanged(NmtState),
    /// Reset node (0x81): reset the application's objects, then the
    /// communication objects, then boot up.
    ResetNode,
    /// Reset communication (0x82): reset the communication objects
    /// (0x1000..=0x1FFF) to their defaults, then boot up.
    ResetCommunication,
}

/// The NMT slave state machine of one node.
#[derive(Clone, Copy, Debug)]
pub struct Nmt {
    node: u8,
    state: NmtState,
}

impl Nmt {
    /// A node in Initialising; call [`Nmt::boot`] once initialised.
    pub fn new(node: u8) -> Self {
        Self {
            node,
            state: NmtState::Initialising,
        }
    }

    /// The current state.
    pub fn state(&self) -> NmtState {
        self.state
    }

    /// Ends initialisation: enters pre-operational and returns the boot-up
    /// message (0x700 + node, data 0x00).
    pub fn boot(&mut self) -> CanFrame {
        self.state = NmtState::PreOperational;
        CanFrame::new(0x700 + self.node as u16, &[0x00]).unwrap_or_default()
    }

    /// Handles the data of an NMT command frame. Frames not addressed to
    /// this node, with a length other than 2 or with an unknown command
    /// specifier change nothing and return `None`. A reset returns the
    /// node to Initialising; the caller resets what the event names and
    /// calls [`Nmt::boot`].
    pub fn on_command(&mut self, data: &[u8]) -> Option<NmtEvent> {
        let [cs, node] = data else {
            return None;
        };
        if *node != 0 && *node != self.node {
            return None;
        }
        if self.state == NmtState::Initialising {
            return None;
        }
        let next = match cs {
            0x01 => NmtState::Operational,
            0x02 => NmtState::Stopped,
            0x80 => NmtState::PreOperational,
            0x81 => {
                self.state = NmtState::Initialising;
                return Some(NmtEvent::ResetNode);
            }
            0x82 => {
                self.state = NmtState::Initialising;
                return Some(NmtEvent::ResetCommunication);
            }
            _ => return None,
        };
        self.state = next;
        Some(NmtEvent::StateChanged(next))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn booted(node: u8) -> Nmt {
        let mut n = Nmt::new(node);
        n.boot();
        n
    }

    #[test]
    fn boot_up_message() {
        let mut n = Nmt::new(0x22);
        assert_eq!(n.state(), NmtState::Initialising);
        // CiA 301 §7.2.8: boot-up is COB-ID 0x700 + node, one byte 0.
        let f = n.boot();
        assert_eq!(f.id(), 0x722);
        assert_eq!(f.data(), &[0x00]);
        assert_eq!(n.state(), NmtState::PreOperational);
    }

    #[test]
    fn every_command_from_every_state() {
        use NmtState::*;
        let cases = [(0x01, Operational), (0x02, Stopped), (0x80, PreOperational)];
        for from_cmd in [0x01u8, 0x02, 0x80] {
            for (cmd, to) in cases {
                let mut n = booted(3);
                n.on_command(&[from_cmd, 3]);
                assert_eq!(n.on_command(&[cmd, 3]), Some(NmtEvent::StateChanged(to)));
                assert_eq!(n.state(), to);
            }
            let mut n = booted(3);
            n.on_command(&[from_cmd, 3]);
            assert_eq!(n.on_command(&[0x81, 3]), Some(NmtEvent::ResetNode));
            assert_eq!(n.state(), Initialising);
            let mut n = booted(3);
            n.on_command(&[from_cmd, 3]);
            assert_eq!(n.on_command(&[0x82, 0]), Some(NmtEvent::ResetCommunication));
            assert_eq!(n.state(), Initialising);
        }
    }

    #[test]
    fn addressing_and_malformed_commands() {
        let mut n = booted(3);
        assert_eq!(n.on_command(&[0x01, 4]), None);
        assert_eq!(n.state(), NmtState::PreOperational);
        assert_eq!(
            n.on_command(&[0x01, 0]),
            Some(NmtEvent::StateChanged(NmtState::Operational))
        );
        for bad in [&[][..], &[0x02], &[0x02, 3, 0], &[0x03, 3], &[0xFF, 0]] {
            assert_eq!(n.on_command(bad), None);
            assert_eq!(n.state(), NmtState::Operational);
        }
    }

    #[test]
    fn services_per_state() {
        // CiA 301 v4.2: services per NMT state.
        use NmtState::*;
        assert!(!Initialising.sdo_allowed());
        assert!(PreOperational.sdo_allowed());
        assert!(Operational.sdo_allowed());
        assert!(!Stopped.sdo_allowed());
        assert!(!PreOperational.pdo_allowed());
        assert!(Operational.pdo_allowed());
        assert!(!Stopped.pdo_allowed());
        assert!(!Stopped.sync_emcy_allowed());
        assert_eq!(Stopped.heartbeat_byte(), 4);
        assert_eq!(Operational.heartbeat_byte(), 5);
        assert_eq!(PreOperational.heartbeat_byte(), 127);
    }
}
