# The C API reference (issue 10 item 5): scripts/docs builds it with doxygen
# and fails on any doxygen warning, so the header comments stay valid.
find_program(CYCLIDE_DOXYGEN doxygen)
if(CYCLIDE_DOXYGEN)
  add_test(NAME ffi.docs.doxygen
           COMMAND ${PROJECT_SOURCE_DIR}/scripts/docs ${CMAKE_CURRENT_BINARY_DIR}/docs)
  set_tests_properties(ffi.docs.doxygen PROPERTIES LABELS "ffi;docs")
else()
  message(STATUS "doxygen not found: the API reference test is skipped (scripts/docs installs it)")
endif()
