//! Prints the register table (`regmap::BLOCKS`) as one JSON document on
//! stdout, for tools outside Rust (the cocotb AXI-Lite test): blocks with
//! their base address, registers with offset, access, width, reset, write
//! rule (`invalid`), hardware kind and fields. Data only; the rules that
//! give it meaning are the table's documentation (`regmap` crate doc).
use regmap::{Access, Hw, Invalid, BASE_ADDR, BLOCKS, BLOCK_SIZE};

/// A JSON string literal (names and kinds are ASCII identifiers).
fn s(x: &str) -> String {
    format!("\"{}\"", x.replace('\\', "\\\\").replace('"', "\\\""))
}

fn main() {
    let mut blocks = Vec::new();
    for b in BLOCKS {
        let base = BASE_ADDR + usize::from(b.index) * BLOCK_SIZE;
        let mut regs = Vec::new();
        for r in b.registers {
            let access = match r.access {
                Access::Rw => "RW",
                Access::Ro => "RO",
                Access::W1c => "W1C",
            };
            let invalid = match r.invalid {
                Invalid::AllValid => "{\"kind\":\"all_valid\"}".to_string(),
                Invalid::Clamp { min, max } => {
                    format!("{{\"kind\":\"clamp\",\"min\":{min},\"max\":{max}}}")
                }
                Invalid::Reject { max } => format!("{{\"kind\":\"reject\",\"max\":{max}}}"),
            };
            let hw = match r.hw {
                Hw::Plain => "plain",
                Hw::Const => "const",
                Hw::Strobe => "strobe",
                Hw::HwClear => "hw_clear",
                Hw::Errors => "errors",
            };
            let fields: Vec<String> = r
                .fields
                .iter()
                .map(|f| {
                    format!(
                        "{{\"name\":{},\"lsb\":{},\"width\":{}}}",
                        s(f.name),
                        f.lsb,
                        f.width
                    )
                })
                .collect();
            regs.push(format!(
                "{{\"name\":{},\"offset\":{},\"access\":{},\"width\":{},\"reset\":{},\
                 \"invalid\":{invalid},\"hw\":{},\"fields\":[{}]}}",
                s(r.name),
                r.offset,
                s(access),
                r.width,
                r.reset,
                s(hw),
                fields.join(",")
            ));
        }
        blocks.push(format!(
            "{{\"name\":{},\"index\":{},\"base\":{base},\"registers\":[{}]}}",
            s(b.name),
            b.index,
            regs.join(",")
        ));
    }
    println!(
        "{{\"base\":{BASE_ADDR},\"block_size\":{BLOCK_SIZE},\"blocks\":[{}]}}",
        blocks.join(",")
    );
}
