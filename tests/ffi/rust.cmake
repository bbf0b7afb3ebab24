# Issue 10: the Rust crates (bindings/rust) against the installed library.
#   ffi.rust.check_sys  check_sys.py: cyclide-sys declares every CYC_API
#                       function, struct and constant of the source tree's
#                       cyclide.h (and tests/layout.c prints every struct)
#   ffi.rust.sys        cargo test of cyclide-sys: the layout of every
#                       struct against the C compiler's (tests/layout.c,
#                       compiled with CMAKE_C_COMPILER against the installed
#                       header), every symbol resolved, raw calls
#   ffi.rust.safe       cargo test of the safe wrapper crate cyclide
# Debian's cargo and rustc (/usr/bin first: the toolchain CI installs with
# CYCLIDE_FFI_PACKAGES; override with -DCYCLIDE_CARGO=..., rustc and rustdoc
# are taken from the same directory, so a rustup toolchain earlier in PATH
# is not mixed in).
# Offline (the crates have no dependencies), two jobs, the target directory
# inside the build tree. Without cargo nothing is registered.
find_program(CYCLIDE_CARGO NAMES cargo HINTS /usr/bin)
if(NOT CYCLIDE_CARGO)
  message(STATUS "ffi: cargo not found, Rust binding tests skipped "
                 "(scripts/deps.sh installs it with CYCLIDE_FFI_PACKAGES)")
  return()
endif()
get_filename_component(_cyc_cargo_dir "${CYCLIDE_CARGO}" DIRECTORY)
find_program(CYCLIDE_RUSTC NAMES rustc HINTS ${_cyc_cargo_dir} NO_DEFAULT_PATH)
if(NOT CYCLIDE_RUSTC)
  find_program(CYCLIDE_RUSTC NAMES rustc)
endif()
find_program(CYCLIDE_RUSTDOC NAMES rustdoc HINTS ${_cyc_cargo_dir} NO_DEFAULT_PATH)
if(NOT CYCLIDE_RUSTDOC)
  find_program(CYCLIDE_RUSTDOC NAMES rustdoc)
endif()
if(NOT CYCLIDE_RUSTC OR NOT CYCLIDE_RUSTDOC)
  message(STATUS "ffi: rustc/rustdoc not found next to ${CYCLIDE_CARGO}, Rust binding tests skipped")
  return()
endif()
find_program(CYCLIDE_RUST_PYTHON3 NAMES python3 HINTS /usr/bin)

if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(_cyc_rs_libdir "${CMAKE_INSTALL_LIBDIR}")
else()
  set(_cyc_rs_libdir "${CYCLIDE_FFI_PREFIX}/${CMAKE_INSTALL_LIBDIR}")
endif()
if(IS_ABSOLUTE "${CMAKE_INSTALL_INCLUDEDIR}")
  set(_cyc_rs_incdir "${CMAKE_INSTALL_INCLUDEDIR}")
else()
  set(_cyc_rs_incdir "${CYCLIDE_FFI_PREFIX}/${CMAKE_INSTALL_INCLUDEDIR}")
endif()
set(_cyc_rs_src ${PROJECT_SOURCE_DIR}/bindings/rust)
set(_cyc_rs_env
    "CYCLIDE_LIB_DIR=${_cyc_rs_libdir}"
    "CYCLIDE_INCLUDE_DIR=${_cyc_rs_incdir}"
    "LD_LIBRARY_PATH=${_cyc_rs_libdir}"
    "CARGO_TARGET_DIR=${CMAKE_CURRENT_BINARY_DIR}/cargo"
    "CARGO_BUILD_JOBS=2"
    "CARGO_TERM_COLOR=never"
    "CARGO_NET_OFFLINE=true"
    "RUSTC=${CYCLIDE_RUSTC}"
    "RUSTDOC=${CYCLIDE_RUSTDOC}"
    "CC=${CMAKE_C_COMPILER}")

if(CYCLIDE_RUST_PYTHON3)
  add_test(NAME ffi.rust.check_sys
           COMMAND ${CYCLIDE_RUST_PYTHON3} ${_cyc_rs_src}/check_sys.py
                   ${PROJECT_SOURCE_DIR}/capi/include ${_cyc_rs_src}/cyclide-sys)
  set_tests_properties(ffi.rust.check_sys PROPERTIES LABELS "ffi;rust" TIMEOUT 60)
endif()

foreach(_crate sys safe)
  if(_crate STREQUAL "sys")
    set(_dir cyclide-sys)
  else()
    set(_dir cyclide)
  endif()
  add_test(NAME ffi.rust.${_crate}
           COMMAND ${CYCLIDE_CARGO} test --offline --manifest-path ${_cyc_rs_src}/${_dir}/Cargo.toml
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(ffi.rust.${_crate} PROPERTIES
    LABELS "ffi;rust"
    FIXTURES_REQUIRED cyclide_installed
    RESOURCE_LOCK cyclide_cargo_target
    TIMEOUT 600
    ENVIRONMENT "${_cyc_rs_env}")
endforeach()
