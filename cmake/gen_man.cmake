# Writes the man page of a program from its own --help and --version texts with help2man, so the
# page never drifts from the program. With COMMANDS=ON, every subcommand's --help (as listed by
# the top-level --help, plus "synth arm" and "synth marker") becomes a COMMANDS section.
#   cmake -D PROGRAM=... -D HELP2MAN=... -D NAME="one line" -D COMMANDS=ON|OFF
#         -D INCLUDE=static.h2m -D OUTPUT=page.1.gz -P gen_man.cmake
cmake_minimum_required(VERSION 3.22)

# Text as roff lines shown as they are: backslashes escaped, a leading '.' or "'" neutralised.
function(roff_literal text out)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

file(READ "${INCLUDE}" include_text)
if(COMMANDS)
  execute_process(COMMAND "${PROGRAM}" --help OUTPUT_VARIABLE top RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${PROGRAM} --help failed (${rc})")
  endif()
  string(REGEX MATCH "Commands:\n(  [^\n]*\n)+" listing "${top}")
  string(REGEX MATCHALL "\n  [a-z][a-z0-9-]*" names "${listing}")
  set(commands "")
  foreach(n IN LISTS names)
    string(STRIP "${n}" n)
    list(APPEND commands "${n}")
    if(n STREQUAL "synth")
      list(APPEND commands "synth arm" "synth marker")
    endif()
  endforeach()
  set(section "[COMMANDS]\n")
  foreach(c IN LISTS commands)
    separate_arguments(words UNIX_COMMAND "${c}")
    execute_process(COMMAND "${PROGRAM}" ${words} --help OUTPUT_VARIABLE help RESULT_VARIABLE rc)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${PROGRAM} ${c} --help failed (${rc})")
    endif()
    roff_literal("${help}" help)
    string(APPEND section ".SS ${c}\n.nf\n${help}.fi\n")
  endforeach()
  set(include_text "${section}\n${include_text}")
endif()
get_filename_component(dir "${OUTPUT}" DIRECTORY)
get_filename_component(base "${OUTPUT}" NAME_WE)
file(WRITE "${dir}/${base}.h2m" "${include_text}")
execute_process(
  COMMAND "${HELP2MAN}" --no-info --section=1 "--name=${NAME}" "--include=${dir}/${base}.h2m"
          "--output=${dir}/${base}.1" "${PROGRAM}"
  RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "help2man failed on ${PROGRAM} (${rc})")
endif()
execute_process(COMMAND gzip -9n -c "${dir}/${base}.1" OUTPUT_FILE "${OUTPUT}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "gzip failed on ${dir}/${base}.1")
endif()
