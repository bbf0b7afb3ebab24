# ffi.abi.symbols (tests/ffi/abi.cmake): the dynamic symbols libcyclide.so
# defines, against the checked-in reference abi/cyclide.symbols (SPEC §9a).
#   LIB          the installed library
#   REFERENCE    abi/cyclide.symbols
#   EXPERIMENTAL abi/experimental.txt (names exempt from the check)
#   SONAME       the expected SONAME (libcyclide.so.<ABI version>)
# A removed symbol is an ABI break (always an error); an added one is an
# error until the reference is regenerated deliberately (scripts/abi-update).
cmake_minimum_required(VERSION 3.20)

# The names as `nm -D --defined-only` prints them (name@@VERSION), sorted;
# absolute symbols (the version node CYCLIDE_0 itself) left out. The same
# extraction as scripts/abi-update.
execute_process(COMMAND nm -D --defined-only ${LIB} OUTPUT_VARIABLE out RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "nm -D --defined-only ${LIB} failed (${rc})")
endif()
string(REPLACE "\n" ";" lines "${out}")
set(current "")
foreach(line IN LISTS lines)
  if(line MATCHES "^[0-9a-f]+ ([A-Za-z]) (.+)$" AND NOT CMAKE_MATCH_1 STREQUAL "A")
    list(APPEND current "${CMAKE_MATCH_2}")
  endif()
endforeach()
list(SORT current)

function(read_names file var)
  set(names "")
  if(EXISTS ${file})
    file(STRINGS ${file} lines ENCODING UTF-8 REGEX "^[^#]")
    foreach(line IN LISTS lines)
      string(STRIP "${line}" line)
      if(line AND NOT line MATCHES "^#")
        list(APPEND names "${line}")
      endif()
    endforeach()
  endif()
  set(${var} "${names}" PARENT_SCOPE)
endfunction()
read_names(${REFERENCE} reference)
read_names(${EXPERIMENTAL} experimental)

function(is_experimental sym var)
  string(REGEX REPLACE "@.*$" "" name "${sym}")
  if(name IN_LIST experimental)
    set(${var} TRUE PARENT_SCOPE)
  else()
    set(${var} FALSE PARENT_SCOPE)
  endif()
endfunction()

set(removed "")
foreach(sym IN LISTS reference)
  if(NOT sym IN_LIST current)
    is_experimental("${sym}" exp)
    if(NOT exp)
      list(APPEND removed "${sym}")
    endif()
  endif()
endforeach()
set(added "")
foreach(sym IN LISTS current)
  if(NOT sym IN_LIST reference)
    is_experimental("${sym}" exp)
    if(NOT exp)
      list(APPEND added "${sym}")
    endif()
  endif()
endforeach()

# The SONAME is the ABI major: libcyclide.so.0 for ABI 0.
execute_process(COMMAND objdump -p ${LIB} OUTPUT_VARIABLE dyn RESULT_VARIABLE rc)
set(soname "")
if(rc EQUAL 0 AND dyn MATCHES "SONAME +([^\n]+)")
  string(STRIP "${CMAKE_MATCH_1}" soname)
endif()

list(LENGTH current n_current)
list(LENGTH reference n_reference)
list(LENGTH added n_added)
list(LENGTH removed n_removed)
message(STATUS "libcyclide.so: ${n_current} symbols, SONAME ${soname}; "
               "reference abi/cyclide.symbols: ${n_reference}")
set(fail "")
if(NOT soname STREQUAL SONAME)
  string(APPEND fail "SONAME is '${soname}', expected '${SONAME}' (CYCLIDE_ABI_VERSION in "
                     "CMakeLists.txt). ")
endif()
foreach(sym IN LISTS removed)
  message("  REMOVED (ABI break): ${sym}")
endforeach()
foreach(sym IN LISTS added)
  message("  added: ${sym}")
endforeach()
if(n_removed GREATER 0)
  string(APPEND fail "${n_removed} symbol(s) of the reference are gone: an ABI break. "
    "Within ABI major ${SONAME} symbols are only ever added (SPEC.md §9a): restore them. "
    "(Only for a deliberate new ABI major: bump CYCLIDE_ABI_VERSION in CMakeLists.txt, "
    "then regenerate the references with scripts/abi-update.) ")
endif()
if(n_added GREATER 0)
  string(APPEND fail "${n_added} symbol(s) are not in the reference abi/cyclide.symbols. "
    "If the additions are deliberate, regenerate the references and commit them with the "
    "change: scripts/abi-update [build dir, default build/dev] && git add abi/ "
    "(it rewrites abi/cyclide.symbols and abi/cyclide.abi.xml from a RelWithDebInfo build). ")
endif()
if(fail)
  message(FATAL_ERROR "${fail}")
endif()
message(STATUS "the exported symbols equal abi/cyclide.symbols")
