//! The CANopen node: one NMT slave with its SDO server, PDOs, SYNC
//! consumer, heartbeat producer and consumer, EMCY producer and CiA 402
//! drive state machine, behind three entry points: [`Node::on_frame`] for
//! every received frame, [`Node::on_sync`] for a SYNC (also reached
//! through `on_frame`), and [`Node::tick`] for time. Each returns the
//! frames to transmit, in order, as a bounded [`Frames`].
//!
//! The node owns the communication objects (0x1001, 0x1003, 0x1005,
//! 0x1014, 0x1016, 0x1017, the PDO parameters) and the CiA 402 objects
//! 0x6040, 0x6041, 0x605A, 0x6060, 0x6061 and 0x6502; every other object
//! (0x1000 device type, 0x1018 identity, the drive's values) belongs to
//! the [`Application`], whose dictionary the node consults last.

use crate::cia402::{Drive, Transition};
use crate::emcy::{self, Emcy};
use crate::frame::{CanFrame, Frames};
use crate::heartbeat::{Consumer, ConsumerError, Producer, CONSUMERS};
use crate::nmt::{Nmt, NmtEvent, NmtState, NMT_COB_ID};
use crate::od::{Abort, Access, DataType, Entry, ObjectDictionary};
use crate::pdo::Pdos;
use crate::sdo::{self, SdoServer};
use crate::sync::{self, SYNC_COB_ID};

/// What the node asks of the application beyond its objects.
pub trait Application: ObjectDictionary {
    /// A CiA 402 transition happened: carry out its action (power stage,
    /// drive function, quick stop, fault reaction).
    fn on_drive_transition(&mut self, _t: &Transition) {}
    /// NMT reset node: set the application's own objects to their
    /// power-on values (the node resets its communication objects itself).
    fn on_reset_application(&mut self) {}
}

/// How the node starts.
#[derive(Clone, Copy, Debug)]
pub struct Config {
    /// Node-ID, 1..=127.
    pub node_id: u8,
    /// 0x1017 at power-on and after reset communication, ms (0 = off).
    pub heartbeat_ms: u16,
    /// 0x6502 (see [`crate::cia402::supported_bit`]).
    pub supported_modes: u32,
    /// 0x6060 at power-on.
    pub initial_mode: i8,
    /// 0x605A at power-on (0..=8).
    pub quick_stop_option: i16,
}

/// The communication and drive objects the node owns.
#[derive(Clone, Debug)]
struct Comm {
    node: u8,
    pdos: Pdos,
    emcy: Emcy,
    producer: Producer,
    consumer: Consumer,
    drive: Drive,
}

const fn e(index: u16, sub: u8, dt: DataType, acc: Access) -> Entry {
    Entry::new(index, sub, dt, acc)
}

impl Comm {
    fn entry(&self, index: u16, sub: u8) -> Option<Result<Entry, Abort>> {
        use Access::*;
        use DataType::*;
        if let Some(r) = self.pdos.entry(index, sub) {
            return Some(r);
        }
        let found = match (index, sub) {
            (0x1001, 0) => e(index, sub, Unsigned8, Ro).mappable(),
            (0x1003, 0) => e(index, sub, Unsigned8, Rw),
            (0x1003, 1..=8) => e(index, sub, Unsigned32, Ro),
            (0x1005, 0) => e(index, sub, Unsigned32, Const),
            (0x1014, 0) => e(index, sub, Unsigned32, Const),
            (0x1016, 0) => e(index, sub, Unsigned8, Const),
            (0x1016, 1..=4) => e(index, sub, Unsigned32, Rw),
            (0x1017, 0) => e(index, sub, Unsigned16, Rw),
            (0x6040, 0) => e(index, sub, Unsigned16, Rw).mappable(),
            (0x6041, 0) => e(index, sub, Unsigned16, Ro).mappable(),
            (0x605A, 0) => e(index, sub, Integer16, Rw).range(0, 8),
            (0x6060, 0) => e(index, sub, Integer8, Rw).mappable(),
            (0x6061, 0) => e(index, sub, Integer8, Ro).mappable(),
            (0x6502, 0) => e(index, sub, Unsigned32, Ro),
            (0x1001 | 0x1003 | 0x1005 | 0x1014 | 0x1016 | 0x1017, _)
            | (0x6040 | 0x6041 | 0x605A | 0x6060 | 0x6061 | 0x6502, _) => {
                return Some(Err(Abort::SubindexDoesNotExist))
            }
            _ => return None,
        };
        Some(Ok(found))
    }

    fn read(&self, index: u16, sub: u8, out: &mut [u8]) -> Result<usize, Abort> {
        let mut put = |b: &[u8]| {
            out.get_mut(..b.len())
                .ok_or(Abort::General)?
                .copy_from_slice(b);
            Ok(b.len())
        };
        let d = &self.drive;
        match (index, sub) {
            (0x1001, 0) => put(&[self.emcy.register()]),
            (0x1003, 0) => put(&[self.emcy.count()]),
            (0x1003, n) => put(&self.emcy.history(n).ok_or(Abort::NoData)?.to_le_bytes()),
            (0x1005, 0) => put(&(SYNC_COB_ID as u32).to_le_bytes()),
            (0x1014, 0) => put(&(emcy::cob_id(self.node) as u32).to_le_bytes()),
            (0x1016, 0) => put(&[CONSUMERS as u8]),
            (0x1016, n) => put(&self.consumer.entry(n).ok_or(Abort::General)?.to_le_bytes()),
            (0x1017, 0) => put(&self.producer.period_ms().to_le_bytes()),
            (0x6040, 0) => put(&d.controlword_value().to_le_bytes()),
            (0x6041, 0) => put(&d.statusword().to_le_bytes()),
            (0x605A, 0) => put(&d.quick_stop_option().to_le_bytes()),
            (0x6060, 0) => put(&d.mode().to_le_bytes()),
            (0x6061, 0) => put(&d.mode_display().to_le_bytes()),
            (0x6502, 0) => put(&d.supported_modes().to_le_bytes()),
            _ => self.pdos.read(index, sub, out),
        }
    }
}

/// The node's dictionary as SDO and PDO see it: the node's objects first,
/// then the application's.
struct Dict<'a, A: Application + ?Sized> {
    comm: &'a mut Comm,
    app: &'a mut A,
}

impl<A: Application + ?Sized> ObjectDictionary for Dict<'_, A> {
    fn entry(&self, index: u16, sub: u8) -> Result<Entry, Abort> {
        match self.comm.entry(index, sub) {
            Some(r) => r,
            None => self.app.entry(index, sub),
        }
    }

    fn read(&mut self, index: u16, sub: u8, out: &mut [u8]) -> Result<usize, Abort> {
        match self.comm.entry(index, sub) {
            Some(_) => self.comm.read(index, sub, out),
            None => self.app.read(index, sub, out),
        }
    }

    fn write(&mut self, index: u16, sub: u8, data: &[u8]) -> Result<(), Abort> {
        if self.comm.entry(index, sub).is_none() {
            return self.app.write(index, sub, data);
        }
        let mut b = [0u8; 4];
        let k = data.len().min(4);
        b[..k].copy_from_slice(&data[..k]);
        let v = u32::from_le_bytes(b);
        let c = &mut *self.comm;
        match (index, sub) {
            (0x1003, 0) => {
                if v != 0 {
                    return Err(Abort::ValueRange);
                }
                c.emcy.clear_history();
                Ok(())
            }
            (0x1016, n) => c.consumer.set_entry(n, v).map_err(|e| match e {
                ConsumerError::Duplicate => Abort::ParameterIncompatible,
                ConsumerError::NoSuchEntry => Abort::SubindexDoesNotExist,
            }),
            (0x1017, 0) => {
                c.producer.set_period_ms(v as u16);
                Ok(())
            }
            (0x6040, 0) => {
                let out = c.drive.controlword(v as u16);
                for t in out.iter() {
                    self.app.on_drive_transition(t);
                }
                Ok(())
            }
            (0x605A, 0) => c.drive.set_quick_stop_option(v as u16 as i16),
            (0x6060, 0) => c.drive.set_mode(v as u8 as i8),
            _ => {
                let target = Pdos::mapping_target(index, sub, data).map(|m| {
                    let d: &Self = self;
                    d.entry(m.index, m.sub)
                });
                self.comm.pdos.write(index, sub, data, target)
            }
        }
    }
}

/// A CANopen slave node with the CiA 402 drive profile.
#[derive(Clone, Debug)]
pub struct Node {
    nmt: Nmt,
    sdo: SdoServer,
    comm: Comm,
    pdo_defaults: Pdos,
    heartbeat_default: u16,
    now_us: u64,
}

impl Node {
    /// A node in NMT Initialising and CiA 402 Not ready to switch on;
    /// `None` when the node-ID is outside 1..=127. `pdos` are the PDO
    /// settings at power-on and after reset communication (start from
    /// [`Pdos::new`]).
    pub fn new(config: Config, pdos: Pdos) -> Option<Self> {
        if !(1..=127).contains(&config.node_id) {
            return None;
        }
        Some(Self {
            nmt: Nmt::new(config.node_id),
            sdo: SdoServer::new(),
            comm: Comm {
                node: config.node_id,
                pdos,
                emcy: Emcy::new(),
                producer: Producer::new(config.heartbeat_ms),
                consumer: Consumer::new(),
                drive: Drive::new(
                    config.supported_modes,
                    config.initial_mode,
                    config.quick_stop_option,
                ),
            },
            pdo_defaults: pdos,
            heartbeat_default: config.heartbeat_ms,
            now_us: 0,
        })
    }

    /// The node-ID.
    pub fn id(&self) -> u8 {
        self.comm.node
    }

    /// The NMT state.
    pub fn nmt_state(&self) -> NmtState {
        self.nmt.state()
    }

    /// The CiA 402 drive, for its state and statusword inputs.
    pub fn drive(&self) -> &Drive {
        &self.comm.drive
    }

    /// The drive's statusword inputs (voltage, warning, target reached,
    /// ...). Controlwords go through the dictionary (SDO, RPDO) or
    /// [`Node::controlword`], so that the application hears of transitions.
    pub fn drive_inputs(&mut self) -> &mut Drive {
        &mut self.comm.drive
    }

    /// The PDOs.
    pub fn pdos(&self) -> &Pdos {
        &self.comm.pdos
    }

    /// The EMCY state (error register, history).
    pub fn emcy(&self) -> &Emcy {
        &self.comm.emcy
    }

    /// Ends initialisation: NMT boot-up (the boot-up frame), pre-operational.
    pub fn boot(&mut self) -> Frames {
        let mut out = Frames::new();
        out.push(self.nmt.boot());
        out
    }

    fn notify<A: Application + ?Sized>(app: &mut A, t: Option<Transition>) {
        if let Some(t) = t {
            app.on_drive_transition(&t);
        }
    }

    /// CiA 402 transition 1: the drive's own initialisation ended.
    pub fn drive_initialised<A: Application + ?Sized>(&mut self, app: &mut A) {
        Self::notify(app, self.comm.drive.initialised());
    }

    /// A drive fault: CiA 402 transition 13 and an EMCY with `code` (e.g.
    /// from CiA 402-2's error code list), `register_bits` ORed into 0x1001.
    pub fn drive_fault<A: Application + ?Sized>(
        &mut self,
        app: &mut A,
        code: u16,
        register_bits: u8,
        mfr: [u8; 5],
    ) -> Frames {
        Self::notify(app, self.comm.drive.fault());
        self.emergency(code, register_bits, mfr)
    }

    /// CiA 402 transition 14.
    pub fn fault_reaction_complete<A: Application + ?Sized>(&mut self, app: &mut A) {
        Self::notify(app, self.comm.drive.fault_reaction_complete());
    }

    /// CiA 402 transition 12 after a quick stop (option codes 0..=4).
    pub fn quick_stop_complete<A: Application + ?Sized>(&mut self, app: &mut A) {
        Self::notify(app, self.comm.drive.quick_stop_complete());
    }

    /// Writes the controlword locally, as an SDO or RPDO write would.
    pub fn controlword<A: Application + ?Sized>(&mut self, app: &mut A, value: u16) {
        for t in self.comm.drive.controlword(value).iter() {
            app.on_drive_transition(t);
        }
    }

    /// Records an error in 0x1001/0x1003 and returns its EMCY frame when
    /// NMT allows EMCY (pre-operational, operational).
    pub fn emergency(&mut self, code: u16, register_bits: u8, mfr: [u8; 5]) -> Frames {
        let mut out = Frames::new();
        let f = self
            .comm
            .emcy
            .raise(self.comm.node, code, register_bits, mfr);
        if self.nmt.state().sync_emcy_allowed() {
            out.push(f);
        }
        out
    }

    /// Clears the error register and returns the error-reset EMCY
    /// (code 0x0000) when NMT allows EMCY.
    pub fn clear_errors(&mut self) -> Frames {
        let mut out = Frames::new();
        let f = self.comm.emcy.reset(self.comm.node);
        if self.nmt.state().sync_emcy_allowed() {
            out.push(f);
        }
        out
    }

    /// Marks an application event for TPDO `n` (0..=3).
    pub fn trigger_tpdo(&mut self, n: usize) {
        self.comm.pdos.trigger(n);
    }

    fn reset_communication(&mut self) {
        self.comm.pdos = self.pdo_defaults;
        self.comm.pdos.clear_runtime();
        self.comm.producer = Producer::new(self.heartbeat_default);
        self.comm.consumer = Consumer::new();
        self.sdo.reset();
    }

    /// Handles one received frame.
    pub fn on_frame<A: Application + ?Sized>(&mut self, frame: &CanFrame, app: &mut A) -> Frames {
        let mut out = Frames::new();
        let node = self.comm.node;
        let id = frame.id();
        let state = self.nmt.state();
        if id == NMT_COB_ID {
            match self.nmt.on_command(frame.data()) {
                Some(NmtEvent::StateChanged(s)) => {
                    self.comm.pdos.clear_runtime();
                    if s == NmtState::Stopped {
                        self.sdo.reset();
                    }
                }
                Some(NmtEvent::ResetNode) => {
                    app.on_reset_application();
                    self.reset_communication();
                    out.push(self.nmt.boot());
                }
                Some(NmtEvent::ResetCommunication) => {
                    self.reset_communication();
                    out.push(self.nmt.boot());
                }
                None => {}
            }
            return out;
        }
        if id == SYNC_COB_ID {
            if let Some(s) = sync::decode(frame.data()) {
                return self.on_sync(s.counter, app);
            }
            return out;
        }
        if id == sdo::request_cob_id(node) {
            if state.sdo_allowed() {
                let mut dict = Dict {
                    comm: &mut self.comm,
                    app,
                };
                if let Some(resp) = self.sdo.handle(frame.data(), &mut dict) {
                    out.push(CanFrame::full(sdo::response_cob_id(node), resp));
                }
            }
            return out;
        }
        if (0x701..=0x77F).contains(&id) {
            if state != NmtState::Initialising && frame.data().len() == 1 {
                self.comm
                    .consumer
                    .on_heartbeat((id - 0x700) as u8, self.now_us);
            }
            return out;
        }
        if state.pdo_allowed() {
            if let Some(n) = self.comm.pdos.rpdo_for(id) {
                let mut pdos = self.comm.pdos;
                let r = pdos.on_rpdo(
                    n,
                    frame.data(),
                    &mut Dict {
                        comm: &mut self.comm,
                        app,
                    },
                );
                self.merge_rx_runtime(pdos);
                if r.is_err() {
                    return self.emergency(
                        emcy::code::PDO_LENGTH,
                        emcy::register::COMMUNICATION,
                        [0; 5],
                    );
                }
            }
        }
        out
    }

    /// Takes back the PDOs after working on a copy of them while the
    /// dictionary (which contains them) was lent out. Writes through an
    /// RPDO never reach PDO parameters (they are not mappable), so the
    /// copy is the new state.
    fn merge_rx_runtime(&mut self, worked: Pdos) {
        self.comm.pdos = worked;
    }

    /// A SYNC (counter byte if any): applies the synchronous RPDOs received
    /// since the last one, then returns the TPDOs due. Nothing outside
    /// operational.
    pub fn on_sync<A: Application + ?Sized>(
        &mut self,
        _counter: Option<u8>,
        app: &mut A,
    ) -> Frames {
        let mut out = Frames::new();
        if !self.nmt.state().pdo_allowed() {
            return out;
        }
        let mut pdos = self.comm.pdos;
        pdos.on_sync_rx(&mut Dict {
            comm: &mut self.comm,
            app,
        });
        self.merge_rx_runtime(pdos);
        let due = self.comm.pdos.on_sync_tx();
        self.send_tpdos(due, app, &mut out);
        out
    }

    fn send_tpdos<A: Application + ?Sized>(&mut self, due: u8, app: &mut A, out: &mut Frames) {
        for n in 0..crate::pdo::PDOS {
            if due & (1 << n) == 0 {
                continue;
            }
            let pdos = self.comm.pdos;
            let packed = pdos.pack(
                n,
                &mut Dict {
                    comm: &mut self.comm,
                    app,
                },
            );
            if let Some((id, data, len)) = packed {
                if let Some(f) = CanFrame::new(id, &data[..len]) {
                    out.push(f);
                }
            }
        }
    }

    /// Time passes (microseconds, monotonic): heartbeat production, heartbeat
    /// consumer timeouts (EMCY 0x8130, communication error), event-driven
    /// TPDOs.
    pub fn tick<A: Application + ?Sized>(&mut self, now_us: u64, app: &mut A) -> Frames {
        self.now_us = now_us;
        let mut out = Frames::new();
        let state = self.nmt.state();
        if state == NmtState::Initialising {
            return out;
        }
        if self.comm.producer.tick(now_us) {
            if let Some(f) = CanFrame::new(0x700 + self.comm.node as u16, &[state.heartbeat_byte()])
            {
                out.push(f);
            }
        }
        while let Some(_lost) = self.comm.consumer.tick(now_us) {
            let f = self.comm.emcy.raise(
                self.comm.node,
                emcy::code::HEARTBEAT,
                emcy::register::COMMUNICATION,
                [0; 5],
            );
            if state.sync_emcy_allowed() {
                out.push(f);
            }
        }
        if state.pdo_allowed() {
            let due = self.comm.pdos.tick(now_us);
            self.send_tpdos(due, app, &mut out);
        }
        out
    }

    /// The description of (index, sub) as SDO and PDO see it: the node's
    /// own objects first, then the application's (for an EDS and local
    /// tools).
    pub fn entry<A: Application + ?Sized>(
        &self,
        app: &A,
        index: u16,
        sub: u8,
    ) -> Result<Entry, Abort> {
        match self.comm.entry(index, sub) {
            Some(r) => r,
            None => app.entry(index, sub),
        }
    }

    /// Reads an object as an SDO upload would (for local tools and tests).
    pub fn read<A: Application + ?Sized>(
        &mut self,
        app: &mut A,
        index: u16,
        sub: u8,
        out: &mut [u8],
    ) -> Result<usize, Abort> {
        crate::od::read_checked(
            &mut Dict {
                comm: &mut self.comm,
                app,
            },
            index,
            sub,
            out,
        )
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::cia402::mode;
    use crate::od::testod::TestOd;
    use crate::pdo::{Dir, Mapped};
    use std::vec::Vec;

    /// The test dictionary plus a log of the transitions the node reported.
    #[derive(Default)]
    struct App {
        od: TestOd,
        transitions: Vec<u8>,
        resets: usize,
    }

    impl ObjectDictionary for App {
        fn entry(&self, index: u16, sub: u8) -> Result<Entry, Abort> {
            self.od.entry(index, sub)
        }
        fn read(&mut self, index: u16, sub: u8, out: &mut [u8]) -> Result<usize, Abort> {
            self.od.read(index, sub, out)
        }
        fn write(&mut self, index: u16, sub: u8, data: &[u8]) -> Result<(), Abort> {
            self.od.write(index, sub, data)
        }
    }

    impl Application for App {
        fn on_drive_transition(&mut self, t: &Transition) {
            self.transitions.push(t.number);
        }
        fn on_reset_application(&mut self) {
            self.resets += 1;
        }
    }

    const NODE: u8 = 0x05;

    fn config() -> Config {
        Config {
            node_id: NODE,
            heartbeat_ms: 0,
            // CSP, CSV, CST: bits 7, 8, 9 = 0x0380.
            supported_modes: 0x0380,
            initial_mode: mode::CYCLIC_SYNC_POSITION,
            quick_stop_option: 2,
        }
    }

    fn booted() -> (Node, App) {
        let mut n = Node::new(config(), Pdos::new(NODE)).unwrap();
        let mut app = App::default();
        n.boot();
        n.drive_initialised(&mut app);
        (n, app)
    }

    fn f(id: u16, d: &[u8]) -> CanFrame {
        CanFrame::new(id, d).unwrap()
    }

    fn list(fs: &Frames) -> Vec<(u16, Vec<u8>)> {
        fs.iter().map(|f| (f.id(), f.data().to_vec())).collect()
    }

    /// One SDO request to node 5 (0x605), its response data (0x585).
    fn sdo(n: &mut Node, app: &mut App, req: [u8; 8]) -> Option<[u8; 8]> {
        let out = n.on_frame(&f(0x605, &req), app);
        assert!(out.len() <= 1);
        out.iter().next().map(|r| {
            assert_eq!(r.id(), 0x585);
            let mut b = [0u8; 8];
            b.copy_from_slice(r.data());
            b
        })
    }

    fn ok_download(index: u16, sub: u8) -> [u8; 8] {
        let i = index.to_le_bytes();
        [0x60, i[0], i[1], sub, 0, 0, 0, 0]
    }

    fn abort(index: u16, sub: u8, code: u32) -> [u8; 8] {
        let i = index.to_le_bytes();
        let c = code.to_le_bytes();
        [0x80, i[0], i[1], sub, c[0], c[1], c[2], c[3]]
    }

    #[test]
    fn node_id_range() {
        let mut c = config();
        c.node_id = 0;
        assert!(Node::new(c, Pdos::new(0)).is_none());
        c.node_id = 128;
        assert!(Node::new(c, Pdos::new(0)).is_none());
        c.node_id = 127;
        assert!(Node::new(c, Pdos::new(127)).is_some());
    }

    #[test]
    fn boot_up_and_heartbeat() {
        let mut n = Node::new(config(), Pdos::new(NODE)).unwrap();
        let mut app = App::default();
        // Nothing is served while initialising.
        assert!(sdo(&mut n, &mut app, [0x40, 0x00, 0x10, 0, 0, 0, 0, 0]).is_none());
        assert!(n.tick(0, &mut app).is_empty());
        // CiA 301 §7.2.8: boot-up 0x705 [00].
        assert_eq!(list(&n.boot()), [(0x705, vec![0x00])]);
        // 0x1017 = 100 ms: 0x2B 17 10 00 64 00.
        assert_eq!(
            sdo(&mut n, &mut app, [0x2B, 0x17, 0x10, 0, 0x64, 0, 0, 0]),
            Some(ok_download(0x1017, 0))
        );
        // Pre-operational: state byte 0x7F.
        assert_eq!(list(&n.tick(1_000, &mut app)), [(0x705, vec![0x7F])]);
        assert!(n.tick(100_999, &mut app).is_empty());
        n.on_frame(&f(0x000, &[0x02, NODE]), &mut app);
        assert_eq!(list(&n.tick(101_000, &mut app)), [(0x705, vec![0x04])]);
        n.on_frame(&f(0x000, &[0x01, 0]), &mut app);
        assert_eq!(list(&n.tick(201_000, &mut app)), [(0x705, vec![0x05])]);
    }

    #[test]
    fn nmt_gates_sdo_and_pdo() {
        let mut app = App::default();
        // RPDO1 on 0x205: 0x2000 (INTEGER16); TPDO1 on 0x185: 0x6041, type 1.
        let mut pdos = Pdos::new(NODE);
        pdos.configure(
            Dir::Rx,
            0,
            255,
            &[Mapped {
                index: 0x2000,
                sub: 0,
                bits: 16,
            }],
        );
        pdos.configure(
            Dir::Tx,
            0,
            1,
            &[Mapped {
                index: 0x6041,
                sub: 0,
                bits: 16,
            }],
        );
        let mut n = Node::new(config(), pdos).unwrap();
        n.boot();
        n.drive_initialised(&mut app);
        // Pre-operational: SDO yes, PDO no.
        assert!(sdo(&mut n, &mut app, [0x40, 0x00, 0x10, 0, 0, 0, 0, 0]).is_some());
        n.on_frame(&f(0x205, &[0x10, 0x00]), &mut app);
        assert_eq!(app.od.i16_2000, 0);
        assert!(n.on_frame(&f(0x080, &[]), &mut app).is_empty());
        // Operational: both. Statusword Switch on disabled + remote = 0x0240.
        n.on_frame(&f(0x000, &[0x01, NODE]), &mut app);
        n.on_frame(&f(0x205, &[0x10, 0x00]), &mut app);
        assert_eq!(app.od.i16_2000, 16);
        assert_eq!(
            list(&n.on_frame(&f(0x080, &[]), &mut app)),
            [(0x185, vec![0x40, 0x02])]
        );
        // Stopped: neither; the SDO request gets no answer at all.
        n.on_frame(&f(0x000, &[0x02, NODE]), &mut app);
        assert!(sdo(&mut n, &mut app, [0x40, 0x00, 0x10, 0, 0, 0, 0, 0]).is_none());
        n.on_frame(&f(0x205, &[0x20, 0x00]), &mut app);
        assert_eq!(app.od.i16_2000, 16);
        assert!(n.on_frame(&f(0x080, &[]), &mut app).is_empty());
        // Back to pre-operational: SDO again.
        n.on_frame(&f(0x000, &[0x80, 0]), &mut app);
        assert!(sdo(&mut n, &mut app, [0x40, 0x00, 0x10, 0, 0, 0, 0, 0]).is_some());
    }

    #[test]
    fn drive_through_sdo() {
        let (mut n, mut app) = booted();
        assert_eq!(app.transitions, [1]);
        // 0x6040 = 0x0006, 0x0007, 0x000F (0x2B: two bytes).
        for cw in [0x06u8, 0x07, 0x0F] {
            assert_eq!(
                sdo(&mut n, &mut app, [0x2B, 0x40, 0x60, 0, cw, 0, 0, 0]),
                Some(ok_download(0x6040, 0))
            );
        }
        assert_eq!(app.transitions, [1, 2, 3, 4]);
        // 0x6041 upload: 0x4B, 0x0227 (Operation enabled + remote).
        assert_eq!(
            sdo(&mut n, &mut app, [0x40, 0x41, 0x60, 0, 0, 0, 0, 0]),
            Some([0x4B, 0x41, 0x60, 0, 0x27, 0x02, 0, 0])
        );
        // 0x6041 is read-only.
        assert_eq!(
            sdo(&mut n, &mut app, [0x2B, 0x41, 0x60, 0, 0, 0, 0, 0]),
            Some(abort(0x6041, 0, 0x0601_0002))
        );
        // 0x6060 = 9 (CSV, 0x2F one byte): 0x6061 follows.
        assert_eq!(
            sdo(&mut n, &mut app, [0x2F, 0x60, 0x60, 0, 9, 0, 0, 0]),
            Some(ok_download(0x6060, 0))
        );
        assert_eq!(
            sdo(&mut n, &mut app, [0x40, 0x61, 0x60, 0, 0, 0, 0, 0]),
            Some([0x4F, 0x61, 0x60, 0, 9, 0, 0, 0])
        );
        // Profile position (1) is not in 0x6502 = 0x0380: 0x0609 0030.
        assert_eq!(
            sdo(&mut n, &mut app, [0x2F, 0x60, 0x60, 0, 1, 0, 0, 0]),
            Some(abort(0x6060, 0, 0x0609_0030))
        );
        assert_eq!(
            sdo(&mut n, &mut app, [0x40, 0x61, 0x60, 0, 0, 0, 0, 0]),
            Some([0x4F, 0x61, 0x60, 0, 9, 0, 0, 0])
        );
        // 0x6502 upload: 0x43, 80 03 00 00.
        assert_eq!(
            sdo(&mut n, &mut app, [0x40, 0x02, 0x65, 0, 0, 0, 0, 0]),
            Some([0x43, 0x02, 0x65, 0, 0x80, 0x03, 0, 0])
        );
        // 0x605A = 9 is above its range 0..=8: 0x0609 0031.
        assert_eq!(
            sdo(&mut n, &mut app, [0x2B, 0x5A, 0x60, 0, 9, 0, 0, 0]),
            Some(abort(0x605A, 0, 0x0609_0031))
        );
        // Fault: transition 13, EMCY 0x85: 10 23 | register 0x23 (generic,
        // current, device profile) | manufacturer bytes.
        let out = n.drive_fault(&mut app, 0x2310, 0x22, [1, 2, 3, 4, 5]);
        assert_eq!(list(&out), [(0x085, vec![0x10, 0x23, 0x23, 1, 2, 3, 4, 5])]);
        n.fault_reaction_complete(&mut app);
        // Statusword Fault + remote = 0x0208.
        assert_eq!(
            sdo(&mut n, &mut app, [0x40, 0x41, 0x60, 0, 0, 0, 0, 0]),
            Some([0x4B, 0x41, 0x60, 0, 0x08, 0x02, 0, 0])
        );
        // Fault reset: 0x0080 after 0x000F.
        sdo(&mut n, &mut app, [0x2B, 0x40, 0x60, 0, 0x80, 0, 0, 0]);
        assert_eq!(app.transitions, [1, 2, 3, 4, 13, 14, 15]);
        // 0x1001, 0x1003: one error, code 0x2310 with mfr bytes 01 02.
        assert_eq!(
            sdo(&mut n, &mut app, [0x40, 0x01, 0x10, 0, 0, 0, 0, 0]),
            Some([0x4F, 0x01, 0x10, 0, 0x23, 0, 0, 0])
        );
        assert_eq!(
            sdo(&mut n, &mut app, [0x40, 0x03, 0x10, 0, 0, 0, 0, 0]),
            Some([0x4F, 0x03, 0x10, 0, 1, 0, 0, 0])
        );
        assert_eq!(
            sdo(&mut n, &mut app, [0x40, 0x03, 0x10, 1, 0, 0, 0, 0]),
            Some([0x43, 0x03, 0x10, 1, 0x10, 0x23, 0x01, 0x02])
        );
        assert_eq!(
            sdo(&mut n, &mut app, [0x40, 0x03, 0x10, 2, 0, 0, 0, 0]),
            Some(abort(0x1003, 2, 0x0800_0024))
        );
        assert_eq!(
            sdo(&mut n, &mut app, [0x2F, 0x03, 0x10, 0, 1, 0, 0, 0]),
            Some(abort(0x1003, 0, 0x0609_0030))
        );
        assert_eq!(
            sdo(&mut n, &mut app, [0x2F, 0x03, 0x10, 0, 0, 0, 0, 0]),
            Some(ok_download(0x1003, 0))
        );
        assert_eq!(
            sdo(&mut n, &mut app, [0x40, 0x03, 0x10, 0, 0, 0, 0, 0]),
            Some([0x4F, 0x03, 0x10, 0, 0, 0, 0, 0])
        );
        // Error reset EMCY: 0x85, all zero.
        assert_eq!(list(&n.clear_errors()), [(0x085, vec![0; 8])]);
    }

    #[test]
    fn remap_over_sdo_then_cyclic_exchange() {
        let (mut n, mut app) = booted();
        let steps: &[([u8; 8], [u8; 8])] = &[
            // RPDO1 0x1400: COB-ID 0x8000_0205 (not valid).
            (
                [0x23, 0x00, 0x14, 1, 0x05, 0x02, 0, 0x80],
                ok_download(0x1400, 1),
            ),
            // 0x1600 sub 0 = 0; sub 1 = 0x6040_0010; sub 2 = 0x6060_0008; sub 0 = 2.
            ([0x2F, 0x00, 0x16, 0, 0, 0, 0, 0], ok_download(0x1600, 0)),
            (
                [0x23, 0x00, 0x16, 1, 0x10, 0x00, 0x40, 0x60],
                ok_download(0x1600, 1),
            ),
            (
                [0x23, 0x00, 0x16, 2, 0x08, 0x00, 0x60, 0x60],
                ok_download(0x1600, 2),
            ),
            ([0x2F, 0x00, 0x16, 0, 2, 0, 0, 0], ok_download(0x1600, 0)),
            // Transmission type 1 (synchronous), then valid: 0x0000_0205.
            ([0x2F, 0x00, 0x14, 2, 1, 0, 0, 0], ok_download(0x1400, 2)),
            (
                [0x23, 0x00, 0x14, 1, 0x05, 0x02, 0, 0],
                ok_download(0x1400, 1),
            ),
            // TPDO1: 0x1800 not valid, 0x1A00 = 0x6041_0010, 0x6061_0008.
            (
                [0x23, 0x00, 0x18, 1, 0x85, 0x01, 0, 0x80],
                ok_download(0x1800, 1),
            ),
            ([0x2F, 0x00, 0x1A, 0, 0, 0, 0, 0], ok_download(0x1A00, 0)),
            (
                [0x23, 0x00, 0x1A, 1, 0x10, 0x00, 0x41, 0x60],
                ok_download(0x1A00, 1),
            ),
            (
                [0x23, 0x00, 0x1A, 2, 0x08, 0x00, 0x61, 0x60],
                ok_download(0x1A00, 2),
            ),
            ([0x2F, 0x00, 0x1A, 0, 2, 0, 0, 0], ok_download(0x1A00, 0)),
            ([0x2F, 0x00, 0x18, 2, 1, 0, 0, 0], ok_download(0x1800, 2)),
            (
                [0x23, 0x00, 0x18, 1, 0x85, 0x01, 0, 0],
                ok_download(0x1800, 1),
            ),
            // Refusals: mapping a valid PDO (0x0601 0000); mapping 0x6502
            // (not mappable, 0x0604 0041); 0x1003 sub 0 into an RPDO
            // (0x0604 0041).
            (
                [0x2F, 0x00, 0x1A, 0, 0, 0, 0, 0],
                abort(0x1A00, 0, 0x0601_0000),
            ),
            (
                [0x23, 0x01, 0x1A, 1, 0x20, 0x00, 0x02, 0x65],
                abort(0x1A01, 1, 0x0604_0041),
            ),
            (
                [0x23, 0x01, 0x16, 1, 0x08, 0x00, 0x03, 0x10],
                abort(0x1601, 1, 0x0604_0041),
            ),
        ];
        for (req, resp) in steps {
            assert_eq!(sdo(&mut n, &mut app, *req), Some(*resp), "{req:02X?}");
        }
        n.on_frame(&f(0x000, &[0x01, NODE]), &mut app);
        // RPDO 0x205: controlword 0x0006, mode 10 (CST); applied at SYNC.
        assert!(n
            .on_frame(&f(0x205, &[0x06, 0x00, 0x0A]), &mut app)
            .is_empty());
        assert_eq!(app.transitions, [1]);
        // SYNC: RPDO applied first, then TPDO 0x185: statusword 0x0221
        // (Ready to switch on + remote), mode display 0x0A.
        assert_eq!(
            list(&n.on_frame(&f(0x080, &[]), &mut app)),
            [(0x185, vec![0x21, 0x02, 0x0A])]
        );
        assert_eq!(app.transitions, [1, 2]);
        // A short RPDO (2 < 3 bytes): EMCY 0x8210, register 0x11.
        assert_eq!(
            list(&n.on_frame(&f(0x205, &[0x07, 0x00]), &mut app)),
            [(0x085, vec![0x10, 0x82, 0x11, 0, 0, 0, 0, 0])]
        );
        // Reset communication: boot-up, PDOs back to the power-on defaults.
        assert_eq!(
            list(&n.on_frame(&f(0x000, &[0x82, NODE]), &mut app)),
            [(0x705, vec![0x00])]
        );
        assert_eq!(n.nmt_state(), NmtState::PreOperational);
        assert_eq!(
            sdo(&mut n, &mut app, [0x40, 0x00, 0x18, 1, 0, 0, 0, 0]),
            Some([0x43, 0x00, 0x18, 1, 0x85, 0x01, 0, 0x80])
        );
        // Reset node also resets the application.
        n.on_frame(&f(0x000, &[0x81, 0]), &mut app);
        assert_eq!(app.resets, 1);
    }

    #[test]
    fn heartbeat_consumer_emcy() {
        let (mut n, mut app) = booted();
        // 0x1016 sub 1 = node 0x07, 100 ms: 0x0007_0064.
        assert_eq!(
            sdo(
                &mut n,
                &mut app,
                [0x23, 0x16, 0x10, 1, 0x64, 0x00, 0x07, 0x00]
            ),
            Some(ok_download(0x1016, 1))
        );
        // The same node again in sub 2: 0x0604 0043.
        assert_eq!(
            sdo(
                &mut n,
                &mut app,
                [0x23, 0x16, 0x10, 2, 0xC8, 0x00, 0x07, 0x00]
            ),
            Some(abort(0x1016, 2, 0x0604_0043))
        );
        assert_eq!(
            sdo(&mut n, &mut app, [0x23, 0x16, 0x10, 5, 0, 0, 0, 0]),
            Some(abort(0x1016, 5, 0x0609_0011))
        );
        n.tick(1_000_000, &mut app);
        n.on_frame(&f(0x707, &[0x05]), &mut app);
        assert!(n.tick(1_100_000, &mut app).is_empty());
        // Late: EMCY 0x8130, register generic + communication = 0x11.
        assert_eq!(
            list(&n.tick(1_100_001, &mut app)),
            [(0x085, vec![0x30, 0x81, 0x11, 0, 0, 0, 0, 0])]
        );
        assert!(n.tick(1_200_000, &mut app).is_empty());
    }

    #[test]
    fn malformed_frames_change_nothing() {
        let (mut n, mut app) = booted();
        // NMT with 1 or 3 bytes, unknown specifier.
        for d in [&[0x01][..], &[0x01, NODE, 0], &[0x03, NODE]] {
            assert!(n.on_frame(&f(0x000, d), &mut app).is_empty());
            assert_eq!(n.nmt_state(), NmtState::PreOperational);
        }
        // SYNC with 2 bytes, heartbeat with 2 bytes, unknown identifiers.
        n.on_frame(&f(0x000, &[0x01, NODE]), &mut app);
        assert!(n.on_frame(&f(0x080, &[1, 2]), &mut app).is_empty());
        assert!(n.on_frame(&f(0x707, &[5, 5]), &mut app).is_empty());
        assert!(n.on_frame(&f(0x123, &[1, 2, 3]), &mut app).is_empty());
        // SDO with 3 bytes: abort 0x0504 0001 on 0x585.
        assert_eq!(
            list(&n.on_frame(&f(0x605, &[0x40, 0x00, 0x10]), &mut app)),
            [(0x585, vec![0x80, 0, 0, 0, 0x01, 0x00, 0x04, 0x05])]
        );
        // SDO to another node: not ours.
        assert!(n
            .on_frame(&f(0x606, &[0x40, 0, 0x10, 0, 0, 0, 0, 0]), &mut app)
            .is_empty());
        // Application objects are reached through the node.
        assert_eq!(
            sdo(&mut n, &mut app, [0x40, 0x00, 0x10, 0, 0, 0, 0, 0]),
            Some([0x43, 0x00, 0x10, 0, 0x92, 0x01, 0x02, 0x00])
        );
        assert_eq!(
            sdo(&mut n, &mut app, [0x40, 0x41, 0x60, 1, 0, 0, 0, 0]),
            Some(abort(0x6041, 1, 0x0609_0011))
        );
    }

    /// A small deterministic generator (64-bit LCG, Knuth's constants) for
    /// the robustness test.
    struct Lcg(u64);
    impl Lcg {
        fn next(&mut self) -> u32 {
            self.0 = self
                .0
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (self.0 >> 33) as u32
        }
    }

    #[test]
    fn random_frames_never_panic() {
        let mut pdos = Pdos::new(NODE);
        pdos.configure(
            Dir::Rx,
            0,
            1,
            &[Mapped {
                index: 0x6040,
                sub: 0,
                bits: 16,
            }],
        );
        pdos.configure(
            Dir::Tx,
            0,
            1,
            &[Mapped {
                index: 0x6041,
                sub: 0,
                bits: 16,
            }],
        );
        let mut n = Node::new(config(), pdos).unwrap();
        let mut app = App::default();
        n.boot();
        let mut rng = Lcg(1);
        let ids = [0x000, 0x080, 0x205, 0x605, 0x705, 0x707, 0x185, 0x7FF];
        for i in 0..50_000u64 {
            let id = ids[rng.next() as usize % ids.len()];
            let len = rng.next() as usize % 9;
            let mut d = [0u8; 8];
            for b in d.iter_mut() {
                *b = rng.next() as u8;
            }
            // Bias towards the node's own SDO command specifiers and
            // indices so that transfers get under way.
            if id == 0x605 && rng.next() % 2 == 0 {
                d[1] = [0x00, 0x03, 0x40, 0x00, 0x17][rng.next() as usize % 5];
                d[2] = [0x20, 0x60, 0x16, 0x1A, 0x10][rng.next() as usize % 5];
                d[3] = (rng.next() % 4) as u8;
            }
            // Keep NMT mostly operational so that PDOs are exercised.
            if id == 0x000 && rng.next() % 4 != 0 {
                d[0] = 0x01;
                d[1] = NODE;
            }
            let out = n.on_frame(&f(id, &d[..len]), &mut app);
            assert_eq!(out.dropped(), 0);
            n.tick(i * 100, &mut app);
        }
    }
}
