//! The drive's electronic data sheet (CiA 306 v1.3, EDS format 4.0): every
//! object of its dictionary with type, access, PDO mapping, limits and
//! power-on value, written from the dictionary itself (the node's objects
//! and [`super::objects`]), so it cannot disagree with the device.
//!
//! A value that follows the node-ID (a COB-ID) is written as
//! `$NODEID+0x...`, found by reading it on nodes 1 and 2.

use super::objects::{
    config_index, config_sub, ConfigPort, DriveObjects, CONFIG_OBJECTS, DEVICE_NAME, OBJECTS,
};
use crate::config::PARAMS;
use canopen::cia402::mode;
use canopen::node::{Config, Node};
use canopen::od::{Access, DataType, Entry, Limits};
use canopen::pdo::Pdos;
use core::fmt::{self, Write};

/// Producer heartbeat at power-on, ms.
pub const HEARTBEAT_MS: u16 = 100;

/// The modes in 0x6502, the ones [`super::axis`] carries out: HM (method
/// 37), CSP, CSV, CST and the vendor impedance mode.
pub fn supported_modes() -> u32 {
    [
        mode::HOMING,
        mode::CYCLIC_SYNC_POSITION,
        mode::CYCLIC_SYNC_VELOCITY,
        mode::CYCLIC_SYNC_TORQUE,
        mode::VENDOR,
    ]
    .iter()
    .filter_map(|m| canopen::cia402::supported_bit(*m))
    .fold(0, |a, b| a | b)
}

/// The node's settings for `node_id`: power-on mode CST, quick stop
/// option 2 (ramp at the quick stop deceleration, then switch on
/// disabled).
pub fn node_config(node_id: u8) -> Config {
    Config {
        node_id,
        heartbeat_ms: HEARTBEAT_MS,
        supported_modes: supported_modes(),
        initial_mode: mode::CYCLIC_SYNC_TORQUE,
        quick_stop_option: 2,
    }
}

/// The node's own objects (communication, PDO parameters, the CiA 402
/// objects of its state machine), with their names and the highest
/// sub-index to look for.
const NODE_OBJECTS: &[(u16, &str, u8)] = &[
    (0x1001, "Error register", 0),
    (0x1003, "Pre-defined error field", 8),
    (0x1005, "COB-ID SYNC", 0),
    (0x1014, "COB-ID EMCY", 0),
    (0x1016, "Consumer heartbeat time", 4),
    (0x1017, "Producer heartbeat time", 0),
    (0x1400, "RPDO1 communication parameter", 5),
    (0x1401, "RPDO2 communication parameter", 5),
    (0x1402, "RPDO3 communication parameter", 5),
    (0x1403, "RPDO4 communication parameter", 5),
    (0x1600, "RPDO1 mapping parameter", 8),
    (0x1601, "RPDO2 mapping parameter", 8),
    (0x1602, "RPDO3 mapping parameter", 8),
    (0x1603, "RPDO4 mapping parameter", 8),
    (0x1800, "TPDO1 communication parameter", 5),
    (0x1801, "TPDO2 communication parameter", 5),
    (0x1802, "TPDO3 communication parameter", 5),
    (0x1803, "TPDO4 communication parameter", 5),
    (0x1A00, "TPDO1 mapping parameter", 8),
    (0x1A01, "TPDO2 mapping parameter", 8),
    (0x1A02, "TPDO3 mapping parameter", 8),
    (0x1A03, "TPDO4 mapping parameter", 8),
    (0x6040, "Controlword", 0),
    (0x6041, "Statusword", 0),
    (0x605A, "Quick stop option code", 0),
    (0x6060, "Modes of operation", 0),
    (0x6061, "Modes of operation display", 0),
    (0x6502, "Supported drive modes", 0),
];

/// The name of sub-index `sub` of a node object `index`.
fn node_sub_name(index: u16, sub: u8) -> &'static str {
    match (index & 0xFF00, sub) {
        (_, 0) if index == 0x1003 => "Number of errors",
        (0x1000, _) if index == 0x1003 => "Standard error field",
        (_, 0) if index == 0x1016 => "Highest sub-index supported",
        (0x1000, _) if index == 0x1016 => "Consumer heartbeat time",
        (0x1400 | 0x1800, 0) => "Highest sub-index supported",
        (0x1400 | 0x1800, 1) => "COB-ID used by PDO",
        (0x1400 | 0x1800, 2) => "Transmission type",
        (0x1400 | 0x1800, 3) => "Inhibit time",
        (0x1400 | 0x1800, 5) => "Event timer",
        (0x1600 | 0x1A00, 0) => "Number of mapped objects",
        (0x1600 | 0x1A00, _) => "Mapped object",
        _ => "",
    }
}

/// An object list of the EDS: its title and which indices it holds.
type Section = (&'static str, fn(u16) -> bool);

/// One object as the EDS lists it.
struct Described<'a> {
    index: u16,
    name: &'a str,
    /// (sub, name, entry); a VAR has exactly sub 0.
    subs: heapless::Vec<(u8, &'a str, Entry), 9>,
    var: bool,
}

fn access(a: Access) -> &'static str {
    match a {
        Access::Ro => "ro",
        Access::Wo => "wo",
        Access::Rw => "rw",
        Access::Const => "const",
    }
}

/// The value of `bytes` as an EDS writes it: unsigned in hex, signed and
/// REAL32 in decimal, a string as it is.
fn write_value<W: Write>(out: &mut W, dt: DataType, bytes: &[u8]) -> fmt::Result {
    let u = {
        let mut b = [0u8; 4];
        let k = bytes.len().min(4);
        b[..k].copy_from_slice(&bytes[..k]);
        u32::from_le_bytes(b)
    };
    match dt {
        DataType::Boolean | DataType::Unsigned8 | DataType::Unsigned16 | DataType::Unsigned32 => {
            write!(out, "0x{u:X}")
        }
        DataType::Integer8 | DataType::Integer16 | DataType::Integer32 => {
            write!(out, "{}", dt.decode_int(bytes).unwrap_or(0))
        }
        DataType::Real32 => write!(out, "{}", f32::from_le_bytes(u.to_le_bytes())),
        DataType::VisibleString(_) => {
            for &c in bytes {
                out.write_char(if c.is_ascii_graphic() || c == b' ' {
                    c as char
                } else {
                    '?'
                })?;
            }
            Ok(())
        }
    }
}

fn write_limits<W: Write>(out: &mut W, e: &Entry) -> fmt::Result {
    match e.limits {
        Limits::None => Ok(()),
        Limits::Int { min, max } => {
            if e.data_type.code() >= 0x0005 {
                write!(out, "LowLimit=0x{min:X}\r\nHighLimit=0x{max:X}\r\n")
            } else {
                write!(out, "LowLimit={min}\r\nHighLimit={max}\r\n")
            }
        }
        Limits::Real { min, max } => write!(out, "LowLimit={min}\r\nHighLimit={max}\r\n"),
    }
}

/// Writes the EDS of a drive whose configuration is `config` (its values
/// are the power-on values the file lists). Lines end in CR LF, as the
/// INI files of CiA 306 tools do.
pub fn write_eds<W: Write, C: ConfigPort + Clone>(out: &mut W, config: C) -> fmt::Result {
    let node = |id: u8| Node::new(node_config(id), Pdos::new(id));
    let (Some(mut n1), Some(mut n2)) = (node(1), node(2)) else {
        return Err(fmt::Error);
    };
    let mut a1 = DriveObjects::new(config.clone());
    let mut a2 = DriveObjects::new(config);

    let mut objects: heapless::Vec<Described, 128> = heapless::Vec::new();
    let mut describe =
        |index: u16, name: &'static str, max_sub: u8, sub_name: &dyn Fn(u8) -> &'static str| {
            let mut d = Described {
                index,
                name,
                subs: heapless::Vec::new(),
                var: true,
            };
            for sub in 0..=max_sub {
                if let Ok(e) = n1.entry(&a1, index, sub) {
                    d.subs
                        .push((sub, sub_name(sub), e))
                        .map_err(|_| fmt::Error)?;
                }
            }
            d.var = max_sub == 0;
            objects.push(d).map_err(|_| fmt::Error)
        };
    for &(index, name, max_sub) in NODE_OBJECTS {
        describe(index, name, max_sub, &|sub| {
            if max_sub == 0 {
                name
            } else {
                node_sub_name(index, sub)
            }
        })?;
    }
    for o in OBJECTS {
        let max_sub = o.subs.iter().map(|s| s.sub).max().unwrap_or(0);
        describe(o.index, o.name, max_sub, &|sub| {
            o.subs.iter().find(|s| s.sub == sub).map_or("", |s| s.name)
        })?;
    }
    for (ix, p) in PARAMS.iter().enumerate() {
        let index = config_index(ix).ok_or(fmt::Error)?;
        let name = config_sub(p).name;
        describe(index, name, 0, &|_| name)?;
    }
    objects.sort_unstable_by_key(|d| d.index);

    write!(
        out,
        "[FileInfo]\r\nFileName=drive.eds\r\nFileVersion=1\r\nFileRevision=0\r\nEDSVersion=4.0\r\n\
         Description=CiA 402 servo drive with MPDTC and FOC torque loops\r\nCreatedBy=drivectl\r\n\r\n"
    )?;
    write!(
        out,
        "[DeviceInfo]\r\nVendorName=\r\nVendorNumber=0x0\r\nProductName={DEVICE_NAME}\r\n\
         ProductNumber=0x402\r\nRevisionNumber=0x{:X}\r\nOrderCode=\r\n\
         BaudRate_10=0\r\nBaudRate_20=0\r\nBaudRate_50=0\r\nBaudRate_125=0\r\nBaudRate_250=0\r\n\
         BaudRate_500=0\r\nBaudRate_800=0\r\nBaudRate_1000=1\r\nSimpleBootUpMaster=0\r\n\
         SimpleBootUpSlave=1\r\nGranularity=8\r\nDynamicChannelsSupported=0\r\nGroupMessaging=0\r\n\
         NrOfRXPDO=4\r\nNrOfTXPDO=4\r\nLSS_Supported=0\r\n\r\n",
        super::objects::revision_number(super::objects::SOFTWARE_VERSION)
    )?;
    write!(out, "[DummyUsage]\r\n")?;
    for t in 1..=7 {
        write!(out, "Dummy000{t}=0\r\n")?;
    }
    write!(
        out,
        "\r\n[Comments]\r\nLines=3\r\nLine1=Positions in encoder counts (0x608F), velocities in counts/s,\r\n\
         Line2=torques in per mille of 0x6076 (mN m), vendor objects 0x2000.. in the unit of `config list`.\r\n\
         Line3=Generated from the firmware's dictionary; do not edit.\r\n\r\n"
    )?;
    let sections: [Section; 3] = [
        ("MandatoryObjects", |i| {
            matches!(i, 0x1000 | 0x1001 | 0x1018)
        }),
        ("OptionalObjects", |i| {
            !matches!(i, 0x1000 | 0x1001 | 0x1018) && !(0x2000..0x6000).contains(&i)
        }),
        ("ManufacturerObjects", |i| (0x2000..0x6000).contains(&i)),
    ];
    for (title, member) in sections {
        let n = objects.iter().filter(|d| member(d.index)).count();
        write!(out, "[{title}]\r\nSupportedObjects={n}\r\n")?;
        for (k, d) in objects.iter().filter(|d| member(d.index)).enumerate() {
            write!(out, "{}=0x{:04X}\r\n", k + 1, d.index)?;
        }
        write!(out, "\r\n")?;
    }
    for d in objects.iter() {
        if !d.var {
            write!(
                out,
                "[{:04X}]\r\nParameterName={}\r\nObjectType=0x9\r\nSubNumber={}\r\n\r\n",
                d.index,
                d.name,
                d.subs.len()
            )?;
        }
        for (sub, name, e) in d.subs.iter() {
            if d.var {
                write!(out, "[{:04X}]\r\n", d.index)?;
            } else {
                write!(out, "[{:04X}sub{:X}]\r\n", d.index, sub)?;
            }
            let name = if name.is_empty() { d.name } else { name };
            write!(
                out,
                "ParameterName={name}\r\nObjectType=0x7\r\nDataType=0x{:04X}\r\nAccessType={}\r\n",
                e.data_type.code(),
                access(e.access)
            )?;
            if e.access.readable() {
                let mut b1 = [0u8; 64];
                let mut b2 = [0u8; 64];
                let r1 = n1.read(&mut a1, d.index, *sub, &mut b1);
                let r2 = n2.read(&mut a2, d.index, *sub, &mut b2);
                if let (Ok(k1), Ok(k2)) = (r1, r2) {
                    let (v1, v2) = (&b1[..k1], &b2[..k2]);
                    out.write_str("DefaultValue=")?;
                    let follows_id = v1 != v2 && e.data_type == DataType::Unsigned32 && {
                        let (x1, x2) = (le(v1), le(v2));
                        x2.wrapping_sub(x1) == 1
                    };
                    if follows_id {
                        write!(out, "$NODEID+0x{:X}", le(v1).wrapping_sub(1))?;
                    } else {
                        write_value(out, e.data_type, v1)?;
                    }
                    out.write_str("\r\n")?;
                }
            }
            write_limits(out, e)?;
            write!(out, "PDOMapping={}\r\n\r\n", u8::from(e.pdo_mappable))?;
        }
    }
    debug_assert_eq!(CONFIG_OBJECTS.len(), PARAMS.len());
    Ok(())
}

fn le(b: &[u8]) -> u32 {
    let mut x = [0u8; 4];
    let k = b.len().min(4);
    x[..k].copy_from_slice(&b[..k]);
    u32::from_le_bytes(x)
}
