//! Board file against the real top-level port list: every PL port bit of
//! `board_top` is constrained exactly once, and every constrained pin names
//! a port bit that exists.
use crate::board::{parse_port_bit, Board};
use crate::verilog::{Dir, Port};
use std::collections::BTreeMap;

/// Ports placed by the PS7 itself (DDR and fixed MIO): never in a board
/// file's pin list.
pub const PS_PORT_PREFIXES: [&str; 2] = ["ddr_", "fixed_io_"];

pub fn is_ps_port(name: &str) -> bool {
    PS_PORT_PREFIXES.iter().any(|p| name.starts_with(p))
}

/// Every mismatch between the board's pins and the ports (empty = consistent).
pub fn port_problems(board: &Board, ports: &[Port]) -> Vec<String> {
    let mut problems = Vec::new();
    let by_name: BTreeMap<&str, &Port> = ports.iter().map(|p| (p.name.as_str(), p)).collect();
    // How often each (port, bit) is constrained.
    let mut count: BTreeMap<(String, Option<u32>), usize> = BTreeMap::new();
    for pin in &board.pins {
        let pb = match parse_port_bit(&pin.port) {
            Ok(pb) => pb,
            Err(e) => {
                problems.push(e.0);
                continue;
            }
        };
        let Some(port) = by_name.get(pb.name.as_str()) else {
            problems.push(format!(
                "pin {} constrains `{}`, which board_top does not have",
                pin.pin, pin.port
            ));
            continue;
        };
        if is_ps_port(&port.name) {
            problems.push(format!(
                "pin {} constrains PS port `{}` (the PS7 places it)",
                pin.pin, pin.port
            ));
            continue;
        }
        match (port.range, pb.bit) {
            (None, Some(_)) => {
                problems.push(format!(
                    "pin {}: `{}` is a scalar port, `{}` has a bit index",
                    pin.pin, port.name, pin.port
                ));
                continue;
            }
            (Some(_), None) => {
                problems.push(format!(
                    "pin {}: `{}` is a vector, name one bit (`{}[n]`)",
                    pin.pin, port.name, port.name
                ));
                continue;
            }
            (Some(_), Some(b)) if !port.bits().contains(&b) => {
                problems.push(format!("pin {}: `{}` has no bit {b}", pin.pin, port.name));
                continue;
            }
            _ => {}
        }
        *count.entry((pb.name, pb.bit)).or_default() += 1;
    }
    for port in ports.iter().filter(|p| !is_ps_port(&p.name)) {
        let bits: Vec<Option<u32>> = match port.range {
            None => vec![None],
            Some(_) => port.bits().into_iter().map(Some).collect(),
        };
        for bit in bits {
            let label = match bit {
                Some(b) => format!("{}[{b}]", port.name),
                None => port.name.clone(),
            };
            match count.get(&(port.name.clone(), bit)).copied().unwrap_or(0) {
                0 => problems.push(format!("port `{label}` of board_top has no pin")),
                1 => {}
                n => problems.push(format!("port `{label}` is constrained {n} times")),
            }
        }
    }
    for name in &board.timing.strobed_inputs {
        match by_name.get(name.as_str()) {
            Some(p) if p.dir == Dir::Input => {}
            Some(_) => problems.push(format!("timing.strobed_inputs: `{name}` is not an input")),
            None => problems.push(format!(
                "timing.strobed_inputs: board_top has no port `{name}`"
            )),
        }
    }
    match by_name.get(board.timing.strobe.as_str()) {
        Some(p) if p.dir == Dir::Input && p.range.is_none() => {}
        Some(_) => problems.push(format!(
            "timing.strobe: `{}` is not a one-bit input",
            board.timing.strobe
        )),
        None => problems.push(format!(
            "timing.strobe: board_top has no port `{}`",
            board.timing.strobe
        )),
    }
    problems
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::verilog::module_ports;

    const TOP: &str = include_str!("../../../pl-bitstream-src/board/board_top.v");
    const ZEDBOARD: &str = include_str!("../../../boards/zedboard.toml");

    fn problems(board: &str, top: &str) -> Vec<String> {
        let b = Board::parse(board).unwrap();
        port_problems(&b, &module_ports(top, "board_top").unwrap())
    }

    #[test]
    fn zedboard_constrains_every_pl_port_of_board_top_once() {
        assert_eq!(problems(ZEDBOARD, TOP), Vec::<String>::new());
    }

    #[test]
    fn a_port_without_pin_is_reported() {
        let top = TOP.replace(
            "output wire [ 3:0] led_o",
            "output wire [ 3:0] led_o,\n    output wire spare_o",
        );
        assert_eq!(
            problems(ZEDBOARD, &top),
            ["port `spare_o` of board_top has no pin"]
        );
        let top = TOP.replace("[ 3:0] led_o", "[ 4:0] led_o");
        assert_eq!(
            problems(ZEDBOARD, &top),
            ["port `led_o[4]` of board_top has no pin"]
        );
    }

    #[test]
    fn a_pin_without_port_is_reported() {
        let top = TOP.replace("[ 3:0] led_o", "[ 2:0] led_o");
        assert_eq!(problems(ZEDBOARD, &top), ["pin U21: `led_o` has no bit 3"]);
        let board = ZEDBOARD.replace("port = \"led_o[3]\"", "port = \"led3_o\"");
        assert_eq!(
            problems(&board, TOP),
            [
                "pin U21 constrains `led3_o`, which board_top does not have",
                "port `led_o[3]` of board_top has no pin"
            ]
        );
        let board = ZEDBOARD.replace("port = \"enc_z_i\"", "port = \"enc_z_i[0]\"");
        assert_eq!(
            problems(&board, TOP).len(),
            2,
            "{:?}",
            problems(&board, TOP)
        );
    }

    #[test]
    fn ps_ports_and_strobed_inputs_are_checked() {
        let board = ZEDBOARD.replace("port = \"led_o[3]\"", "port = \"ddr_cke_io\"");
        assert!(problems(&board, TOP).iter().any(|p| p.contains("PS port")));
        let board = ZEDBOARD.replace(
            "strobed_inputs = [\"adc_data_i\"",
            "strobed_inputs = [\"adc_cnv_o\"",
        );
        assert_eq!(
            problems(&board, TOP),
            ["timing.strobed_inputs: `adc_cnv_o` is not an input"]
        );
        let board = ZEDBOARD.replace("strobe = \"adc_drdy_i\"", "strobe = \"adc_data_i\"");
        assert_eq!(
            problems(&board, TOP),
            ["timing.strobe: `adc_data_i` is not a one-bit input"]
        );
    }
}
