# The guard, counts and size queries (SPEC §9b.1-9b.3).
set(_header ${PROJECT_SOURCE_DIR}/capi/include/cyclide/cyclide.h)
set(_entries ${CMAKE_CURRENT_BINARY_DIR}/generated/cyclide_entry_points.inc)
add_custom_command(OUTPUT ${_entries}
  COMMAND ${CMAKE_COMMAND} -DHEADER=${_header} -DOUT=${_entries}
          -P ${PROJECT_SOURCE_DIR}/cmake/cyclide_entry_points.cmake
  DEPENDS ${_header} ${PROJECT_SOURCE_DIR}/cmake/cyclide_entry_points.cmake
  COMMENT "Listing the C entry points of cyclide.h")
cyclide_hardening_test(test_hardening_guard SOURCES guard_test.cpp ${_entries} LABELS capi C_API)
target_include_directories(test_hardening_guard PRIVATE ${CMAKE_CURRENT_BINARY_DIR}/generated)
