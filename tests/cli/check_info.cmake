# Runs `snaxels-cli info --json MESH` and compares counts with the expected
# ones given as -DEXPECT="key=value;key=value".
execute_process(COMMAND ${CLI} info --json ${MESH}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "snaxels-cli info failed (${rc}): ${err}")
endif()
foreach(pair IN LISTS EXPECT)
  string(REPLACE "=" ";" kv "${pair}")
  list(GET kv 0 key)
  list(GET kv 1 want)
  string(REPLACE "." ";" path "${key}") # engine.faces: a member of a member
  string(JSON got ERROR_VARIABLE jerr GET "${out}" ${path})
  if(jerr)
    message(FATAL_ERROR "no key '${key}' in the JSON: ${out}")
  endif()
  if(NOT got EQUAL want)
    message(FATAL_ERROR "${MESH}: ${key} is ${got}, expected ${want}")
  endif()
  message("${key} = ${got}")
endforeach()
