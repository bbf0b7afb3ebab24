# Issue 10 item: C consumers of the library (label ffi). Each builds
# tests/consumer/consumer.c — a canal blend of the cones of Fig. 6 built and
# evaluated through the C API, points and normals checked, exit status
# non-zero on any failure — the way a user's project would
# (tests/consumer/run.cmake does the steps):
#   ffi.c.find_package      a CMake project, find_package(cyclide) in the
#                           installed prefix ${CYCLIDE_FFI_PREFIX}
#   ffi.c.pkgconfig         cc consumer.c $(pkg-config --cflags --libs cyclide)
#                           against the same prefix
#   ffi.c.add_subdirectory  a CMake project vendoring the source tree
#                           (tests/ffi/add_subdirectory): builds the library
#                           target only, in its own kept build directory
set(_cyc_run ${PROJECT_SOURCE_DIR}/tests/consumer/run.cmake)
set(_cyc_common -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DGENERATOR=${CMAKE_GENERATOR}
                -DC_COMPILER=${CMAKE_C_COMPILER})

add_test(NAME ffi.c.find_package
         COMMAND ${CMAKE_COMMAND} ${_cyc_common} -DMODE=find_package
                 -DPREFIX=${CYCLIDE_FFI_PREFIX}
                 -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/consumer-find_package -P ${_cyc_run})
set_tests_properties(ffi.c.find_package PROPERTIES LABELS ffi
                     FIXTURES_REQUIRED cyclide_installed)

find_program(CYCLIDE_PKG_CONFIG pkg-config)
if(CYCLIDE_PKG_CONFIG)
  add_test(NAME ffi.c.pkgconfig
           COMMAND ${CMAKE_COMMAND} ${_cyc_common} -DMODE=pkgconfig
                   -DPREFIX=${CYCLIDE_FFI_PREFIX} -DLIBDIR=${CMAKE_INSTALL_LIBDIR}
                   -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/consumer-pkgconfig -P ${_cyc_run})
else()
  add_test(NAME ffi.c.pkgconfig
           COMMAND ${CMAKE_COMMAND} -E echo
                   "pkg-config not found at configure time: install it (Debian: apt-get install pkg-config), then reconfigure")
  set_tests_properties(ffi.c.pkgconfig PROPERTIES WILL_FAIL ON)
endif()
set_tests_properties(ffi.c.pkgconfig PROPERTIES LABELS ffi FIXTURES_REQUIRED cyclide_installed)

# The vendored build compiles the library again (once: the build directory
# is kept; later runs rebuild only what changed), unoptimized (Debug at -O0,
# without debug info: about half the compile time of -O2; the consumer's
# checks are not about speed) and without Ceres, to keep CI's budget. It
# does not use the installed prefix, so no fixture.
add_test(NAME ffi.c.add_subdirectory
         COMMAND ${CMAKE_COMMAND} ${_cyc_common} -DMODE=add_subdirectory
                 -DCXX_COMPILER=${CMAKE_CXX_COMPILER} -DBUILD_TYPE=Debug -DDEBUG_FLAGS=-O0
                 -DWITH_CERES=OFF
                 -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/consumer-add_subdirectory -P ${_cyc_run})
set_tests_properties(ffi.c.add_subdirectory PROPERTIES LABELS ffi TIMEOUT 1800)
