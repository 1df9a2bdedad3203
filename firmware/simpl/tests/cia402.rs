//! CiA 402 over CANopen on the simulated PL: a client's frames (NMT, SDO,
//! PDO, SYNC) go into the drive's node (`canopen::node::Node` with
//! `drive::fieldbus`'s dictionary), the axis glue carries the state
//! machine and the set-points to the servo, and the servo runs the
//! simulated motor. The bytes a client would send and expect are written
//! out by hand from CiA 301 and CiA 402.
use canopen::{CanFrame, Frames};
use drive::fieldbus::{ConfigValues, Link};
use drive::servo::sensors::PlTime;
use drive::servo::{Servo, ServoConfig};
use regmap::bus::{BusError, RegisterBus};
use simpl::{SimConfig, SimDrive};

const NODE: u8 = 1;

/// The simulated PL with its time under the drive's control (the sensor
/// check before the first enable waits on it).
struct Bus(SimDrive);

impl RegisterBus for Bus {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        self.0.read(addr)
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        self.0.write(addr, value)
    }
}

impl PlTime for Bus {
    fn wait_cycles(&mut self, cycles: u64) {
        let _ = self.0.advance(cycles);
    }
}

struct Bench {
    sim: Bus,
    servo: Servo,
    link: Link<ConfigValues>,
    /// Frames the drive sent, in order.
    sent: Vec<CanFrame>,
}

impl Bench {
    fn new(locked: bool) -> Self {
        let mut sim = SimDrive::new(&SimConfig::default()).unwrap();
        let cfg = ServoConfig::for_plant(sim.config().motor, sim.config().adc_amps_per_count);
        let mut servo = Servo::new(&cfg).unwrap();
        servo.init(&mut sim).unwrap();
        sim.sim_set("locked", if locked { 1.0 } else { 0.0 })
            .unwrap();
        let mut link = Link::new(NODE, ConfigValues::new(cfg)).unwrap();
        let sent = link.boot().iter().copied().collect();
        Self {
            sim: Bus(sim),
            servo,
            link,
            sent,
        }
    }

    fn keep(&mut self, f: Frames) -> Vec<CanFrame> {
        let v: Vec<CanFrame> = f.iter().copied().collect();
        self.sent.extend(v.iter().copied());
        v
    }

    /// One frame from the client; the drive's answers.
    fn frame(&mut self, id: u16, data: &[u8]) -> Vec<CanFrame> {
        let f = CanFrame::new(id, data).unwrap();
        let out = self
            .link
            .on_frame(&f, &mut self.servo, &mut self.sim)
            .unwrap();
        self.keep(out)
    }

    /// An expedited SDO download of `value` (1, 2 or 4 bytes); the answer.
    fn sdo_write(&mut self, index: u16, sub: u8, value: &[u8]) -> [u8; 8] {
        let cmd = match value.len() {
            1 => 0x2F,
            2 => 0x2B,
            4 => 0x23,
            n => panic!("{n} bytes"),
        };
        let i = index.to_le_bytes();
        let mut d = [cmd, i[0], i[1], sub, 0, 0, 0, 0];
        d[4..4 + value.len()].copy_from_slice(value);
        self.sdo(&d)
    }

    fn sdo_read(&mut self, index: u16, sub: u8) -> [u8; 8] {
        let i = index.to_le_bytes();
        self.sdo(&[0x40, i[0], i[1], sub, 0, 0, 0, 0])
    }

    fn sdo(&mut self, d: &[u8; 8]) -> [u8; 8] {
        let answers = self.frame(0x600 + u16::from(NODE), d);
        let r = answers
            .iter()
            .find(|f| f.id() == 0x580 + u16::from(NODE))
            .expect("an SDO answer");
        r.data().try_into().unwrap()
    }

    fn ok(&mut self, index: u16, sub: u8, value: &[u8]) {
        let i = index.to_le_bytes();
        assert_eq!(
            self.sdo_write(index, sub, value),
            [0x60, i[0], i[1], sub, 0, 0, 0, 0],
            "{index:#x}:{sub}"
        );
    }

    fn statusword(&mut self) -> u16 {
        let r = self.sdo_read(0x6041, 0);
        assert_eq!(r[0], 0x4B, "{r:?}");
        u16::from_le_bytes([r[4], r[5]])
    }

    /// The control period of the servo's present mode, PL cycles.
    fn period(&self) -> u64 {
        libm::round(f64::from(regmap::PL_CLOCK_HZ) / self.servo.control_rate_hz()) as u64
    }

    /// `n` control periods: the servo's step, then the axis's exchange.
    fn run(&mut self, n: u32) {
        let period = self.period();
        let dt = period as f64 / f64::from(regmap::PL_CLOCK_HZ);
        for _ in 0..n {
            self.sim.0.advance_to_boundary(2 * period);
            self.servo.control_step(&mut self.sim).unwrap();
            let out = self
                .link
                .boundary(&mut self.servo, &mut self.sim, dt)
                .unwrap();
            self.keep(out);
        }
    }

    fn periods_in(&self, s: f64) -> u32 {
        (s * f64::from(regmap::PL_CLOCK_HZ) / self.period() as f64).ceil() as u32
    }

    /// NMT start, the mode, then shutdown / switch on / enable operation.
    fn enable_operation_in(&mut self, mode: i8, torque_loop: u8) {
        assert!(self.frame(0x000, &[0x01, NODE]).is_empty());
        self.ok(0x2100, 0, &[torque_loop]);
        self.ok(0x6060, 0, &[mode as u8]);
        for cw in [0x06u16, 0x07, 0x0F] {
            self.ok(0x6040, 0, &cw.to_le_bytes());
        }
        // Operation enabled: xxxx xxxx x01x 0111.
        assert_eq!(self.statusword() & 0x6F, 0x27);
        assert!(self.servo.gates_on(&mut self.sim).unwrap());
    }
}

fn i16_at(r: &[u8; 8]) -> i16 {
    i16::from_le_bytes([r[4], r[5]])
}

#[test]
fn boot_up_and_the_state_machine_reach_the_gates() {
    let mut b = Bench::new(true);
    // Boot-up: 0x700 + node, one byte 0.
    assert_eq!(b.sent[0].id(), 0x701);
    assert_eq!(b.sent[0].data(), [0x00]);
    // Switch on disabled before anything: x0xx 0000 with bit 6.
    assert!(b.frame(0x000, &[0x80, NODE]).is_empty());
    assert_eq!(b.statusword() & 0x4F, 0x40);
    b.enable_operation_in(10, 1);
    // Disable voltage: gates off, switch on disabled.
    b.ok(0x6040, 0, &0x00u16.to_le_bytes());
    assert_eq!(b.statusword() & 0x4F, 0x40);
    assert!(!b.servo.gates_on(&mut b.sim).unwrap());
}

#[test]
fn cyclic_torque_on_a_locked_rotor_through_sdo() {
    let mut b = Bench::new(true);
    b.enable_operation_in(10, 1);
    // Past the MPDTC's rotor alignment.
    while b.servo.aligning_left_s().is_some() {
        b.run(100);
    }
    // 300 per mille of the rated 1 N m.
    b.ok(0x6071, 0, &300i16.to_le_bytes());
    let n = b.periods_in(0.01);
    b.run(n);
    assert!((b.servo.torque_ref_nm() - 0.3).abs() < 1e-12);
    let t = i16_at(&b.sdo_read(0x6077, 0));
    assert!((270..=330).contains(&t), "torque actual {t} per mille");
    // Beyond 0x6072 (here 200 per mille) the reference is held at it.
    b.ok(0x6072, 0, &200u16.to_le_bytes());
    b.run(1);
    assert!((b.servo.torque_ref_nm() - 0.2).abs() < 1e-12);
}

#[test]
fn a_fault_raises_an_emcy_and_a_fault_reset_clears_it() {
    let mut b = Bench::new(true);
    b.enable_operation_in(10, 0);
    b.ok(0x6071, 0, &500i16.to_le_bytes());
    b.run(200);
    b.sim.0.sim_set("phase_open", 2.0).unwrap();
    let before = b.sent.len();
    b.run(100);
    let emcy: Vec<&CanFrame> = b.sent[before..]
        .iter()
        .filter(|f| f.id() == 0x081)
        .collect();
    assert_eq!(emcy.len(), 1, "{:?}", &b.sent[before..]);
    // EMCY: error code 0x3130 (phase failure) LE, error register with
    // the generic bit, then the drive's fault bits (PHASE_OPEN, bit 9).
    assert_eq!(emcy[0].data()[..3], [0x30, 0x31, 0x01]);
    assert_eq!(emcy[0].data()[3..5], [0x00, 0x02]);
    // Fault: xxxx xxxx x0xx 1000.
    assert_eq!(b.statusword() & 0x4F, 0x08);
    assert_eq!(
        u16::from_le_bytes(b.sdo_read(0x603F, 0)[4..6].try_into().unwrap()),
        0x3130
    );
    assert!(!b.servo.gates_on(&mut b.sim).unwrap());
    // The phase back; fault reset (bit 7 rising): switch on disabled, the
    // error-reset EMCY (code 0).
    b.sim.0.sim_set("phase_open", 0.0).unwrap();
    let before = b.sent.len();
    b.ok(0x6040, 0, &0x80u16.to_le_bytes());
    assert_eq!(b.statusword() & 0x4F, 0x40);
    let reset: Vec<&CanFrame> = b.sent[before..]
        .iter()
        .filter(|f| f.id() == 0x081)
        .collect();
    assert_eq!(reset.len(), 1);
    assert_eq!(reset[0].data()[..3], [0, 0, 0]);
    // And the drive runs again.
    b.ok(0x6040, 0, &0x06u16.to_le_bytes());
    b.ok(0x6040, 0, &0x0Fu16.to_le_bytes());
    assert_eq!(b.statusword() & 0x6F, 0x27);
}

#[test]
fn cyclic_position_follows_a_set_point_stream_one_tpdo_per_sync() {
    let mut b = Bench::new(false);
    b.enable_operation_in(8, 0);
    // RPDO1: 0x607A, synchronous; TPDO1: 0x6064 and 0x6041 at every SYNC.
    b.ok(0x1400, 1, &0x8000_0201u32.to_le_bytes());
    b.ok(0x1600, 0, &[0]);
    b.ok(0x1600, 1, &0x607A_0020u32.to_le_bytes());
    b.ok(0x1600, 0, &[1]);
    b.ok(0x1400, 2, &[1]);
    b.ok(0x1400, 1, &0x0000_0201u32.to_le_bytes());
    b.ok(0x1800, 1, &0x8000_0181u32.to_le_bytes());
    b.ok(0x1A00, 0, &[0]);
    b.ok(0x1A00, 1, &0x6064_0020u32.to_le_bytes());
    b.ok(0x1A00, 2, &0x6041_0010u32.to_le_bytes());
    b.ok(0x1A00, 0, &[2]);
    b.ok(0x1800, 2, &[1]);
    b.ok(0x1800, 1, &0x0000_0181u32.to_le_bytes());
    // 1 kHz SYNC; the set-point ramps at 1 rev/s (4.096 counts per ms)
    // for 0.5 s, then holds.
    let per_sync = b.periods_in(1e-3) - 1;
    let syncs = 800;
    let mut tpdos = 0;
    let mut last_pos = 0;
    for k in 0..syncs {
        let target = (4.096 * f64::from(k.min(500))).round() as i32;
        assert!(b.frame(0x201, &target.to_le_bytes()).is_empty());
        let out = b.frame(0x080, &[]);
        let t: Vec<&CanFrame> = out.iter().filter(|f| f.id() == 0x181).collect();
        assert_eq!(t.len(), 1, "SYNC {k}: {out:?}");
        tpdos += 1;
        let d = t[0].data();
        assert_eq!(d.len(), 6);
        last_pos = i32::from_le_bytes(d[..4].try_into().unwrap());
        assert_eq!(u16::from_le_bytes([d[4], d[5]]) & 0x6F, 0x27, "SYNC {k}");
        b.run(per_sync);
    }
    assert_eq!(tpdos, syncs);
    assert_eq!(b.servo.overruns(), 0);
    // The end: within a count of the last set-point, 2048 counts.
    assert!((last_pos - 2048).abs() <= 1, "position {last_pos}");
    let fe = i32::from_le_bytes(b.sdo_read(0x60F4, 0)[4..8].try_into().unwrap());
    assert!(fe.abs() <= 1, "following error {fe}");
    // What `status` shows of it.
    let st = b.link.status();
    assert!(st.owns);
    let c = st.counters;
    assert_eq!((c.syncs, c.rpdos, c.tpdos, c.errors), (800, 800, 800, 0));
    // 20 SDOs: 6 to enable, 13 to map the PDOs, 1 for 0x60F4. The line
    // docs/canopen.md shows.
    let line = std::format!("canopen: {st}");
    assert_eq!(
        line,
        "canopen: node 1, nmt operational, cia402 operation-enabled, mode 8 (csp), syncs 800, \
         rpdos 800, tpdos 800, sdos 20, errors 0, owns the motor"
    );
    let doc = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../docs/canopen.md"
    ))
    .unwrap();
    assert!(
        doc.contains(&std::format!("\n{line}\n")),
        "docs/canopen.md lacks {line}"
    );
}

/// A master that stops its heartbeat: the consumer (0x1016) reports it
/// with EMCY 0x8130, and the drive quick-stops (0x6007 = 3, the default):
/// the velocity loop brakes the free rotor, then the gates go off and the
/// state is Switch on disabled.
#[test]
fn a_lost_master_heartbeat_quick_stops_the_motor() {
    let mut b = Bench::new(false);
    b.enable_operation_in(9, 0);
    // Watch node 0x7F at 100 ms: 0x007F_0064.
    b.ok(0x1016, 1, &0x007F_0064u32.to_le_bytes());
    // 2 rev/s.
    b.ok(0x60FF, 0, &8192i32.to_le_bytes());
    // The master's heartbeat (operational), then silence.
    let mut now_us = 0u64;
    assert!(b.frame(0x77F, &[0x05]).is_empty());
    let period_us = b.period() as f64 / 100.0;
    let tick = |b: &mut Bench, now_us: u64| {
        let out = b.link.tick(now_us, &mut b.servo, &mut b.sim).unwrap();
        b.keep(out)
    };
    // 50 ms of motion with the master alive (a heartbeat every 50 ms).
    for k in 0..1000u64 {
        b.run(1);
        now_us = (k as f64 * period_us) as u64;
        if k % 800 == 0 {
            assert!(b.frame(0x77F, &[0x05]).is_empty());
        }
        assert!(tick(&mut b, now_us).iter().all(|f| f.id() != 0x081));
    }
    assert!(b.servo.motion_status().velocity_rev_s > 1.0);
    // Silence: the loss is reported once, after 100 ms.
    let before = b.sent.len();
    let mut k = 0u64;
    while b.servo.gates_on(&mut b.sim).unwrap() {
        b.run(1);
        now_us += period_us as u64;
        tick(&mut b, now_us);
        k += 1;
        assert!(k < 40_000, "gates still on");
    }
    let emcy: Vec<&CanFrame> = b.sent[before..]
        .iter()
        .filter(|f| f.id() == 0x081)
        .collect();
    assert_eq!(emcy.len(), 1, "{emcy:?}");
    // The last heartbeat came at 50 ms, the silence began at 62.5 ms: no
    // reaction before 150 ms.
    let silent_us = k as f64 * period_us;
    assert!(silent_us >= 87_000.0, "{silent_us} us");
    // 0x8130, communication bit (4) and generic (0) in the register.
    assert_eq!(emcy[0].data()[..2], [0x30, 0x81]);
    // Switch on disabled: x0xx 0000 with bit 6; the rotor braked first.
    assert_eq!(b.statusword() & 0x4F, 0x40);
    assert!(b.servo.motion_status().velocity_rev_s.abs() < 1.0);
}
