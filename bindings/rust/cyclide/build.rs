//! Adds an rpath to libcyclide.so's directory (found by cyclide-sys's
//! build.rs, passed as DEP_CYCLIDE_LIB_DIR) for this package's tests and
//! examples, so `cargo test` runs without LD_LIBRARY_PATH.
fn main() {
    println!("cargo:rerun-if-env-changed=DEP_CYCLIDE_LIB_DIR");
    if let Ok(dir) = std::env::var("DEP_CYCLIDE_LIB_DIR") {
        let family = std::env::var("CARGO_CFG_TARGET_FAMILY").unwrap_or_default();
        let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
        if family == "unix" && os != "macos" && os != "ios" {
            println!("cargo:rustc-link-arg=-Wl,-rpath,{}", dir);
        }
    }
}
