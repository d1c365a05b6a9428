# Runs a link command so that its program appears whole or not at all: the linker writes
# <program>.linking, which is then renamed over <program> (one atomic step on POSIX). A program that is
# running as it is replaced keeps its file (the old one, until it exits); one started meanwhile starts
# the old or the new one, never half of one; and a link that fails (or two builds at once, one of which
# fails) leaves the last good program in place rather than none. Every link and archive rule of the
# build runs through it (RULE_LAUNCH_LINK, set in the top CMakeLists.txt):
#
#   cmake -P RaylabAtomicLink.cmake -- <link command...>
#
# A command without `-o` (an archive's, MSVC's /out:) runs as it is.
set(command "")
set(program "")
set(next_is_program FALSE)
set(started FALSE)
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(k RANGE ${last})
  set(arg "${CMAKE_ARGV${k}}")
  if(NOT started)
    if(arg STREQUAL "--")
      set(started TRUE)
    endif()
    continue()
  endif()
  if(next_is_program)
    set(program "${arg}")
    set(arg "${arg}.linking")
    set(next_is_program FALSE)
  elseif(arg STREQUAL "-o")
    set(next_is_program TRUE)
  endif()
  list(APPEND command "${arg}")
endforeach()
if(NOT command)
  message(FATAL_ERROR "RaylabAtomicLink.cmake: no command after --")
endif()
execute_process(COMMAND ${command} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  if(program)
    file(REMOVE "${program}.linking")
  endif()
  message(FATAL_ERROR "the link failed (status ${status}): the linker's words are above; ${program} is left as it was")
endif()
if(program)
  file(RENAME "${program}.linking" "${program}")
endif()
