//! The configuration in SPI NOR flash: a versioned record with a CRC in
//! two alternating slots (one erase sector each), so that a power cut
//! during a save leaves the old or the new configuration, never garbage.
//!
//! Record (little endian), at the start of its slot:
//!
//! | offset | size | field |
//! |---|---|---|
//! | 0 | 4 | magic `DCFG` (0x47464344) |
//! | 4 | 2 | format version ([`FORMAT_VERSION`]) |
//! | 6 | 2 | number of parameters `n` |
//! | 8 | 4 | table fingerprint: CRC-32 of the parameter names joined by `,` |
//! | 12 | 4 | sequence number (each save: the newest + 1) |
//! | 16 | 8 n | the values, `f64` bits, in table order |
//! | 16 + 8 n | 4 | CRC-32 (ISO-HDLC: reflected 0x04C11DB7, init and xorout all ones) of bytes 0 .. 16 + 8 n |
//!
//! A save erases the slot that does not hold the newest valid record, then
//! programs the record there; the CRC is the last thing written, so a cut
//! anywhere leaves that slot invalid and the other one intact. At load the
//! valid record with the higher sequence number wins; a record of an
//! earlier parameter table ([`EARLIER_TABLES`]: its count and fingerprint)
//! loads value by name, the parameters it lacks at their defaults; a record
//! whose CRC, version or table does not match is ignored and reported.
use super::{Config, ConfigError, N_PARAMS, PARAMS};
use crate::servo::ServoConfig;

/// Record layout version.
pub const FORMAT_VERSION: u16 = 1;
/// `DCFG`.
pub const MAGIC: u32 = 0x4746_4344;
/// Erase sector of the flash (the n25q128's 64 KiB sector), bytes.
pub const SECTOR_BYTES: u32 = 64 * 1024;
/// Program page of the flash, bytes.
pub const PAGE_BYTES: u32 = 256;
/// Flash address of slot 0 (14 MiB: clear of a boot image at the start of
/// a 16 MiB part); slot 1 is the next sector.
pub const SLOT0_ADDR: u32 = 14 * 1024 * 1024;
/// Record length, bytes.
pub const RECORD_BYTES: usize = 16 + 8 * N_PARAMS + 4;

/// A flash access failed (the driver's word for it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FlashError;

/// SPI NOR flash as the store needs it. `program` may span pages (the
/// driver splits it); programming only clears bits; erase sets a sector to
/// 0xFF.
pub trait NorFlash {
    /// Reads `buf.len()` bytes at `addr`.
    fn read(&mut self, addr: u32, buf: &mut [u8]) -> Result<(), FlashError>;
    /// Erases the sector at `addr` (sector aligned).
    fn erase_sector(&mut self, addr: u32) -> Result<(), FlashError>;
    /// Programs `data` at `addr`.
    fn program(&mut self, addr: u32, data: &[u8]) -> Result<(), FlashError>;
}

/// CRC-32/ISO-HDLC (the zip/Ethernet CRC), bitwise: the record is small.
pub fn crc32(data: &[u8]) -> u32 {
    crc32_update(0xFFFF_FFFF, data) ^ 0xFFFF_FFFF
}

fn crc32_update(mut crc: u32, data: &[u8]) -> u32 {
    for &b in data {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 != 0 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    crc
}

/// CRC-32 of the parameter names joined by `,`: a record written for
/// another table (renamed, reordered, added) does not load.
pub fn table_fingerprint() -> u32 {
    fingerprint_of(PARAMS.iter().map(|p| p.name))
}

fn fingerprint_of<'a>(names: impl Iterator<Item = &'a str>) -> u32 {
    let mut crc = 0xFFFF_FFFF;
    for (i, name) in names.enumerate() {
        if i > 0 {
            crc = crc32_update(crc, b",");
        }
        crc = crc32_update(crc, name.as_bytes());
    }
    crc ^ 0xFFFF_FFFF
}

/// Parameter tables of earlier firmware, oldest first, whose records
/// [`decode`] still reads: each value goes to the parameter of the same
/// name, and a parameter the old table lacks takes its default. So a
/// firmware update that adds parameters keeps a saved configuration (the
/// next `config save` writes the present table).
pub const EARLIER_TABLES: [&[&str]; 1] = [&[
    "motor_r_s",
    "motor_l",
    "motor_psi_pm",
    "motor_pole_pairs",
    "u_dc",
    "enc_cpr",
    "enc_zero",
    "dead_time",
    "adc_period",
    "foc_half_period",
    "foc_pole",
    "foc_pred_gain",
    "mpdtc_t_tol",
    "mpdtc_p",
    "mpdtc_k",
    "mpdtc_int_limit",
    "obs_kp",
    "obs_ki",
    "obs_limit",
    "mpdtc_align_time",
    "torque_limit",
    "current_limit",
    "watchdog_timeout",
    "mpdtc_ps_fed",
    "vel_kp",
    "vel_ki",
    "pos_kp",
    "load_inertia",
    "traj_vel_limit",
    "traj_accel_limit",
    "vel_limit",
    "pos_min",
    "pos_max",
    "imp_kp_max",
    "imp_kd_max",
    "calibration_current",
    "calibration_voltage",
]];

/// What a slot holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SlotState {
    /// Erased (all 0xFF at the record's place).
    Empty,
    /// A record with a good CRC and this sequence number.
    Valid(u32),
    /// Not erased, CRC wrong (e.g. a save cut short).
    BadCrc,
    /// CRC right, but another format version or parameter table.
    BadVersion,
    /// CRC and version right, values refused by [`Config::check`].
    BadValues,
}

impl SlotState {
    /// The word `status` prints.
    pub fn name(self) -> &'static str {
        match self {
            SlotState::Empty => "empty",
            SlotState::Valid(_) => "valid",
            SlotState::BadCrc => "bad-crc",
            SlotState::BadVersion => "bad-version",
            SlotState::BadValues => "bad-values",
        }
    }
}

/// What [`load`] found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Loaded {
    /// The newest valid configuration and its slot, if any.
    pub config: Option<(Config, usize)>,
    /// Each slot's state.
    pub slots: [SlotState; 2],
}

fn slot_addr(slot: usize) -> u32 {
    SLOT0_ADDR + slot as u32 * SECTOR_BYTES
}

/// The record of `cfg` with sequence number `seq`.
pub fn encode(cfg: &Config, seq: u32) -> [u8; RECORD_BYTES] {
    let mut r = [0u8; RECORD_BYTES];
    r[0..4].copy_from_slice(&MAGIC.to_le_bytes());
    r[4..6].copy_from_slice(&FORMAT_VERSION.to_le_bytes());
    r[6..8].copy_from_slice(&(N_PARAMS as u16).to_le_bytes());
    r[8..12].copy_from_slice(&table_fingerprint().to_le_bytes());
    r[12..16].copy_from_slice(&seq.to_le_bytes());
    for (i, v) in cfg.values().iter().enumerate() {
        r[16 + 8 * i..24 + 8 * i].copy_from_slice(&v.to_bits().to_le_bytes());
    }
    let n = RECORD_BYTES - 4;
    let crc = crc32(&r[..n]);
    r[n..].copy_from_slice(&crc.to_le_bytes());
    r
}

fn u32_at(r: &[u8], at: usize) -> u32 {
    u32::from_le_bytes([r[at], r[at + 1], r[at + 2], r[at + 3]])
}

/// The state of a record and, if valid, its configuration.
pub fn decode(r: &[u8; RECORD_BYTES], base: &ServoConfig) -> (SlotState, Option<Config>) {
    if r.iter().all(|&b| b == 0xFF) {
        return (SlotState::Empty, None);
    }
    // The count comes before the CRC: a record of an earlier, shorter
    // table ends before the present one's length.
    let count = usize::from(u16::from_le_bytes([r[6], r[7]]));
    if count == 0 || count > N_PARAMS {
        return if crc32(&r[..RECORD_BYTES - 4]) == u32_at(r, RECORD_BYTES - 4) {
            (SlotState::BadVersion, None)
        } else {
            (SlotState::BadCrc, None)
        };
    }
    let n = 16 + 8 * count;
    if crc32(&r[..n]) != u32_at(r, n) {
        return (SlotState::BadCrc, None);
    }
    let version = u16::from_le_bytes([r[4], r[5]]);
    if u32_at(r, 0) != MAGIC || version != FORMAT_VERSION {
        return (SlotState::BadVersion, None);
    }
    let value = |i: usize| {
        let mut b = [0u8; 8];
        b.copy_from_slice(&r[16 + 8 * i..24 + 8 * i]);
        f64::from_bits(u64::from_le_bytes(b))
    };
    let fingerprint = u32_at(r, 8);
    let mut values = *Config::default().values();
    if count == N_PARAMS && fingerprint == table_fingerprint() {
        for (i, v) in values.iter_mut().enumerate() {
            *v = value(i);
        }
    } else if let Some(old) = EARLIER_TABLES
        .iter()
        .find(|t| t.len() == count && fingerprint_of(t.iter().copied()) == fingerprint)
    {
        for (i, name) in old.iter().enumerate() {
            if let Some(j) = PARAMS.iter().position(|p| p.name == *name) {
                values[j] = value(i);
            }
        }
    } else {
        return (SlotState::BadVersion, None);
    }
    match Config::from_values(values, base) {
        Ok(c) => (SlotState::Valid(u32_at(r, 12)), Some(c)),
        Err(_) => (SlotState::BadValues, None),
    }
}

/// Reads both slots: the newest valid configuration and what each holds.
pub fn load<F: NorFlash>(flash: &mut F, base: &ServoConfig) -> Result<Loaded, FlashError> {
    let mut slots = [SlotState::Empty; 2];
    let mut best: Option<(Config, usize, u32)> = None;
    for (slot, state) in slots.iter_mut().enumerate() {
        let mut r = [0u8; RECORD_BYTES];
        flash.read(slot_addr(slot), &mut r)?;
        let (st, cfg) = decode(&r, base);
        *state = st;
        if let (SlotState::Valid(seq), Some(c)) = (st, cfg) {
            // Sequence numbers compare with wrap-around.
            if best.is_none_or(|(_, _, s)| seq.wrapping_sub(s) as i32 > 0) {
                best = Some((c, slot, seq));
            }
        }
    }
    Ok(Loaded {
        config: best.map(|(c, s, _)| (c, s)),
        slots,
    })
}

/// Saves `cfg` into the slot not holding the newest valid record; returns
/// the slot written. Erase, then the record without its CRC, then the CRC.
pub fn save<F: NorFlash>(
    flash: &mut F,
    cfg: &Config,
    base: &ServoConfig,
) -> Result<usize, FlashError> {
    let mut newest: Option<(usize, u32)> = None;
    for slot in 0..2 {
        let mut r = [0u8; RECORD_BYTES];
        flash.read(slot_addr(slot), &mut r)?;
        if let (SlotState::Valid(seq), _) = decode(&r, base) {
            if newest.is_none_or(|(_, s)| seq.wrapping_sub(s) as i32 > 0) {
                newest = Some((slot, seq));
            }
        }
    }
    let (slot, seq) = match newest {
        Some((s, seq)) => (1 - s, seq.wrapping_add(1)),
        None => (0, 1),
    };
    let rec = encode(cfg, seq);
    let addr = slot_addr(slot);
    flash.erase_sector(addr)?;
    let n = RECORD_BYTES - 4;
    flash.program(addr, &rec[..n])?;
    flash.program(addr + n as u32, &rec[n..])?;
    Ok(slot)
}

/// A flash whose erases and programs each take longer: `pause` runs before
/// and after every one. QEMU's flash model erases and programs at once,
/// where a part takes up to seconds per sector erase and milliseconds per
/// page; held apart, the steps of a save are wide enough for a power cut
/// to land between any two of them.
pub struct PacedFlash<F, P> {
    /// The flash.
    pub flash: F,
    /// Waits.
    pub pause: P,
}

impl<F: NorFlash, P: FnMut()> NorFlash for PacedFlash<F, P> {
    fn read(&mut self, addr: u32, buf: &mut [u8]) -> Result<(), FlashError> {
        self.flash.read(addr, buf)
    }
    fn erase_sector(&mut self, addr: u32) -> Result<(), FlashError> {
        (self.pause)();
        let r = self.flash.erase_sector(addr);
        (self.pause)();
        r
    }
    fn program(&mut self, addr: u32, data: &[u8]) -> Result<(), FlashError> {
        (self.pause)();
        let r = self.flash.program(addr, data);
        (self.pause)();
        r
    }
}

impl Config {
    /// A configuration from stored values, checked like [`Config::set`].
    pub fn from_values(values: [f64; N_PARAMS], base: &ServoConfig) -> Result<Self, ConfigError> {
        let c = Config { values };
        c.check(base)?;
        Ok(c)
    }
}

#[cfg(test)]
mod tests;
