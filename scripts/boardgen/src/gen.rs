//! Files generated from a board file: the XDC, the PS7 configuration (Tcl),
//! the pin table (Markdown) and the firmware's clock constants (Rust).
use crate::board::Board;
use crate::verilog::{Dir, Port};
use std::fmt::Write;

fn header(b: &Board, comment: &str) -> String {
    format!(
        "{comment} Generated from boards/{}.toml by `cargo run -p boardgen -- gen`; do not edit.\n",
        b.board.name
    )
}

/// Hz as the MHz decimal Vivado's PS7 parameters take (`33.333333`, `100`).
pub fn mhz(hz: u32) -> String {
    let s = format!("{}.{:06}", hz / 1_000_000, hz % 1_000_000);
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// The XDC: one PACKAGE_PIN/IOSTANDARD line per constrained bit, pull-ups
/// and pull-downs, and the I/O timing (false paths for asynchronous inputs
/// and for outputs, a datapath-only maximum delay for the strobed ADC bus;
/// no input delay: no clock of the PL reaches the converter).
pub fn xdc(b: &Board, ports: &[Port]) -> String {
    let mut s = header(b, "#");
    let _ = writeln!(
        s,
        "# {}, {}; top level board_top.",
        b.board.title, b.board.part
    );
    let _ = writeln!(
        s,
        "# FCLK0 (clk_fpga_0, {} MHz) is created by the PS7's own constraints.",
        mhz(b.ps.fclk0_hz)
    );
    s.push_str(
        "\n# Pins: port, package pin, IO standard; the comment names the board's connector pin.\n",
    );
    for p in &b.pins {
        let _ = writeln!(
            s,
            "set_property -dict {{PACKAGE_PIN {} IOSTANDARD {}}} [get_ports {{{}}}] ;# {}: {}",
            p.pin, p.io, p.port, p.connector, p.note
        );
    }
    for p in b.pins.iter().filter(|p| p.pullup) {
        let _ = writeln!(s, "set_property PULLUP true [get_ports {{{}}}]", p.port);
    }
    for p in b.pins.iter().filter(|p| p.pulldown) {
        let _ = writeln!(s, "set_property PULLDOWN true [get_ports {{{}}}]", p.port);
    }
    let pl: Vec<&Port> = ports
        .iter()
        .filter(|p| !crate::check::is_ps_port(&p.name))
        .collect();
    let pattern = |p: &Port| match p.range {
        Some(_) => format!("{}[*]", p.name),
        None => p.name.clone(),
    };
    let is_sync = |p: &Port| b.timing.strobed_inputs.contains(&p.name);
    let is_strobe = |p: &Port| b.timing.strobe == p.name;
    let async_in: Vec<String> = pl
        .iter()
        .filter(|p| p.dir == Dir::Input && !is_sync(p) && !is_strobe(p))
        .map(|p| pattern(p))
        .collect();
    let sync_in: Vec<String> = pl
        .iter()
        .filter(|p| p.dir == Dir::Input && is_sync(p))
        .map(|p| pattern(p))
        .collect();
    let outs: Vec<String> = pl
        .iter()
        .filter(|p| p.dir == Dir::Output)
        .map(|p| pattern(p))
        .collect();
    s.push_str("\n# Timing.\n");
    if !async_in.is_empty() {
        s.push_str("# Asynchronous inputs: each passes a two-flop synchroniser (sync2).\n");
        let _ = writeln!(
            s,
            "set_false_path -from [get_ports {{{}}}]",
            async_in.join(" ")
        );
    }
    if !outs.is_empty() {
        s.push_str(
            "# Outputs leave PL registers; their ns-scale skew is small against the dead\n\
             # time (DEAD_TIME, 500 ns from reset) and the ADC period (3.9 us).\n",
        );
        let _ = writeln!(s, "set_false_path -to [get_ports {{{}}}]", outs.join(" "));
    }
    if pl.iter().any(|p| p.dir == Dir::Input && is_strobe(p)) {
        s.push_str(
            "# The strobe of the captured inputs (the ADC's data-ready) is asynchronous too\n\
             # (sync2; the converter sees no PL clock), but its pin-to-flop delay decides\n\
             # when the data is captured: 2 to 3 periods plus this delay after the pin's\n\
             # edge, inside the converter's data-valid window (timing.strobe_max_delay_ns).\n",
        );
        let _ = writeln!(
            s,
            "set_max_delay -datapath_only -from [get_ports {{{}}}] {}",
            b.timing.strobe, b.timing.strobe_max_delay_ns
        );
    }
    if !sync_in.is_empty() {
        s.push_str(
            "# Inputs captured at the clock edge after the synchronised data-ready rose\n\
             # (adc_frontend: 2 to 3 periods after the pin's edge). Their pin-to-register\n\
             # delay only has to be shorter than that (timing.strobed_max_delay_ns).\n",
        );
        let _ = writeln!(
            s,
            "set_max_delay -datapath_only -from [get_ports {{{}}}] {}",
            sync_in.join(" "),
            b.timing.strobed_max_delay_ns
        );
    }
    s
}

/// Width of the PS7's EMIO GPIO (GPIO 54..85, the GPIO controller's bank 2):
/// board_top drives the 32-bit signature (the register map's `ID` value)
/// that the firmware reads in `DATA_RO_2` before any GP0 access.
pub const EMIO_GPIO_WIDTH: u32 = 32;

/// The PS7 configuration as a Tcl list of CONFIG.* pairs plus the board
/// facts bitstream.tcl needs.
pub fn ps7_tcl(b: &Board) -> String {
    let ps = &b.ps;
    let mut s = header(b, "#");
    let _ = writeln!(
        s,
        "# PS7 configuration of the {}; sourced by scripts/vivado/bitstream.tcl.",
        b.board.title
    );
    let _ = writeln!(s, "set board_name {}", b.board.name);
    let _ = writeln!(s, "set board_part {}", b.board.part);
    let _ = writeln!(s, "set fclk0_hz {}", ps.fclk0_hz);
    // The PL's AXI window: the register map's base and its 2^AXI_ADDR_BITS bytes.
    let _ = writeln!(s, "set pl_base 0x{:08X}", regmap::BASE_ADDR);
    let _ = writeln!(
        s,
        "set pl_range {}K",
        (1usize << regmap::AXI_ADDR_BITS) / 1024
    );
    // The width of the block design's emio_gpio_i port, the same number as
    // PCW_GPIO_EMIO_GPIO_IO below.
    let _ = writeln!(s, "set emio_gpio_width {EMIO_GPIO_WIDTH}");
    let bit = |v: bool| if v { "1" } else { "0" };
    let mut cfg: Vec<(String, String)> = vec![
        ("PCW_CRYSTAL_PERIPHERAL_FREQMHZ".into(), mhz(ps.ps_clk_hz)),
        ("PCW_APU_PERIPHERAL_FREQMHZ".into(), mhz(ps.cpu_hz)),
        ("PCW_UIPARAM_DDR_MEMORY_TYPE".into(), "DDR 3".into()),
        ("PCW_UIPARAM_DDR_PARTNO".into(), ps.ddr_partno.clone()),
        ("PCW_UIPARAM_DDR_BUS_WIDTH".into(), "32 Bit".into()),
        ("PCW_UIPARAM_DDR_FREQ_MHZ".into(), ps.ddr_mhz.clone()),
        ("PCW_UIPARAM_DDR_TRAIN_WRITE_LEVEL".into(), "1".into()),
        ("PCW_UIPARAM_DDR_TRAIN_READ_GATE".into(), "1".into()),
        ("PCW_UIPARAM_DDR_TRAIN_DATA_EYE".into(), "1".into()),
        (
            "PCW_UIPARAM_DDR_USE_INTERNAL_VREF".into(),
            bit(ps.ddr_internal_vref).into(),
        ),
    ];
    for (i, v) in ps.ddr_board_delay_ns.iter().enumerate() {
        cfg.push((format!("PCW_UIPARAM_DDR_BOARD_DELAY{i}"), v.clone()));
    }
    for (i, v) in ps.ddr_dqs_to_clk_delay_ns.iter().enumerate() {
        cfg.push((format!("PCW_UIPARAM_DDR_DQS_TO_CLK_DELAY_{i}"), v.clone()));
    }
    cfg.extend([
        ("PCW_PRESET_BANK0_VOLTAGE".into(), ps.mio_bank0.clone()),
        ("PCW_PRESET_BANK1_VOLTAGE".into(), ps.mio_bank1.clone()),
        ("PCW_UART_PERIPHERAL_FREQMHZ".into(), mhz(ps.uart_ref_hz)),
        ("PCW_UART0_PERIPHERAL_ENABLE".into(), "1".into()),
        ("PCW_UART0_UART0_IO".into(), ps.uart0_mio.clone()),
        ("PCW_UART1_PERIPHERAL_ENABLE".into(), "1".into()),
        ("PCW_UART1_UART1_IO".into(), ps.uart1_mio.clone()),
        ("PCW_SD0_PERIPHERAL_ENABLE".into(), "1".into()),
        ("PCW_SD0_SD0_IO".into(), ps.sd0_mio.clone()),
        ("PCW_SD0_GRP_CD_ENABLE".into(), "1".into()),
        ("PCW_SD0_GRP_CD_IO".into(), format!("MIO {}", ps.sd0_cd_mio)),
        ("PCW_QSPI_PERIPHERAL_ENABLE".into(), bit(ps.qspi).into()),
        ("PCW_QSPI_GRP_SINGLE_SS_ENABLE".into(), bit(ps.qspi).into()),
        ("PCW_EN_CLK0_PORT".into(), "1".into()),
        ("PCW_FPGA0_PERIPHERAL_FREQMHZ".into(), mhz(ps.fclk0_hz)),
        ("PCW_EN_RST0_PORT".into(), "1".into()),
        ("PCW_USE_M_AXI_GP0".into(), "1".into()),
        ("PCW_USE_FABRIC_INTERRUPT".into(), "1".into()),
        ("PCW_IRQ_F2P_INTR".into(), "1".into()),
        // EMIO GPIO for the bitstream's signature (a PS read, no AXI).
        ("PCW_GPIO_EMIO_GPIO_ENABLE".into(), "1".into()),
        ("PCW_GPIO_EMIO_GPIO_IO".into(), EMIO_GPIO_WIDTH.to_string()),
    ]);
    s.push_str("set ps7_config [list \\\n");
    for (k, v) in cfg {
        let _ = writeln!(s, "    CONFIG.{k} {{{v}}} \\");
    }
    s.push_str("]\n");
    s
}

/// The wiring table for docs/board.md.
pub fn pins_md(b: &Board) -> String {
    let mut s = header(b, "<!--");
    s.truncate(s.trim_end().len());
    s.push_str(" -->\n\n");
    let _ = writeln!(s, "# Pins of the {}, {}\n", b.board.title, b.board.part);
    s.push_str("| signal (board_top port) | connector pin | package pin | IO standard | use |\n|---|---|---|---|---|\n");
    for p in &b.pins {
        let pull = if p.pullup {
            " (internal pull-up)"
        } else if p.pulldown {
            " (internal pull-down)"
        } else {
            ""
        };
        let _ = writeln!(
            s,
            "| `{}` | {} | {} | {} | {}{} |",
            p.port, p.connector, p.pin, p.io, p.note, pull
        );
    }
    let ps = &b.ps;
    let _ = writeln!(
        s,
        "\nPS: UART0 (defmt log) on {}, UART1 (console) on {}, UART reference {} MHz, \
         CPU {} MHz (timer PERIPHCLK {} Hz), FCLK0 {} MHz, DDR3 {} at {} MHz.",
        ps.uart0_mio,
        ps.uart1_mio,
        mhz(ps.uart_ref_hz),
        mhz(ps.cpu_hz),
        b.periphclk_hz(),
        mhz(ps.fclk0_hz),
        ps.ddr_partno,
        ps.ddr_mhz
    );
    s
}

/// Rust constants for the firmware (included by firmware/src/board.rs).
pub fn firmware_consts(b: &Board) -> String {
    format!(
        "// Generated from boards/{name}.toml by firmware/build.rs.\n\
         /// UART reference clock set by the FSBL, Hz.\n\
         pub const UART_REF_CLK_HZ: u32 = {uart};\n\
         /// PERIPHCLK of the A9 private and global timers (CPU_6x4x / 2), Hz.\n\
         pub const PERIPHCLK_HZ: u32 = {periph};\n",
        name = b.board.name,
        uart = b.ps.uart_ref_hz,
        periph = b.periphclk_hz()
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::verilog::module_ports;

    const TOP: &str = include_str!("../../../pl-bitstream-src/board/board_top.v");
    const ZEDBOARD: &str = include_str!("../../../boards/zedboard.toml");

    fn zed() -> (Board, Vec<Port>) {
        (
            Board::parse(ZEDBOARD).unwrap(),
            module_ports(TOP, "board_top").unwrap(),
        )
    }

    #[test]
    fn mhz_formatting() {
        assert_eq!(mhz(100_000_000), "100");
        assert_eq!(mhz(33_333_333), "33.333333");
        assert_eq!(mhz(666_666_667), "666.666667");
        assert_eq!(mhz(50_500_000), "50.5");
    }

    #[test]
    fn xdc_has_one_line_per_pin_and_the_timing_classes() {
        let (b, ports) = zed();
        let x = xdc(&b, &ports);
        assert_eq!(x.matches("PACKAGE_PIN").count(), b.pins.len());
        assert!(x.contains(
            "set_property -dict {PACKAGE_PIN Y11 IOSTANDARD LVCMOS33} [get_ports {gate_hi_o[2]}]"
        ));
        assert!(x.contains("set_property PULLUP true [get_ports {fault_ext_ni}]"));
        assert!(x.contains("set_property PULLDOWN true [get_ports {adc_drdy_i}]"));
        assert!(x.contains("set_property PULLDOWN true [get_ports {adc_data_i[35]}]"));
        assert!(
            x.contains("set_false_path -from [get_ports {enc_a_i enc_b_i enc_z_i fault_ext_ni}]")
        );
        // The data-ready's delay is bounded: the capture time depends on it.
        assert!(x.contains("set_max_delay -datapath_only -from [get_ports {adc_drdy_i}] 5.0"));
        assert!(!x
            .lines()
            .any(|l| l.starts_with("set_false_path") && l.contains("adc_drdy_i")));
        assert!(x.contains(
            "set_false_path -to [get_ports {gate_hi_o[*] gate_lo_o[*] gate_en_o adc_cnv_o led_o[*]}]"
        ));
        assert!(x.contains("set_max_delay -datapath_only -from [get_ports {adc_data_i[*]}] 10.0"));
        // No clock of the PL reaches the converter: no input delays.
        assert!(!x.contains("set_input_delay"));
        // PS pins are the PS7's business.
        assert!(!x.contains("ddr_") && !x.contains("fixed_io"));
    }

    #[test]
    fn ps7_config_carries_the_board_facts() {
        let (b, _) = zed();
        let t = ps7_tcl(&b);
        for line in [
            "CONFIG.PCW_FPGA0_PERIPHERAL_FREQMHZ {100}",
            "CONFIG.PCW_UART_PERIPHERAL_FREQMHZ {50}",
            "CONFIG.PCW_UART0_UART0_IO {MIO 14 .. 15}",
            "CONFIG.PCW_UART1_UART1_IO {MIO 48 .. 49}",
            "CONFIG.PCW_UIPARAM_DDR_DQS_TO_CLK_DELAY_3 {-0.061}",
            "CONFIG.PCW_USE_M_AXI_GP0 {1}",
            "CONFIG.PCW_GPIO_EMIO_GPIO_ENABLE {1}",
            "CONFIG.PCW_GPIO_EMIO_GPIO_IO {32}",
            "set board_part xc7z020clg484-1",
            "set pl_base 0x43C00000",
            "set pl_range 32K",
            "set emio_gpio_width 32",
        ] {
            assert!(t.contains(line), "missing {line}");
        }
    }

    #[test]
    fn firmware_constants_are_the_board_clocks() {
        let (b, _) = zed();
        let c = firmware_consts(&b);
        assert!(c.contains("pub const UART_REF_CLK_HZ: u32 = 50000000;"));
        assert!(c.contains("pub const PERIPHCLK_HZ: u32 = 333333333;"));
    }
}
