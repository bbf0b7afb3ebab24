# Issue 10: the ctypes binding (bindings/python) against the installed
# library. Debian's python3 (/usr/bin first; override with
# -DCYCLIDE_PYTHON3=...). Two runs of the same unittest suite: with numpy
# (skipped, exit 77, when python3-numpy is missing) and with the list/tuple
# fallback forced (CYCLIDE_NO_NUMPY=1). The completeness table checks the
# binding against the source tree's cyclide.h.
find_program(CYCLIDE_PYTHON3 NAMES python3 HINTS /usr/bin)
if(NOT CYCLIDE_PYTHON3)
  message(STATUS "ffi: python3 not found, Python binding tests skipped")
  return()
endif()

if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(_cyc_py_libdir "${CMAKE_INSTALL_LIBDIR}")
else()
  set(_cyc_py_libdir "${CYCLIDE_FFI_PREFIX}/${CMAKE_INSTALL_LIBDIR}")
endif()

foreach(_mode numpy no-numpy)
  set(_name ffi.python.${_mode})
  add_test(NAME ${_name}
           COMMAND ${CYCLIDE_PYTHON3} ${PROJECT_SOURCE_DIR}/bindings/python/tests/run.py --${_mode}
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(${_name} PROPERTIES
    LABELS "ffi;python"
    FIXTURES_REQUIRED cyclide_installed
    SKIP_RETURN_CODE 77
    TIMEOUT 300
    ENVIRONMENT "PYTHONPATH=${PROJECT_SOURCE_DIR}/bindings/python;CYCLIDE_LIB_DIR=${_cyc_py_libdir};CYCLIDE_HEADER=${PROJECT_SOURCE_DIR}/capi/include/cyclide/cyclide.h;PYTHONDONTWRITEBYTECODE=1")
endforeach()
