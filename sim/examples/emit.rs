//! Prints the Verilog of one block: `cargo run -p merkur-sim --example emit -- nrzi_tx`.
fn main() {
    let which = std::env::args().nth(1).unwrap_or_default();
    let blocks = merkur_rtl::emit::verilog::all_blocks();
    match blocks.iter().find(|(n, _)| *n == which) {
        Some((_, v)) => print!("{v}"),
        None => {
            let names: Vec<&str> = blocks.iter().map(|(n, _)| *n).collect();
            eprintln!(
                "error: unknown block {which:?}; blocks: {}",
                names.join(", ")
            );
            std::process::exit(2);
        }
    }
}
