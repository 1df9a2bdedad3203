//! The object dictionary (CiA 301 v4.2 §7.4): what an entry is (index,
//! sub-index, data type, access, PDO-mappability, value range), the trait
//! through which the application exposes its objects (so the drive's state
//! stays the source of truth and no copy of it lives here), a static table
//! type to describe entries, and the checks every SDO or PDO access goes
//! through. Values travel as little-endian bytes, as on the bus
//! (CiA 301: basic data types are transferred least significant
//! byte first).

/// SDO abort codes (CiA 301 v4.2 §7.2.4, Table 22). Every refusal of
/// an access is one of these, so the SDO server can send it unchanged.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u32)]
pub enum Abort {
    /// 0x0503 0000: toggle bit not alternated.
    ToggleNotAlternated = 0x0503_0000,
    /// 0x0504 0001: client/server command specifier not valid or unknown.
    InvalidCommand = 0x0504_0001,
    /// 0x0601 0000: unsupported access to an object.
    UnsupportedAccess = 0x0601_0000,
    /// 0x0601 0001: attempt to read a write-only object.
    ReadWriteOnly = 0x0601_0001,
    /// 0x0601 0002: attempt to write a read-only object.
    WriteReadOnly = 0x0601_0002,
    /// 0x0602 0000: object does not exist in the object dictionary.
    ObjectDoesNotExist = 0x0602_0000,
    /// 0x0604 0041: object cannot be mapped to the PDO.
    CannotMap = 0x0604_0041,
    /// 0x0604 0042: the number and length of the objects to be mapped
    /// would exceed the PDO length.
    MapTooLong = 0x0604_0042,
    /// 0x0604 0043: general parameter incompatibility.
    ParameterIncompatible = 0x0604_0043,
    /// 0x0607 0010: data type does not match, length of service parameter
    /// does not match.
    TypeMismatch = 0x0607_0010,
    /// 0x0607 0012: data type does not match, length too high.
    TooLong = 0x0607_0012,
    /// 0x0607 0013: data type does not match, length too low.
    TooShort = 0x0607_0013,
    /// 0x0609 0011: sub-index does not exist.
    SubindexDoesNotExist = 0x0609_0011,
    /// 0x0609 0030: invalid value for parameter (value range exceeded).
    ValueRange = 0x0609_0030,
    /// 0x0609 0031: value of parameter written too high.
    ValueTooHigh = 0x0609_0031,
    /// 0x0609 0032: value of parameter written too low.
    ValueTooLow = 0x0609_0032,
    /// 0x0800 0000: general error.
    General = 0x0800_0000,
    /// 0x0800 0020: data cannot be transferred or stored to the
    /// application (for 0x1010/0x1011: the signature is not "save"/"load").
    CannotStore = 0x0800_0020,
    /// 0x0800 0022: data cannot be transferred or stored because of the
    /// present device state.
    WrongDeviceState = 0x0800_0022,
    /// 0x0800 0024: no data available.
    NoData = 0x0800_0024,
}

impl Abort {
    /// The 32-bit code as sent in an abort frame.
    pub fn code(self) -> u32 {
        self as u32
    }
}

/// Basic data types (CiA 301 v4.2 §7.4; the number is the
/// index of the data type definition object).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DataType {
    /// 0x0001, one byte 0 or 1.
    Boolean,
    /// 0x0002.
    Integer8,
    /// 0x0003.
    Integer16,
    /// 0x0004.
    Integer32,
    /// 0x0005.
    Unsigned8,
    /// 0x0006.
    Unsigned16,
    /// 0x0007.
    Unsigned32,
    /// 0x0008, IEEE 754 single precision.
    Real32,
    /// 0x0009, ISO 646 characters; the number is the capacity in bytes.
    /// A shorter value is accepted (its length is the transfer's length).
    VisibleString(u8),
}

impl DataType {
    /// Size in bytes of a fixed-size type; `None` for strings.
    pub const fn size(self) -> Option<usize> {
        match self {
            DataType::Boolean | DataType::Integer8 | DataType::Unsigned8 => Some(1),
            DataType::Integer16 | DataType::Unsigned16 => Some(2),
            DataType::Integer32 | DataType::Unsigned32 | DataType::Real32 => Some(4),
            DataType::VisibleString(_) => None,
        }
    }

    /// Largest number of bytes a value of this type can have.
    pub const fn capacity(self) -> usize {
        match self {
            DataType::VisibleString(n) => n as usize,
            other => match other.size() {
                Some(n) => n,
                None => 0,
            },
        }
    }

    /// The data type's index in the dictionary (0x0001..=0x0009).
    pub const fn code(self) -> u16 {
        match self {
            DataType::Boolean => 0x0001,
            DataType::Integer8 => 0x0002,
            DataType::Integer16 => 0x0003,
            DataType::Integer32 => 0x0004,
            DataType::Unsigned8 => 0x0005,
            DataType::Unsigned16 => 0x0006,
            DataType::Unsigned32 => 0x0007,
            DataType::Real32 => 0x0008,
            DataType::VisibleString(_) => 0x0009,
        }
    }

    /// The integer value of `bytes` (little-endian, sign-extended for the
    /// INTEGER types); `None` for REAL32, strings or a wrong length.
    pub fn decode_int(self, bytes: &[u8]) -> Option<i64> {
        if Some(bytes.len()) != self.size() {
            return None;
        }
        let mut b = [0u8; 4];
        b[..bytes.len()].copy_from_slice(bytes);
        let u = u32::from_le_bytes(b);
        Some(match self {
            DataType::Boolean | DataType::Unsigned8 | DataType::Unsigned16 => u as i64,
            DataType::Unsigned32 => u as i64,
            DataType::Integer8 => u as u8 as i8 as i64,
            DataType::Integer16 => u as u16 as i16 as i64,
            DataType::Integer32 => u as i32 as i64,
            DataType::Real32 | DataType::VisibleString(_) => return None,
        })
    }
}

/// Access type of an entry (CiA 301 v4.2 §7.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Access {
    /// Read only (the value may change, e.g. a statusword).
    Ro,
    /// Write only.
    Wo,
    /// Read and write.
    Rw,
    /// Read only, value never changes.
    Const,
}

impl Access {
    /// Whether an SDO upload or a TPDO may read it.
    pub const fn readable(self) -> bool {
        !matches!(self, Access::Wo)
    }

    /// Whether an SDO download or an RPDO may write it.
    pub const fn writable(self) -> bool {
        matches!(self, Access::Wo | Access::Rw)
    }
}

/// The allowed values of a numeric entry, inclusive, in the entry's own
/// unit. Checked on every write before the application sees the value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Limits {
    /// The whole range of the data type.
    None,
    /// For the integer types.
    Int { min: i64, max: i64 },
    /// For REAL32 (NaN is refused as out of range).
    Real { min: f32, max: f32 },
}

/// One object dictionary entry's description.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Entry {
    pub index: u16,
    pub sub: u8,
    pub data_type: DataType,
    pub access: Access,
    /// Whether the entry may be mapped into a PDO.
    pub pdo_mappable: bool,
    pub limits: Limits,
}

impl Entry {
    /// A non-mappable entry without limits.
    pub const fn new(index: u16, sub: u8, data_type: DataType, access: Access) -> Self {
        Self {
            index,
            sub,
            data_type,
            access,
            pdo_mappable: false,
            limits: Limits::None,
        }
    }

    /// The same entry, PDO-mappable.
    pub const fn mappable(mut self) -> Self {
        self.pdo_mappable = true;
        self
    }

    /// The same entry with integer limits (inclusive).
    pub const fn range(mut self, min: i64, max: i64) -> Self {
        self.limits = Limits::Int { min, max };
        self
    }

    /// The same entry with REAL32 limits (inclusive).
    pub const fn real_range(mut self, min: f32, max: f32) -> Self {
        self.limits = Limits::Real { min, max };
        self
    }

    /// Bit length of the value as a PDO mapping entry states it; 0 for
    /// strings (never mappable here).
    pub fn bits(&self) -> u8 {
        match self.data_type.size() {
            Some(n) => (n * 8) as u8,
            None => 0,
        }
    }
}

/// The application's objects. The implementation describes its entries
/// (usually through a [`Table`]) and reads and writes the values where they
/// live. `read` and `write` are only called after [`read_checked`] /
/// [`write_checked`] validated access, length and range against
/// [`ObjectDictionary::entry`]; they may still refuse with any [`Abort`],
/// e.g. [`Abort::WrongDeviceState`].
pub trait ObjectDictionary {
    /// The description of (index, sub); [`Abort::ObjectDoesNotExist`] when
    /// the index is unknown, [`Abort::SubindexDoesNotExist`] when only the
    /// sub-index is.
    fn entry(&self, index: u16, sub: u8) -> Result<Entry, Abort>;
    /// Writes the value's little-endian bytes into `out` (at least the
    /// type's capacity long) and returns how many.
    fn read(&mut self, index: u16, sub: u8, out: &mut [u8]) -> Result<usize, Abort>;
    /// Stores a value (little-endian bytes, length already checked).
    fn write(&mut self, index: u16, sub: u8, data: &[u8]) -> Result<(), Abort>;
}

/// A static list of entry descriptions, searched by (index, sub).
#[derive(Clone, Copy, Debug)]
pub struct Table<'a> {
    entries: &'a [Entry],
}

impl<'a> Table<'a> {
    /// A table over `entries` (any order).
    pub const fn new(entries: &'a [Entry]) -> Self {
        Self { entries }
    }

    /// The description of (index, sub), or which of the two is unknown.
    pub fn entry(&self, index: u16, sub: u8) -> Result<Entry, Abort> {
        let mut index_known = false;
        for e in self.entries {
            if e.index == index {
                if e.sub == sub {
                    return Ok(*e);
                }
                index_known = true;
            }
        }
        Err(if index_known {
            Abort::SubindexDoesNotExist
        } else {
            Abort::ObjectDoesNotExist
        })
    }

    /// All entries.
    pub fn entries(&self) -> &'a [Entry] {
        self.entries
    }
}

/// Reads (index, sub) for an SDO upload or a TPDO: refuses write-only
/// entries ([`Abort::ReadWriteOnly`]), an `out` shorter than the type's
/// capacity and a value the application returned with the wrong length
/// ([`Abort::General`]).
pub fn read_checked<D: ObjectDictionary + ?Sized>(
    od: &mut D,
    index: u16,
    sub: u8,
    out: &mut [u8],
) -> Result<usize, Abort> {
    let e = od.entry(index, sub)?;
    if !e.access.readable() {
        return Err(Abort::ReadWriteOnly);
    }
    if out.len() < e.data_type.capacity() {
        // The caller's buffer cannot hold the value.
        return Err(Abort::General);
    }
    let n = od.read(index, sub, out)?;
    match e.data_type.size() {
        Some(s) if s != n => Err(Abort::General),
        None if n > e.data_type.capacity() => Err(Abort::General),
        _ => Ok(n),
    }
}

/// Checks a value against an entry's type and limits without storing it:
/// length (fixed types must match exactly; strings up to their capacity),
/// BOOLEAN 0/1, the limits.
pub fn check_value(e: &Entry, data: &[u8]) -> Result<(), Abort> {
    match e.data_type.size() {
        Some(s) if data.len() > s => return Err(Abort::TooLong),
        Some(s) if data.len() < s => return Err(Abort::TooShort),
        None if data.len() > e.data_type.capacity() => return Err(Abort::TooLong),
        _ => {}
    }
    if e.data_type == DataType::Boolean && data[0] > 1 {
        return Err(Abort::ValueRange);
    }
    match e.limits {
        Limits::None => {}
        Limits::Int { min, max } => {
            let v = e.data_type.decode_int(data).ok_or(Abort::General)?;
            if v > max {
                return Err(Abort::ValueTooHigh);
            }
            if v < min {
                return Err(Abort::ValueTooLow);
            }
        }
        Limits::Real { min, max } => {
            if e.data_type != DataType::Real32 {
                return Err(Abort::General);
            }
            let v = f32::from_le_bytes([data[0], data[1], data[2], data[3]]);
            if v.is_nan() {
                return Err(Abort::ValueRange);
            }
            if v > max {
                return Err(Abort::ValueTooHigh);
            }
            if v < min {
                return Err(Abort::ValueTooLow);
            }
        }
    }
    Ok(())
}

/// Writes (index, sub) for an SDO download or an RPDO: refuses read-only
/// and constant entries ([`Abort::WriteReadOnly`]), then
/// [`check_value`], then hands the value to the application.
pub fn write_checked<D: ObjectDictionary + ?Sized>(
    od: &mut D,
    index: u16,
    sub: u8,
    data: &[u8],
) -> Result<(), Abort> {
    let e = od.entry(index, sub)?;
    if !e.access.writable() {
        return Err(Abort::WriteReadOnly);
    }
    check_value(&e, data)?;
    od.write(index, sub, data)
}

#[cfg(test)]
pub(crate) mod testod {
    //! A small application dictionary the tests of every module share.
    use super::*;

    pub const ENTRIES: &[Entry] = &[
        // Device type (CiA 301 object 0x1000): CiA 402 drive, 0x0002_0192.
        Entry::new(0x1000, 0, DataType::Unsigned32, Access::Const),
        Entry::new(0x2000, 0, DataType::Integer16, Access::Rw)
            .mappable()
            .range(-1000, 1000),
        Entry::new(0x2001, 0, DataType::Unsigned32, Access::Rw).mappable(),
        Entry::new(0x2002, 0, DataType::Unsigned8, Access::Wo).mappable(),
        Entry::new(0x2003, 0, DataType::VisibleString(20), Access::Rw),
        Entry::new(0x2004, 0, DataType::Boolean, Access::Rw).mappable(),
        Entry::new(0x2005, 0, DataType::Real32, Access::Rw)
            .mappable()
            .real_range(-1.5, 2.5),
        Entry::new(0x2006, 1, DataType::Integer32, Access::Ro).mappable(),
        Entry::new(0x2006, 2, DataType::Unsigned16, Access::Rw),
        Entry::new(0x2007, 0, DataType::Unsigned32, Access::Rw).mappable(),
        Entry::new(0x2008, 0, DataType::Integer8, Access::Rw).mappable(),
        // Its read returns 3 bytes: an application bug the checks catch.
        Entry::new(0x2009, 0, DataType::Unsigned32, Access::Ro).mappable(),
    ];

    /// Values kept as plain fields; `refuse` makes every write fail with
    /// that code, to test that application refusals pass through.
    #[derive(Default, Debug)]
    pub struct TestOd {
        pub i16_2000: i16,
        pub u32_2001: u32,
        pub u8_2002: u8,
        pub s_2003: [u8; 20],
        pub s_2003_len: usize,
        pub b_2004: u8,
        pub f_2005: f32,
        pub i32_2006: i32,
        pub u16_2006: u16,
        pub u32_2007: u32,
        pub i8_2008: i8,
        pub refuse: Option<Abort>,
        pub writes: usize,
    }

    impl ObjectDictionary for TestOd {
        fn entry(&self, index: u16, sub: u8) -> Result<Entry, Abort> {
            Table::new(ENTRIES).entry(index, sub)
        }
        fn read(&mut self, index: u16, sub: u8, out: &mut [u8]) -> Result<usize, Abort> {
            let mut put = |b: &[u8]| {
                out[..b.len()].copy_from_slice(b);
                Ok(b.len())
            };
            match (index, sub) {
                (0x1000, 0) => put(&0x0002_0192u32.to_le_bytes()),
                (0x2000, 0) => put(&self.i16_2000.to_le_bytes()),
                (0x2001, 0) => put(&self.u32_2001.to_le_bytes()),
                (0x2003, 0) => put(&self.s_2003[..self.s_2003_len]),
                (0x2004, 0) => put(&[self.b_2004]),
                (0x2005, 0) => put(&self.f_2005.to_le_bytes()),
                (0x2006, 1) => put(&self.i32_2006.to_le_bytes()),
                (0x2006, 2) => put(&self.u16_2006.to_le_bytes()),
                (0x2007, 0) => put(&self.u32_2007.to_le_bytes()),
                (0x2008, 0) => put(&self.i8_2008.to_le_bytes()),
                (0x2009, 0) => put(&[1, 2, 3]),
                _ => Err(Abort::General),
            }
        }
        fn write(&mut self, index: u16, sub: u8, d: &[u8]) -> Result<(), Abort> {
            if let Some(a) = self.refuse {
                return Err(a);
            }
            self.writes += 1;
            let mut b = [0u8; 4];
            let n = d.len().min(4);
            b[..n].copy_from_slice(&d[..n]);
            match (index, sub) {
                (0x2000, 0) => self.i16_2000 = i16::from_le_bytes([b[0], b[1]]),
                (0x2001, 0) => self.u32_2001 = u32::from_le_bytes(b),
                (0x2002, 0) => self.u8_2002 = b[0],
                (0x2003, 0) => {
                    self.s_2003[..d.len()].copy_from_slice(d);
                    self.s_2003_len = d.len();
                }
                (0x2004, 0) => self.b_2004 = b[0],
                (0x2005, 0) => self.f_2005 = f32::from_le_bytes(b),
                (0x2006, 2) => self.u16_2006 = u16::from_le_bytes([b[0], b[1]]),
                (0x2007, 0) => self.u32_2007 = u32::from_le_bytes(b),
                (0x2008, 0) => self.i8_2008 = b[0] as i8,
                _ => return Err(Abort::General),
            }
            Ok(())
        }
    }
}

#[cfg(test)]
mod tests {
    use super::testod::*;
    use super::*;

    #[test]
    fn abort_codes_are_the_standard_numbers() {
        // CiA 301 v4.2 Table 22.
        assert_eq!(Abort::ToggleNotAlternated.code(), 0x0503_0000);
        assert_eq!(Abort::InvalidCommand.code(), 0x0504_0001);
        assert_eq!(Abort::UnsupportedAccess.code(), 0x0601_0000);
        assert_eq!(Abort::ReadWriteOnly.code(), 0x0601_0001);
        assert_eq!(Abort::WriteReadOnly.code(), 0x0601_0002);
        assert_eq!(Abort::ObjectDoesNotExist.code(), 0x0602_0000);
        assert_eq!(Abort::CannotMap.code(), 0x0604_0041);
        assert_eq!(Abort::MapTooLong.code(), 0x0604_0042);
        assert_eq!(Abort::ParameterIncompatible.code(), 0x0604_0043);
        assert_eq!(Abort::TypeMismatch.code(), 0x0607_0010);
        assert_eq!(Abort::TooLong.code(), 0x0607_0012);
        assert_eq!(Abort::TooShort.code(), 0x0607_0013);
        assert_eq!(Abort::SubindexDoesNotExist.code(), 0x0609_0011);
        assert_eq!(Abort::ValueRange.code(), 0x0609_0030);
        assert_eq!(Abort::ValueTooHigh.code(), 0x0609_0031);
        assert_eq!(Abort::ValueTooLow.code(), 0x0609_0032);
        assert_eq!(Abort::General.code(), 0x0800_0000);
        assert_eq!(Abort::CannotStore.code(), 0x0800_0020);
        assert_eq!(Abort::WrongDeviceState.code(), 0x0800_0022);
        assert_eq!(Abort::NoData.code(), 0x0800_0024);
    }

    #[test]
    fn table_lookup_distinguishes_index_and_sub() {
        let t = Table::new(ENTRIES);
        assert_eq!(t.entry(0x2006, 2).unwrap().data_type, DataType::Unsigned16);
        assert_eq!(t.entry(0x2006, 3), Err(Abort::SubindexDoesNotExist));
        assert_eq!(t.entry(0x2999, 0), Err(Abort::ObjectDoesNotExist));
    }

    #[test]
    fn write_checks_access_length_and_range() {
        let mut od = TestOd::default();
        assert_eq!(
            write_checked(&mut od, 0x1000, 0, &[0; 4]),
            Err(Abort::WriteReadOnly)
        );
        assert_eq!(
            write_checked(&mut od, 0x2006, 1, &[0; 4]),
            Err(Abort::WriteReadOnly)
        );
        assert_eq!(
            write_checked(&mut od, 0x2000, 0, &[0; 3]),
            Err(Abort::TooLong)
        );
        assert_eq!(
            write_checked(&mut od, 0x2000, 0, &[0; 1]),
            Err(Abort::TooShort)
        );
        // 1001 = 0x03E9 > 1000; -1001 = 0xFC17 < -1000.
        assert_eq!(
            write_checked(&mut od, 0x2000, 0, &[0xE9, 0x03]),
            Err(Abort::ValueTooHigh)
        );
        assert_eq!(
            write_checked(&mut od, 0x2000, 0, &[0x17, 0xFC]),
            Err(Abort::ValueTooLow)
        );
        assert_eq!(od.writes, 0);
        // -1000 = 0xFC18 is the lower limit itself.
        assert_eq!(write_checked(&mut od, 0x2000, 0, &[0x18, 0xFC]), Ok(()));
        assert_eq!(od.i16_2000, -1000);
        // BOOLEAN takes 0 or 1 only (CiA 301 BOOLEAN).
        assert_eq!(
            write_checked(&mut od, 0x2004, 0, &[2]),
            Err(Abort::ValueRange)
        );
        // REAL32 3.0 = 0x40400000 > 2.5; -2.0 = 0xC0000000 < -1.5; NaN.
        assert_eq!(
            write_checked(&mut od, 0x2005, 0, &[0, 0, 0x40, 0x40]),
            Err(Abort::ValueTooHigh)
        );
        assert_eq!(
            write_checked(&mut od, 0x2005, 0, &[0, 0, 0, 0xC0]),
            Err(Abort::ValueTooLow)
        );
        assert_eq!(
            write_checked(&mut od, 0x2005, 0, &[0, 0, 0xC0, 0x7F]),
            Err(Abort::ValueRange)
        );
        // A string up to its capacity (20).
        assert_eq!(
            write_checked(&mut od, 0x2003, 0, &[b'x'; 21]),
            Err(Abort::TooLong)
        );
        assert_eq!(write_checked(&mut od, 0x2003, 0, b"abc"), Ok(()));
        od.refuse = Some(Abort::WrongDeviceState);
        assert_eq!(
            write_checked(&mut od, 0x2001, 0, &[0; 4]),
            Err(Abort::WrongDeviceState)
        );
    }

    #[test]
    fn read_refuses_write_only() {
        let mut od = TestOd::default();
        let mut b = [0u8; 32];
        assert_eq!(
            read_checked(&mut od, 0x2002, 0, &mut b),
            Err(Abort::ReadWriteOnly)
        );
        assert_eq!(read_checked(&mut od, 0x1000, 0, &mut b), Ok(4));
        assert_eq!(&b[..4], &[0x92, 0x01, 0x02, 0x00]);
        // A value of the wrong length from the application; a buffer
        // shorter than the type.
        assert_eq!(
            read_checked(&mut od, 0x2009, 0, &mut b),
            Err(Abort::General)
        );
        assert_eq!(
            read_checked(&mut od, 0x1000, 0, &mut b[..3]),
            Err(Abort::General)
        );
    }

    #[test]
    fn integer_decoding_sign_extends() {
        assert_eq!(DataType::Integer8.decode_int(&[0xFF]), Some(-1));
        assert_eq!(DataType::Unsigned8.decode_int(&[0xFF]), Some(255));
        assert_eq!(
            DataType::Integer32.decode_int(&[0, 0, 0, 0x80]),
            Some(-2_147_483_648)
        );
        assert_eq!(
            DataType::Unsigned32.decode_int(&[0xFF; 4]),
            Some(0xFFFF_FFFF)
        );
        assert_eq!(DataType::Unsigned16.decode_int(&[1]), None);
    }
}
