# The panel firmware core must run on a bare microcontroller: no heap, no libc, no OS calls.
# Checks that every symbol libweft_firmware.a needs from outside is its own (weft::firmware).
# Usage: cmake -DNM=<nm> -DLIB=<libweft_firmware.a> -P firmware_freestanding_check.cmake
execute_process(COMMAND ${NM} -u ${LIB} OUTPUT_VARIABLE out RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "nm failed on ${LIB}")
endif()
string(REGEX MATCHALL "U [^\n]+" undefined "${out}")
set(foreign "")
foreach(u IN LISTS undefined)
  string(REGEX REPLACE "^U " "" sym "${u}")
  # memcpy/memset/memmove: what a compiler may emit for struct copies; every freestanding
  # toolchain provides them.
  if(NOT sym MATCHES "^_ZN4weft8firmware" AND NOT sym MATCHES "^(memcpy|memset|memmove)$")
    list(APPEND foreign ${sym})
  endif()
endforeach()
if(foreign)
  message(FATAL_ERROR "weft_firmware depends on symbols outside itself (heap, libc or OS?): ${foreign}")
endif()
message(STATUS "weft_firmware is self-contained (${LIB})")
