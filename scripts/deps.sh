# Sourced by scripts/demo, scripts/test and scripts/fuzz: installs the Debian
# packages that are missing (apt-get; sudo when not root). Idempotent: a
# machine that has everything is not touched.
cyclide_ensure_packages() {
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" ||
      missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  echo "cyclide: installing missing packages: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# What building cyclide needs (the core, the C library, the optimizer tier).
CYCLIDE_BUILD_PACKAGES=(cmake ninja-build g++ pkg-config libeigen3-dev libceres-dev)
# What the tests, benchmarks and fuzzers need on top.
CYCLIDE_TEST_PACKAGES=(libgtest-dev librapidcheck-dev libbenchmark-dev clang
                       libclang-rt-14-dev binutils)
# What the FFI tests need (issue 10, label ffi): Rust, Python with numpy,
# libabigail's abidiff, doxygen.
CYCLIDE_FFI_PACKAGES=(cargo rustc python3 python3-numpy abigail-tools doxygen)
