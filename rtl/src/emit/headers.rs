//! # headers — every emitted module says what it is
//!
//! A reviewer of the emitted Verilog (docs/architecture.md) meets a module
//! per rust-hdl block. [`with_headers`] puts a comment before each: the
//! Rust block it comes from and its source file, and — at the first module
//! of that block in the text — the block's documentation from its source
//! (the file's module doc: purpose, port table, latency, timing diagram).
//! A later module of the same block names the first one instead of
//! repeating it. rust-hdl's ROM and memory modules get a line or two.
//!
//! The block of a child module is found from the module's name: rust-hdl
//! names a child `<parent>__<field>` after the parent's field, and
//! `rtl/build.rs` collected every block's fields from the sources.

use std::collections::HashMap;

/// One rust-hdl block of `rtl/src` as `rtl/build.rs` found it.
pub(crate) struct BlockDoc {
    /// Type name (`Switchbox`).
    pub name: &'static str,
    /// Source file (`rtl/src/node/switchbox.rs`).
    pub file: &'static str,
    /// The file's module doc (`//!`).
    pub module_doc: &'static str,
    /// The struct's doc (`///`), one line.
    pub doc: &'static str,
    /// Fields: name and type name.
    pub fields: &'static [(&'static str, &'static str)],
}

include!(concat!(env!("OUT_DIR"), "/blocks.rs"));

fn block(name: &str) -> Option<&'static BlockDoc> {
    BLOCKS.iter().find(|b| b.name == name)
}

/// The block type of module `module` (`top`, `top__sbox`, …), the text's
/// top being of type `root`; `None` for a field that is not one of ours
/// (a rust-hdl ROM or memory).
fn resolve(module: &str, root: &str) -> Option<(&'static BlockDoc, String)> {
    let path = module.strip_prefix("top")?;
    let mut b = block(root)?;
    let mut field = String::new();
    for f in path.split("__").filter(|f| !f.is_empty()) {
        let ty = b.fields.iter().find(|(n, _)| *n == f)?.1;
        b = block(ty)?;
        field = f.to_string();
    }
    Some((b, field))
}

/// The text (rust-hdl's, through [`crate::emit::readable`], top module `top` of
/// block type `root`, e.g. `"Slave"`) with a header before every module.
pub fn with_headers(text: &str, root: &str) -> String {
    let mut first: HashMap<&str, String> = HashMap::new();
    let mut out = String::with_capacity(text.len() + 16 * 1024);
    for line in text.split_inclusive('\n') {
        if let Some(rest) = line.strip_prefix("module ") {
            let module = rest.split('(').next().unwrap_or(rest).trim();
            let rom = rest.contains("(address,data)");
            out.push_str(&header(module, rom, root, &mut first));
        }
        out.push_str(line);
    }
    out
}

/// The header of one module. Module names in it are in backticks, so that
/// [`crate::emit::verilog::rename_top`] renames them with the module.
fn header<'a>(
    module: &str,
    rom: bool,
    root: &'a str,
    first: &mut HashMap<&'a str, String>,
) -> String {
    let rule = format!("// {}\n", "-".repeat(74));
    let Some((b, field)) = resolve(module, root) else {
        let (parent, field) = module.rsplit_once("__").unwrap_or(("", module));
        let what = if rom {
            "a table (rust-hdl ROM), read combinationally"
        } else {
            "a memory (rust-hdl RAM): written on `write_clock`, read one clock after\n// `read_address` on `read_clock`"
        };
        return format!("{rule}// `{field}` of `{parent}`: {what}.\n{rule}");
    };
    let what = if field.is_empty() {
        format!("// {}: {} ({})\n", b.name, b.doc, b.file)
    } else {
        format!("// `{field}`: {}, {} ({})\n", b.name, b.doc, b.file)
    };
    if let Some(m) = first.get(b.name) {
        return format!("{rule}{what}// Documented at module `{m}` above.\n{rule}");
    }
    first.insert(b.name, module.to_string());
    let doc: String = b
        .module_doc
        .lines()
        .map(|l| {
            if l.is_empty() {
                "//\n".to_string()
            } else {
                format!("// {l}\n")
            }
        })
        .collect();
    format!("{rule}{what}//\n{doc}{rule}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_build_script_found_the_blocks_and_their_fields() {
        let s = block("Slave").expect("Slave");
        assert_eq!(s.file, "rtl/src/node/slave.rs");
        assert!(s.fields.contains(&("sbox", "Switchbox")));
        let sb = block("Switchbox").expect("Switchbox");
        assert!(
            sb.module_doc.contains("| port | dir |"),
            "{}",
            sb.module_doc
        );
        assert!(sb.module_doc.contains("Latency"));
    }

    #[test]
    fn child_modules_resolve_through_their_parents_fields() {
        assert_eq!(resolve("top", "Slave").unwrap().0.name, "Slave");
        let (b, f) = resolve("top__sbox", "Slave").unwrap();
        assert_eq!((b.name, f.as_str()), ("Switchbox", "sbox"));
        assert!(resolve("top__no_such_field", "Slave").is_none());
    }

    #[test]
    fn the_first_module_of_a_block_carries_its_doc_the_others_point_to_it() {
        let v = crate::emit::verilog::block_verilog(crate::node::slave::Slave::default());
        let sb = v.find("module top__sbox(").expect("switchbox module");
        let before = &v[..sb];
        let head = &before[before.rfind("// `sbox`").expect("the switchbox header")..];
        assert!(head.contains("| `i_mode` | in | 2 |"), "{head}");
        assert!(head.contains("Latency"), "{head}");
        let rx = v
            .matches("Documented at module `top__rx_in` above.")
            .count()
            + v.matches("Documented at module `top__rx_bsr` above.")
                .count();
        assert_eq!(rx, 1, "the second receive port points to the first");
    }
}
