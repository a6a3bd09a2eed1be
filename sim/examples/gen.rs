//! Rewrites everything in `gen/` from the generators: the board
//! constraints (`gen/constraints/`, from rtl/src/top/boards.rs) and the
//! standard nodes' Verilog with its lint waivers (`gen/verilog/`, from
//! rtl/src/emit/standard.rs), and the timing diagrams of `docs/timing/`
//! (drawn from RTL runs, sim/src/timing.rs): `cargo run -p merkur-sim
//! --example gen`. `sim/tests/boards.rs` and `sim/tests/gen.rs` fail when
//! a committed file drifts.

fn write(path: &std::path::Path, text: &str) {
    if let Err(e) = std::fs::write(path, text) {
        eprintln!("error: cannot write {}: {e}", path.display());
        std::process::exit(1);
    }
    println!("wrote {}", path.display());
}

fn main() {
    let gen = merkur_sim::repo_root().join("gen");
    for b in merkur_rtl::top::boards::all() {
        let path = gen.join("constraints").join(b.file);
        write(&path, &merkur_rtl::top::boards::constraints_file(&b));
    }
    let dir = gen.join("verilog");
    if let Err(e) = std::fs::create_dir_all(&dir) {
        eprintln!("error: cannot create {}: {e}", dir.display());
        std::process::exit(1);
    }
    for f in merkur_rtl::emit::standard::standard_files() {
        write(&dir.join(f.name), &f.text);
    }
    let timing = merkur_sim::repo_root().join("docs/timing");
    let work = std::env::temp_dir().join(format!("merkur-timing-{}", std::process::id()));
    match merkur_sim::timing::render_all(&merkur_sim::timing::diagrams(), &work) {
        Ok(all) => {
            for (file, svg) in all {
                write(&timing.join(file), &svg);
            }
        }
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(1);
        }
    }
    let _ = std::fs::remove_dir_all(&work);
}
