use super::*;
use std::vec::Vec;

/// SPI NOR flash in memory: erase sets a sector to 0xFF, programming
/// clears bits (AND), and an optional power cut stops it after `budget`
/// bytes (an erase counts as one, and a cut erase leaves the sector half
/// erased).
struct FakeFlash {
    mem: Vec<u8>,
    budget: Option<usize>,
}

impl FakeFlash {
    fn new() -> Self {
        Self {
            mem: std::vec![0xFF; 16 << 20],
            budget: None,
        }
    }
    fn spend(&mut self) -> Result<(), FlashError> {
        match &mut self.budget {
            Some(0) => Err(FlashError),
            Some(n) => {
                *n -= 1;
                Ok(())
            }
            None => Ok(()),
        }
    }
}

impl NorFlash for FakeFlash {
    fn read(&mut self, addr: u32, buf: &mut [u8]) -> Result<(), FlashError> {
        let a = addr as usize;
        buf.copy_from_slice(&self.mem[a..a + buf.len()]);
        Ok(())
    }
    fn erase_sector(&mut self, addr: u32) -> Result<(), FlashError> {
        assert_eq!(addr % SECTOR_BYTES, 0);
        let a = addr as usize;
        if self.spend().is_err() {
            // Cut mid-erase: the first half erased, garbage after.
            self.mem[a..a + 100].fill(0xFF);
            return Err(FlashError);
        }
        self.mem[a..a + SECTOR_BYTES as usize].fill(0xFF);
        Ok(())
    }
    fn program(&mut self, addr: u32, data: &[u8]) -> Result<(), FlashError> {
        for (k, &b) in data.iter().enumerate() {
            self.spend()?;
            self.mem[addr as usize + k] &= b;
        }
        Ok(())
    }
}

fn cfg_with(t_tol: f64) -> Config {
    let mut c = Config::default();
    c.set(&ServoConfig::default(), "mpdtc_t_tol", t_tol)
        .unwrap();
    c
}

#[test]
fn crc32_check_value() {
    // The CRC-32/ISO-HDLC check value of "123456789".
    assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
    assert_eq!(crc32(b""), 0);
}

#[test]
fn record_layout() {
    let r = encode(&Config::default(), 7);
    assert_eq!(&r[0..4], b"DCFG");
    assert_eq!(u16::from_le_bytes([r[4], r[5]]), FORMAT_VERSION);
    assert_eq!(usize::from(u16::from_le_bytes([r[6], r[7]])), N_PARAMS);
    assert_eq!(u32_at(&r, 12), 7);
    // motor_r_s first.
    let mut b = [0u8; 8];
    b.copy_from_slice(&r[16..24]);
    assert_eq!(f64::from_bits(u64::from_le_bytes(b)), 0.555);
    assert_eq!(RECORD_BYTES, 16 + 8 * N_PARAMS + 4);
    assert!(RECORD_BYTES as u32 <= SECTOR_BYTES);
}

#[test]
fn empty_flash_loads_nothing_then_saves_alternate() {
    let base = ServoConfig::default();
    let mut f = FakeFlash::new();
    let l = load(&mut f, &base).unwrap();
    assert_eq!(l.config, None);
    assert_eq!(l.slots, [SlotState::Empty, SlotState::Empty]);
    for (k, want_slot) in [0, 1, 0, 1, 0].into_iter().enumerate() {
        let c = cfg_with(0.01 * (k + 1) as f64);
        assert_eq!(save(&mut f, &c, &base).unwrap(), want_slot);
        let l = load(&mut f, &base).unwrap();
        assert_eq!(l.config, Some((c, want_slot)));
        assert_eq!(l.slots[want_slot], SlotState::Valid(k as u32 + 1));
        if k > 0 {
            assert_eq!(l.slots[1 - want_slot], SlotState::Valid(k as u32));
        }
    }
}

#[test]
fn corrupt_and_foreign_records_are_ignored_and_reported() {
    let base = ServoConfig::default();
    let mut f = FakeFlash::new();
    let old = cfg_with(0.03);
    save(&mut f, &old, &base).unwrap();
    save(&mut f, &cfg_with(0.04), &base).unwrap();
    // Flip one bit of slot 1's value: CRC fails, slot 0 wins.
    f.mem[SLOT0_ADDR as usize + SECTOR_BYTES as usize + 20] ^= 0x10;
    let l = load(&mut f, &base).unwrap();
    assert_eq!(l.slots, [SlotState::Valid(1), SlotState::BadCrc]);
    assert_eq!(l.config, Some((old, 0)));
    // Another format version with a correct CRC: reported as such.
    let mut r = encode(&cfg_with(0.05), 9);
    r[4] = 2;
    let n = RECORD_BYTES - 4;
    let crc = crc32(&r[..n]);
    r[n..].copy_from_slice(&crc.to_le_bytes());
    let (st, c) = decode(&r, &base);
    assert_eq!((st, c), (SlotState::BadVersion, None));
    // Another table (fingerprint) and out-of-range values.
    let mut r = encode(&cfg_with(0.05), 9);
    r[8] ^= 1;
    let crc = crc32(&r[..n]);
    r[n..].copy_from_slice(&crc.to_le_bytes());
    assert_eq!(decode(&r, &base).0, SlotState::BadVersion);
    let mut r = encode(&cfg_with(0.05), 9);
    r[16..24].copy_from_slice(&f64::NAN.to_bits().to_le_bytes());
    let crc = crc32(&r[..n]);
    r[n..].copy_from_slice(&crc.to_le_bytes());
    assert_eq!(decode(&r, &base).0, SlotState::BadValues);
    // The next save goes to the slot without the newest valid record.
    assert_eq!(save(&mut f, &cfg_with(0.06), &base).unwrap(), 1);
    assert_eq!(load(&mut f, &base).unwrap().slots[1], SlotState::Valid(2));
}

/// A cut after every possible number of flash operations of a save:
/// the load gives the old or the new configuration, never anything else.
#[test]
fn a_cut_save_leaves_the_old_or_the_new_configuration() {
    let base = ServoConfig::default();
    let mut clean = FakeFlash::new();
    save(&mut clean, &cfg_with(0.01), &base).unwrap();
    save(&mut clean, &cfg_with(0.02), &base).unwrap();
    let old = cfg_with(0.02);
    let new = cfg_with(0.03);
    let ops = 1 + RECORD_BYTES;
    let (mut saw_old, mut saw_new) = (0, 0);
    for cut in 0..=ops {
        let mut f = FakeFlash {
            mem: clean.mem.clone(),
            budget: Some(cut),
        };
        let r = save(&mut f, &new, &base);
        assert_eq!(r.is_ok(), cut >= ops, "{cut}");
        f.budget = None;
        let got = load(&mut f, &base).unwrap().config.map(|(c, _)| c);
        if got == Some(old) {
            saw_old += 1;
        } else if got == Some(new) {
            saw_new += 1;
        } else {
            panic!("cut after {cut} operations: {got:?}");
        }
    }
    // Only the complete save (its CRC's last byte) gives the new one.
    assert_eq!((saw_old, saw_new), (ops, 1));
}

#[test]
fn sequence_numbers_wrap() {
    let base = ServoConfig::default();
    let mut f = FakeFlash::new();
    let a = encode(&cfg_with(0.01), u32::MAX);
    let b = encode(&cfg_with(0.02), 0);
    f.program(SLOT0_ADDR, &a).unwrap();
    f.program(SLOT0_ADDR + SECTOR_BYTES, &b).unwrap();
    assert_eq!(
        load(&mut f, &base).unwrap().config,
        Some((cfg_with(0.02), 1))
    );
}

/// The pauses bracket each erase and program of a save: three writes
/// (erase, values, CRC), so six pauses, and the record is the same.
#[test]
fn paced_flash_pauses_around_every_write_and_changes_nothing_else() {
    let base = ServoConfig::default();
    let mut pauses = 0;
    let mut f = PacedFlash {
        flash: FakeFlash::new(),
        pause: || pauses += 1,
    };
    let c = cfg_with(0.05);
    assert_eq!(save(&mut f, &c, &base), Ok(0));
    let l = load(&mut f, &base).unwrap();
    assert_eq!(l.config, Some((c, 0)));
    drop(f);
    assert_eq!(pauses, 6);
}

/// A record written by the firmware before `mpdtc_k_auto` and `mpdtc_aw`
/// (37 parameters, the table of `EARLIER_TABLES[0]`), built by hand: it
/// loads, each value by its name, the two new parameters at their
/// defaults; the next save writes the present table.
#[test]
fn a_record_of_the_earlier_table_loads_by_name() {
    let base = ServoConfig::default();
    let old = EARLIER_TABLES[0];
    assert_eq!(old.len(), 37);
    let mut r = [0xFFu8; RECORD_BYTES];
    r[0..4].copy_from_slice(&MAGIC.to_le_bytes());
    r[4..6].copy_from_slice(&FORMAT_VERSION.to_le_bytes());
    r[6..8].copy_from_slice(&37u16.to_le_bytes());
    // CRC-32 of the 37 names joined by ",".
    let joined = old.join(",");
    r[8..12].copy_from_slice(&crc32(joined.as_bytes()).to_le_bytes());
    r[12..16].copy_from_slice(&5u32.to_le_bytes());
    let defaults = Config::default();
    for (i, name) in old.iter().enumerate() {
        let v = match *name {
            "motor_r_s" => 0.7,
            "mpdtc_k" => 3000.0,
            "calibration_voltage" => defaults.get("calibration_voltage").unwrap() * 0.5,
            n => defaults.get(n).expect("an earlier name is a present one"),
        };
        r[16 + 8 * i..24 + 8 * i].copy_from_slice(&v.to_bits().to_le_bytes());
    }
    let n = 16 + 8 * 37;
    let crc = crc32(&r[..n]);
    r[n..n + 4].copy_from_slice(&crc.to_le_bytes());
    let (st, c) = decode(&r, &base);
    assert_eq!(st, SlotState::Valid(5));
    let c = c.expect("loaded");
    assert_eq!(c.get("motor_r_s"), Some(0.7));
    assert_eq!(c.get("mpdtc_k"), Some(3000.0));
    assert_eq!(
        c.get("calibration_voltage"),
        Some(defaults.get("calibration_voltage").unwrap() * 0.5)
    );
    assert_eq!(c.get("mpdtc_aw"), defaults.get("mpdtc_aw"));
    assert_eq!(c.get("mpdtc_k_auto"), defaults.get("mpdtc_k_auto"));
    // A fingerprint of no known table is still refused.
    r[8] ^= 1;
    let crc = crc32(&r[..n]);
    r[n..n + 4].copy_from_slice(&crc.to_le_bytes());
    assert_eq!(decode(&r, &base).0, SlotState::BadVersion);
}
