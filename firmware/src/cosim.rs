//! The PL as a co-simulation under QEMU: every register access travels
//! over semihosting to the host process `pl-cosim` (Verilated `pl_top` and
//! the plant, wire format `simpl::cosim`) and waits for its reply.
//!
//! Selected when semihosting answers and the host's command line for the
//! guest has `cosim=<dir>`: requests go to the FIFO `<dir>/req`, replies
//! come from `<dir>/rep` (opened in that order, as `pl-cosim` does).
//! Guest time is the global-timer count, one PL cycle per count under QEMU
//! (both 100 MHz; see `simpl::cosim`).
use crate::ps::timer;
use crate::semihosting::{self, HostFile};
use models::pmsm::sim_motor::{SimMotor, SimSetError, SIM_PARAMS};
use regmap::bus::{BusError, RegisterBus};
use simpl::cosim::{cycle_after_write, Op, Reply, Request, Status, REPLY_LEN, REQUEST_LEN};

/// Posted writes held back at most (then sent on their own). They go out
/// with the next request that waits, in the same `SYS_WRITE`: each
/// semihosting call costs QEMU more than a control step's instructions,
/// and the host serves the records in order whenever they arrive, at
/// their own stamps, so holding them changes no reply (the request stream
/// is the same, record for record). 16 records (384 bytes) stay below the
/// 4,096 bytes a FIFO writes at once, with the reads sent with them.
const HELD_MAX: usize = 16;

/// Reads sent in one round trip by `read_many` at most.
const READ_MANY_MAX: usize = 8;

/// The bridge to `pl-cosim`.
pub struct Cosim {
    req: HostFile,
    rep: HostFile,
    /// The last reply (PL time, boundaries). After a posted write only
    /// `pl_cycles` is brought up to date (exactly: `cycle_after_write`);
    /// [`Self::last_exact`] asks for the rest.
    pub last: Reply,
    /// `last` is from before a posted write.
    stale: bool,
    /// (guest time, PL cycle) of the first request, as the host maps time
    /// (`None` before it: writes wait then).
    origin: Option<(u64, u64)>,
    /// The simulated motor's parameters as the host was told them (it
    /// checks them with the same code).
    pub motor: SimMotor,
    /// Request records not yet sent: posted writes, then the request that
    /// sends them.
    out: [u8; (HELD_MAX + READ_MANY_MAX) * REQUEST_LEN],
    /// Bytes of `out` in use.
    held: usize,
    /// Register writes sent (posted or not), wrapping: a write may move
    /// the control-period boundaries (mode, ADC and PWM timing).
    pub writes: u32,
}

/// Counts per revolution of the bridge's simulated encoder
/// (`simpl::SimConfig`'s default).
const SIM_CPR: u32 = 4096;

/// The map's writable registers (RW and W1C), one bit per 32-bit word of
/// the GP0 window: the posted-write check in a few instructions (the
/// guest's time is the PL's, so a search through the map would lengthen
/// every register write's critical section).
const WRITABLE: [u32; regmap::BLOCKS.len() * regmap::BLOCK_SIZE / 128] = writable_words();

const fn writable_words() -> [u32; regmap::BLOCKS.len() * regmap::BLOCK_SIZE / 128] {
    let mut w = [0u32; regmap::BLOCKS.len() * regmap::BLOCK_SIZE / 128];
    let mut i = 0;
    while i < regmap::WRITABLE_COUNT {
        let word = (regmap::WRITABLE_ADDRS[i] - regmap::BASE_ADDR) / 4;
        w[word / 32] |= 1 << (word % 32);
        i += 1;
    }
    w
}

/// Longest `<dir>` accepted, bytes.
const DIR_MAX: usize = 200;

impl Cosim {
    /// Probes semihosting and opens the bridge named on the guest's command
    /// line; `None` (nothing touched but the probe) when either is missing.
    pub fn open() -> Option<Self> {
        if !semihosting::probe() {
            return None;
        }
        let mut line = [0u8; 256];
        let n = semihosting::cmdline(&mut line)?;
        let text = core::str::from_utf8(&line[..n]).ok()?;
        let dir = text
            .split_whitespace()
            .find_map(|w| w.strip_prefix("cosim="))?
            .trim_end_matches('\0');
        if dir.is_empty() || dir.len() > DIR_MAX {
            return None;
        }
        let path = |name: &[u8]| {
            let mut p = [0u8; DIR_MAX + 8];
            p[..dir.len()].copy_from_slice(dir.as_bytes());
            p[dir.len()] = b'/';
            p[dir.len() + 1..dir.len() + 1 + name.len()].copy_from_slice(name);
            (p, dir.len() + 1 + name.len() + 1)
        };
        let (p, n) = path(b"req\0");
        let req = HostFile::open(&p[..n], true)?;
        let (p, n) = path(b"rep\0");
        let rep = HostFile::open(&p[..n], false)?;
        let mut c = Self {
            req,
            rep,
            last: Reply {
                status: Status::Ok,
                data: 0,
                boundaries: 0,
                since_boundary: u32::MAX,
                pl_cycles: 0,
            },
            motor: SimMotor::default(),
            stale: false,
            origin: None,
            out: [0; (HELD_MAX + READ_MANY_MAX) * REQUEST_LEN],
            held: 0,
            writes: 0,
        };
        // The first request: the host's time origin, where the PL is.
        let guest = timer::global_count();
        let first = c.transact_at(Op::Sync, 0, 0, guest).ok()?;
        c.origin = Some((guest, first.pl_cycles));
        Some(c)
    }

    fn transact(&mut self, op: Op, addr: usize, data: u32) -> Result<Reply, BusError> {
        self.transact_at(op, addr, data, timer::global_count())
    }

    fn transact_at(
        &mut self,
        op: Op,
        addr: usize,
        data: u32,
        guest: u64,
    ) -> Result<Reply, BusError> {
        let r = Request {
            op,
            addr: addr as u32,
            data,
            guest,
        };
        let reply = self.round_trip(&r)?;
        self.last = reply;
        self.stale = false;
        match reply.status {
            Status::Ok => Ok(reply),
            Status::SlaveError | Status::BadRequest => Err(BusError::SlaveError),
        }
    }

    /// Sends the held posted writes and `r` in one host write, then waits
    /// for `r`'s reply.
    fn round_trip(&mut self, r: &Request) -> Result<Reply, BusError> {
        self.hold(r);
        let mut b = [0u8; REPLY_LEN];
        if !(self.flush() && self.rep.read_exact(&mut b)) {
            // The host went away: no PL answers any more.
            return Err(BusError::Absent);
        }
        Reply::decode(&b).map_err(|_| BusError::Absent)
    }

    /// Appends a record to the ones to send (room for `READ_MANY_MAX`
    /// more than `HELD_MAX` posted writes is always left).
    fn hold(&mut self, r: &Request) {
        self.out[self.held..self.held + REQUEST_LEN].copy_from_slice(&r.encode());
        self.held += REQUEST_LEN;
    }

    /// Sends the held records; false if the host could not take them.
    fn flush(&mut self) -> bool {
        let n = core::mem::take(&mut self.held);
        n == 0 || self.req.write_all(&self.out[..n])
    }

    /// `sim set`: checked here, then on the host; nothing changes when
    /// either refuses.
    pub fn sim_set(&mut self, name: &str, v: f64) -> Result<Result<(), SimSetError>, BusError> {
        let mut next = self.motor;
        if let Err(e) = next.set(name, v, SIM_CPR) {
            return Ok(Err(e));
        }
        let row = SIM_PARAMS.iter().position(|p| p.name == name).unwrap_or(0);
        self.sim_request(Op::SimSet, row, v.to_bits())?;
        self.motor = next;
        Ok(Ok(()))
    }

    /// `sim reset`.
    pub fn sim_reset(&mut self) -> Result<(), BusError> {
        self.sim_request(Op::SimReset, 0, 0)?;
        self.motor = SimMotor::default();
        Ok(())
    }

    /// PL cycle from which all six gate outputs have been off (`None`
    /// while one is on); the PL does not run.
    pub fn gates_off_since(&mut self) -> Result<Option<u64>, BusError> {
        let r = self.sim_request(Op::GatesOff, 0, 0)?;
        Ok((r.data != u32::MAX).then(|| r.pl_cycles - u64::from(r.data)))
    }

    fn sim_request(&mut self, op: Op, addr: usize, bits: u64) -> Result<Reply, BusError> {
        let r = Request {
            op,
            addr: addr as u32,
            data: 0,
            guest: bits,
        };
        let reply = self.round_trip(&r)?;
        match reply.status {
            Status::Ok => Ok(reply),
            Status::SlaveError | Status::BadRequest => Err(BusError::SlaveError),
        }
    }

    /// Runs the PL to now; the reply's boundaries are those since the
    /// previous sync.
    pub fn sync(&mut self) -> Result<Reply, BusError> {
        self.transact(Op::Sync, 0, 0)
    }

    /// The reply to the last access, also after a posted write (then the
    /// host is asked; the PL does not run).
    pub fn last_exact(&mut self) -> Result<Reply, BusError> {
        if self.stale {
            self.transact(Op::State, 0, 0)?;
        }
        Ok(self.last)
    }

    /// A write without waiting for the host (`Op::PostedWrite`, held and
    /// sent with the next request that waits), where its outcome is known: a writable register of the map answers OKAY to any
    /// value (a rejected value sets ERR.BAD_VALUE, as on the bus), in
    /// `WRITE_CYCLES` from its stamp. `None`: not postable (waits).
    fn post(&mut self, addr: usize, value: u32) -> Option<Result<(), BusError>> {
        let origin = self.origin?;
        let word = addr.checked_sub(regmap::BASE_ADDR)? / 4;
        if !addr.is_multiple_of(4) || WRITABLE.get(word / 32)? & (1 << (word % 32)) == 0 {
            return None;
        }
        let guest = timer::global_count();
        let r = Request {
            op: Op::PostedWrite,
            addr: addr as u32,
            data: value,
            guest,
        };
        self.hold(&r);
        if self.held >= HELD_MAX * REQUEST_LEN && !self.flush() {
            return Some(Err(BusError::Absent));
        }
        self.last.pl_cycles = cycle_after_write(origin, guest, self.last.pl_cycles);
        self.stale = true;
        Some(Ok(()))
    }
}

impl RegisterBus for Cosim {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        Ok(self.transact(Op::Read, addr, 0)?.data)
    }
    /// Reads sent together (with the held posted writes) under one stamp:
    /// the host serves them back to back from that cycle, each an ordinary
    /// `Op::Read` with its own reply, and sends the replies together. One
    /// round trip instead of one per register.
    fn read_many(&mut self, addrs: &[usize], out: &mut [u32]) -> Result<(), BusError> {
        let n = addrs.len().min(out.len()).min(READ_MANY_MAX);
        let guest = timer::global_count();
        for a in &addrs[..n] {
            self.hold(&Request {
                op: Op::Read,
                addr: *a as u32,
                data: 0,
                guest,
            });
        }
        let mut b = [0u8; READ_MANY_MAX * REPLY_LEN];
        if !(self.flush() && self.rep.read_exact(&mut b[..n * REPLY_LEN])) {
            return Err(BusError::Absent);
        }
        let mut first = Ok(());
        for (rec, o) in b[..n * REPLY_LEN]
            .chunks_exact(REPLY_LEN)
            .zip(out.iter_mut())
        {
            let mut r = [0u8; REPLY_LEN];
            r.copy_from_slice(rec);
            let reply = Reply::decode(&r).map_err(|_| BusError::Absent)?;
            self.last = reply;
            self.stale = false;
            *o = reply.data;
            if reply.status != Status::Ok {
                *o = 0;
                first = first.and(Err(BusError::SlaveError));
            }
        }
        // Longer lists than one round trip carries: the rest in another.
        if n < addrs.len().min(out.len()) {
            let rest = self.read_many(&addrs[n..], &mut out[n..]);
            first = first.and(rest);
        }
        first
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        self.writes = self.writes.wrapping_add(1);
        if let Some(r) = self.post(addr, value) {
            return r;
        }
        self.transact(Op::Write, addr, value).map(|_| ())
    }
}
