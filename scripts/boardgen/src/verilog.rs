//! The port list of a Verilog module with an ANSI header (the style of
//! every module in pl-bitstream-src): enough of Verilog to read ports, and
//! a clear error for anything else.
use std::fmt;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dir {
    Input,
    Output,
    Inout,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Port {
    pub name: String,
    pub dir: Dir,
    /// `[msb:lsb]`, or None for a scalar.
    pub range: Option<(u32, u32)>,
}

impl Port {
    /// Bit indices of the port (empty for a scalar).
    pub fn bits(&self) -> Vec<u32> {
        match self.range {
            None => Vec::new(),
            Some((a, b)) => (a.min(b)..=a.max(b)).collect(),
        }
    }
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ParseError(pub String);

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ParseError {}

/// Removes `//` and `/* */` comments and `(* attributes *)`, keeping line
/// structure irrelevant (ports are separated by commas, not lines).
fn strip_comments(src: &str) -> String {
    let mut out = String::with_capacity(src.len());
    let b = src.as_bytes();
    let mut i = 0;
    while i < b.len() {
        if b[i..].starts_with(b"//") {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if b[i..].starts_with(b"/*") || b[i..].starts_with(b"(*") {
            let close: &[u8] = if b[i] == b'/' { b"*/" } else { b"*)" };
            i += 2;
            while i < b.len() && !b[i..].starts_with(close) {
                i += 1;
            }
            i += 2;
            out.push(' ');
        } else {
            out.push(b[i] as char);
            i += 1;
        }
    }
    out
}

/// The ports of `module`, in declaration order.
pub fn module_ports(src: &str, module: &str) -> Result<Vec<Port>, ParseError> {
    let e = |m: String| Err(ParseError(format!("module {module}: {m}")));
    let text = strip_comments(src);
    let mut rest = None;
    let mut search = text.as_str();
    while let Some(pos) = search.find("module") {
        let before_ok = pos == 0 || !is_ident_char(search.as_bytes()[pos - 1]);
        let after = &search[pos + "module".len()..];
        let name_start = after.trim_start();
        if before_ok && after.starts_with(char::is_whitespace) {
            let name: String = name_start
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            if name == module {
                rest = Some(&name_start[name.len()..]);
                break;
            }
        }
        search = after;
    }
    let Some(mut rest) = rest else {
        return e("not found".into());
    };
    rest = rest.trim_start();
    if let Some(params) = rest.strip_prefix('#') {
        let Some(after) = skip_parens(params.trim_start()) else {
            return e("unbalanced parameter list".into());
        };
        rest = after.trim_start();
    }
    let Some(list) = rest.strip_prefix('(') else {
        return e("expected `(` after the module name".into());
    };
    let Some(end) = list.find(')') else {
        return e("port list not closed".into());
    };
    let list = &list[..end];
    let mut ports = Vec::new();
    let mut dir = None;
    let mut range = None;
    for item in list.split(',') {
        let mut toks = tokens(item);
        if toks.is_empty() {
            return e("empty port in the list".into());
        }
        if let Some(d) = match toks[0].as_str() {
            "input" => Some(Dir::Input),
            "output" => Some(Dir::Output),
            "inout" => Some(Dir::Inout),
            _ => None,
        } {
            dir = Some(d);
            range = None;
            toks.remove(0);
            if toks
                .first()
                .is_some_and(|t| t == "wire" || t == "reg" || t == "logic")
            {
                toks.remove(0);
            }
            if toks.first().is_some_and(|t| t == "signed") {
                toks.remove(0);
            }
            if toks.first().is_some_and(|t| t.starts_with('[')) {
                range = Some(
                    parse_range(&toks.remove(0))
                        .map_err(|m| ParseError(format!("module {module}: {m}")))?,
                );
            }
        }
        let Some(d) = dir else {
            return e(format!(
                "`{}`: non-ANSI port lists are not supported",
                item.trim()
            ));
        };
        if toks.len() != 1 || !toks[0].bytes().all(is_ident_char) {
            return e(format!("cannot read port `{}`", item.trim()));
        }
        ports.push(Port {
            name: toks[0].clone(),
            dir: d,
            range,
        });
    }
    Ok(ports)
}

fn is_ident_char(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_' || c == b'$'
}

/// Whitespace-separated tokens, with a `[...]` range kept as one token.
fn tokens(s: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut cur = String::new();
    let mut depth = 0;
    for c in s.chars() {
        match c {
            '[' => {
                if depth == 0 && !cur.is_empty() {
                    out.push(std::mem::take(&mut cur));
                }
                depth += 1;
                cur.push(c);
            }
            ']' => {
                depth -= 1;
                cur.push(c);
                if depth == 0 {
                    out.push(std::mem::take(&mut cur));
                }
            }
            c if c.is_whitespace() && depth == 0 => {
                if !cur.is_empty() {
                    out.push(std::mem::take(&mut cur));
                }
            }
            c if c.is_whitespace() => {}
            _ => cur.push(c),
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}

fn parse_range(t: &str) -> Result<(u32, u32), String> {
    let inner = t.trim_start_matches('[').trim_end_matches(']');
    let Some((a, b)) = inner.split_once(':') else {
        return Err(format!("range `{t}`: expected [msb:lsb]"));
    };
    match (a.trim().parse(), b.trim().parse()) {
        (Ok(a), Ok(b)) => Ok((a, b)),
        _ => Err(format!(
            "range `{t}`: only numeric bounds are supported at the top level"
        )),
    }
}

/// Skips a balanced `( ... )` and returns what follows it.
fn skip_parens(s: &str) -> Option<&str> {
    let mut depth = 0usize;
    for (i, c) in s.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => {
                depth = depth.checked_sub(1)?;
                if depth == 0 {
                    return Some(&s[i + 1..]);
                }
            }
            _ if depth == 0 => return None,
            _ => {}
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_ansi_ports_with_ranges_comments_and_parameters() {
        let src = "// module fake (input x);\nmodule other (input wire q);\nendmodule\n\
                   module m #(parameter W = 8, parameter [0:0] R = 1'b0) (\n\
                   input  wire        clk_i, // clock\n\
                   /* block */ output wire [ 2:0] g_o,\n\
                   (* keep *) inout  wire [53:0] mio_io,\n\
                   input  signed [7:0] s_i,\n\
                   output reg  a_o, b_o\n);\nendmodule\n";
        let p = module_ports(src, "m").unwrap();
        let names: Vec<_> = p.iter().map(|p| p.name.as_str()).collect();
        assert_eq!(names, ["clk_i", "g_o", "mio_io", "s_i", "a_o", "b_o"]);
        assert_eq!(p[1].range, Some((2, 0)));
        assert_eq!(p[2].dir, Dir::Inout);
        assert_eq!(p[2].bits().len(), 54);
        assert_eq!(p[3].range, Some((7, 0)));
        // `b_o` inherits `output reg` and no range.
        assert_eq!((p[5].dir, p[5].range), (Dir::Output, None));
        assert_eq!(module_ports(src, "other").unwrap().len(), 1);
    }

    #[test]
    fn unsupported_forms_fail_clearly() {
        assert!(module_ports("module m (a, b); input a; endmodule", "m")
            .unwrap_err()
            .0
            .contains("non-ANSI"));
        assert!(module_ports("module m (input [W-1:0] a);", "m")
            .unwrap_err()
            .0
            .contains("numeric"));
        assert!(module_ports("module x (input a);", "m")
            .unwrap_err()
            .0
            .contains("not found"));
        assert!(module_ports("module m (input a,);", "m").is_err());
    }

    #[test]
    fn reads_the_real_top_level() {
        let src = include_str!("../../../pl-bitstream-src/board/board_top.v");
        let p = module_ports(src, "board_top").unwrap();
        let adc = p.iter().find(|p| p.name == "adc_data_i").unwrap();
        assert_eq!((adc.dir, adc.range), (Dir::Input, Some((35, 0))));
        assert!(p
            .iter()
            .any(|p| p.name == "fixed_io_mio_io" && p.range == Some((53, 0))));
    }
}
