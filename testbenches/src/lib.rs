//! # merkur-testbenches
//!
//! The Verilator harness and the block and ring tests live here (issue 3 on).
//! For now this crate holds the toolchain check: the system tools the
//! project pins in `scripts/tools.lock` are installed at those versions.

use std::path::PathBuf;

/// One pinned tool from `scripts/tools.lock`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PinnedTool {
    /// Debian package.
    pub package: String,
    /// Exact Debian version.
    pub version: String,
    /// Command the package provides.
    pub command: String,
}

/// Path of the repository root.
pub fn repo_root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("crate lives in the workspace")
        .to_path_buf()
}

/// Parses `scripts/tools.lock`.
pub fn pinned_tools() -> Result<Vec<PinnedTool>, String> {
    let path = repo_root().join("scripts/tools.lock");
    let text = std::fs::read_to_string(&path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let mut out = vec![];
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let f: Vec<&str> = line.split_whitespace().collect();
        if f.len() != 3 {
            return Err(format!(
                "{}:{}: expected `package version command`, found {line:?}",
                path.display(),
                i + 1
            ));
        }
        out.push(PinnedTool {
            package: f[0].into(),
            version: f[1].into(),
            command: f[2].into(),
        });
    }
    Ok(out)
}
