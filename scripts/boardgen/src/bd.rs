//! The block design as the Vivado flow builds it (facts recorded by
//! scripts/vivado/stub-run.tcl) against the RTL and the register map: the
//! ports match the `ps_bd` stand-in that board_top is linted with, the PL
//! window is the register map's, FCLK0 is the PL clock, the PL's
//! control interrupt reaches the PS: port `irq_f2p` (level high) on the
//! net of `ps7/IRQ_F2P`, with the PS7's fabric interrupts enabled, and the
//! bitstream's signature reaches the GPIO controller: port `emio_gpio_i`
//! on the net of `ps7/GPIO_I`, with the PS7's EMIO GPIO enabled at the
//! signature's width.
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
    let mut irq_net = false;
    let mut irq_level = None;
    let mut f2p = (false, false);
    let mut emio_net = false;
    let mut emio = (false, None);
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
            ["ps7", "CONFIG.PCW_USE_FABRIC_INTERRUPT", v] => f2p.0 = *v == "1",
            ["ps7", "CONFIG.PCW_IRQ_F2P_INTR", v] => f2p.1 = *v == "1",
            ["ps7", "CONFIG.PCW_GPIO_EMIO_GPIO_ENABLE", v] => emio.0 = *v == "1",
            ["ps7", "CONFIG.PCW_GPIO_EMIO_GPIO_IO", v] => emio.1 = Some(v.to_string()),
            ["portprop", "irq_f2p", "CONFIG.SENSITIVITY", v] => irq_level = Some(v.to_string()),
            ["net", ends @ ..] => {
                irq_net |= ends.contains(&"port:irq_f2p") && ends.contains(&"pin:ps7/IRQ_F2P");
                emio_net |= ends.contains(&"port:emio_gpio_i") && ends.contains(&"pin:ps7/GPIO_I");
            }
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
    if !irq_net {
        out.push("port irq_f2p (pl_top's irq_o) is not connected to ps7/IRQ_F2P".into());
    }
    if irq_level.as_deref() != Some("LEVEL_HIGH") {
        out.push(format!(
            "port irq_f2p sensitivity {irq_level:?}: the control interrupt is a level (LEVEL_HIGH)"
        ));
    }
    if f2p != (true, true) {
        out.push(
            "PS7 fabric interrupts (PCW_USE_FABRIC_INTERRUPT, PCW_IRQ_F2P_INTR) not enabled".into(),
        );
    }
    // The firmware reads the signature in bank 2 (DATA_RO_2) before any GP0
    // access: EMIO GPIO on, as wide as the signature, fed by board_top.
    if !emio_net {
        out.push(
            "port emio_gpio_i (the bitstream's signature) is not connected to ps7/GPIO_I".into(),
        );
    }
    let want_emio = crate::gen::EMIO_GPIO_WIDTH.to_string();
    if emio != (true, Some(want_emio.clone())) {
        out.push(format!(
            "PS7 EMIO GPIO (PCW_GPIO_EMIO_GPIO_ENABLE, PCW_GPIO_EMIO_GPIO_IO) {emio:?}, \
             the signature needs it enabled with {want_emio} bits"
        ));
    }
    let emio_port = ports.iter().find(|p| p.0 == "emio_gpio_i");
    if emio_port.map(|p| (p.1.as_str(), p.2)) != Some(("input", crate::gen::EMIO_GPIO_WIDTH)) {
        out.push(format!(
            "port emio_gpio_i {emio_port:?}: the signature needs an input of {want_emio} bits"
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
        let mut s = String::from(
            "part xc7z020clg484-1\naddress 0x43C00000 32K\ntop board_top\n\
             ps7 CONFIG.PCW_FPGA0_PERIPHERAL_FREQMHZ 100\n\
             ps7 CONFIG.PCW_USE_FABRIC_INTERRUPT 1\nps7 CONFIG.PCW_IRQ_F2P_INTR 1\n\
             portprop irq_f2p CONFIG.SENSITIVITY LEVEL_HIGH\n\
             net port:irq_f2p pin:ps7/IRQ_F2P\n\
             ps7 CONFIG.PCW_GPIO_EMIO_GPIO_ENABLE 1\nps7 CONFIG.PCW_GPIO_EMIO_GPIO_IO 32\n\
             net port:emio_gpio_i pin:ps7/GPIO_I\n",
        );
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
            (
                "net port:irq_f2p pin:ps7/IRQ_F2P",
                "net port:irq_f2p pin:ps7/Core0_nIRQ",
                "not connected to ps7/IRQ_F2P",
            ),
            ("LEVEL_HIGH", "EDGE_RISING", "sensitivity"),
            (
                "PCW_IRQ_F2P_INTR 1",
                "PCW_IRQ_F2P_INTR 0",
                "fabric interrupts",
            ),
            (
                "net port:emio_gpio_i pin:ps7/GPIO_I",
                "net port:emio_gpio_i pin:ps7/GPIO_O",
                "not connected to ps7/GPIO_I",
            ),
            (
                "PCW_GPIO_EMIO_GPIO_ENABLE 1",
                "PCW_GPIO_EMIO_GPIO_ENABLE 0",
                "EMIO GPIO",
            ),
            (
                "PCW_GPIO_EMIO_GPIO_IO 32",
                "PCW_GPIO_EMIO_GPIO_IO 16",
                "EMIO GPIO",
            ),
            (
                "port emio_gpio_i input 32",
                "port emio_gpio_i input 16",
                "emio_gpio_i",
            ),
        ];
        for (from, to, needle) in cases {
            assert!(good.contains(from), "{from}");
            let p = problems(&good.replace(from, to), &stub, &board);
            assert!(p.iter().any(|m| m.contains(needle)), "{to}: {p:?}");
        }
    }
}
