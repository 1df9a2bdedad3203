//! The co-simulation bridge's wire format: the firmware under QEMU sends
//! each register access (and a periodic time sync) to a host process that
//! runs the Verilated `pl_top` with the plant (`rtl-sim`'s `pl-cosim`), and
//! waits for the reply. One definition for both ends.
//!
//! Transport: two host FIFOs opened by the guest through ARM semihosting
//! (`SYS_OPEN`/`SYS_WRITE`/`SYS_READ`), one for requests and one for
//! replies; every message is a fixed-size little-endian record.
//!
//! Time mapping: `guest` is the A9 global-timer count. Under QEMU that
//! timer ticks at 100 MHz (10 ns), the PL clock is 100 MHz, so one count is
//! one PL cycle: the host runs the PL to `guest - guest_0` cycles after the
//! PL cycle of the first request (`guest_0` its time) before answering. The
//! PL never runs backwards: a request stamped earlier than the PL's present
//! cycle (two accesses closer than the three or four cycles an AXI access
//! takes) is served at the present cycle.

/// Bytes of a request.
pub const REQUEST_LEN: usize = 24;

/// PL cycles of a register write, AW and W to B (`rtl-sim`'s `RtlPl`).
pub const WRITE_CYCLES: u64 = 4;

/// The PL cycle a request stamped `guest` is served at: `origin` is
/// (guest time, PL cycle) of the first request, `now` the PL's present
/// cycle (the PL never runs backwards).
pub fn serve_cycle(origin: (u64, u64), guest: u64, now: u64) -> u64 {
    (origin.1 + guest.saturating_sub(origin.0)).max(now)
}

/// The PL cycle after a write stamped `guest` that finds the PL at `now`
/// (what the guest of a posted write knows without a reply).
pub fn cycle_after_write(origin: (u64, u64), guest: u64, now: u64) -> u64 {
    serve_cycle(origin, guest, now) + WRITE_CYCLES
}
/// Bytes of a reply.
pub const REPLY_LEN: usize = 24;

/// What a request asks for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Op {
    /// Read the register at `addr`.
    Read,
    /// Write `data` to the register at `addr` (all byte strobes).
    Write,
    /// Only run the PL to the guest time and report the boundaries.
    Sync,
    /// Set a parameter of the simulated motor (`sim set`): `addr` is its
    /// row in `models::pmsm::sim_motor::SIM_PARAMS`, `guest` carries the
    /// value's `f64` bits (the PL does not run). SLVERR: refused, nothing
    /// changed.
    SimSet,
    /// The simulated motor's defaults (`sim reset`); the PL does not run.
    SimReset,
    /// How long all six gate outputs have been off: the reply's `data` is
    /// the PL cycles since they went off (`u32::MAX`: one is on, or longer
    /// ago); the PL does not run.
    GatesOff,
    /// A write as [`Op::Write`] (the same PL cycles), which the guest does
    /// not wait for and the host does not answer: only to a writable
    /// register of the map, where the PL's response is OKAY whatever the
    /// value, so the guest knows the outcome, and the PL cycle after it
    /// ([`cycle_after_write`]). The guest runs on while the host runs the
    /// PL; the next request that waits sees every posted write done.
    PostedWrite,
    /// The reply to the last access again (PL cycle, boundaries since the
    /// last sync, cycles since the last boundary); the PL does not run.
    /// After a posted write: what a waiting write's reply would have said.
    State,
}

impl Op {
    fn code(self) -> u32 {
        match self {
            Op::Read => 1,
            Op::Write => 2,
            Op::Sync => 3,
            Op::SimSet => 4,
            Op::SimReset => 5,
            Op::GatesOff => 6,
            Op::PostedWrite => 7,
            Op::State => 8,
        }
    }
}

/// One request, guest to host.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Request {
    /// Operation.
    pub op: Op,
    /// Absolute byte address of the register (reads, writes).
    pub addr: u32,
    /// Value written (writes).
    pub data: u32,
    /// Guest time: A9 global-timer count (see the module doc).
    pub guest: u64,
}

/// Why a record was refused.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WireError {
    /// Unknown operation code.
    BadOp(u32),
    /// Unknown reply status.
    BadStatus(u32),
}

impl Request {
    /// The record on the wire.
    pub fn encode(&self) -> [u8; REQUEST_LEN] {
        let mut b = [0u8; REQUEST_LEN];
        b[0..4].copy_from_slice(&self.op.code().to_le_bytes());
        b[4..8].copy_from_slice(&self.addr.to_le_bytes());
        b[8..12].copy_from_slice(&self.data.to_le_bytes());
        b[16..24].copy_from_slice(&self.guest.to_le_bytes());
        b
    }

    /// Parses a record.
    pub fn decode(b: &[u8; REQUEST_LEN]) -> Result<Self, WireError> {
        let op = match u32_at(b, 0) {
            1 => Op::Read,
            2 => Op::Write,
            3 => Op::Sync,
            4 => Op::SimSet,
            5 => Op::SimReset,
            6 => Op::GatesOff,
            7 => Op::PostedWrite,
            8 => Op::State,
            x => return Err(WireError::BadOp(x)),
        };
        Ok(Self {
            op,
            addr: u32_at(b, 4),
            data: u32_at(b, 8),
            guest: u64_at(b, 16),
        })
    }
}

/// How the access ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Status {
    /// OKAY.
    Ok,
    /// The PL answered SLVERR.
    SlaveError,
    /// The host could not parse the request (nothing was done).
    BadRequest,
}

/// One reply, host to guest.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Reply {
    /// Response.
    pub status: Status,
    /// Data read (0 for writes and syncs).
    pub data: u32,
    /// Control-period boundaries crossed since the previous sync (PWM
    /// period starts in mode FOC-PWM, ADC average strobes otherwise).
    pub boundaries: u32,
    /// PL cycles since the last boundary (`u32::MAX`: none yet).
    pub since_boundary: u32,
    /// PL cycles since the release of reset, after the access.
    pub pl_cycles: u64,
}

impl Reply {
    /// The record on the wire.
    pub fn encode(&self) -> [u8; REPLY_LEN] {
        let mut b = [0u8; REPLY_LEN];
        let st: u32 = match self.status {
            Status::Ok => 0,
            Status::SlaveError => 1,
            Status::BadRequest => 2,
        };
        b[0..4].copy_from_slice(&st.to_le_bytes());
        b[4..8].copy_from_slice(&self.data.to_le_bytes());
        b[8..12].copy_from_slice(&self.boundaries.to_le_bytes());
        b[12..16].copy_from_slice(&self.since_boundary.to_le_bytes());
        b[16..24].copy_from_slice(&self.pl_cycles.to_le_bytes());
        b
    }

    /// Parses a record.
    pub fn decode(b: &[u8; REPLY_LEN]) -> Result<Self, WireError> {
        let status = match u32_at(b, 0) {
            0 => Status::Ok,
            1 => Status::SlaveError,
            2 => Status::BadRequest,
            x => return Err(WireError::BadStatus(x)),
        };
        Ok(Self {
            status,
            data: u32_at(b, 4),
            boundaries: u32_at(b, 8),
            since_boundary: u32_at(b, 12),
            pl_cycles: u64_at(b, 16),
        })
    }
}

fn u32_at(b: &[u8], i: usize) -> u32 {
    u32::from_le_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]])
}

fn u64_at(b: &[u8], i: usize) -> u64 {
    u64::from(u32_at(b, i)) | u64::from(u32_at(b, i + 4)) << 32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_write_is_served_at_its_stamp_never_backwards() {
        // Origin: guest 1,000 at PL cycle 50. Stamp 1,100 is cycle 150.
        assert_eq!(serve_cycle((1000, 50), 1100, 120), 150);
        assert_eq!(cycle_after_write((1000, 50), 1100, 120), 154);
        // The PL is already past the stamp: served at once.
        assert_eq!(cycle_after_write((1000, 50), 1100, 160), 164);
    }

    #[test]
    fn records_round_trip_and_have_the_documented_layout() {
        let r = Request {
            op: Op::Write,
            addr: 0x43C0_1004,
            data: 0xDEAD_BEEF,
            guest: 0x0102_0304_0506_0708,
        };
        let b = r.encode();
        // Hand-written layout: op 2, addr, data, 4 reserved zero bytes, guest.
        assert_eq!(&b[0..4], &[2, 0, 0, 0]);
        assert_eq!(&b[4..8], &[0x04, 0x10, 0xC0, 0x43]);
        assert_eq!(&b[8..12], &[0xEF, 0xBE, 0xAD, 0xDE]);
        assert_eq!(&b[12..16], &[0, 0, 0, 0]);
        assert_eq!(&b[16..24], &[8, 7, 6, 5, 4, 3, 2, 1]);
        assert_eq!(Request::decode(&b), Ok(r));
        let p = Reply {
            status: Status::SlaveError,
            data: 7,
            boundaries: 3,
            since_boundary: u32::MAX,
            pl_cycles: 1 << 40,
        };
        let b = p.encode();
        assert_eq!(&b[0..4], &[1, 0, 0, 0]);
        assert_eq!(&b[16..24], &[0, 0, 0, 0, 0, 1, 0, 0]);
        assert_eq!(Reply::decode(&b), Ok(p));
    }

    #[test]
    fn unknown_codes_are_refused() {
        let mut b = [0u8; REQUEST_LEN];
        b[0] = 9;
        assert_eq!(Request::decode(&b), Err(WireError::BadOp(9)));
        b[0] = 7;
        assert_eq!(Request::decode(&b).map(|r| r.op), Ok(Op::PostedWrite));
        let mut b = [0u8; REPLY_LEN];
        b[0] = 3;
        assert_eq!(Reply::decode(&b), Err(WireError::BadStatus(3)));
    }
}
