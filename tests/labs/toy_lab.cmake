# The toy-lab test: adding a lab, function checks included, is its own folders. In a copy of the tree
# it adds labs/lab6_toy/ (its lab.toml, one stub function, a README), its completed twin in
# solutions/, its scene file and its grading folder framework/grader/labs/lab6_toy/ (a probe, a check,
# its English and French messages), then builds, renders, makes lab 6's references, grades and
# reports it as an instructor and a student would, and lists what changed under framework/: only
# the new lab's grading folder and the references `raylab references` made.
#
#   cmake -DSTEP=<step> -DSOURCE=<tree> -DWORK=<scratch folder> -DTOY=tests/labs/toy [-DGENERATOR=Ninja]
#         [-DCCACHE=<ccache>] -P tests/labs/toy_lab.cmake
# It runs in steps, one ctest test each (tests/CMakeLists.txt), each in the tree the steps before it
# left (ctest prints nothing while a test runs; with a warm compiler cache each step lasts seconds): copy, then
# build-framework, build-grader, build-cli, build-programs, render, grade, report, written-after-build,
# does-not-compile, lab-rebuilds, hints, framework-unchanged.
# Every program runs from an argument vector (execute_process), never through a shell.

foreach(var STEP SOURCE WORK TOY)
  if(NOT ${var})
    message(FATAL_ERROR "toy lab: -D${var}=... is required")
  endif()
endforeach()
set(tree ${WORK}/tree)
# The build folder inside the tree, as build/ is in the repository: the compiler then sees the same
# relative paths as the repository's own build, so that ccache (with CCACHE_BASEDIR, .ci/run) reuses
# its objects of the framework and the grader instead of compiling them again.
set(build ${tree}/build)
set(bin ${build}/bin)

set(STEP_PREFIX "toy lab")
include(${CMAKE_CURRENT_LIST_DIR}/script_steps.cmake)

# 1. The copy of the tree (no build folders, no out/, no tests/), and the toy lab added to it.
function(step_copy)
  file(REMOVE_RECURSE ${WORK})
  file(MAKE_DIRECTORY ${tree})
  foreach(part framework labs solutions scenes cmake)
    file(COPY ${SOURCE}/${part} DESTINATION ${tree})
  endforeach()
  file(COPY ${SOURCE}/CMakeLists.txt ${SOURCE}/CMakePresets.json DESTINATION ${tree})
  file(COPY ${TOY}/lab.toml ${TOY}/README.md ${TOY}/toy_colour.cpp DESTINATION ${tree}/labs/lab6_toy)
  file(COPY ${TOY}/solution/toy_colour.cpp DESTINATION ${tree}/solutions/lab6_toy)
  file(COPY ${TOY}/lab6_toy.toml DESTINATION ${tree}/labs/lab6_toy/scenes)
  file(COPY ${TOY}/grading/ DESTINATION ${tree}/framework/grader/labs/lab6_toy)

  # 2. Configured to build the programs a course uses (no test suite: tests/ is not copied).
  # Without link-time optimisation: this test is about adding a lab, not its speed (quicker links).
  set(configure ${CMAKE_COMMAND} -S ${tree} -B ${build} -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF -DRAYLAB_LTO=OFF)
  if(GENERATOR)
    list(APPEND configure -G ${GENERATOR})
  endif()
  if(CCACHE)
    list(APPEND configure -DCMAKE_CXX_COMPILER_LAUNCHER=${CCACHE})
  endif()
  run(output 0 ${configure})
  expect("${output}" "lab5_antialiasing;lab6_toy" "CMake found the sixth lab")
endfunction()

# The build, a few targets at a time: the framework, the grader (lab 6's check and messages in it),
# the command-line tool's library, then the programs (the labs' objects and the links).
function(step_build_framework)
  build(raylab_framework)
endfunction()
function(step_build_grader)
  build(raylab_grader raylab_agent_objects)
endfunction()
function(step_build_cli)
  build(raylab_cli)
endfunction()
function(step_build_programs)
  build(raylab raylab-reference raylab-agents raylab-agent-reference)
  foreach(agent raylab-agent-lab6 raylab-agent-reference raylab-agent)
    if(NOT EXISTS ${bin}/${agent})
      message(FATAL_ERROR "toy lab: ${agent} was not built")
    endif()
  endforeach()
endfunction()

# 3. Rendered by the reference build, and lab 6's references made from it (its scene alone).
function(step_render)
  run(output 0 ${bin}/raylab-reference figures --out ${WORK}/figures)
  expect("${output}" "lab6_toy" "raylab-reference figures lists lab 6's figure")
  if(NOT EXISTS ${WORK}/figures/lab6_toy.png)
    message(FATAL_ERROR "toy lab: raylab-reference figures wrote no lab6_toy.png")
  endif()
  file(MAKE_DIRECTORY ${WORK}/lab6-scenes)
  file(COPY ${tree}/labs/lab6_toy/scenes/lab6_toy.toml DESTINATION ${WORK}/lab6-scenes)
  run(output 0 ${bin}/raylab-reference references --scenes ${WORK}/lab6-scenes)
  expect("${output}" "lab6_toy" "raylab references made lab 6's reference")
endfunction()

# 4. Graded: the reference code gets every point, the stub is told to write toyColour.
function(step_grade)
  run(output 0 ${bin}/raylab grade --lab 6 --agent ${bin}/raylab-agent-reference --report ${WORK}/grade-reference)
  expect("${output}" "PASS  lab6  figure lab6_toy" "the reference's figure passes")
  expect("${output}" "PASS  lab6  toyColour: 1 - (d + 1) / 2 for each direction d" "the reference passes lab 6's check")
  expect("${output}" "lab 6: 7 / 7 points" "the reference gets lab 6's points")
  run(output nonzero ${bin}/raylab grade --lab 6 --report ${WORK}/grade-student)
  expect("${output}" "lab 6 not done yet: write toyColour" "the stub is not done yet")
  expect("${output}" "lab 6: 0 / 7 points" "the stub gets no point")
endfunction()

# 5. Reported: the lab's section with its title, handout number and caption, from its lab.toml.
function(step_report)
  run(output 0 ${bin}/raylab report --impl reference --out ${WORK}/report-reference)
  file(READ ${WORK}/report-reference/report.md report)
  expect("${report}" "## Lab 6: A toy lab" "the report has lab 6's section")
  expect("${report}" "### Figure 7 (lab6_toy)" "the report numbers lab 6's figure")
  expect("${report}" "1 - (d + 1) / 2" "the report shows lab 6's caption")
  expect("${report}" "![lab6_toy](figures/lab6_toy.png)" "the report shows lab 6's picture")
  run(output 0 ${bin}/raylab report --lang fr --out ${WORK}/report-student)
  file(READ ${WORK}/report-student/report.md report)
  expect("${report}" "## TP 6 : Un TP jouet" "the French report has lab 6's section")
  # The student build's labs are all stubs: lab 6's figure waits for lab 2's camera first.
  string(FIND "${report}" "## TP 6 : Un TP jouet" section)
  string(SUBSTRING "${report}" ${section} -1 section)
  expect("${section}" "La direction d de chaque rayon primaire" "the French report shows lab 6's French caption")
  expect("${section}" "TP 6 : écrivez toyColour dans labs/lab6_toy/ ; cette figure attend d'abord le TP 2 : écrivez PerspectiveCamera::updateViewport"
         "the student's French report names lab 6's function and the earlier lab it waits for")
endfunction()

# 5b. The student writes lab 6 after the build: `raylab grade` and `raylab lab` rebuild first, and
# grade and draw the code as it is now (written anew, so that it is newer than the build).
function(step_written_after_build)
  file(READ ${TOY}/solution/toy_colour.cpp written)
  file(WRITE ${tree}/labs/lab6_toy/toy_colour.cpp "${written}")
  run(output nonzero ${bin}/raylab grade --report ${WORK}/grade-written)
  expect("${output}" "labs/lab6_toy/toy_colour.cpp changed since the last build: rebuilding first" "raylab grade rebuilds")
  expect("${output}" "lab 6: 7 / 7 points" "the grade follows the code written after the build")
endfunction()

# A lab that does not compile: `raylab grade` grades labs/ as a submission, in a build folder of its
# own (out/grade-build, from nothing: the longest step).
function(step_does_not_compile)
  file(READ ${TOY}/solution/toy_colour.cpp written)
  file(WRITE ${tree}/labs/lab6_toy/toy_colour.cpp "${written}\nint unfinished(\n")
  # Its build folder beside build/ (not out/grade-build, the default): the same relative paths, so
  # that the compiler cache (CMAKE_CXX_COMPILER_LAUNCHER in the environment) finds the tree's objects.
  run(output nonzero ${bin}/raylab grade --report ${WORK}/grade-broken --build-dir ${tree}/grade-build)
  expect("${output}" "grading labs/ as a submission" "a build that fails is graded as a submission")
  expect("${output}" "lab 6: 0 / 7 points" "lab 6 that does not compile gets no point")
  expect("${output}" "lab 1: 0 / 10 points" "the other labs are graded (lab 1 is a stub)")
  file(WRITE ${tree}/labs/lab6_toy/toy_colour.cpp "${written}")
endfunction()

function(step_lab_rebuilds)
  file(READ ${SOURCE}/solutions/lab1_first_image/gradient.cpp written)
  file(WRITE ${tree}/labs/lab1_first_image/gradient.cpp "${written}")
  run(output 0 ${bin}/raylab lab 1 --out ${WORK}/lab1-written)
  expect("${output}" "labs/lab1_first_image/gradient.cpp changed since the last build: rebuilding first" "raylab lab rebuilds")
  if(NOT EXISTS ${WORK}/lab1-written/lab1_gradient.png)
    message(FATAL_ERROR "toy lab: raylab lab 1 drew nothing from the code written after the build")
  endif()
  # A lab function that crashes costs its figure only: the command names the lab and the function,
  # draws the other figures and exits with an error status, not a signal.
  file(WRITE ${tree}/labs/lab1_first_image/gradient.cpp "#include \"raylab/gradient.h\"\nnamespace raylab {\nvoid fillGradient(Texture&) { *static_cast<volatile int*>(nullptr) = 1; }\n}\n")
  run(output 1 ${bin}/raylab figures --out ${WORK}/figures-crash)
  expect("${output}" "lab 1: fillGradient in labs/lab1_first_image/ crashed (" "the crash names lab 1 and fillGradient")
  expect("${output}" "lab2_directions" "the figures after the crash are still drawn")
endfunction()

# A wrong toyColour fails the check with the lab's own English hint, and its French one in French.
function(step_hints)
  file(READ ${TOY}/solution/toy_colour.cpp written)
  string(REPLACE "Color(1.f) - (ray.direction + 1.f) * 0.5f" "(ray.direction + 1.f) * 0.5f" wrong "${written}")
  if(wrong STREQUAL written)
    message(FATAL_ERROR "toy lab: the solution's formula was not found to make a wrong one")
  endif()
  file(WRITE ${tree}/labs/lab6_toy/toy_colour.cpp "${wrong}")
  run(output nonzero ${bin}/raylab grade --lab 6 --report ${WORK}/grade-wrong)
  expect("${output}" "toyColour returns 1 - (d + 1) / 2: the direction's colour, inverted" "the check's English hint")
  run(output nonzero ${bin}/raylab grade --lab 6 --lang fr --report ${WORK}/grade-wrong-fr)
  expect("${output}" "toyColour renvoie 1 - (d + 1) / 2" "the check's French hint")
  expect("${output}" "1 - (d + 1) / 2 pour chaque direction d" "the check's French title")
  # The instructor rewords the hint in the grading folder: `raylab grade` rebuilds the grader first.
  set(messages ${tree}/framework/grader/labs/lab6_toy/messages.en.toml)
  file(READ ${messages} hints)
  string(REPLACE "the direction's colour, inverted" "the direction's colour, upside down" reworded "${hints}")
  file(WRITE ${messages} "${reworded}")
  run(output nonzero ${bin}/raylab grade --lab 6 --report ${WORK}/grade-reworded)
  expect("${output}" "framework/grader/labs/lab6_toy/messages.en.toml changed since the last build: rebuilding first"
         "raylab grade rebuilds when the lab's grading folder changed")
  expect("${output}" "toyColour returns 1 - (d + 1) / 2: the direction's colour, upside down" "the reworded hint")
  file(WRITE ${messages} "${hints}")
endfunction()

# 6. What adding the lab changed under framework/, listed: files added in lab 6's grading folder and
# the references `raylab references` made for it, nothing else added, changed or removed.
function(step_framework_unchanged)
  file(GLOB_RECURSE sources RELATIVE ${SOURCE}/framework ${SOURCE}/framework/*)
  file(GLOB_RECURSE copied RELATIVE ${tree}/framework ${tree}/framework/*)
  set(added ${copied})
  list(REMOVE_ITEM added ${sources})
  set(removed ${sources})
  list(REMOVE_ITEM removed ${copied})
  set(changed "")
  foreach(file IN LISTS sources)
    if(EXISTS ${tree}/framework/${file})
      file(SHA256 ${SOURCE}/framework/${file} a)
      file(SHA256 ${tree}/framework/${file} b)
      if(NOT a STREQUAL b)
        list(APPEND changed ${file})
      endif()
    endif()
  endforeach()
  string(REPLACE ";" "\n    " listed "${added}")
  message(STATUS "toy lab: framework/ files added by lab 6:\n    ${listed}")
  set(outside ${added})
  list(FILTER outside EXCLUDE REGEX "^grader/labs/lab6_toy/")
  if(changed OR removed OR outside)
    message(FATAL_ERROR "toy lab: adding lab 6 changed framework/ outside its grading folder: changed [${changed}], "
                        "removed [${removed}], added [${outside}]")
  endif()
  foreach(file checks.cpp probes.cpp probes.h messages.en.toml messages.fr.toml)
    list(FIND added grader/labs/lab6_toy/${file} at) # (a script has no IN_LIST without a policy)
    if(at EQUAL -1)
      message(FATAL_ERROR "toy lab: lab 6's grading folder has no ${file}")
    endif()
  endforeach()
  message(STATUS "toy lab: lab 6 built, rendered, graded and reported; framework/ changed only in lab 6's grading folder")
endfunction()

run_step()
