//! The PS CAN driver (`drive::can`) on the controller model
//! (`simpl::ps_can`): frames between two controllers, acceptance filters,
//! the FIFOs' limits, fault confinement and recovery. Expectations are
//! computed by hand from the TRM's register values and the ISO 11898-1
//! counter rules, not read back from the model.

use canopen::CanFrame;
use drive::can::wire::AcceptanceFilter;
use drive::can::{CanConfig, CanError, ErrorState, ErrorStatus, Mode, PsCan};
use regmap::bus::RegisterBus;
use regmap::ps_can as reg;
use simpl::ps_can::bus::{self, Transfer};
use simpl::ps_can::PsCanModel;

const MHZ_100: u32 = 100_000_000;
const MBIT_1: u32 = 1_000_000;

fn config(mode: Mode, filters: &[AcceptanceFilter]) -> CanConfig<'_> {
    CanConfig {
        ref_clock_hz: MHZ_100,
        bit_rate_bps: MBIT_1,
        mode,
        filters,
    }
}

/// A controller model on CAN0 with a `ref_clock_hz` reference clock,
/// under the driver, not configured.
fn controller(ref_clock_hz: u32) -> PsCan<PsCanModel> {
    PsCan::new(
        PsCanModel::new(reg::CAN0_BASE, ref_clock_hz),
        reg::CAN0_BASE,
    )
}

fn node(mode: Mode, filters: &[AcceptanceFilter]) -> PsCan<PsCanModel> {
    let mut c = controller(MHZ_100);
    c.configure(&config(mode, filters)).unwrap();
    c
}

/// A controller configured 1 Mbit/s from 24 MHz with `filters`.
fn node_24mhz(filters: &[AcceptanceFilter]) -> PsCan<PsCanModel> {
    let mut c = controller(24_000_000);
    c.configure(&CanConfig {
        ref_clock_hz: 24_000_000,
        ..config(Mode::Normal, filters)
    })
    .unwrap();
    c
}

fn frame(id: u16, data: &[u8]) -> CanFrame {
    CanFrame::new(id, data).unwrap()
}

fn receive_all(c: &mut PsCan<PsCanModel>) -> Vec<CanFrame> {
    let mut out = Vec::new();
    while let Some(f) = c.receive().unwrap() {
        out.push(f);
    }
    out
}

fn run(a: &mut PsCan<PsCanModel>, b: &mut PsCan<PsCanModel>, slots: usize) -> usize {
    bus::run(&mut [a.bus_mut(), b.bus_mut()], slots)
}

fn step(a: &mut PsCan<PsCanModel>, b: &mut PsCan<PsCanModel>) -> Transfer {
    bus::step(&mut [a.bus_mut(), b.bus_mut()])
}

fn status(tec: u8, rec: u8, state: ErrorState) -> ErrorStatus {
    ErrorStatus { tec, rec, state }
}

#[test]
fn frames_round_trip_between_two_controllers() {
    let mut a = node(Mode::Normal, &[]);
    let mut b = node(Mode::Normal, &[]);
    // 1 Mbit/s from 100 MHz: prescaler 5, TS1 16, TS2 3, SJW 3 quanta.
    let base = reg::CAN0_BASE;
    assert_eq!(a.bus_mut().read(base + reg::BRPR), Ok(4));
    assert_eq!(a.bus_mut().read(base + reg::BTR), Ok(0x12F));
    let sent_a = [
        frame(0x701, &[0x05]),
        frame(0x000, &[]),
        frame(0x7FF, &[1, 2, 3, 4, 5, 6, 7, 8]),
    ];
    for f in &sent_a {
        a.send(f).unwrap();
    }
    b.send(&frame(0x181, &[0xAA, 0x55])).unwrap();
    // Four frames, then an idle slot.
    assert_eq!(run(&mut a, &mut b, 100), 4);
    assert_eq!(receive_all(&mut b), sent_a);
    assert_eq!(receive_all(&mut a), [frame(0x181, &[0xAA, 0x55])]);
    assert_eq!(a.error_status(), Ok(status(0, 0, ErrorState::Active)));
    assert_eq!(b.error_status(), Ok(status(0, 0, ErrorState::Active)));
    for c in [&mut a, &mut b] {
        let m = c.bus_mut();
        assert_eq!((m.ignored_config_writes, m.ignored_filter_writes), (0, 0));
        assert_eq!((m.dropped_tx_writes, m.rx_dropped), (0, 0));
    }
}

#[test]
fn arbitration_sends_the_lower_identifier_first() {
    let mut a = node(Mode::Normal, &[]);
    let mut b = node(Mode::Normal, &[]);
    a.send(&frame(0x300, &[3])).unwrap();
    b.send(&frame(0x080, &[8])).unwrap();
    assert!(matches!(
        step(&mut a, &mut b),
        Transfer::Sent { from: 1, .. }
    ));
    assert!(matches!(
        step(&mut a, &mut b),
        Transfer::Sent { from: 0, .. }
    ));
    assert_eq!(
        a.bus_mut().read(reg::CAN0_BASE + reg::ISR).unwrap() & reg::IXR_ARBLST,
        reg::IXR_ARBLST
    );
}

#[test]
fn acceptance_filters_pass_and_block_the_right_identifiers() {
    let mut a = node(Mode::Normal, &[]);
    // One identifier exactly, and the block 0x600..=0x67F (SDO requests).
    let filters = [
        AcceptanceFilter {
            id: 0x181,
            mask: 0x7FF,
        },
        AcceptanceFilter {
            id: 0x600,
            mask: 0x780,
        },
    ];
    let mut b = node(Mode::Normal, &filters);
    let ids = [
        0x181, 0x182, 0x180, 0x600, 0x67F, 0x680, 0x5FF, 0x601, 0x000, 0x7FF,
    ];
    for id in ids {
        a.send(&frame(id, &[id as u8])).unwrap();
    }
    assert_eq!(run(&mut a, &mut b, 100), ids.len());
    let got: Vec<u16> = receive_all(&mut b).iter().map(|f| f.id()).collect();
    // By hand: 0x181 exactly; 0x600 & 0x780 == 0x600 for 0x600, 0x67F,
    // 0x601; 0x680 & 0x780 = 0x680, 0x5FF & 0x780 = 0x580.
    assert_eq!(got, [0x181, 0x600, 0x67F, 0x601]);
    // Every frame was acknowledged and counted as a good reception.
    assert_eq!(a.error_status().unwrap().tec, 0);
}

#[test]
fn a_full_rx_fifo_keeps_64_in_order_and_counts_the_65th() {
    let mut a = node(Mode::Normal, &[]);
    let mut b = node(Mode::Normal, &[]);
    let f = |i: u16| frame(0x100 + i, &[i as u8, 0xC3]);
    for i in 0..64 {
        a.send(&f(i)).unwrap();
    }
    assert_eq!(run(&mut a, &mut b, 1000), 64);
    a.send(&f(64)).unwrap();
    assert_eq!(run(&mut a, &mut b, 1000), 1);
    let ev = b.poll_events().unwrap();
    assert!(ev.rx_overflow);
    assert_eq!(b.stats().rx_overflows, 1);
    assert_eq!(b.bus_mut().rx_dropped, 1);
    let kept = receive_all(&mut b);
    assert_eq!(kept, (0..64).map(f).collect::<Vec<_>>());
    // The flag was cleared: a second poll counts nothing new.
    assert!(!b.poll_events().unwrap().rx_overflow);
    assert_eq!(b.stats().rx_overflows, 1);
}

#[test]
fn a_full_tx_fifo_refuses_the_frame_and_loses_nothing() {
    let mut a = node(Mode::Normal, &[]);
    let mut b = node(Mode::Normal, &[]);
    let f = |i: u16| frame(i, &[i as u8]);
    for i in 0..64 {
        a.send(&f(i)).unwrap();
    }
    assert_eq!(a.send(&f(64)), Err(CanError::TxFifoFull));
    assert_eq!(a.bus_mut().dropped_tx_writes, 0);
    assert_eq!(run(&mut a, &mut b, 1000), 64);
    assert_eq!(receive_all(&mut b), (0..64).map(f).collect::<Vec<_>>());
    // Room again.
    a.send(&f(64)).unwrap();
}

#[test]
fn loopback_receives_its_own_frames_and_snoop_only_listens() {
    let mut l = node(Mode::Loopback, &[]);
    let mut other = node(Mode::Normal, &[]);
    l.send(&frame(0x222, &[2])).unwrap();
    assert!(matches!(
        step(&mut l, &mut other),
        Transfer::Looped { node: 0, .. }
    ));
    assert_eq!(receive_all(&mut l), [frame(0x222, &[2])]);
    assert_eq!(receive_all(&mut other), Vec::<CanFrame>::new());
    // Nor does the loopback node take frames from the bus.
    other.send(&frame(0x223, &[3])).unwrap();
    assert_eq!(step(&mut l, &mut other), Transfer::AckError { from: 1 });
    assert_eq!(receive_all(&mut l), Vec::<CanFrame>::new());

    let mut a = node(Mode::Normal, &[]);
    let mut b = node(Mode::Normal, &[]);
    let mut s = node(Mode::Snoop, &[]);
    a.send(&frame(0x333, &[3])).unwrap();
    s.send(&frame(0x001, &[])).unwrap();
    let mut nodes = [a.bus_mut(), b.bus_mut(), s.bus_mut()];
    // The snooper's frame never goes out, even with the lower identifier.
    assert_eq!(
        bus::step(&mut nodes),
        Transfer::Sent {
            from: 0,
            msg: simpl::ps_can::fifo::Message {
                id: 0x333 << 21,
                dlc: 1 << 28,
                data1: 0x0300_0000,
                data2: 0,
            }
        }
    );
    assert_eq!(bus::step(&mut nodes), Transfer::Idle);
    assert_eq!(receive_all(&mut s), [frame(0x333, &[3])]);
    assert_eq!(receive_all(&mut b), [frame(0x333, &[3])]);

    // A snooper does not acknowledge: alone with it, a sender meets
    // acknowledge errors.
    let mut lone = node(Mode::Normal, &[]);
    let mut s2 = node(Mode::Snoop, &[]);
    lone.send(&frame(0x444, &[])).unwrap();
    assert_eq!(step(&mut lone, &mut s2), Transfer::AckError { from: 0 });
}

/// ISO 11898-1: each transmit error adds 8; error passive at TEC 128 (16
/// errors), bus off above 255 (the 32nd error: 256). The receiver counts 1
/// per error frame it sees.
#[test]
fn bit_errors_drive_the_sender_to_passive_and_bus_off_and_it_recovers() {
    let mut a = node(Mode::Normal, &[]);
    let mut b = node(Mode::Normal, &[]);
    a.bus_mut().inject_tx_bit_errors(32);
    a.send(&frame(0x123, &[1])).unwrap();
    for k in 1..=15u8 {
        assert_eq!(step(&mut a, &mut b), Transfer::BitError { from: 0 });
        assert_eq!(a.error_status(), Ok(status(8 * k, 0, ErrorState::Active)));
    }
    assert_eq!(step(&mut a, &mut b), Transfer::BitError { from: 0 });
    assert_eq!(a.error_status(), Ok(status(128, 0, ErrorState::Passive)));
    assert_eq!(b.error_status(), Ok(status(0, 16, ErrorState::Active)));
    for _ in 17..=31 {
        step(&mut a, &mut b);
    }
    assert_eq!(a.error_status(), Ok(status(248, 0, ErrorState::Passive)));
    assert!(!a.poll_events().unwrap().bus_off);
    step(&mut a, &mut b);
    assert_eq!(a.error_status().unwrap().state, ErrorState::BusOff);
    let ev = a.poll_events().unwrap();
    assert!(ev.bus_off);
    assert_eq!(ev.errors & reg::ESR_BERR, reg::ESR_BERR);
    assert_eq!(a.stats().bus_off_entries, 1);
    // Bus off: the frame stays queued and nothing goes out.
    assert_eq!(step(&mut a, &mut b), Transfer::Idle);
    assert_eq!(a.bus_mut().tx_len(), 1);

    // Automatic recovery: 128 occurrences of 11 recessive bits; one bit
    // short is not enough.
    bus::idle(&mut [a.bus_mut(), b.bus_mut()], 128 * 11 - 1);
    assert_eq!(a.error_status().unwrap().state, ErrorState::BusOff);
    bus::idle(&mut [a.bus_mut(), b.bus_mut()], 1);
    assert_eq!(a.error_status(), Ok(status(0, 0, ErrorState::Active)));
    // The queued frame goes out; B's good reception takes 1 from its 32.
    assert!(matches!(
        step(&mut a, &mut b),
        Transfer::Sent { from: 0, .. }
    ));
    assert_eq!(receive_all(&mut b), [frame(0x123, &[1])]);
    assert_eq!(b.error_status(), Ok(status(0, 31, ErrorState::Active)));
}

#[test]
fn a_requested_recovery_leaves_bus_off_at_once_with_the_configuration() {
    let filters = [AcceptanceFilter {
        id: 0x080,
        mask: 0x7FF,
    }];
    let mut a = node_24mhz(&filters);
    let mut b = node(Mode::Normal, &[]);
    a.bus_mut().inject_tx_bit_errors(32);
    a.send(&frame(0x123, &[1])).unwrap();
    for _ in 0..32 {
        step(&mut a, &mut b);
    }
    assert_eq!(a.error_status().unwrap().state, ErrorState::BusOff);
    a.recover().unwrap();
    assert_eq!(a.error_status(), Ok(status(0, 0, ErrorState::Active)));
    assert_eq!(a.stats().recoveries, 1);
    // The reset dropped the queued frame; the configuration is back.
    assert_eq!(a.bus_mut().tx_len(), 0);
    let base = reg::CAN0_BASE;
    assert_eq!(a.bus_mut().read(base + reg::BRPR), Ok(1));
    assert_eq!(a.bus_mut().read(base + reg::AFR), Ok(1));
    b.send(&frame(0x081, &[])).unwrap();
    b.send(&frame(0x080, &[8])).unwrap();
    a.send(&frame(0x700, &[0x05])).unwrap();
    assert_eq!(run(&mut a, &mut b, 10), 3);
    assert_eq!(receive_all(&mut a), [frame(0x080, &[8])]);
    assert_eq!(receive_all(&mut b), [frame(0x700, &[0x05])]);
}

/// ISO 11898-1, rule 3's exception: an error-passive transmitter whose
/// error is a missing acknowledge keeps its TEC, so a node alone on the bus
/// stops at 128 and never goes bus off.
#[test]
fn acknowledge_errors_alone_stop_at_error_passive() {
    let mut a = node(Mode::Normal, &[]);
    let mut off = controller(MHZ_100);
    a.send(&frame(0x700, &[0x7F])).unwrap();
    for _ in 0..16 {
        assert_eq!(step(&mut a, &mut off), Transfer::AckError { from: 0 });
    }
    assert_eq!(a.error_status(), Ok(status(128, 0, ErrorState::Passive)));
    for _ in 0..200 {
        step(&mut a, &mut off);
    }
    assert_eq!(a.error_status(), Ok(status(128, 0, ErrorState::Passive)));
    assert_eq!(a.poll_events().unwrap().errors, reg::ESR_ACKER);
}

/// One success takes 1 from TEC: 128 (passive) becomes 127 (active).
/// Receive errors add 1 each: 128 makes a receiver passive; a good
/// reception then sets REC to a value from 119 to 127 (active again).
#[test]
fn good_frames_bring_the_counters_down() {
    let mut a = node(Mode::Normal, &[]);
    let mut b = node(Mode::Normal, &[]);
    a.bus_mut().inject_tx_bit_errors(16);
    a.send(&frame(0x010, &[])).unwrap();
    assert_eq!(run(&mut a, &mut b, 100), 17);
    assert_eq!(a.error_status(), Ok(status(127, 0, ErrorState::Active)));
    // B saw 16 error frames and one good frame.
    assert_eq!(b.error_status(), Ok(status(0, 15, ErrorState::Active)));

    b.bus_mut().inject_rx_errors(113);
    assert_eq!(b.error_status(), Ok(status(0, 128, ErrorState::Passive)));
    a.send(&frame(0x011, &[])).unwrap();
    run(&mut a, &mut b, 10);
    let s = b.error_status().unwrap();
    assert!((119..=127).contains(&s.rec), "{s:?}");
    assert_eq!(s.state, ErrorState::Active);
}

#[test]
fn a_refused_configuration_writes_nothing() {
    let mut c = node(Mode::Normal, &[]);
    let base = reg::CAN0_BASE;
    let before = c.bus_mut().clone();
    let f = AcceptanceFilter { id: 1, mask: 0x7FF };
    let five = [f; 5];
    assert_eq!(
        c.configure(&config(Mode::Normal, &five)),
        Err(CanError::TooManyFilters)
    );
    let wide = [AcceptanceFilter {
        id: 0x800,
        mask: 0x7FF,
    }];
    assert_eq!(
        c.configure(&config(Mode::Normal, &wide)),
        Err(CanError::FilterOutOfRange)
    );
    let odd = CanConfig {
        bit_rate_bps: 1_100_000,
        ..config(Mode::Normal, &[])
    };
    assert!(matches!(c.configure(&odd), Err(CanError::BitTiming(_))));
    assert_eq!(*c.bus_mut(), before);
    assert_eq!(
        c.bus_mut().read(base + reg::SR).unwrap() & reg::SR_NORMAL,
        reg::SR_NORMAL
    );

    let mut fresh = controller(MHZ_100);
    assert_eq!(
        fresh.error_status(),
        Ok(status(0, 0, ErrorState::Configuration))
    );
    assert_eq!(fresh.send(&frame(1, &[])), Err(CanError::NotConfigured));
    assert_eq!(fresh.recover(), Err(CanError::NotConfigured));
}

#[test]
fn the_bit_timing_of_24_mhz_reaches_the_registers() {
    let mut c = node_24mhz(&[]);
    let base = reg::CAN0_BASE;
    // 1 Mbit/s from 24 MHz: prescaler 2, TS1 9, TS2 2, SJW 2 quanta.
    assert_eq!(c.bus_mut().read(base + reg::BRPR), Ok(1));
    assert_eq!(c.bus_mut().read(base + reg::BTR), Ok(0x98));
    assert_eq!(c.bus_mut().read(base + reg::AFR), Ok(0));
}

/// The driver's timings from 24 MHz and from 100 MHz give the same bit
/// time (24 x 2 / 24 MHz = 20 x 5 / 100 MHz = 1 us), so the two talk; a
/// node at 500 kbit/s neither acknowledges nor receives, and counts an
/// error per frame.
#[test]
fn nodes_on_different_clocks_meet_at_the_same_bit_rate_only() {
    let mut a = node_24mhz(&[]);
    let mut b = node(Mode::Normal, &[]);
    a.send(&frame(0x1A0, &[0x24])).unwrap();
    b.send(&frame(0x1B0, &[0x64])).unwrap();
    assert_eq!(run(&mut a, &mut b, 10), 2);
    assert_eq!(receive_all(&mut a), [frame(0x1B0, &[0x64])]);
    assert_eq!(receive_all(&mut b), [frame(0x1A0, &[0x24])]);

    let mut slow = controller(MHZ_100);
    slow.configure(&CanConfig {
        bit_rate_bps: 500_000,
        ..config(Mode::Normal, &[])
    })
    .unwrap();
    a.send(&frame(0x1A1, &[])).unwrap();
    assert_eq!(step(&mut a, &mut slow), Transfer::AckError { from: 0 });
    assert_eq!(receive_all(&mut slow), Vec::<CanFrame>::new());
    assert_eq!(slow.error_status(), Ok(status(0, 1, ErrorState::Active)));
    assert_eq!(a.error_status(), Ok(status(8, 0, ErrorState::Active)));
}
