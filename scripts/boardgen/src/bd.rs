//! The block design as the Vivado flow builds it (facts recorded by
//! scripts/vivado/stub-run.tcl) against the RTL and the register map: the
//! ports match the `ps_bd` stand-in that board_top is linted with, the PL
//! window is the register map's, FCLK0 is the PL clock.
use crate::verilog::{Dir, Port};
use crate::Board;

/// Path of the `ps_bd` stand-in module.
pub const PS_BD_STUB: &str = "pl-bitstream-src/board/lint/ps_bd.v";

/// Every mismatch between the recorded facts and the expectations.
pub fn problems(facts: &str, stub_ports: &[Port], board: &Board) -> Vec<String> {
    let mut out = Vec::new();
    let mut ports = Vec::new();
    let mut address = None;
    let mut top = None;
    let mut part = None;
    let mut fclk = None;
    for line in facts.lines().filter(|l| !l.trim().is_empty()) {
        let f: Vec<&str> = line.split_whitespace().collect();
        match f.as_slice() {
            ["port", name, dir, width] => ports.push((
                name.to_string(),
                dir.to_string(),
                width.parse::<u32>().unwrap_or(0),
            )),
            ["address", off, range] => address = Some((off.to_string(), range.to_string())),
            ["top", t] => top = Some(t.to_string()),
            ["part", p] => part = Some(p.to_string()),
            ["ps7", "CONFIG.PCW_FPGA0_PERIPHERAL_FREQMHZ", v] => fclk = Some(v.to_string()),
            _ => {}
        }
    }
    let stub: Vec<(String, String, u32)> = stub_ports
        .iter()
        .map(|p| {
            let dir = match p.dir {
                Dir::Input => "input",
                Dir::Output => "output",
                Dir::Inout => "inout",
            };
            (
                p.name.clone(),
                dir.to_string(),
                p.bits().len().max(1) as u32,
            )
        })
        .collect();
    for p in &ports {
        if !stub.contains(p) {
            out.push(format!(
                "block design port `{} {} [{}]` is not in {PS_BD_STUB}",
                p.1, p.0, p.2
            ));
        }
    }
    for p in &stub {
        if !ports.contains(p) {
            out.push(format!(
                "{PS_BD_STUB} port `{} {} [{}]` is not created by bitstream.tcl",
                p.1, p.0, p.2
            ));
        }
    }
    let want_addr = (
        format!("0x{:08X}", regmap::BASE_ADDR),
        format!("{}K", (1usize << regmap::AXI_ADDR_BITS) / 1024),
    );
    if address.as_ref() != Some(&want_addr) {
        out.push(format!(
            "PL address window {address:?}, the register map needs {want_addr:?}"
        ));
    }
    if top.as_deref() != Some(crate::TOP_MODULE) {
        out.push(format!(
            "synthesis top {top:?}, expected {}",
            crate::TOP_MODULE
        ));
    }
    if part.as_deref() != Some(board.board.part.as_str()) {
        out.push(format!(
            "part {part:?}, the board file says {}",
            board.board.part
        ));
    }
    let want_fclk = crate::gen::mhz(regmap::PL_CLOCK_HZ);
    if fclk.as_deref() != Some(want_fclk.as_str()) {
        out.push(format!(
            "PS7 FCLK0 {fclk:?} MHz, the register map needs {want_fclk} MHz"
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::verilog::module_ports;

    const STUB: &str = include_str!("../../../pl-bitstream-src/board/lint/ps_bd.v");
    const ZEDBOARD: &str = include_str!("../../../boards/zedboard.toml");

    fn facts_for(stub: &[Port]) -> String {
        let mut s = String::from("part xc7z020clg484-1\naddress 0x43C00000 32K\ntop board_top\nps7 CONFIG.PCW_FPGA0_PERIPHERAL_FREQMHZ 100\n");
        for p in stub {
            let dir = match p.dir {
                Dir::Input => "input",
                Dir::Output => "output",
                Dir::Inout => "inout",
            };
            s += &format!("port {} {dir} {}\n", p.name, p.bits().len().max(1));
        }
        s
    }

    #[test]
    fn matching_facts_pass_and_each_difference_is_named() {
        let stub = module_ports(STUB, "ps_bd").unwrap();
        let board = Board::parse(ZEDBOARD).unwrap();
        let good = facts_for(&stub);
        assert_eq!(problems(&good, &stub, &board), Vec::<String>::new());
        let cases = [
            (
                "address 0x43C00000 32K",
                "address 0x40000000 32K",
                "address window",
            ),
            (
                "port M_AXI_PL_araddr output 32",
                "port M_AXI_PL_araddr output 15",
                "M_AXI_PL_araddr",
            ),
            ("port irq_f2p input 1\n", "", "irq_f2p"),
            ("top board_top", "top pl_top", "synthesis top"),
            ("FREQMHZ 100", "FREQMHZ 125", "FCLK0"),
        ];
        for (from, to, needle) in cases {
            assert!(good.contains(from), "{from}");
            let p = problems(&good.replace(from, to), &stub, &board);
            assert!(p.iter().any(|m| m.contains(needle)), "{to}: {p:?}");
        }
    }
}
