# Builds and runs tests/consumer/consumer.c as a user would (cmake -P; the
# tests ffi.c.* of tests/ffi/c.cmake). Variables:
#   MODE        find_package | add_subdirectory | pkgconfig
#   SOURCE_DIR  the cyclide source tree
#   WORK_DIR    a scratch build directory of this test
#   PREFIX      the installed prefix (find_package, pkgconfig)
#   LIBDIR      its library directory name (lib, lib64, ...)
#   GENERATOR   the CMake generator of the consumer projects
#   C_COMPILER  the C compiler
#   BUILD_TYPE  add_subdirectory: the consumer's CMAKE_BUILD_TYPE
#   DEBUG_FLAGS add_subdirectory: CMAKE_{C,CXX}_FLAGS_DEBUG (with BUILD_TYPE Debug)
#   CXX_COMPILER, WITH_CERES  add_subdirectory: the C++ compiler, CYCLIDE_WITH_CERES
# Fails (FATAL_ERROR) when a step fails; prints the consumer's report.
cmake_minimum_required(VERSION 3.20)

function(run what)
  string(REPLACE ";" " " shown "${ARGN}")
  message(STATUS "${what}: ${shown}")
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "ffi.c.${MODE}: ${what} failed (${rc}): ${shown}")
  endif()
endfunction()

set(consumer ${SOURCE_DIR}/tests/consumer/consumer.c)
if(MODE STREQUAL "find_package")
  # A fresh project each time: configure, build and run against PREFIX only.
  file(REMOVE_RECURSE ${WORK_DIR})
  run(configure ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer -B ${WORK_DIR} -G ${GENERATOR}
      -DCMAKE_C_COMPILER=${C_COMPILER} -DCMAKE_PREFIX_PATH=${PREFIX}
      -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
  file(STRINGS ${WORK_DIR}/CMakeCache.txt found REGEX "^cyclide_DIR:")
  string(FIND "${found}" "${PREFIX}/" at)
  if(NOT at GREATER -1)
    message(FATAL_ERROR "ffi.c.find_package: found ${found}, not the package in ${PREFIX}")
  endif()
  run(build ${CMAKE_COMMAND} --build ${WORK_DIR})
  # The imported target carries the installed library's path: CMake's build
  # RPATH points into PREFIX, nothing else is on the loader's path.
  run(run ${WORK_DIR}/consumer_find_package)
elseif(MODE STREQUAL "add_subdirectory")
  # The build directory is kept between runs: the library is compiled once,
  # later runs only relink what changed.
  run(configure ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/ffi/add_subdirectory -B ${WORK_DIR}
      -G ${GENERATOR} -DCMAKE_C_COMPILER=${C_COMPILER} -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
      -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCYCLIDE_WITH_CERES=${WITH_CERES}
      "-DCMAKE_CXX_FLAGS_DEBUG=${DEBUG_FLAGS}" "-DCMAKE_C_FLAGS_DEBUG=${DEBUG_FLAGS}"
      -DCYCLIDE_SOURCE_DIR=${SOURCE_DIR})
  run(build ${CMAKE_COMMAND} --build ${WORK_DIR} --target consumer_add_subdirectory)
  run(run ${WORK_DIR}/consumer_add_subdirectory)
elseif(MODE STREQUAL "pkgconfig")
  # Literally what a user types: cc consumer.c $(pkg-config --cflags --libs cyclide).
  file(REMOVE_RECURSE ${WORK_DIR})
  file(MAKE_DIRECTORY ${WORK_DIR})
  set(ENV{PKG_CONFIG_PATH} ${PREFIX}/${LIBDIR}/pkgconfig)
  run(compile sh -c "flags=$(pkg-config --cflags --libs cyclide) && echo \"pkg-config: $flags\" && ${C_COMPILER} -std=c99 -Wall -Wextra -pedantic -Werror -o '${WORK_DIR}/consumer_pkgconfig' '${consumer}' $flags -lm")
  # No rpath in a plain cc line: the loader finds the library by LD_LIBRARY_PATH.
  set(ENV{LD_LIBRARY_PATH} ${PREFIX}/${LIBDIR})
  run(run ${WORK_DIR}/consumer_pkgconfig)
else()
  message(FATAL_ERROR "run.cmake: unknown MODE '${MODE}'")
endif()
