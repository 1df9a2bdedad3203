extern crate std;

use super::eds::{node_config, write_eds};
use super::objects::*;
use crate::config::{self, PARAMS};
use crate::servo::ServoConfig;
use canopen::node::Node;
use canopen::od::{read_checked, write_checked, Abort};
use canopen::pdo::Pdos;
use canopen::CanFrame;
use std::collections::BTreeMap;
use std::string::{String, ToString};
use std::vec::Vec;

type Port = ConfigValues;

fn objects() -> DriveObjects<Port> {
    DriveObjects::new(ConfigValues::new(ServoConfig::default()))
}

fn read(d: &mut DriveObjects<Port>, index: u16, sub: u8) -> Result<Vec<u8>, Abort> {
    let mut b = [0u8; 64];
    let n = read_checked(d, index, sub, &mut b)?;
    Ok(b[..n].to_vec())
}

fn write(d: &mut DriveObjects<Port>, index: u16, sub: u8, v: &[u8]) -> Result<(), Abort> {
    write_checked(d, index, sub, v)
}

#[test]
fn every_parameter_has_one_vendor_object_and_none_collides() {
    let mut seen = BTreeMap::new();
    for (name, index) in CONFIG_OBJECTS {
        assert!(config::lookup(name).is_some(), "{name}: not a parameter");
        assert!((0x2000..0x2100).contains(&index), "{name}: {index:#x}");
        assert!(seen.insert(index, name).is_none(), "{index:#x} twice");
        assert!(OBJECTS.iter().all(|o| o.index != index), "{index:#x}");
    }
    for (ix, p) in PARAMS.iter().enumerate() {
        let index = config_index(ix).unwrap_or_else(|| panic!("{} has no object", p.name));
        assert_eq!(config_param(index).unwrap().1.name, p.name);
    }
    // The assignment is the table's order today; it must never move.
    assert_eq!(config_index(0), Some(0x2000));
    assert_eq!(config_param(0x200C).unwrap().1.name, "mpdtc_t_tol");
    assert_eq!(config_param(0x2026).unwrap().1.name, "calibration_voltage");
}

#[test]
fn every_object_reads_with_its_types_length() {
    let mut d = objects();
    for o in OBJECTS {
        for s in o.subs {
            let v = read(&mut d, o.index, s.sub)
                .unwrap_or_else(|e| panic!("{:#x}:{}: {e:?}", o.index, s.sub));
            match s.data_type.size() {
                Some(n) => assert_eq!(v.len(), n, "{:#x}:{}", o.index, s.sub),
                None => assert!(!v.is_empty(), "{:#x}", o.index),
            }
        }
    }
    for (_, index) in CONFIG_OBJECTS {
        assert_eq!(read(&mut d, index, 0).unwrap().len(), 4, "{index:#x}");
        assert_eq!(read(&mut d, index, 1), Err(Abort::SubindexDoesNotExist));
    }
}

#[test]
fn identity_and_device_type_are_the_standards_values() {
    let mut d = objects();
    // Profile 402 in the low word, "servo drive" (2) above it.
    assert_eq!(read(&mut d, 0x1000, 0).unwrap(), [0x92, 0x01, 0x02, 0x00]);
    assert_eq!(read(&mut d, 0x1018, 0).unwrap(), [4]);
    assert_eq!(
        read(&mut d, 0x100A, 0).unwrap(),
        env!("CARGO_PKG_VERSION").as_bytes()
    );
    assert_eq!(revision_number("0.1.0"), 0x0000_0001);
    assert_eq!(revision_number("2.3.9"), 0x0002_0003);
    assert_eq!(revision_number("x"), 0);
    assert_eq!(read(&mut d, 0x1018, 5), Err(Abort::SubindexDoesNotExist));
    assert_eq!(read(&mut d, 0x1234, 0), Err(Abort::ObjectDoesNotExist));
    assert_eq!(write(&mut d, 0x1000, 0, &[0; 4]), Err(Abort::WriteReadOnly));
}

#[test]
fn set_points_round_trip_and_actual_values_refuse_writes() {
    let mut d = objects();
    write(&mut d, 0x6071, 0, &(-250i16).to_le_bytes()).unwrap();
    assert_eq!(d.image.target_torque_permille, -250);
    write(&mut d, 0x607A, 0, &(-123_456i32).to_le_bytes()).unwrap();
    assert_eq!(
        read(&mut d, 0x607A, 0).unwrap(),
        (-123_456i32).to_le_bytes()
    );
    write(&mut d, 0x60FF, 0, &40_960i32.to_le_bytes()).unwrap();
    assert_eq!(d.image.target_velocity_counts_s, 40_960);
    d.image.position_actual_counts = 77;
    assert_eq!(read(&mut d, 0x6064, 0).unwrap(), 77i32.to_le_bytes());
    assert_eq!(
        write(&mut d, 0x6064, 0, &0i32.to_le_bytes()),
        Err(Abort::WriteReadOnly)
    );
    // Limits: 0x6072 at most 1000 per mille; homing method 37 only.
    assert_eq!(
        write(&mut d, 0x6072, 0, &1001u16.to_le_bytes()),
        Err(Abort::ValueTooHigh)
    );
    assert_eq!(write(&mut d, 0x6098, 0, &[1]), Err(Abort::ValueTooLow));
    assert_eq!(d.image.max_torque_permille, 1000);
    // Wrong lengths change nothing.
    assert_eq!(write(&mut d, 0x6071, 0, &[1]), Err(Abort::TooShort));
    assert_eq!(write(&mut d, 0x6071, 0, &[1, 2, 3]), Err(Abort::TooLong));
    assert_eq!(d.image.target_torque_permille, -250);
    // The impedance record, REAL32; NaN is refused.
    write(&mut d, IMPEDANCE, 1, &12.5f32.to_le_bytes()).unwrap();
    assert_eq!(d.image.impedance.kp_nm_per_rev, 12.5);
    assert_eq!(
        write(&mut d, IMPEDANCE, 2, &f32::NAN.to_le_bytes()),
        Err(Abort::ValueRange)
    );
    assert_eq!(
        write(&mut d, IMPEDANCE, 1, &(-1.0f32).to_le_bytes()),
        Err(Abort::ValueTooLow)
    );
}

#[test]
fn configuration_objects_are_config_set_with_its_refusals() {
    let mut d = objects();
    let t_tol = config::lookup("mpdtc_t_tol").unwrap().0;
    let index = config_index(t_tol).unwrap();
    // REAL32 0.05 is the decimal 0.05 in the configuration, not the
    // binary neighbour 0.0500000007.
    write(&mut d, index, 0, &0.05f32.to_le_bytes()).unwrap();
    assert_eq!(d.config.value(t_tol), 0.05);
    assert_eq!(read(&mut d, index, 0).unwrap(), 0.05f32.to_le_bytes());
    // The table's range [0, 0.5] N m.
    assert_eq!(
        write(&mut d, index, 0, &0.6f32.to_le_bytes()),
        Err(Abort::ValueTooHigh)
    );
    assert_eq!(d.config.value(t_tol), 0.05);
    // An integer parameter is UNSIGNED32.
    let cpr = config::lookup("enc_cpr").unwrap().0;
    assert_eq!(
        read(&mut d, config_index(cpr).unwrap(), 0).unwrap(),
        4096u32.to_le_bytes()
    );
    // In range alone, but the configuration refuses it: enc_zero must
    // stay below enc_cpr.
    let zero = config::lookup("enc_zero").unwrap().0;
    write(
        &mut d,
        config_index(zero).unwrap(),
        0,
        &4000u32.to_le_bytes(),
    )
    .unwrap();
    assert_eq!(
        write(
            &mut d,
            config_index(cpr).unwrap(),
            0,
            &2048u32.to_le_bytes()
        ),
        Err(Abort::ParameterIncompatible)
    );
    assert_eq!(d.config.value(cpr), 4096.0);
    // A parameter that needs the gates off, while they are on.
    d.config.gates_on = true;
    assert_eq!(
        write(&mut d, index, 0, &0.07f32.to_le_bytes()),
        Err(Abort::WrongDeviceState)
    );
    assert_eq!(d.config.value(t_tol), 0.05);
}

#[test]
fn software_position_limits_are_the_configurations_in_counts() {
    let mut d = objects();
    // pos_min = -1000 rev at 4096 counts per turn.
    assert_eq!(
        read(&mut d, 0x607D, 1).unwrap(),
        (-4_096_000i32).to_le_bytes()
    );
    write(&mut d, 0x607D, 2, &2048i32.to_le_bytes()).unwrap();
    let pos_max = config::lookup("pos_max").unwrap().0;
    assert_eq!(d.config.value(pos_max), 0.5);
    assert_eq!(read(&mut d, 0x608F, 1).unwrap(), 4096u32.to_le_bytes());
    assert_eq!(read(&mut d, 0x6076, 0).unwrap(), 1000u32.to_le_bytes());
}

#[test]
fn store_and_restore_need_their_signatures() {
    let mut d = objects();
    assert_eq!(
        write(&mut d, 0x1010, 1, &0x1234u32.to_le_bytes()),
        Err(Abort::CannotStore)
    );
    assert!(!d.requests.save);
    // "save" = 73 61 76 65 on the wire.
    write(&mut d, 0x1010, 1, &[0x73, 0x61, 0x76, 0x65]).unwrap();
    assert!(d.requests.save);
    write(&mut d, 0x1011, 1, &[0x6C, 0x6F, 0x61, 0x64]).unwrap();
    assert!(d.requests.restore);
}

/// An expedited SDO upload through the node, as a client's frames.
fn sdo_upload(n: &mut Node, d: &mut DriveObjects<Port>, index: u16, sub: u8) -> [u8; 8] {
    let i = index.to_le_bytes();
    let req = CanFrame::new(0x601, &[0x40, i[0], i[1], sub, 0, 0, 0, 0]).unwrap();
    let out = n.on_frame(&req, d);
    let r = out.iter().next().expect("an answer");
    assert_eq!(r.id(), 0x581);
    r.data().try_into().unwrap()
}

#[test]
fn a_client_reads_the_drive_through_the_node() {
    let mut n = Node::new(node_config(1), Pdos::new(1)).unwrap();
    let mut d = objects();
    n.boot();
    // Expedited upload response, 4 bytes: 0x43, index, sub, value.
    assert_eq!(
        sdo_upload(&mut n, &mut d, 0x1000, 0),
        [0x43, 0x00, 0x10, 0x00, 0x92, 0x01, 0x02, 0x00]
    );
    // The node's own 0x6502: HM (bit 5), CSP (7), CSV (8), CST (9) and
    // the vendor mode -1 (bit 16).
    assert_eq!(
        sdo_upload(&mut n, &mut d, 0x6502, 0),
        [0x43, 0x02, 0x65, 0x00, 0xA0, 0x03, 0x01, 0x00]
    );
    // A vendor object the node does not know reaches the drive: abort
    // "object does not exist" for one that is not there.
    assert_eq!(
        sdo_upload(&mut n, &mut d, 0x2FFF, 0),
        [0x80, 0xFF, 0x2F, 0x00, 0x00, 0x00, 0x02, 0x06]
    );
}

/// The EDS as an INI file: section name to its keys.
fn parse_ini(text: &str) -> BTreeMap<String, BTreeMap<String, String>> {
    let mut out: BTreeMap<String, BTreeMap<String, String>> = BTreeMap::new();
    let mut cur = String::new();
    for line in text.split("\r\n") {
        if let Some(s) = line.strip_prefix('[').and_then(|l| l.strip_suffix(']')) {
            cur = s.to_string();
            assert!(
                out.insert(cur.clone(), BTreeMap::new()).is_none(),
                "[{s}] twice"
            );
        } else if let Some((k, v)) = line.split_once('=') {
            out.get_mut(&cur)
                .unwrap()
                .insert(k.to_string(), v.to_string());
        } else {
            assert!(line.is_empty(), "{line:?}");
        }
    }
    out
}

fn eds_text() -> String {
    let mut s = String::new();
    write_eds(&mut s, ConfigValues::new(ServoConfig::default())).unwrap();
    s
}

/// Every object section of the EDS names the type and access the device
/// answers with, and the device has no readable object the EDS leaves
/// out (checked over every index the EDS lists and every sub-index up to
/// 9); the committed file is the generated one (`EDS_WRITE=1 cargo test -p
/// drive eds` rewrites it).
#[test]
fn the_eds_describes_the_device_and_is_committed() {
    let text = eds_text();
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/canopen/drive.eds");
    if std::env::var_os("EDS_WRITE").is_some() {
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(&path, &text).unwrap();
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == text,
        "docs/canopen/drive.eds is not the device's: EDS_WRITE=1 cargo test -p drive eds"
    );

    let ini = parse_ini(&text);
    let n = Node::new(node_config(1), Pdos::new(1)).unwrap();
    let d = objects();
    let mut listed = Vec::new();
    for sec in ["MandatoryObjects", "OptionalObjects", "ManufacturerObjects"] {
        let keys = &ini[sec];
        let count: usize = keys["SupportedObjects"].parse().unwrap();
        for k in 1..=count {
            let v = &keys[&k.to_string()];
            listed.push(u16::from_str_radix(v.trim_start_matches("0x"), 16).unwrap());
        }
    }
    assert!(listed.len() > 80, "{}", listed.len());
    for &index in &listed {
        let var = ini.contains_key(&std::format!("{index:04X}"))
            && !ini.contains_key(&std::format!("{index:04X}sub0"));
        for sub in 0..=9u8 {
            let sec = if var {
                std::format!("{index:04X}")
            } else {
                std::format!("{index:04X}sub{sub:X}")
            };
            let e = n.entry(&d, index, sub);
            let keys = if var && sub > 0 { None } else { ini.get(&sec) };
            match (e, keys) {
                (Ok(e), Some(k)) => {
                    assert_eq!(
                        k["DataType"],
                        std::format!("0x{:04X}", e.data_type.code()),
                        "{sec}"
                    );
                    let acc = match e.access {
                        canopen::od::Access::Ro => "ro",
                        canopen::od::Access::Wo => "wo",
                        canopen::od::Access::Rw => "rw",
                        canopen::od::Access::Const => "const",
                    };
                    assert_eq!(k["AccessType"], acc, "{sec}");
                    assert_eq!(
                        k["PDOMapping"],
                        if e.pdo_mappable { "1" } else { "0" },
                        "{sec}"
                    );
                }
                (Err(_), None) => {}
                (e, k) => panic!("{sec}: device {e:?}, EDS {k:?}"),
            }
        }
    }
    // Values the standard fixes, as a client reads them from the file.
    assert_eq!(ini["1000"]["DefaultValue"], "0x20192");
    // PDO COB-IDs: 0x200/0x180 plus the node-ID, bit 31 (not valid) set
    // until the master configures and enables the PDO.
    assert_eq!(ini["1400sub1"]["DefaultValue"], "$NODEID+0x80000200");
    assert_eq!(ini["1800sub1"]["DefaultValue"], "$NODEID+0x80000180");
    assert_eq!(ini["1014"]["DefaultValue"], "$NODEID+0x80");
    assert_eq!(ini["200C"]["DataType"], "0x0008");
    assert_eq!(ini["200C"]["HighLimit"], "0.5");
    assert_eq!(ini["6502"]["DefaultValue"], "0x103A0");
}
