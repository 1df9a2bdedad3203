//! The wire between controller models: one call of [`step`] is one frame
//! slot on the bus.
//!
//! - A node in loopback sends to itself; its frames never reach the wire,
//!   and it receives nothing from the wire.
//! - Of the nodes in normal mode with a message pending, the one whose
//!   identifier word is lowest wins arbitration: the word holds the
//!   arbitration field in bus order from bit 31 down (IDH, SRR/RTR, IDE,
//!   IDL, RTR), and a dominant bit is 0. The others set `ISR.ARBLST` and
//!   keep their message.
//! - An injected bit error: the sender's error flag, TEC + 8; every other
//!   node on the bus detects it as a stuff error, REC + 1. The message stays
//!   queued.
//! - A node whose bit time differs from the sender's (`BRPR`, `BTR`, its
//!   reference clock) detects a form error, REC + 1, and neither
//!   acknowledges nor receives.
//! - No other node acknowledges (none in normal mode at the sender's bit
//!   rate and not bus off): an acknowledge error for the sender; the
//!   message stays queued.
//! - Otherwise the message is sent and every other node on the bus (normal
//!   or snoop) at the sender's bit rate receives it.

use super::fifo::Message;
use super::{BusMode, PsCanModel};
use regmap::ps_can as reg;

/// What one frame slot carried.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Transfer {
    /// No node had anything to send.
    Idle,
    /// Node `from` sent `msg` onto the bus.
    Sent {
        /// Index of the sender in the slice given to [`step`].
        from: usize,
        /// The message.
        msg: Message,
    },
    /// Node `node` in loopback received its own `msg`.
    Looped {
        /// Index of the node.
        node: usize,
        /// The message.
        msg: Message,
    },
    /// Node `from`'s attempt met a bit error.
    BitError {
        /// Index of the sender.
        from: usize,
    },
    /// Node `from`'s frame was not acknowledged.
    AckError {
        /// Index of the sender.
        from: usize,
    },
}

/// One frame slot on the bus of `nodes`.
pub fn step(nodes: &mut [&mut PsCanModel]) -> Transfer {
    for (i, n) in nodes.iter_mut().enumerate() {
        if n.mode() != BusMode::Loopback {
            continue;
        }
        if let Some(msg) = n.pending() {
            if n.take_bit_error() {
                n.transmit_error(reg::ESR_BERR, false);
                return Transfer::BitError { from: i };
            }
            n.transmitted();
            n.receive(&msg);
            return Transfer::Looped { node: i, msg };
        }
    }
    let winner = nodes
        .iter()
        .enumerate()
        .filter(|(_, n)| n.mode() == BusMode::Normal)
        .filter_map(|(i, n)| n.pending().map(|m| (i, m)))
        .min_by_key(|(_, m)| m.id);
    let Some((from, msg)) = winner else {
        return Transfer::Idle;
    };
    for (i, n) in nodes.iter_mut().enumerate() {
        if i != from && n.mode() == BusMode::Normal && n.pending().is_some() {
            n.isr |= reg::IXR_ARBLST;
        }
    }
    if nodes[from].take_bit_error() {
        nodes[from].transmit_error(reg::ESR_BERR, false);
        for (i, n) in nodes.iter_mut().enumerate() {
            if i != from {
                n.receive_error(reg::ESR_STER);
            }
        }
        return Transfer::BitError { from };
    }
    let bit_time = nodes[from].bit_time();
    let acked = nodes
        .iter()
        .enumerate()
        .any(|(i, n)| i != from && n.acknowledges() && n.bit_time_is(bit_time));
    // A node at another bit rate sees a broken frame whatever happens.
    for (i, n) in nodes.iter_mut().enumerate() {
        if i != from && !n.bit_time_is(bit_time) {
            n.receive_error(reg::ESR_FMER);
        }
    }
    if !acked {
        nodes[from].transmit_error(reg::ESR_ACKER, true);
        return Transfer::AckError { from };
    }
    nodes[from].transmitted();
    for (i, n) in nodes.iter_mut().enumerate() {
        if i != from && n.bit_time_is(bit_time) {
            n.deliver(&msg);
        }
    }
    Transfer::Sent { from, msg }
}

/// Steps until a slot is idle or `max_slots` slots have passed; the
/// number of slots that carried something.
pub fn run(nodes: &mut [&mut PsCanModel], max_slots: usize) -> usize {
    (0..max_slots)
        .take_while(|_| step(nodes) != Transfer::Idle)
        .count()
}

/// The bus stays recessive for `bits` bit times (every node sees it).
pub fn idle(nodes: &mut [&mut PsCanModel], bits: u32) {
    for n in nodes.iter_mut() {
        n.idle_bits(bits);
    }
}
