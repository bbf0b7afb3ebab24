# Lists what a generic caller of the C ABI needs to know about cyclide.h
# (tests/hardening/guard_test.cpp, fuzz/fuzz_abi.cpp), so that a new entry
# point is tried as soon as it is declared:
#   CYC_ENTRY(name)           every status-returning entry point whose first
#                             parameter is the context
#                             (`CYC_API int cyc_x(cyc_context* ctx`)
#   CYC_POINTER_STRUCT(name)  every struct with a pointer member (directly or
#                             in a member struct): a caller cannot fill it
#                             with arbitrary bytes
# cmake -DHEADER=cyclide.h -DOUT=file.inc -P cyclide_entry_points.cmake
cmake_minimum_required(VERSION 3.20)
file(READ "${HEADER}" text)
string(REGEX REPLACE "/\\*([^*]|\\*+[^*/])*\\*+/" "" code "${text}")  # drop comments
string(REPLACE ";" "@" code "${code}")  # ';' would split CMake lists
set(lines "// Generated from cyclide.h by cmake/cyclide_entry_points.cmake.\n")
string(REGEX MATCHALL "CYC_API int cyc_[a-z0-9_]+\\(cyc_context\\* ctx" decls "${code}")
foreach(d IN LISTS decls)
  string(REGEX REPLACE "CYC_API int (cyc_[a-z0-9_]+)\\(.*" "\\1" name "${d}")
  string(APPEND lines "CYC_ENTRY(${name})\n")
endforeach()
string(REGEX MATCHALL "typedef struct cyc_[a-z0-9_]+ {[^}]*} cyc_[a-z0-9_]+@" structs "${code}")
set(pointerful "")
foreach(pass 1 2 3)
  foreach(st IN LISTS structs)
    string(REGEX REPLACE "typedef struct (cyc_[a-z0-9_]+) .*" "\\1" name "${st}")
    if(name IN_LIST pointerful)
      continue()
    endif()
    string(REGEX REPLACE "^typedef struct cyc_[a-z0-9_]+ {(.*)} cyc_[a-z0-9_]+@$" "\\1" body "${st}")
    set(has OFF)
    if(body MATCHES "\\*")
      set(has ON)
    endif()
    foreach(p IN LISTS pointerful)
      if(body MATCHES "(^|[^a-z0-9_])${p}[^a-z0-9_]")
        set(has ON)
      endif()
    endforeach()
    if(has)
      list(APPEND pointerful ${name})
    endif()
  endforeach()
endforeach()
foreach(p IN LISTS pointerful)
  string(APPEND lines "CYC_POINTER_STRUCT(${p})\n")
endforeach()
file(WRITE "${OUT}.tmp" "${lines}")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different "${OUT}.tmp" "${OUT}")
file(REMOVE "${OUT}.tmp")
