//! Collects, for the headers of the emitted Verilog (`src/emit/headers.rs`),
//! every rust-hdl block of `src/` and its folders: its type name, its source file, the
//! file's module doc (purpose, port table, latency), the struct's own doc
//! line, and its fields (name and type), from which a child module's block
//! type is found. Writes `$OUT_DIR/blocks.rs`.

use std::fmt::Write as _;
use std::path::Path;

/// One block: type, file, module doc, struct doc, fields.
struct Block {
    name: String,
    file: String,
    module_doc: String,
    doc: String,
    fields: Vec<(String, String)>,
}

fn ident(s: &str) -> &str {
    let end = s
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .unwrap_or(s.len());
    &s[..end]
}

fn blocks_of(file: &str, text: &str) -> Vec<Block> {
    let lines: Vec<&str> = text.lines().collect();
    let module_doc: Vec<&str> = lines
        .iter()
        .map_while(|l| l.strip_prefix("//!"))
        .map(|l| l.strip_prefix(' ').unwrap_or(l))
        .collect();
    let mut out = vec![];
    for (i, l) in lines.iter().enumerate() {
        if !(l.starts_with("#[derive(") && l.contains("LogicBlock")) {
            continue;
        }
        let doc: Vec<&str> = lines[..i]
            .iter()
            .rev()
            .map_while(|l| l.strip_prefix("///"))
            .map(|l| l.strip_prefix(' ').unwrap_or(l))
            .collect();
        let Some(j) = (i + 1..lines.len()).find(|&j| lines[j].starts_with("pub struct ")) else {
            continue;
        };
        let name = ident(&lines[j]["pub struct ".len()..]).to_string();
        let mut fields = vec![];
        for f in lines[j + 1..].iter().take_while(|f| !f.starts_with('}')) {
            let t = f.trim_start();
            let t = t.strip_prefix("pub ").unwrap_or(t);
            if let Some((n, ty)) = t.split_once(": ") {
                if !n.is_empty() && ident(n) == n {
                    fields.push((n.to_string(), ident(ty.trim()).to_string()));
                }
            }
        }
        out.push(Block {
            name,
            file: file.to_string(),
            module_doc: module_doc.join("\n"),
            doc: doc.into_iter().rev().collect::<Vec<_>>().join(" "),
            fields,
        });
    }
    out
}

/// Every `.rs` file under `dir`, folders included (`src/line/cdr.rs`).
fn rust_files(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for e in std::fs::read_dir(dir).expect("rtl/src folder") {
        let p = e.expect("dir entry").path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            out.push(p);
        }
    }
}

fn main() {
    println!("cargo:rerun-if-changed=src");
    let mut files = vec![];
    rust_files(Path::new("src"), &mut files);
    files.sort();
    let mut blocks = vec![];
    for p in &files {
        let text = std::fs::read_to_string(p).expect("source file");
        let rel = p.strip_prefix("src").expect("under src");
        let rel: Vec<_> = rel.iter().map(|c| c.to_string_lossy()).collect();
        let file = format!("rtl/src/{}", rel.join("/"));
        blocks.extend(blocks_of(&file, &text));
    }
    let mut s = String::from(
        "/// Every rust-hdl block of rtl/src (written by rtl/build.rs).\n\
         pub(crate) static BLOCKS: &[BlockDoc] = &[\n",
    );
    for b in &blocks {
        let fields: Vec<String> = b
            .fields
            .iter()
            .map(|(n, t)| format!("({n:?}, {t:?})"))
            .collect();
        writeln!(
            s,
            "    BlockDoc {{ name: {:?}, file: {:?}, module_doc: {:?}, doc: {:?}, fields: &[{}] }},",
            b.name,
            b.file,
            b.module_doc,
            b.doc,
            fields.join(", ")
        )
        .expect("write");
    }
    s.push_str("];\n");
    let out = Path::new(&std::env::var("OUT_DIR").expect("OUT_DIR")).join("blocks.rs");
    std::fs::write(out, s).expect("write blocks.rs");
}
