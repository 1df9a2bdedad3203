//! The board file (`boards/<name>.toml`): parsing and validation.
//!
//! A board file names the part, the PS configuration that the firmware and
//! the FSBL depend on (clocks, DDR, UART MIO pins) and one package pin per
//! bit of every PL port of `board_top`. Everything else (XDC, PS7 Tcl,
//! pin table, the firmware's clock constants) is derived from it.
use serde::Deserialize;
use std::collections::BTreeMap;
use std::fmt;

/// A problem in a board file; the message names the field.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BoardError(pub String);

impl fmt::Display for BoardError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for BoardError {}

fn err<T>(msg: impl Into<String>) -> Result<T, BoardError> {
    Err(BoardError(msg.into()))
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Board {
    pub board: Meta,
    pub ps: Ps,
    pub timing: Timing,
    #[serde(rename = "pin")]
    pub pins: Vec<Pin>,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Meta {
    /// File stem and the name scripts take (`--board zedboard`).
    pub name: String,
    pub title: String,
    /// Vivado part name, e.g. `xc7z020clg484-1`.
    pub part: String,
    pub openfpgaloader_board: String,
}

/// PS7 configuration. Clock fields are in Hz; decimal strings are passed to
/// Vivado verbatim (they are validated as decimal numbers).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Ps {
    pub ps_clk_hz: u32,
    /// CPU_6x4x clock; PERIPHCLK of the A9 timers is half of it.
    pub cpu_hz: u32,
    pub uart_ref_hz: u32,
    pub fclk0_hz: u32,
    pub ddr_partno: String,
    pub ddr_mhz: String,
    pub ddr_board_delay_ns: [String; 4],
    pub ddr_dqs_to_clk_delay_ns: [String; 4],
    pub ddr_internal_vref: bool,
    pub uart0_mio: String,
    pub uart1_mio: String,
    pub sd0_mio: String,
    pub sd0_cd_mio: u8,
    pub qspi: bool,
    pub mio_bank0: String,
    pub mio_bank1: String,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Timing {
    /// Input ports captured only at the clock edge after a synchronised
    /// strobe rose (the ADC data bus); every other input is asynchronous.
    pub strobed_inputs: Vec<String>,
    /// Largest pin-to-register delay of the strobed inputs, ns
    /// (`set_max_delay -datapath_only`): shorter than the strobe's
    /// synchroniser delay, so the data has settled when it is captured.
    pub strobed_max_delay_ns: String,
    /// The asynchronous strobe of the strobed inputs (the ADC's data-ready):
    /// still asynchronous (a two-flop synchroniser), but its pin-to-flop
    /// delay sets when the data is captured, so it is bounded
    /// (`set_max_delay -datapath_only`), not a false path.
    pub strobe: String,
    /// Largest pin-to-first-flop delay of `strobe`, ns: the capture edge is
    /// 2 to 3 clock periods plus this after the pin's edge, which must stay
    /// inside the converter's data-valid window.
    pub strobe_max_delay_ns: String,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Pin {
    /// `name` or `name[bit]`, a port (bit) of board_top.
    pub port: String,
    /// Package pin, e.g. `Y11`.
    pub pin: String,
    /// Header pin as printed on the board, e.g. `JA1`.
    pub connector: String,
    /// IO standard.
    pub io: String,
    #[serde(default)]
    pub pullup: bool,
    #[serde(default)]
    pub pulldown: bool,
    pub note: String,
}

/// One bit of a port: `gate_hi_o[2]` is ("gate_hi_o", Some(2)).
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord)]
pub struct PortBit {
    pub name: String,
    pub bit: Option<u32>,
}

impl fmt::Display for PortBit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.bit {
            Some(b) => write!(f, "{}[{}]", self.name, b),
            None => f.write_str(&self.name),
        }
    }
}

/// Parses `name` or `name[bit]`.
pub fn parse_port_bit(s: &str) -> Result<PortBit, BoardError> {
    let ident = |n: &str| {
        !n.is_empty()
            && n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
            && !n.starts_with(|c: char| c.is_ascii_digit())
    };
    let (name, bit) = match s.split_once('[') {
        None => (s, None),
        Some((n, rest)) => {
            let Some(num) = rest.strip_suffix(']') else {
                return err(format!("port `{s}`: expected `name[bit]`"));
            };
            match num.parse::<u32>() {
                Ok(b) => (n, Some(b)),
                Err(_) => return err(format!("port `{s}`: bit index `{num}` is not a number")),
            }
        }
    };
    if !ident(name) {
        return err(format!("port `{s}`: `{name}` is not a Verilog identifier"));
    }
    Ok(PortBit {
        name: name.to_string(),
        bit,
    })
}

/// IO standards a board file may use for the PL pins (single-ended only:
/// every drive signal is single-ended).
pub const IO_STANDARDS: [&str; 4] = ["LVCMOS33", "LVCMOS25", "LVCMOS18", "LVCMOS15"];

fn is_decimal(s: &str) -> bool {
    let t = s.strip_prefix('-').unwrap_or(s);
    let mut parts = t.splitn(2, '.');
    let int = parts.next().unwrap_or("");
    let frac = parts.next();
    !int.is_empty()
        && int.chars().all(|c| c.is_ascii_digit())
        && frac.is_none_or(|f| !f.is_empty() && f.chars().all(|c| c.is_ascii_digit()))
}

fn is_mio_range(s: &str) -> bool {
    // Vivado's form: "MIO 14 .. 15".
    let Some(rest) = s.strip_prefix("MIO ") else {
        return false;
    };
    let Some((a, b)) = rest.split_once(" .. ") else {
        return false;
    };
    matches!((a.parse::<u8>(), b.parse::<u8>()), (Ok(a), Ok(b)) if a < b && b <= 53)
}

/// Console and log baud rate of the firmware (app.rs).
pub const BAUD: u32 = 115_200;
/// The firmware's tick (app.rs `TICK_HZ`).
pub const TICK_HZ: u32 = 1000;

impl Board {
    /// Parses and validates a board file.
    pub fn parse(text: &str) -> Result<Board, BoardError> {
        let b: Board = toml::from_str(text).map_err(|e| BoardError(format!("board file: {e}")))?;
        b.validate()?;
        Ok(b)
    }

    /// PERIPHCLK of the A9 private and global timers, Hz.
    pub fn periphclk_hz(&self) -> u32 {
        self.ps.cpu_hz / 2
    }

    /// Every rule a board file must follow; the first broken one is returned.
    pub fn validate(&self) -> Result<(), BoardError> {
        let m = &self.board;
        if m.name.is_empty()
            || !m
                .name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-')
        {
            return err(format!(
                "board.name `{}`: use letters, digits and '-'",
                m.name
            ));
        }
        if !m.part.starts_with("xc7z") {
            return err(format!("board.part `{}` is not a Zynq-7000 part", m.part));
        }
        let ps = &self.ps;
        // The register map counts time in PL cycles of this clock.
        if ps.fclk0_hz != regmap::PL_CLOCK_HZ {
            return err(format!(
                "ps.fclk0_hz = {} Hz: the PL design and its register map assume {} Hz",
                ps.fclk0_hz,
                regmap::PL_CLOCK_HZ
            ));
        }
        if drive::zynq::uart_divisors(ps.uart_ref_hz, BAUD).is_none() {
            return err(format!(
                "ps.uart_ref_hz = {} Hz: no UART divisors reach {BAUD} baud",
                ps.uart_ref_hz
            ));
        }
        if drive::zynq::private_timer_load(self.periphclk_hz(), TICK_HZ).is_none() {
            return err(format!(
                "ps.cpu_hz = {} Hz: the private timer cannot tick at {TICK_HZ} Hz",
                ps.cpu_hz
            ));
        }
        if !(30_000_000..=60_000_000).contains(&ps.ps_clk_hz) {
            return err(format!(
                "ps.ps_clk_hz = {} Hz: outside 30..60 MHz",
                ps.ps_clk_hz
            ));
        }
        for (name, v) in [
            ("uart0_mio", &ps.uart0_mio),
            ("uart1_mio", &ps.uart1_mio),
            ("sd0_mio", &ps.sd0_mio),
        ] {
            if !is_mio_range(v) {
                return err(format!("ps.{name} = `{v}`: expected `MIO a .. b`"));
            }
        }
        if ps.sd0_cd_mio > 53 {
            return err(format!(
                "ps.sd0_cd_mio = {}: MIO pins are 0..53",
                ps.sd0_cd_mio
            ));
        }
        let decimals = std::iter::once(("ps.ddr_mhz", &ps.ddr_mhz))
            .chain(
                ps.ddr_board_delay_ns
                    .iter()
                    .map(|v| ("ps.ddr_board_delay_ns", v)),
            )
            .chain(
                ps.ddr_dqs_to_clk_delay_ns
                    .iter()
                    .map(|v| ("ps.ddr_dqs_to_clk_delay_ns", v)),
            )
            .chain(std::iter::once((
                "timing.strobed_max_delay_ns",
                &self.timing.strobed_max_delay_ns,
            )));
        for (name, v) in decimals {
            if !is_decimal(v) {
                return err(format!("{name}: `{v}` is not a decimal number"));
            }
        }
        // A decimal (checked above), so it parses.
        let max_delay: f64 = self.timing.strobed_max_delay_ns.parse().unwrap_or(0.0);
        // The strobe's synchroniser gives the data 2 FCLK0 periods.
        let two_periods_ns = 2e9 / f64::from(ps.fclk0_hz);
        if max_delay <= 0.0 || max_delay >= two_periods_ns {
            return err(format!(
                "timing.strobed_max_delay_ns: expected more than 0 and less than two FCLK0 periods ({two_periods_ns} ns)"
            ));
        }

        let mut by_port: BTreeMap<PortBit, &Pin> = BTreeMap::new();
        let mut by_pin: BTreeMap<&str, &Pin> = BTreeMap::new();
        for p in &self.pins {
            let pb = parse_port_bit(&p.port)?;
            if let Some(prev) = by_port.insert(pb, p) {
                return err(format!(
                    "port `{}` is constrained twice (pins {} and {})",
                    p.port, prev.pin, p.pin
                ));
            }
            let pin_ok = p.pin.len() >= 2
                && p.pin
                    .chars()
                    .all(|c| c.is_ascii_uppercase() || c.is_ascii_digit())
                && p.pin.starts_with(|c: char| c.is_ascii_uppercase())
                && p.pin.ends_with(|c: char| c.is_ascii_digit());
            if !pin_ok {
                return err(format!(
                    "port `{}`: `{}` is not a package pin name",
                    p.port, p.pin
                ));
            }
            if let Some(prev) = by_pin.insert(&p.pin, p) {
                return err(format!(
                    "package pin {} is used twice (ports {} and {})",
                    p.pin, prev.port, p.port
                ));
            }
            if p.pullup && p.pulldown {
                return err(format!("port `{}`: pullup and pulldown", p.port));
            }
            if !IO_STANDARDS.contains(&p.io.as_str()) {
                return err(format!(
                    "port `{}`: IO standard `{}` is not one of {:?}",
                    p.port, p.io, IO_STANDARDS
                ));
            }
        }
        Ok(())
    }

    /// The constrained port bits with their pins.
    pub fn port_bits(&self) -> Vec<(PortBit, &Pin)> {
        self.pins
            .iter()
            .filter_map(|p| parse_port_bit(&p.port).ok().map(|pb| (pb, p)))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    pub(crate) const ZEDBOARD: &str = include_str!("../../../boards/zedboard.toml");

    fn edited(from: &str, to: &str) -> Result<Board, BoardError> {
        assert!(ZEDBOARD.contains(from), "test edit `{from}` not found");
        Board::parse(&ZEDBOARD.replacen(from, to, 1))
    }

    #[test]
    fn zedboard_parses_with_its_clocks() {
        let b = Board::parse(ZEDBOARD).unwrap();
        assert_eq!(b.board.part, "xc7z020clg484-1");
        // 666.667 MHz / 2, the constant the firmware used before board files.
        assert_eq!(b.periphclk_hz(), 333_333_333);
        assert_eq!(b.ps.uart_ref_hz, 50_000_000);
        // 6 gates + gate enable + cnv + drdy + 36 data + A/B/Z + fault + 4 LEDs.
        assert_eq!(b.pins.len(), 6 + 1 + 2 + 36 + 3 + 1 + 4);
        // The ADC inputs read 0 without a converter card.
        assert_eq!(b.pins.iter().filter(|p| p.pulldown).count(), 37);
    }

    #[test]
    fn port_bit_syntax() {
        assert_eq!(
            parse_port_bit("adc_data_i[35]").unwrap(),
            PortBit {
                name: "adc_data_i".into(),
                bit: Some(35)
            }
        );
        assert_eq!(parse_port_bit("enc_a_i").unwrap().bit, None);
        for bad in ["", "a[", "a[x]", "a[1", "1abc", "a b", "a[1]x"] {
            assert!(parse_port_bit(bad).is_err(), "{bad} accepted");
        }
    }

    #[test]
    fn duplicate_port_and_pin_are_rejected() {
        let e = edited("port = \"gate_lo_o[2]\"", "port = \"gate_hi_o[2]\"").unwrap_err();
        assert!(e.0.contains("constrained twice"), "{e}");
        let e = edited("pin = \"AA11\"", "pin = \"Y11\"").unwrap_err();
        assert!(e.0.contains("used twice"), "{e}");
    }

    #[test]
    fn bad_values_are_rejected_with_the_field_name() {
        let cases = [
            (
                "fclk0_hz = 100_000_000",
                "fclk0_hz = 125_000_000",
                "fclk0_hz",
            ),
            (
                "uart_ref_hz = 50_000_000",
                "uart_ref_hz = 1000",
                "uart_ref_hz",
            ),
            (
                "uart0_mio = \"MIO 14 .. 15\"",
                "uart0_mio = \"MIO 14-15\"",
                "uart0_mio",
            ),
            ("ddr_mhz = \"533.333313\"", "ddr_mhz = \"533,3\"", "ddr_mhz"),
            (
                "strobed_max_delay_ns = \"10.0\"",
                "strobed_max_delay_ns = \"20.0\"",
                "strobed_max_delay_ns",
            ),
            (
                "pullup = true",
                "pullup = true\npulldown = true",
                "pullup and pulldown",
            ),
            ("io = \"LVCMOS33\"", "io = \"LVDS_25\"", "IO standard"),
            ("pin = \"Y11\"", "pin = \"y11\"", "package pin"),
            ("part = \"xc7z020clg484-1\"", "part = \"xc7a35t\"", "Zynq"),
            ("qspi = true", "qspi = true\nusb = true", "unknown field"),
        ];
        for (from, to, needle) in cases {
            let e = edited(from, to).unwrap_err();
            assert!(e.0.contains(needle), "{to}: {e}");
        }
    }

    #[test]
    fn decimals() {
        for ok in ["0", "0.41", "-0.061", "533.333313"] {
            assert!(is_decimal(ok), "{ok}");
        }
        for bad in ["", "-", ".5", "1.", "1e3", "1.2.3", "--1"] {
            assert!(!is_decimal(bad), "{bad}");
        }
    }
}
