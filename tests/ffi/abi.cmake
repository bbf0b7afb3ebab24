# Issue 10: ABI stability checks of the installed library (label ffi,
# SPEC.md §9a). The references live in abi/ and are regenerated only
# deliberately, by scripts/abi-update.
#   ffi.abi.symbols  the exported symbols (name@@version) and the SONAME
#                    against abi/cyclide.symbols: a removal is an ABI break,
#                    an addition fails until the reference is updated
#   ffi.abi.abidiff  abidiff of abi/cyclide.abi.xml against the library:
#                    incompatible changes fail, other changes fail until the
#                    baseline is updated; the report is printed
set(_cyc_abi_dir ${PROJECT_SOURCE_DIR}/abi)
set(_cyc_installed_lib ${CYCLIDE_FFI_PREFIX}/${CMAKE_INSTALL_LIBDIR}/libcyclide.so)

add_test(NAME ffi.abi.symbols
         COMMAND ${CMAKE_COMMAND} -DLIB=${_cyc_installed_lib}
                 -DREFERENCE=${_cyc_abi_dir}/cyclide.symbols
                 -DEXPERIMENTAL=${_cyc_abi_dir}/experimental.txt
                 -DSONAME=libcyclide.so.${CYCLIDE_ABI_VERSION}
                 -P ${_cyc_abi_dir}/check_symbols.cmake)
set_tests_properties(ffi.abi.symbols PROPERTIES LABELS ffi FIXTURES_REQUIRED cyclide_installed)

find_program(CYCLIDE_ABIDIFF abidiff)
if(NOT CYCLIDE_ABIDIFF)
  add_test(NAME ffi.abi.abidiff
           COMMAND ${CMAKE_COMMAND} -E echo
                   "abidiff not found at configure time: install abigail-tools (Debian: apt-get install abigail-tools; scripts/test installs CYCLIDE_FFI_PACKAGES of scripts/deps.sh), then reconfigure")
  set_tests_properties(ffi.abi.abidiff PROPERTIES WILL_FAIL ON)
elseif(NOT CMAKE_BUILD_TYPE MATCHES "^(RelWithDebInfo|Debug)$")
  # abidiff compares DWARF: a build without it cannot be checked (skipped).
  add_test(NAME ffi.abi.abidiff
           COMMAND sh -c "echo 'ffi.abi.abidiff: a ${CMAKE_BUILD_TYPE} build has no DWARF to compare; skipped (the baseline is checked in RelWithDebInfo builds, e.g. scripts/test)'; exit 77")
  set_tests_properties(ffi.abi.abidiff PROPERTIES SKIP_RETURN_CODE 77)
else()
  add_test(NAME ffi.abi.abidiff
           COMMAND ${CMAKE_COMMAND} -DABIDIFF=${CYCLIDE_ABIDIFF} -DLIB=${_cyc_installed_lib}
                   -DBASELINE=${_cyc_abi_dir}/cyclide.abi.xml
                   -DHEADERS_DIR=${CYCLIDE_FFI_PREFIX}/${CMAKE_INSTALL_INCLUDEDIR}/cyclide
                   -DEXPERIMENTAL=${_cyc_abi_dir}/experimental.txt
                   -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/abidiff
                   -P ${_cyc_abi_dir}/check_abidiff.cmake)
endif()
set_tests_properties(ffi.abi.abidiff PROPERTIES LABELS ffi FIXTURES_REQUIRED cyclide_installed)
