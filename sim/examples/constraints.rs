//! Writes every board's constraints file into `constraints/` from
//! rtl/src/top/boards.rs: `cargo run -p merkur-sim --example constraints`.
fn main() {
    let dir = merkur_sim::repo_root().join("constraints");
    for b in merkur_rtl::top::boards::all() {
        let path = dir.join(b.file);
        if let Err(e) = std::fs::write(&path, merkur_rtl::top::boards::constraints_file(&b)) {
            eprintln!("error: cannot write {}: {e}", path.display());
            std::process::exit(1);
        }
        println!("wrote {}", path.display());
    }
}
