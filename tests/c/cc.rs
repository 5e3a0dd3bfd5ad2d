//! Shared by the C-host tests of hawser-capi and hawser-moordyn (included with `#[path]`):
//! find the static library cargo built for this test run and compile a C host against it.
//!
//! `cargo test` builds a library's staticlib beside its rlib in `target/<profile>/deps` when
//! the crate also has an `rlib` type (it is then a dependency of the integration tests), but
//! copies it up to `target/<profile>` only when the library itself is asked for (`cargo
//! build`). A fresh clone running README's `cargo test --workspace --release` has only the
//! first, so the `deps` copy is preferred; the other is a fallback for a library built by hand.

use std::path::{Path, PathBuf};
use std::process::Command;

/// `target/<profile>`, the parent of the folder holding the test executable.
fn profile_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("test path");
    exe.parent()
        .and_then(Path::parent)
        .expect("profile dir")
        .to_path_buf()
}

/// The path of `lib<name>.a` built for this run.
pub fn static_library(name: &str) -> PathBuf {
    let file = format!("lib{name}.a");
    let dir = profile_dir();
    let candidates = [dir.join("deps").join(&file), dir.join(&file)];
    candidates
        .iter()
        .find(|p| p.is_file())
        .cloned()
        .unwrap_or_else(|| panic!("{file} not found in {} or its deps folder", dir.display()))
}

/// Compiles `source` with the system's C compiler (`$CC`, else `cc`), warnings as errors,
/// against the headers in `include` and the static library `lib`.
pub fn compile(source: &Path, include: &Path, lib: &Path, out: &Path) {
    let status = Command::new(std::env::var("CC").unwrap_or_else(|_| "cc".into()))
        .args([
            "-std=c99",
            "-D_DEFAULT_SOURCE",
            "-Wall",
            "-Werror",
            "-O1",
            "-o",
        ])
        .arg(out)
        .arg(source)
        .arg("-I")
        .arg(include)
        .arg(lib)
        .args(["-lpthread", "-ldl", "-lm"])
        .status()
        .expect("run cc");
    assert!(status.success(), "cc failed on {}", source.display());
}
