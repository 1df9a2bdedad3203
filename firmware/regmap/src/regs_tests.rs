//! Tests of the generated accessors in `regs` against hand-computed words
//! and the fixed addresses of the map.
use crate as regmap;
use crate::bus::{BusError, RegisterBus};
use crate::regs::{fault, mpdtc, pwm, top};

/// A bus with a log of every access and one stored word per address.
#[derive(Default)]
struct LogBus {
    mem: Vec<(usize, u32)>,
    log: Vec<(char, usize, u32)>,
}

impl RegisterBus for LogBus {
    fn read(&mut self, addr: usize) -> Result<u32, BusError> {
        let v = self
            .mem
            .iter()
            .find(|(a, _)| *a == addr)
            .map_or(0, |(_, v)| *v);
        self.log.push(('r', addr, v));
        Ok(v)
    }
    fn write(&mut self, addr: usize, value: u32) -> Result<(), BusError> {
        self.log.push(('w', addr, value));
        match self.mem.iter_mut().find(|(a, _)| *a == addr) {
            Some(slot) => slot.1 = value,
            None => self.mem.push((addr, value)),
        }
        Ok(())
    }
}

#[test]
fn addresses_are_the_maps() {
    // Fixed by the panic handler and the docs: GATE_CTRL at 0x43C0_3000.
    assert_eq!(pwm::GateCtrl::ADDR, 0x43C0_3000);
    assert_eq!(pwm::DutyB::ADDR, 0x43C0_3010);
    assert_eq!(top::Heartbeat::ADDR, 0x43C0_0014);
    assert_eq!(fault::OcLimit::ADDR, 0x43C0_6008);
    assert_eq!(mpdtc::MpdtcAlignPos::ADDR, 0x43C0_10B4);
    assert_eq!(pwm::BASE, 0x43C0_3000);
    assert_eq!(pwm::GateCtrl::DEF.name, "GATE_CTRL");
    assert_eq!(
        pwm::DutyA::ADDR,
        regmap::PWM.addr(&regmap::DUTY_A),
        "the raw constants and the typed layer agree"
    );
}

#[test]
fn fields_pack_and_unpack() {
    // MPDTC_STATUS: BUSY bit 0, S_NEXT bits 3:1, DONE_COUNT bits 31:16.
    let v = mpdtc::MpdtcStatusValue::from_bits(0x1234_000B);
    assert!(v.busy());
    assert_eq!(v.s_next(), 0b101);
    assert_eq!(v.done_count(), 0x1234);
    let w = mpdtc::MpdtcSeqStatusValue::ZERO
        .with_state(4)
        .with_aligned(true)
        .with_overruns(0x1FF) // 9 bits into an 8-bit field: the 9th is dropped
        .with_periods(0xABCD);
    assert_eq!(w.bits(), 0xABCD_FF14);
    assert_eq!(w.with_aligned(false).bits(), 0xABCD_FF04);
    // A register without fields has one field, `value`.
    assert_eq!(pwm::DeadTimeValue::ZERO.with_value(0xFFFF).bits(), 0x3FF);
    assert_eq!(
        top::ScratchValue::ZERO.with_value(u32::MAX).value(),
        u32::MAX
    );
    assert_eq!(pwm::DeadTimeValue::RESET.value(), 50);
    assert_eq!(pwm::DeadTimeValue::default(), pwm::DeadTimeValue::RESET);
}

#[test]
fn read_write_modify_are_single_word_accesses() {
    let mut bus = LogBus::default();
    pwm::GateCtrl::write(&mut bus, pwm::GateCtrlValue::ZERO.with_gate_en(true)).unwrap();
    pwm::DutyA::modify(&mut bus, |v| v.with_value(v.value() + 7)).unwrap();
    let st = fault::FaultStatusValue::ZERO.with_watchdog(true);
    fault::FaultStatus::write(&mut bus, st).unwrap();
    assert!(pwm::GateCtrl::read(&mut bus).unwrap().gate_en());
    assert_eq!(
        bus.log,
        [
            ('w', 0x43C0_3000, 1),
            ('r', 0x43C0_300C, 0),
            ('w', 0x43C0_300C, 7),
            ('w', 0x43C0_6000, 0b100),
            ('r', 0x43C0_3000, 1),
        ]
    );
}

#[test]
fn bus_errors_pass_through_and_modify_stops_at_a_failed_read() {
    struct Dead(usize);
    impl RegisterBus for Dead {
        fn read(&mut self, _: usize) -> Result<u32, BusError> {
            Err(BusError::Absent)
        }
        fn write(&mut self, _: usize, _: u32) -> Result<(), BusError> {
            self.0 += 1;
            Err(BusError::Absent)
        }
    }
    let mut bus = Dead(0);
    assert_eq!(top::Id::read(&mut bus), Err(BusError::Absent));
    assert_eq!(top::Ctrl::modify(&mut bus, |v| v), Err(BusError::Absent));
    assert_eq!(bus.0, 0, "no write after a failed read");
}

#[test]
fn signed_registers_sign_extend_and_mask() {
    use crate::regs::{adc, enc};
    // ADC_IA: 16 bits, two's complement; -100 = 0xFF9C.
    assert_eq!(adc::AdcIaValue::from_bits(0xFF9C).value_i32(), -100);
    assert_eq!(adc::AdcIaValue::from_bits(0x7FFF).value_i32(), 32767);
    assert_eq!(adc::AdcIaValue::ZERO.with_value_i32(-1).bits(), 0xFFFF);
    assert_eq!(enc::EncSpeedValue::from_bits(0x8000).value_i32(), -32768);
    // MPDTC_IN_ID: 25 bits (sQ8.16); -1 LSB is all 25 bits set.
    let id = mpdtc::MpdtcInIdValue::ZERO.with_value_i32(-1);
    assert_eq!(id.bits(), 0x1FF_FFFF);
    assert_eq!(id.value_i32(), -1);
    // Out of range: the low 25 bits only, as the hardware stores it.
    assert_eq!(
        mpdtc::MpdtcInIdValue::ZERO
            .with_value_i32(1 << 24)
            .value_i32(),
        -(1 << 24)
    );
    // MPDTC_IN_SIN1 (18 bits, sQ1.16): -1.0 = 0x3_0000.
    assert_eq!(
        mpdtc::MpdtcInSin1Value::ZERO.with_value_i32(-65536).bits(),
        0x3_0000
    );
}
