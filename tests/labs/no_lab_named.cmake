# No code of framework/ or cmake/ names a lab: a lab is its folders (labs/<lab>/, solutions/<lab>/ and
# its grading folder framework/grader/labs/<lab>/; in a students' tree, a given lab's reference,
# framework/given/<lab>/), and everything else takes the labs from the catalogue and the course's list.
# Finds every lab<N>_<name> in the code outside the labs' folders.
#
#   cmake -DSOURCE=<tree> -P tests/labs/no_lab_named.cmake

if(NOT SOURCE)
  message(FATAL_ERROR "no lab named: -DSOURCE=<tree> is required")
endif()
file(GLOB_RECURSE files RELATIVE ${SOURCE}
     ${SOURCE}/framework/*.cpp ${SOURCE}/framework/*.h ${SOURCE}/framework/*.in ${SOURCE}/framework/*.txt
     ${SOURCE}/framework/*.cmake ${SOURCE}/cmake/*)
list(FILTER files EXCLUDE REGEX "^framework/(grader/labs|given)/")
set(found "")
foreach(file IN LISTS files)
  file(STRINGS ${SOURCE}/${file} lines REGEX "lab[0-9]+_[a-z]")
  foreach(line IN LISTS lines)
    string(STRIP "${line}" line)
    string(APPEND found "\n  ${file}: ${line}")
  endforeach()
endforeach()
if(found)
  message(FATAL_ERROR "no lab named: code outside the labs' folders names a lab (take it from the catalogue, "
                      "or the grading folder's RAYLAB_LAB_ID):${found}")
endif()
list(LENGTH files count)
message(STATUS "no lab named: ${count} files of framework/ and cmake/, none names a lab")
