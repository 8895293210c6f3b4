# cmake -DCC=... -DAPIDOC=... -DROOT=... -DUMBRELLA=... -DABI=N -DHISTORY=FILE -P abi_record.cmake
# Records the fingerprint of the public types for ABI version N in HISTORY
# (one line "N SHA256" per ABI version). A version is recorded once: when N
# is already there with another fingerprint the public types changed since
# it was released, and the ABI version must be raised instead.
execute_process(COMMAND ${CC} -E -I${ROOT} ${UMBRELLA}
                COMMAND ${APIDOC} types --root ${ROOT} ${UMBRELLA}
                OUTPUT_VARIABLE _types RESULT_VARIABLE _result)
if(NOT _result EQUAL 0)
  message(FATAL_ERROR "abi_record: reading the public types failed")
endif()
string(SHA256 _fingerprint "${_types}")
file(STRINGS ${HISTORY} _lines REGEX "^[0-9]+ ")
foreach(_line IN LISTS _lines)
  if(_line MATCHES "^${ABI} (.*)$")
    if(CMAKE_MATCH_1 STREQUAL _fingerprint)
      message(STATUS "abi_record: ABI ${ABI} is already recorded with these types")
      return()
    endif()
    math(EXPR _next "${ABI} + 1")
    message(FATAL_ERROR "abi_record: ABI ${ABI} was recorded with other public types; they changed since. "
                        "Raise CANDELA_ABI_VERSION in CMakeLists.txt to ${_next}, then record again.")
  endif()
endforeach()
file(APPEND ${HISTORY} "${ABI} ${_fingerprint}\n")
message(STATUS "abi_record: recorded ABI ${ABI} (${_fingerprint}) in ${HISTORY}")
