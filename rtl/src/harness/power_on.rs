//! # power_on — a power-on reset for the ring top's restarted nodes
//!
//! A node that gets power again after it died (scenario fault `restart`,
//! protocol §12) starts as at power-up: every register at its power-up
//! value, every memory zero. rust-hdl 0.46 blocks have no reset (their
//! registers start from `initial` values), so [`with_power_on_reset`]
//! rewrites a node's Verilog ([`crate::emit::readable`] text) for the ring top:
//! every module of the node's hierarchy that holds state gets an input
//! `i_por`, and while it is 1 at a clock edge
//!
//! - a register takes its `initial` value (`always @(posedge clock) x_q <=
//!   i_por ? 1'h0 : x_d;`),
//! - a memory is cleared (its write port writes zeros everywhere),
//!
//! and every instance of such a module passes `i_por` on. Only the ring
//! top of a scenario with restarts uses it (the simulation harness holds
//! `i_por` for a few node clocks, [`crate::harness::ring_top`]); synthesis tops and
//! the other rings keep rust-hdl's text, so this costs them nothing.
//!
//! The rewrite refuses (panics with the line) a clocked statement it does
//! not know: a register it would leave out would survive the restart
//! unnoticed.

use std::collections::{HashMap, HashSet};

/// One module of the text: its name and its lines (header to `endmodule`).
struct Module {
    name: String,
    lines: Vec<String>,
}

/// Splits Verilog text into the lines outside modules and the modules.
fn modules(v: &str) -> Vec<Result<String, Module>> {
    let mut out = vec![];
    let mut cur: Option<Module> = None;
    for line in v.lines() {
        if let Some(m) = cur.as_mut() {
            m.lines.push(line.to_string());
            if line.starts_with("endmodule") {
                out.push(Err(cur.take().expect("in a module")));
            }
        } else if let Some(rest) = line.strip_prefix("module ") {
            let name = rest.split('(').next().unwrap_or("").trim().to_string();
            cur = Some(Module {
                name,
                lines: vec![line.to_string()],
            });
        } else {
            out.push(Ok(line.to_string()));
        }
    }
    assert!(cur.is_none(), "unterminated module");
    out
}

/// The module a child-instance line (`    merkur_x__y y(`: two names and
/// the opening parenthesis) instantiates.
fn instance_of(line: &str) -> Option<&str> {
    let t = line.strip_prefix("    ")?;
    if t.starts_with(' ') || !t.ends_with('(') {
        return None;
    }
    let mut it = t.trim_end_matches('(').split(' ');
    let (m, inst, rest) = (it.next()?, it.next()?, it.next());
    let word = |w: &str| !w.is_empty() && w.chars().all(|c| c.is_alphanumeric() || c == '_');
    (rest.is_none() && word(m) && word(inst)).then_some(m)
}

/// Whether the module holds state of its own (a register or a memory).
fn has_state(m: &Module) -> bool {
    m.lines
        .iter()
        .any(|l| l.trim_start().starts_with("always @(posedge"))
}

/// `v` with a power-on reset `i_por` in every module whose name is one of
/// `tops` or starts with `top__` (a child block of it), where that module
/// holds state or instantiates one that does.
pub fn with_power_on_reset(v: &str, tops: &[&str]) -> String {
    let parts = modules(v);
    let ours = |name: &str| {
        tops.iter()
            .any(|t| name == *t || name.starts_with(&format!("{t}__")))
    };
    // The modules that need the reset: those with state, then (to a fixed
    // point) those that instantiate one.
    let mut need: HashSet<String> = HashSet::new();
    let mut children: HashMap<String, Vec<String>> = HashMap::new();
    for m in parts.iter().filter_map(|p| p.as_ref().err()) {
        if !ours(&m.name) {
            continue;
        }
        if has_state(m) {
            need.insert(m.name.clone());
        }
        let kids = m
            .lines
            .iter()
            .filter_map(|l| instance_of(l))
            .map(str::to_string)
            .collect();
        children.insert(m.name.clone(), kids);
    }
    loop {
        let more: Vec<String> = children
            .iter()
            .filter(|(m, kids)| !need.contains(*m) && kids.iter().any(|k| need.contains(k)))
            .map(|(m, _)| m.clone())
            .collect();
        if more.is_empty() {
            break;
        }
        need.extend(more);
    }
    let mut out = String::with_capacity(v.len() + v.len() / 8);
    for p in parts {
        match p {
            Ok(line) => {
                out.push_str(&line);
                out.push('\n');
            }
            Err(m) if need.contains(&m.name) => {
                for line in rewrite(&m, &need) {
                    out.push_str(&line);
                    out.push('\n');
                }
            }
            Err(m) => {
                for line in &m.lines {
                    out.push_str(line);
                    out.push('\n');
                }
            }
        }
    }
    out
}

/// One module with the reset: the port, the registers, the memories, the
/// instances.
fn rewrite(m: &Module, need: &HashSet<String>) -> Vec<String> {
    // Power-up values: `initial x_q = 1'h0;`.
    let inits: HashMap<&str, &str> = m
        .lines
        .iter()
        .filter_map(|l| {
            let t = l.trim().strip_prefix("initial ")?.strip_suffix(';')?;
            let (reg, val) = t.split_once(" = ")?;
            (!reg.contains(' ')).then_some((reg, val))
        })
        .collect();
    let mut out = vec![];
    let mut lines = m.lines.iter().peekable();
    let header = lines.next().expect("a header");
    out.push(header.replacen('(', "(i_por,", 1));
    out.push(
        "    // Power-on reset (rtl/src/harness/power_on.rs): the restarted node starts as at power-up."
            .into(),
    );
    out.push("    input wire i_por;".into());
    // The memory's depth, from its `initial for` clearing loop.
    let mut mem_top: Option<String> = None;
    while let Some(line) = lines.next() {
        let t = line.trim_start();
        if let Some(rest) = t.strip_prefix("initial for (mem_i = 0; mem_i <= ") {
            let top = rest.split(';').next().unwrap_or("").to_string();
            assert!(
                line.trim_end().ends_with("mem[mem_i] = 0;"),
                "{}: a memory with contents other than zeros: {line}",
                m.name
            );
            mem_top = Some(top);
            out.push(line.clone());
        } else if let Some(rest) = t.strip_prefix("always @(posedge clock) ") {
            let (reg, d) = rest
                .strip_suffix(';')
                .and_then(|x| x.split_once(" <= "))
                .unwrap_or_else(|| {
                    panic!("{}: a clocked statement it does not know: {line}", m.name)
                });
            let init = inits
                .get(reg)
                .unwrap_or_else(|| panic!("{}: register {reg} without a power-up value", m.name));
            out.push(format!(
                "    always @(posedge clock) {reg} <= i_por ? {init} : {d};"
            ));
        } else if t.starts_with("always @(posedge write_clock) begin") {
            let top = mem_top
                .clone()
                .unwrap_or_else(|| panic!("{}: a memory without its clearing loop", m.name));
            out.push(line.clone());
            let next = lines.next().expect("the write statement");
            assert!(
                next.trim_start().starts_with("if (write_enable"),
                "{}: a write port it does not know: {next}",
                m.name
            );
            // (Blocking: Verilator 5.006 has no delayed assignment to an
            // array in a loop; nothing reads the memory during the reset.)
            out.push("       /* verilator lint_off BLKSEQ */".into());
            out.push(format!(
                "       if (i_por) for (mem_i = 0; mem_i <= {top}; mem_i = mem_i + 1) mem[mem_i] = 0;"
            ));
            out.push("       /* verilator lint_on BLKSEQ */".into());
            out.push(format!("       else {}", next.trim_start()));
        } else if t.starts_with("always @(posedge read_clock) begin") {
            // The read register follows the cleared memory at the next read.
            out.push(line.clone());
        } else if t.starts_with("always @(posedge") {
            panic!("{}: a clocked statement it does not know: {line}", m.name);
        } else if instance_of(line).is_some_and(|c| need.contains(c)) {
            out.push(line.clone());
            out.push("        .i_por(i_por),".into());
        } else {
            out.push(line.clone());
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    const V: &str = r#"// head
module top_x(clock,i_a,o_b);
    input wire  clock;
    reg  a_q;
    reg  a_d;
    // Child blocks
    top_x__k k(
        .clock(clock)
    );
    top_x__c c(
        .i(a_q)
    );
    initial a_q = 1'h1;
    always @(posedge clock) a_q <= a_d;
endmodule // top_x
module top_x__k(clock);
    reg[15:0] mem[3:0];
    integer mem_i;
    initial for (mem_i = 0; mem_i <= 3; mem_i = mem_i + 1) mem[mem_i] = 0;
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
endmodule // top_x__k
module top_x__c(i);
endmodule // top_x__c
module other(clock);
    initial o_q = 1'h0;
    always @(posedge clock) o_q <= o_d;
endmodule
"#;

    #[test]
    fn registers_take_their_power_up_value_and_memories_clear() {
        let r = with_power_on_reset(V, &["top_x"]);
        assert!(r.contains("module top_x(i_por,clock,i_a,o_b);"));
        assert!(r.contains("always @(posedge clock) a_q <= i_por ? 1'h1 : a_d;"));
        assert!(
            r.contains("if (i_por) for (mem_i = 0; mem_i <= 3; mem_i = mem_i + 1) mem[mem_i] = 0;")
        );
        assert!(r.contains("else if (write_enable) begin"));
        // The stateful child gets the reset; the stateless one and modules
        // of other tops do not.
        assert!(r.contains("top_x__k k(\n        .i_por(i_por),"));
        assert!(r.contains("module top_x__k(i_por,clock);"));
        assert!(r.contains("module top_x__c(i);"));
        assert!(r.contains("top_x__c c(\n        .i(a_q)"));
        assert!(r.contains("module other(clock);"));
        assert!(r.contains("always @(posedge clock) o_q <= o_d;"));
    }

    #[test]
    #[should_panic(expected = "a clocked statement it does not know")]
    fn an_unknown_clocked_statement_is_refused() {
        let v = "module top_y(clock);\n    always @(posedge clock) begin x <= y; end\nendmodule\n";
        with_power_on_reset(v, &["top_y"]);
    }
}
