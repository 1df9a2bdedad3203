//! Process data objects (CiA 301 v4.2 §7.2.2, objects 0x1400..=0x1A03): four
//! receive PDOs (RPDO) and four transmit PDOs (TPDO), each with a
//! communication parameter (0x1400 + n / 0x1800 + n) and a mapping
//! parameter (0x1600 + n / 0x1A00 + n), n = 0..=3.
//!
//! Communication parameter sub-indices: 1 COB-ID (UNSIGNED32: bit 31 = 1
//! PDO not valid, bit 30 = 1 no RTR allowed, bit 29 = 1 29-bit identifier,
//! refused here; bits 0..=10 the CAN-ID), 2 transmission type (UNSIGNED8:
//! 0 synchronous acyclic, 1..=240 synchronous every n-th SYNC, 254/255
//! event-driven; 241..=253 refused), TPDO only: 3 inhibit time (UNSIGNED16,
//! multiples of 100 µs), 5 event timer (UNSIGNED16, ms, 0 = off).
//!
//! A mapping entry is `index << 16 | sub << 8 | bit length`; sub 0 is the
//! number of valid entries. Remapping follows CiA 301's description of the mapping objects: make the
//! PDO not valid (COB-ID bit 31 = 1), write sub 0 = 0, write the entries,
//! write sub 0 = n, make the PDO valid. Mapping writes while the PDO is
//! valid, or entry writes while sub 0 is not 0, are refused with 0x0601
//! 0000; an object that does not exist, is not mappable, cannot be read
//! (TPDO) or written (RPDO), or whose length is not the entry's, with 0x0604
//! 0041; more than 64 bits in all with 0x0604 0042. Only whole-byte objects
//! are mapped. RPDOs may map the dummy entries 0x0002..=0x0007 (the integer
//! data type objects) to skip bytes.
//!
//! Mapped objects are packed in entry order, least significant byte first,
//! with no gaps.

use crate::od::{read_checked, write_checked, Abort, Access, DataType, Entry, ObjectDictionary};

/// Number of RPDOs and of TPDOs.
pub const PDOS: usize = 4;
/// Mapping entries per PDO.
pub const MAX_MAPPED: usize = 8;

/// COB-ID bit 31: PDO not valid.
pub const COB_INVALID: u32 = 1 << 31;
/// COB-ID bit 30: no RTR allowed.
pub const COB_NO_RTR: u32 = 1 << 30;
/// COB-ID bit 29: 29-bit identifier.
pub const COB_EXTENDED: u32 = 1 << 29;

/// Receive or transmit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dir {
    Rx,
    Tx,
}

/// Default COB-ID of PDO `n` (CiA 301 pre-defined connection set):
/// TPDO 0x180/0x280/0x380/0x480 + node, RPDO 0x200/0x300/0x400/0x500 + node.
pub const fn default_cob_id(dir: Dir, n: usize, node: u8) -> u16 {
    let base = match dir {
        Dir::Tx => 0x180,
        Dir::Rx => 0x200,
    };
    base + 0x100 * n as u16 + node as u16
}

/// CAN-IDs no PDO may use: those the CiA 301 pre-defined connection set restricts (NMT,
/// reserved ranges, default SDO, NMT error control, LSS) and the SYNC
/// identifier 0x080 this node consumes.
pub fn restricted_can_id(id: u16) -> bool {
    matches!(id, 0x000 | 0x001..=0x07F | 0x080 | 0x101..=0x180 | 0x581..=0x5FF | 0x601..=0x67F | 0x6E0..=0x6FF | 0x701..=0x77F | 0x780..=0x7FF)
}

/// One mapping entry, decoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mapped {
    pub index: u16,
    pub sub: u8,
    pub bits: u8,
}

impl Mapped {
    /// Decodes `index << 16 | sub << 8 | bits`.
    pub const fn from_u32(v: u32) -> Self {
        Self {
            index: (v >> 16) as u16,
            sub: (v >> 8) as u8,
            bits: v as u8,
        }
    }

    /// Encodes it.
    pub const fn to_u32(self) -> u32 {
        (self.index as u32) << 16 | (self.sub as u32) << 8 | self.bits as u32
    }

    /// True for the RPDO dummy entries 0x0002..=0x0007 (sub 0).
    fn dummy(&self) -> bool {
        matches!(self.index, 0x0002..=0x0007) && self.sub == 0
    }
}

/// One PDO's parameters and run-time state.
#[derive(Clone, Copy, Debug)]
pub struct Pdo {
    cob_id: u32,
    transmission_type: u8,
    inhibit_100us: u16,
    event_timer_ms: u16,
    count: u8,
    map: [u32; MAX_MAPPED],
    // Run time.
    sync_count: u8,
    event: bool,
    last_sent_us: Option<u64>,
    timer_due_us: Option<u64>,
    rx_pending: Option<([u8; 8], u8)>,
}

impl Pdo {
    fn new(cob: u16) -> Self {
        Self {
            cob_id: COB_INVALID | cob as u32,
            transmission_type: 255,
            inhibit_100us: 0,
            event_timer_ms: 0,
            count: 0,
            map: [0; MAX_MAPPED],
            sync_count: 0,
            event: false,
            last_sent_us: None,
            timer_due_us: None,
            rx_pending: None,
        }
    }

    /// Whether the PDO exists (COB-ID bit 31 = 0).
    pub fn valid(&self) -> bool {
        self.cob_id & COB_INVALID == 0
    }

    /// The 11-bit CAN-ID.
    pub fn can_id(&self) -> u16 {
        (self.cob_id & 0x7FF) as u16
    }

    /// Sub 1 of the communication parameter.
    pub fn cob_id(&self) -> u32 {
        self.cob_id
    }

    /// Sub 2 of the communication parameter.
    pub fn transmission_type(&self) -> u8 {
        self.transmission_type
    }

    /// The valid mapping entries.
    pub fn mapped(&self) -> impl Iterator<Item = Mapped> + '_ {
        self.map[..self.count as usize]
            .iter()
            .map(|&v| Mapped::from_u32(v))
    }

    /// Bytes of the PDO's data.
    pub fn len(&self) -> usize {
        self.mapped().map(|m| m.bits as usize / 8).sum()
    }

    /// True with no object mapped.
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    fn synchronous(&self) -> bool {
        self.transmission_type <= 240
    }
}

/// The node's PDOs.
#[derive(Clone, Copy, Debug)]
pub struct Pdos {
    rpdo: [Pdo; PDOS],
    tpdo: [Pdo; PDOS],
}

impl Pdos {
    /// All PDOs with their default COB-IDs, not valid, nothing mapped,
    /// transmission type 255.
    pub fn new(node: u8) -> Self {
        Self {
            rpdo: core::array::from_fn(|n| Pdo::new(default_cob_id(Dir::Rx, n, node))),
            tpdo: core::array::from_fn(|n| Pdo::new(default_cob_id(Dir::Tx, n, node))),
        }
    }

    /// PDO `n` in direction `dir`.
    pub fn get(&self, dir: Dir, n: usize) -> Option<&Pdo> {
        match dir {
            Dir::Rx => self.rpdo.get(n),
            Dir::Tx => self.tpdo.get(n),
        }
    }

    fn get_mut(&mut self, dir: Dir, n: usize) -> Option<&mut Pdo> {
        match dir {
            Dir::Rx => self.rpdo.get_mut(n),
            Dir::Tx => self.tpdo.get_mut(n),
        }
    }

    /// Sets a PDO up directly (the application's power-on defaults), made
    /// valid on its current CAN-ID. The mapping is not checked against the
    /// dictionary: the caller owns it. At most [`MAX_MAPPED`] entries are
    /// taken.
    pub fn configure(&mut self, dir: Dir, n: usize, transmission_type: u8, map: &[Mapped]) {
        if let Some(p) = self.get_mut(dir, n) {
            let k = map.len().min(MAX_MAPPED);
            p.map = [0; MAX_MAPPED];
            for (d, m) in p.map.iter_mut().zip(&map[..k]) {
                *d = m.to_u32();
            }
            p.count = k as u8;
            p.transmission_type = transmission_type;
            p.cob_id &= !COB_INVALID;
        }
    }

    /// Which PDO object (direction, number, is-mapping) `index` is.
    fn object(index: u16) -> Option<(Dir, usize, bool)> {
        let n = (index & 0x00FF) as usize;
        if n >= PDOS {
            return None;
        }
        match index & 0xFF00 {
            0x1400 => Some((Dir::Rx, n, false)),
            0x1600 => Some((Dir::Rx, n, true)),
            0x1800 => Some((Dir::Tx, n, false)),
            0x1A00 => Some((Dir::Tx, n, true)),
            _ => None,
        }
    }

    /// The description of a PDO parameter entry; `None` if `index` is not
    /// one of the PDO objects.
    pub fn entry(&self, index: u16, sub: u8) -> Option<Result<Entry, Abort>> {
        let (dir, _, mapping) = Self::object(index)?;
        let e = |dt, acc| Ok(Entry::new(index, sub, dt, acc));
        Some(match (mapping, dir, sub) {
            (true, _, 0) => {
                Ok(Entry::new(index, 0, DataType::Unsigned8, Access::Rw)
                    .range(0, MAX_MAPPED as i64))
            }
            (true, _, 1..=8) => e(DataType::Unsigned32, Access::Rw),
            (false, _, 0) => e(DataType::Unsigned8, Access::Const),
            (false, _, 1) => e(DataType::Unsigned32, Access::Rw),
            (false, _, 2) => e(DataType::Unsigned8, Access::Rw),
            (false, Dir::Tx, 3) => e(DataType::Unsigned16, Access::Rw),
            (false, Dir::Tx, 5) => e(DataType::Unsigned16, Access::Rw),
            _ => Err(Abort::SubindexDoesNotExist),
        })
    }

    /// Reads a PDO parameter entry (already known to exist).
    pub fn read(&self, index: u16, sub: u8, out: &mut [u8]) -> Result<usize, Abort> {
        let (dir, n, mapping) = Self::object(index).ok_or(Abort::ObjectDoesNotExist)?;
        let p = self.get(dir, n).ok_or(Abort::ObjectDoesNotExist)?;
        let mut put = |b: &[u8]| {
            out.get_mut(..b.len())
                .ok_or(Abort::General)?
                .copy_from_slice(b);
            Ok(b.len())
        };
        match (mapping, sub) {
            (true, 0) => put(&[p.count]),
            (true, 1..=8) => put(&p.map[sub as usize - 1].to_le_bytes()),
            // Highest sub-index supported.
            (false, 0) => put(&[if dir == Dir::Tx { 5 } else { 2 }]),
            (false, 1) => put(&p.cob_id.to_le_bytes()),
            (false, 2) => put(&[p.transmission_type]),
            (false, 3) => put(&p.inhibit_100us.to_le_bytes()),
            (false, 5) => put(&p.event_timer_ms.to_le_bytes()),
            _ => Err(Abort::SubindexDoesNotExist),
        }
    }

    /// For a write of a mapping entry (0x1600/0x1A00 sub 1..=8, 4 bytes),
    /// the object it would map, which the caller looks up and passes to
    /// [`Pdos::write`].
    pub fn mapping_target(index: u16, sub: u8, data: &[u8]) -> Option<Mapped> {
        let (_, _, true) = Self::object(index)? else {
            return None;
        };
        let b: [u8; 4] = data.try_into().ok()?;
        (1..=8)
            .contains(&sub)
            .then(|| Mapped::from_u32(u32::from_le_bytes(b)))
    }

    /// Writes a PDO parameter entry (length already checked). `target` is
    /// the dictionary's answer for [`Pdos::mapping_target`] when writing a
    /// mapping entry.
    pub fn write(
        &mut self,
        index: u16,
        sub: u8,
        data: &[u8],
        target: Option<Result<Entry, Abort>>,
    ) -> Result<(), Abort> {
        let (dir, n, mapping) = Self::object(index).ok_or(Abort::ObjectDoesNotExist)?;
        let p = self.get_mut(dir, n).ok_or(Abort::ObjectDoesNotExist)?;
        let mut b = [0u8; 4];
        let k = data.len().min(4);
        b[..k].copy_from_slice(&data[..k]);
        let v = u32::from_le_bytes(b);
        if mapping {
            if p.valid() {
                return Err(Abort::UnsupportedAccess);
            }
            if sub == 0 {
                let count = v as usize;
                if count > MAX_MAPPED {
                    return Err(Abort::ValueTooHigh);
                }
                let mut bits = 0usize;
                for &e in &p.map[..count] {
                    let m = Mapped::from_u32(e);
                    if m.index == 0 {
                        return Err(Abort::CannotMap);
                    }
                    bits += m.bits as usize;
                }
                if bits > 64 {
                    return Err(Abort::MapTooLong);
                }
                p.count = count as u8;
                return Ok(());
            }
            if p.count != 0 {
                return Err(Abort::UnsupportedAccess);
            }
            if !(1..=MAX_MAPPED as u8).contains(&sub) {
                return Err(Abort::SubindexDoesNotExist);
            }
            if v != 0 {
                check_mappable(dir, Mapped::from_u32(v), target)?;
            }
            let slot = p
                .map
                .get_mut((sub as usize).wrapping_sub(1))
                .ok_or(Abort::SubindexDoesNotExist)?;
            *slot = v;
            return Ok(());
        }
        match sub {
            1 => {
                if v & COB_EXTENDED != 0 {
                    return Err(Abort::ValueRange);
                }
                let new_id = (v & 0x7FF) as u16;
                if p.valid() && v & COB_INVALID == 0 && new_id != p.can_id() {
                    // CiA 301, 0x1400/0x1800 sub 1: the CAN-ID may only change while
                    // the PDO is not valid.
                    return Err(Abort::ValueRange);
                }
                if v & COB_INVALID == 0 && restricted_can_id(new_id) {
                    return Err(Abort::ValueRange);
                }
                p.cob_id = v & (COB_INVALID | COB_NO_RTR | 0x7FF);
                p.sync_count = 0;
                p.event = false;
                p.rx_pending = None;
                p.timer_due_us = None;
                Ok(())
            }
            2 => {
                let t = v as u8;
                if !(t <= 240 || t >= 254) {
                    return Err(Abort::ValueRange);
                }
                p.transmission_type = t;
                p.sync_count = 0;
                Ok(())
            }
            3 if dir == Dir::Tx => {
                p.inhibit_100us = v as u16;
                Ok(())
            }
            5 if dir == Dir::Tx => {
                p.event_timer_ms = v as u16;
                p.timer_due_us = None;
                Ok(())
            }
            _ => Err(Abort::SubindexDoesNotExist),
        }
    }

    /// The RPDO a frame with CAN-ID `id` belongs to (valid ones only).
    pub fn rpdo_for(&self, id: u16) -> Option<usize> {
        self.rpdo.iter().position(|p| p.valid() && p.can_id() == id)
    }

    /// Handles a received RPDO frame: event-driven RPDOs (254/255) are
    /// written to the dictionary at once; synchronous ones are held until
    /// the next SYNC ([`Pdos::on_sync_rx`]). A frame shorter than the
    /// mapping is not processed: `Err(())`, for which CiA 301 has
    /// the EMCY 0x8210. Bytes beyond the mapping are ignored. Objects the
    /// dictionary refuses are skipped.
    #[allow(clippy::result_unit_err)]
    pub fn on_rpdo<D: ObjectDictionary + ?Sized>(
        &mut self,
        n: usize,
        data: &[u8],
        od: &mut D,
    ) -> Result<(), ()> {
        let Some(p) = self.rpdo.get_mut(n) else {
            return Ok(());
        };
        if data.len() < p.len() {
            return Err(());
        }
        if p.synchronous() {
            let mut b = [0u8; 8];
            b[..data.len()].copy_from_slice(data);
            p.rx_pending = Some((b, data.len() as u8));
            return Ok(());
        }
        unpack(p, data, od);
        Ok(())
    }

    /// At a SYNC: writes the data synchronous RPDOs received since the
    /// last one.
    pub fn on_sync_rx<D: ObjectDictionary + ?Sized>(&mut self, od: &mut D) {
        for p in self.rpdo.iter_mut() {
            if let Some((b, len)) = p.rx_pending.take() {
                if p.valid() {
                    unpack(p, &b[..len as usize], od);
                }
            }
        }
    }

    /// At a SYNC: the TPDOs due, as a bit mask (bit n = TPDO n). Type n in
    /// 1..=240 is due at every n-th SYNC; type 0 at the SYNC after an event
    /// ([`Pdos::trigger`]).
    pub fn on_sync_tx(&mut self) -> u8 {
        let mut due = 0;
        for (i, p) in self.tpdo.iter_mut().enumerate() {
            if !p.valid() || p.count == 0 || !p.synchronous() {
                continue;
            }
            let fire = if p.transmission_type == 0 {
                core::mem::take(&mut p.event)
            } else {
                p.sync_count += 1;
                if p.sync_count >= p.transmission_type {
                    p.sync_count = 0;
                    true
                } else {
                    false
                }
            };
            if fire {
                due |= 1 << i;
            }
        }
        due
    }

    /// Marks an application event for TPDO `n` (sent at the next SYNC for
    /// type 0, at the next tick after the inhibit time for 254/255).
    pub fn trigger(&mut self, n: usize) {
        if let Some(p) = self.tpdo.get_mut(n) {
            p.event = true;
        }
    }

    /// The event-driven TPDOs (254/255) due at `now_us`, as a bit mask: on
    /// an event or when the event timer (sub 5) ran out, and not before the
    /// inhibit time (sub 3) since the last transmission. The caller sends
    /// them, so they count as sent now.
    pub fn tick(&mut self, now_us: u64) -> u8 {
        let mut due = 0;
        for (i, p) in self.tpdo.iter_mut().enumerate() {
            if !p.valid() || p.count == 0 || p.synchronous() {
                continue;
            }
            let period = p.event_timer_ms as u64 * 1000;
            if period != 0 && p.timer_due_us.is_none() {
                p.timer_due_us = Some(now_us.saturating_add(period));
            }
            let timer = matches!(p.timer_due_us, Some(t) if now_us >= t);
            let inhibited = matches!(p.last_sent_us,
                Some(t) if now_us < t.saturating_add(p.inhibit_100us as u64 * 100));
            if (p.event || timer) && !inhibited {
                p.event = false;
                p.last_sent_us = Some(now_us);
                p.timer_due_us = (period != 0).then_some(now_us.saturating_add(period));
                due |= 1 << i;
            }
        }
        due
    }

    /// Builds TPDO `n`'s data from the dictionary; `None` when the PDO is
    /// not valid, empty, or an object cannot be read.
    pub fn pack<D: ObjectDictionary + ?Sized>(
        &self,
        n: usize,
        od: &mut D,
    ) -> Option<(u16, [u8; 8], usize)> {
        let p = self.tpdo.get(n)?;
        if !p.valid() || p.count == 0 {
            return None;
        }
        let mut out = [0u8; 8];
        let mut pos = 0;
        for m in p.mapped() {
            let len = m.bits as usize / 8;
            let mut tmp = [0u8; 8];
            let got = read_checked(od, m.index, m.sub, &mut tmp).ok()?;
            if got != len || pos + len > 8 {
                return None;
            }
            out[pos..pos + len].copy_from_slice(&tmp[..len]);
            pos += len;
        }
        Some((p.can_id(), out, pos))
    }

    /// Resets the run-time state (NMT state changes).
    pub fn clear_runtime(&mut self) {
        for p in self.rpdo.iter_mut().chain(self.tpdo.iter_mut()) {
            p.sync_count = 0;
            p.event = false;
            p.last_sent_us = None;
            p.timer_due_us = None;
            p.rx_pending = None;
        }
    }
}

fn check_mappable(dir: Dir, m: Mapped, target: Option<Result<Entry, Abort>>) -> Result<(), Abort> {
    if m.bits == 0 || m.bits % 8 != 0 {
        return Err(Abort::CannotMap);
    }
    if dir == Dir::Rx && m.dummy() {
        let size = match m.index {
            0x0002 | 0x0005 => 1,
            0x0003 | 0x0006 => 2,
            _ => 4,
        };
        return if m.bits as usize == size * 8 {
            Ok(())
        } else {
            Err(Abort::CannotMap)
        };
    }
    let e = match target {
        Some(Ok(e)) => e,
        _ => return Err(Abort::CannotMap),
    };
    let access_ok = match dir {
        Dir::Rx => e.access.writable(),
        Dir::Tx => e.access.readable(),
    };
    if !e.pdo_mappable || !access_ok || e.bits() != m.bits {
        return Err(Abort::CannotMap);
    }
    Ok(())
}

fn unpack<D: ObjectDictionary + ?Sized>(p: &Pdo, data: &[u8], od: &mut D) {
    let mut pos = 0;
    for m in p.mapped() {
        let len = m.bits as usize / 8;
        let Some(bytes) = data.get(pos..pos + len) else {
            return;
        };
        if !m.dummy() {
            let _ = write_checked(od, m.index, m.sub, bytes);
        }
        pos += len;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::od::testod::TestOd;

    /// Writes a PDO parameter as the node does: entry check, then write.
    fn sdo_write(p: &mut Pdos, od: &TestOd, index: u16, sub: u8, v: u32) -> Result<(), Abort> {
        let e = p.entry(index, sub).unwrap()?;
        let bytes = v.to_le_bytes();
        let data = &bytes[..e.data_type.size().unwrap()];
        crate::od::check_value(&e, data)?;
        let target = Pdos::mapping_target(index, sub, data).map(|m| od.entry(m.index, m.sub));
        p.write(index, sub, data, target)
    }

    fn read_u32(p: &Pdos, index: u16, sub: u8) -> u32 {
        let mut b = [0u8; 4];
        let n = p.read(index, sub, &mut b).unwrap();
        assert!(n <= 4);
        u32::from_le_bytes(b)
    }

    #[test]
    fn default_cob_ids() {
        // CiA 301 pre-defined connection set, node 0x10.
        let p = Pdos::new(0x10);
        let expect_t = [0x190, 0x290, 0x390, 0x490];
        let expect_r = [0x210, 0x310, 0x410, 0x510];
        for n in 0..4 {
            assert_eq!(
                read_u32(&p, 0x1800 + n as u16, 1),
                0x8000_0000 | expect_t[n]
            );
            assert_eq!(
                read_u32(&p, 0x1400 + n as u16, 1),
                0x8000_0000 | expect_r[n]
            );
        }
        assert_eq!(read_u32(&p, 0x1800, 0), 5);
        assert_eq!(read_u32(&p, 0x1400, 0), 2);
        assert_eq!(read_u32(&p, 0x1800, 2), 255);
        assert!(p.entry(0x1804, 1).is_none());
        assert!(p.entry(0x1C00, 1).is_none());
        assert_eq!(p.entry(0x1800, 4), Some(Err(Abort::SubindexDoesNotExist)));
        assert_eq!(p.entry(0x1400, 3), Some(Err(Abort::SubindexDoesNotExist)));
        assert_eq!(p.entry(0x1A00, 9), Some(Err(Abort::SubindexDoesNotExist)));
    }

    #[test]
    fn remapping_procedure_and_packing() {
        let mut p = Pdos::new(1);
        let mut od = TestOd {
            i16_2000: 0x1234,
            u32_2001: 0xAABB_CCDD,
            b_2004: 1,
            ..Default::default()
        };
        // TPDO1 mapping: 0x2000 sub 0 16 bits, 0x2001 sub 0 32 bits,
        // 0x2004 sub 0 8 bits.
        assert_eq!(sdo_write(&mut p, &od, 0x1A00, 0, 0), Ok(()));
        assert_eq!(sdo_write(&mut p, &od, 0x1A00, 1, 0x2000_0010), Ok(()));
        assert_eq!(sdo_write(&mut p, &od, 0x1A00, 2, 0x2001_0020), Ok(()));
        assert_eq!(sdo_write(&mut p, &od, 0x1A00, 3, 0x2004_0008), Ok(()));
        assert_eq!(sdo_write(&mut p, &od, 0x1A00, 0, 3), Ok(()));
        assert_eq!(sdo_write(&mut p, &od, 0x1800, 1, 0x0000_0181), Ok(()));
        assert!(p.get(Dir::Tx, 0).unwrap().valid());
        // Little-endian, in entry order: 34 12 | DD CC BB AA | 01.
        let (id, data, len) = p.pack(0, &mut od).unwrap();
        assert_eq!(id, 0x181);
        assert_eq!(&data[..len], &[0x34, 0x12, 0xDD, 0xCC, 0xBB, 0xAA, 0x01]);
        assert_eq!(read_u32(&p, 0x1A00, 0), 3);
        assert_eq!(read_u32(&p, 0x1A00, 2), 0x2001_0020);
    }

    #[test]
    fn remapping_refusals() {
        let mut p = Pdos::new(1);
        let od = TestOd::default();
        // Not mappable (0x2003 string), does not exist, write-only in a
        // TPDO, read-only in an RPDO, wrong bit length, not whole bytes.
        let bad_tx = [
            0x2003_0008,
            0x2999_0010,
            0x2002_0008,
            0x2000_0020,
            0x2000_0004,
        ];
        for v in bad_tx {
            assert_eq!(
                sdo_write(&mut p, &od, 0x1A01, 1, v),
                Err(Abort::CannotMap),
                "{v:#x}"
            );
        }
        assert_eq!(
            sdo_write(&mut p, &od, 0x1601, 1, 0x2006_0120),
            Err(Abort::CannotMap)
        );
        // The dummy UNSIGNED16 (0x0006) in an RPDO, not in a TPDO.
        assert_eq!(sdo_write(&mut p, &od, 0x1601, 1, 0x0006_0010), Ok(()));
        assert_eq!(
            sdo_write(&mut p, &od, 0x1A01, 1, 0x0006_0010),
            Err(Abort::CannotMap)
        );
        assert_eq!(
            sdo_write(&mut p, &od, 0x1601, 2, 0x0006_0008),
            Err(Abort::CannotMap)
        );
        // 3 x 32 bits = 96 > 64.
        for s in 1..=3 {
            sdo_write(&mut p, &od, 0x1A02, s, 0x2001_0020).unwrap();
        }
        assert_eq!(sdo_write(&mut p, &od, 0x1A02, 0, 3), Err(Abort::MapTooLong));
        assert_eq!(read_u32(&p, 0x1A02, 0), 0);
        // Sub 0 over 8; sub 0 over an empty entry.
        assert_eq!(
            sdo_write(&mut p, &od, 0x1A02, 0, 9),
            Err(Abort::ValueTooHigh)
        );
        assert_eq!(sdo_write(&mut p, &od, 0x1A03, 0, 1), Err(Abort::CannotMap));
        // Entries while sub 0 != 0.
        sdo_write(&mut p, &od, 0x1A02, 0, 2).unwrap();
        assert_eq!(
            sdo_write(&mut p, &od, 0x1A02, 1, 0x2000_0010),
            Err(Abort::UnsupportedAccess)
        );
        // Any mapping write while the PDO is valid.
        sdo_write(&mut p, &od, 0x1802, 1, 0x381).unwrap();
        assert_eq!(
            sdo_write(&mut p, &od, 0x1A02, 0, 0),
            Err(Abort::UnsupportedAccess)
        );
        assert_eq!(read_u32(&p, 0x1A02, 0), 2);
        // Direct calls with sub-indices the entry check would have refused.
        assert_eq!(
            p.write(0x1A03, 9, &[0; 4], None),
            Err(Abort::SubindexDoesNotExist)
        );
        assert_eq!(
            p.write(0x1803, 0, &[0], None),
            Err(Abort::SubindexDoesNotExist)
        );
    }

    #[test]
    fn cob_id_and_type_rules() {
        let mut p = Pdos::new(1);
        let od = TestOd::default();
        // 29-bit frames are not supported.
        assert_eq!(
            sdo_write(&mut p, &od, 0x1800, 1, 0x2000_0181),
            Err(Abort::ValueRange)
        );
        // Restricted CAN-IDs: 0x080 (SYNC), 0x601 (SDO), 0x701 (heartbeat).
        for id in [0x080u32, 0x601, 0x701, 0x7FF] {
            assert_eq!(
                sdo_write(&mut p, &od, 0x1800, 1, id),
                Err(Abort::ValueRange)
            );
        }
        // A not-valid COB-ID may carry any identifier.
        assert_eq!(sdo_write(&mut p, &od, 0x1800, 1, 0x8000_0701), Ok(()));
        assert_eq!(sdo_write(&mut p, &od, 0x1800, 1, 0x0000_0185), Ok(()));
        // Changing the CAN-ID of a valid PDO is refused; bit 31 alone is not.
        assert_eq!(
            sdo_write(&mut p, &od, 0x1800, 1, 0x0000_0186),
            Err(Abort::ValueRange)
        );
        assert_eq!(sdo_write(&mut p, &od, 0x1800, 1, 0x8000_0185), Ok(()));
        // Transmission types: 241..=253 refused.
        for t in [241u32, 251, 252, 253] {
            assert_eq!(sdo_write(&mut p, &od, 0x1800, 2, t), Err(Abort::ValueRange));
        }
        for t in [0u32, 1, 240, 254, 255] {
            assert_eq!(sdo_write(&mut p, &od, 0x1800, 2, t), Ok(()));
        }
        assert_eq!(sdo_write(&mut p, &od, 0x1800, 3, 50), Ok(()));
        assert_eq!(read_u32(&p, 0x1800, 3), 50);
        assert_eq!(sdo_write(&mut p, &od, 0x1800, 5, 20), Ok(()));
        assert_eq!(read_u32(&p, 0x1800, 5), 20);
    }

    #[test]
    fn sync_transmission_types() {
        let mut p = Pdos::new(1);
        let m = [Mapped {
            index: 0x2000,
            sub: 0,
            bits: 16,
        }];
        p.configure(Dir::Tx, 0, 1, &m);
        p.configure(Dir::Tx, 1, 3, &m);
        p.configure(Dir::Tx, 2, 0, &m);
        p.configure(Dir::Tx, 3, 255, &m);
        // SYNC 1: TPDO0 (every) ; 2: TPDO0 ; 3: TPDO0 + TPDO1.
        assert_eq!(p.on_sync_tx(), 0b0001);
        assert_eq!(p.on_sync_tx(), 0b0001);
        assert_eq!(p.on_sync_tx(), 0b0011);
        // Type 0: only after an event.
        p.trigger(2);
        assert_eq!(p.on_sync_tx(), 0b0101);
        assert_eq!(p.on_sync_tx(), 0b0001);
    }

    #[test]
    fn event_timer_and_inhibit_time() {
        let mut p = Pdos::new(1);
        let od = TestOd::default();
        let m = [Mapped {
            index: 0x2000,
            sub: 0,
            bits: 16,
        }];
        p.configure(Dir::Tx, 0, 255, &m);
        // Inhibit 100 x 100 us = 10 ms; event timer 50 ms.
        sdo_write(&mut p, &od, 0x1800, 3, 100).unwrap();
        sdo_write(&mut p, &od, 0x1800, 5, 50).unwrap();
        assert_eq!(p.tick(0), 0);
        p.trigger(0);
        assert_eq!(p.tick(1_000), 1);
        p.trigger(0);
        assert_eq!(p.tick(10_999), 0);
        assert_eq!(p.tick(11_000), 1);
        // Timer: 50 ms after the last transmission.
        assert_eq!(p.tick(60_999), 0);
        assert_eq!(p.tick(61_000), 1);
        // Not on SYNC.
        assert_eq!(p.on_sync_tx(), 0);
    }

    #[test]
    fn rpdo_event_and_synchronous_and_short() {
        let mut p = Pdos::new(1);
        let mut od = TestOd::default();
        // RPDO0: 0x2000 (16) + dummy 8 bits + 0x2008 (8), event-driven.
        p.configure(
            Dir::Rx,
            0,
            255,
            &[
                Mapped {
                    index: 0x2000,
                    sub: 0,
                    bits: 16,
                },
                Mapped {
                    index: 0x0005,
                    sub: 0,
                    bits: 8,
                },
                Mapped {
                    index: 0x2008,
                    sub: 0,
                    bits: 8,
                },
            ],
        );
        assert_eq!(p.rpdo_for(0x201), Some(0));
        assert_eq!(p.rpdo_for(0x301), None);
        assert_eq!(p.on_rpdo(0, &[0x2C, 0x01, 0xEE, 0xFF], &mut od), Ok(()));
        assert_eq!(od.i16_2000, 300);
        assert_eq!(od.i8_2008, -1);
        // 3 bytes < 4: not processed.
        assert_eq!(p.on_rpdo(0, &[0x01, 0x00, 0x00], &mut od), Err(()));
        assert_eq!(od.i16_2000, 300);
        // Out of range values (0x03E9 = 1001) are skipped, the rest written.
        assert_eq!(p.on_rpdo(0, &[0xE9, 0x03, 0x00, 0x05], &mut od), Ok(()));
        assert_eq!(od.i16_2000, 300);
        assert_eq!(od.i8_2008, 5);
        // Synchronous: held until the SYNC.
        p.configure(
            Dir::Rx,
            1,
            1,
            &[Mapped {
                index: 0x2001,
                sub: 0,
                bits: 32,
            }],
        );
        assert_eq!(p.on_rpdo(1, &[1, 0, 0, 0], &mut od), Ok(()));
        assert_eq!(od.u32_2001, 0);
        p.on_sync_rx(&mut od);
        assert_eq!(od.u32_2001, 1);
    }
}
