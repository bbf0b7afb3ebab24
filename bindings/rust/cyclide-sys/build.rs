//! Finds libcyclide.so for linking.
//!
//! 1. `CYCLIDE_LIB_DIR` (the directory holding libcyclide.so) and optionally
//!    `CYCLIDE_INCLUDE_DIR` (the directory holding cyclide/cyclide.h, used
//!    only by the layout test; default: `CYCLIDE_LIB_DIR/../include`, or
//!    `../../include` for a multiarch libdir such as lib/x86_64-linux-gnu);
//! 2. else the `pkg-config` program (`$PKG_CONFIG`, default `pkg-config`):
//!    `pkg-config --libs-only-L --libs-only-l cyclide` and
//!    `--variable=includedir` (set `PKG_CONFIG_PATH` for a private prefix).
//!
//! It emits `rustc-link-search=native=DIR` and `rustc-link-lib=dylib=cyclide`,
//! an rpath for this crate's own tests, and the metadata `lib_dir` /
//! `include` (seen by dependents as `DEP_CYCLIDE_LIB_DIR` /
//! `DEP_CYCLIDE_INCLUDE`, so the safe crate can add the rpath to its tests
//! too). Without an rpath (e.g. a binary of another crate), run with
//! `LD_LIBRARY_PATH=DIR` or install the library in a system directory.

use std::env;
use std::path::{Path, PathBuf};
use std::process::Command;

fn main() {
    for var in &[
        "CYCLIDE_LIB_DIR",
        "CYCLIDE_INCLUDE_DIR",
        "PKG_CONFIG",
        "PKG_CONFIG_PATH",
    ] {
        println!("cargo:rerun-if-env-changed={}", var);
    }
    println!("cargo:rerun-if-changed=build.rs");

    let (lib_dirs, libs, include) = match env::var_os("CYCLIDE_LIB_DIR") {
        Some(dir) if !dir.is_empty() => {
            let dir = PathBuf::from(dir);
            let include = env::var_os("CYCLIDE_INCLUDE_DIR")
                .map(PathBuf::from)
                .or_else(|| guess_include(&dir));
            (vec![dir], vec!["cyclide".to_string()], include)
        }
        _ => from_pkg_config(),
    };

    for dir in &lib_dirs {
        println!("cargo:rustc-link-search=native={}", dir.display());
    }
    for lib in &libs {
        println!("cargo:rustc-link-lib=dylib={}", lib);
    }
    if let Some(dir) = lib_dirs.first() {
        // Tests, examples and binaries of this package find the library
        // without LD_LIBRARY_PATH (ELF platforms).
        let family = env::var("CARGO_CFG_TARGET_FAMILY").unwrap_or_default();
        let os = env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
        if family == "unix" && os != "macos" && os != "ios" {
            println!("cargo:rustc-link-arg=-Wl,-rpath,{}", dir.display());
        }
        println!("cargo:lib_dir={}", dir.display());
    }
    if let Some(inc) = include {
        println!("cargo:include={}", inc.display());
        println!("cargo:rustc-env=CYCLIDE_SYS_INCLUDE_DIR={}", inc.display());
    }
}

fn guess_include(lib_dir: &Path) -> Option<PathBuf> {
    for up in &["../include", "../../include"] {
        let cand = lib_dir.join(up);
        if cand.join("cyclide").join("cyclide.h").is_file() {
            return Some(cand);
        }
    }
    None
}

fn from_pkg_config() -> (Vec<PathBuf>, Vec<String>, Option<PathBuf>) {
    let prog = env::var("PKG_CONFIG").unwrap_or_else(|_| "pkg-config".to_string());
    let run = |args: &[&str]| -> String {
        let out = Command::new(&prog).args(args).output().unwrap_or_else(|e| {
            panic!(
                "cyclide-sys: CYCLIDE_LIB_DIR is not set and `{}` could not be run ({}); \
                 set CYCLIDE_LIB_DIR to the directory holding libcyclide.so",
                prog, e
            )
        });
        if !out.status.success() {
            panic!(
                "cyclide-sys: `{} {}` failed: {}; set CYCLIDE_LIB_DIR, or PKG_CONFIG_PATH to \
                 the directory holding cyclide.pc",
                prog,
                args.join(" "),
                String::from_utf8_lossy(&out.stderr).trim()
            );
        }
        String::from_utf8(out.stdout).expect("pkg-config output is not UTF-8")
    };
    let flags = run(&["--libs-only-L", "--libs-only-l", "cyclide"]);
    let mut dirs = Vec::new();
    let mut libs = Vec::new();
    for tok in flags.split_whitespace() {
        if let Some(d) = tok.strip_prefix("-L") {
            dirs.push(PathBuf::from(d));
        } else if let Some(l) = tok.strip_prefix("-l") {
            libs.push(l.to_string());
        }
    }
    if !libs.iter().any(|l| l == "cyclide") {
        libs.push("cyclide".to_string());
    }
    let inc = run(&["--variable=includedir", "cyclide"]);
    let inc = inc.trim();
    let include = if inc.is_empty() {
        None
    } else {
        Some(PathBuf::from(inc))
    };
    (dirs, libs, include)
}
