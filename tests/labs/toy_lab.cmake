# The toy-lab test: adding a lab, function checks included, is its own folders and its number in the
# course's list. In a copy of the whole tree (its files as git lists them: tests/ and docs/ too, no
# build folder) it adds lab N, the next free number: labs/labN_toy/ (its lab.toml, its header, one
# stub function, its own kind of object in shapes.h and of light in lights.h, its handouts in English and French, its scene
# file), its completed twin in solutions/ and its grading folder framework/grader/labs/labN_toy/ (a
# probe, three checks, its shading, its kinds' [[toy_square]] and [[toy_lamp]] tables, its English and French
# messages), and N to course.toml; then builds, renders, makes lab N's references and the
# handouts' figures (docs/instructors.md, "Adding a lab"), checks that nothing changed outside the
# lab's three folders and course.toml, runs the copy's own lab tests, grades and reports it as an
# instructor and a student would, and lists what changed under framework/ by then: only the new lab's
# grading folder (the references `raylab references` made are in it).
#
# The copy's tests: `ctest -L lab`, the command docs/instructors.md gives to check a new lab before
# it is committed (the lab descriptions, figure steps, scene files, both message catalogues, the
# handouts' figure tables and links, no lab named in the framework, the reference's grade, the
# mistakes, the checks, "doing nothing earns no point", what `raylab distribute` ships): what adding
# a lab can break, about 30 s once built. Not the rest of the copy's suite: the tests labelled slow
# build trees of their own (this one among them) and take far longer, and the others test the
# framework, the sandbox and the tools, which a lab's folders do not change.
#
#   cmake -DSTEP=<step> -DSOURCE=<tree> -DWORK=<scratch folder> -DTOY=tests/labs/toy [-DGENERATOR=Ninja]
#         [-DCCACHE=<ccache>] -P tests/labs/toy_lab.cmake
# It runs in steps, one ctest test each (tests/CMakeLists.txt), each in the tree the steps before it
# left (ctest prints nothing while a test runs; with a warm compiler cache each step lasts seconds): copy, then
# build-framework, build-grader, build-cli, build-programs, render, tree-unchanged, lab-tests, grade, report,
# written-after-build, does-not-compile, lab-rebuilds, hints, framework-unchanged.
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

# N: the toy lab's number, the next after every lab of the source tree (whichever labs it has).
file(GLOB lab_files RELATIVE ${SOURCE}/labs ${SOURCE}/labs/lab*/lab.toml)
set(N 1)
foreach(file IN LISTS lab_files)
  if(file MATCHES "^lab([0-9]+)_" AND CMAKE_MATCH_1 GREATER_EQUAL N)
    math(EXPR N "${CMAKE_MATCH_1} + 1")
  endif()
endforeach()
set(id lab${N}_toy)

# 1. The copy of the whole tree (script_steps.cmake), and the toy lab added to it: its files, lab N in
# them (@N@), and N in the course's list.
function(step_copy)
  file(REMOVE_RECURSE ${WORK})
  copy_tree(${SOURCE} ${tree})
  write_copied_hashes()
  foreach(file lab.toml README.md README.fr.md toy_colour.cpp toy_colour.h shapes.h lights.h)
    configure_file(${TOY}/${file} ${tree}/labs/${id}/${file} @ONLY)
  endforeach()
  configure_file(${TOY}/toy.toml ${tree}/labs/${id}/scenes/${id}.toml @ONLY)
  configure_file(${TOY}/solutions/toy_colour.cpp ${tree}/solutions/${id}/toy_colour.cpp @ONLY)
  file(COPY ${TOY}/grading/ DESTINATION ${tree}/framework/grader/labs/${id})
  file(READ ${tree}/course.toml course)
  string(REGEX REPLACE "\nlabs = \\[([^]\n]*)\\]" "\nlabs = [\\1, ${N}]" listed "${course}")
  if(listed STREQUAL course)
    message(FATAL_ERROR "toy lab: no line `labs = [...]` in course.toml to add lab ${N} to")
  endif()
  file(WRITE ${tree}/course.toml "${listed}")

  # 2. Configured, its test suite too.
  configure_tree(output)
  expect("${output}" ";${id}" "CMake found lab ${N}")
endfunction()

# The build, a few targets at a time: the framework, the grader (lab ${N}'s check and messages in it),
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
  foreach(agent raylab-agent-lab${N} raylab-agent-reference raylab-agent)
    if(NOT EXISTS ${bin}/${agent})
      message(FATAL_ERROR "toy lab: ${agent} was not built")
    endif()
  endforeach()
endfunction()

# 3. Rendered by the reference build into the handouts' figures, each in its lab's figures/ (the
# other labs' pictures, whose pixels did not change, left as they are), and lab ${N}'s references
# made from it (its scene alone).
function(step_render)
  run(output 0 ${bin}/raylab-reference figures --handouts)
  expect("${output}" "${id}" "raylab-reference figures lists lab ${N}'s figure")
  if(NOT EXISTS ${tree}/labs/${id}/figures/${id}.png)
    message(FATAL_ERROR "toy lab: raylab-reference figures --handouts wrote no labs/${id}/figures/${id}.png")
  endif()
  file(MAKE_DIRECTORY ${WORK}/toy-scenes)
  file(COPY ${tree}/labs/${id}/scenes/${id}.toml DESTINATION ${WORK}/toy-scenes)
  run(output 0 ${bin}/raylab-reference references --scenes ${WORK}/toy-scenes)
  expect("${output}" "${id}" "raylab references made lab ${N}'s reference")

  # Lab ${N}'s own kind of object, [[toy_square]]: in the scene format, read from a scene file and
  # drawn (the figure without it, or with it behind the camera, is another picture), its errors located.
  run(format 0 ${bin}/raylab-reference scene-format)
  expect("${format}" "[[toy_square]] # a square facing the default camera (the toy lab)" "the scene format lists lab ${N}'s kind")
  expect("${format}" "#   side: number in [" "the scene format lists its parameters")
  file(MAKE_DIRECTORY ${WORK}/toy-scenes-drawn)
  file(READ ${tree}/labs/${id}/scenes/${id}.toml with_square)
  scene_before(without_square "${with_square}" toy_square)
  string(REPLACE "center = [0.5, 0, 3]" "center = [0.5, 0, -3]" behind "${with_square}")
  render_toy_scene(with "${with_square}")
  render_toy_scene(without "${without_square}")
  render_toy_scene(behind "${behind}")
  if(with STREQUAL without OR NOT behind STREQUAL without)
    message(FATAL_ERROR "toy lab: the [[toy_square]] in front of the camera must change the picture, and behind it not "
                        "(with ${with}, without ${without}, behind ${behind})")
  endif()
  expect_bad_table(bad_square "${without_square}" "[[toy_square]]\ncenter = [0, 0, 3]\nside = 0\n" "[[toy_square]] side: 0 is too small")

  # Its own kind of light, [[toy_lamp]], the same way: listed among the lights, read, moved with the
  # scene into the render space and used by its integrator (no lamp, or one behind the square, is
  # another picture), its errors located.
  expect("${format}" "[[toy_lamp]] # a lamp that tints the surfaces facing it (the toy lab)" "the scene format lists lab ${N}'s light")
  string(FIND "${format}" "\n# Lights\n" lights_at)
  string(FIND "${format}" "\n[[toy_lamp]]" lamp_at)
  if(lights_at EQUAL -1 OR lamp_at LESS lights_at)
    message(FATAL_ERROR "toy lab: the scene format lists [[toy_lamp]] outside its lights:\n${format}")
  endif()
  scene_before(unlit_scene "${with_square}" toy_lamp)
  string(REPLACE "position = [0, 0, 0]" "position = [0, 0, 5]" lamp_behind_scene "${with_square}")
  render_toy_scene(unlit "${unlit_scene}")
  render_toy_scene(lamp_behind "${lamp_behind_scene}")
  if(with STREQUAL unlit OR with STREQUAL lamp_behind OR unlit STREQUAL lamp_behind)
    message(FATAL_ERROR "toy lab: the [[toy_lamp]] facing the square, none, and one behind it must be three pictures "
                        "(with ${with}, unlit ${unlit}, behind ${lamp_behind})")
  endif()
  expect_bad_table(bad_lamp "${unlit_scene}" "[[toy_lamp]]\nposition = [0, 0, 0]\ntint = [0, 0, 0]\n"
                   "[[toy_lamp]] tint: a black lamp tints nothing")
endfunction()

# scene_before(OUT TEXT TABLE): the scene file TEXT up to its first [[TABLE]], which must be there.
function(scene_before out text table)
  string(FIND "${text}" "\n[[${table}]]" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "toy lab: lab ${N}'s scene has no [[${table}]] table")
  endif()
  math(EXPR at "${at} + 1")
  string(SUBSTRING "${text}" 0 ${at} before)
  set(${out} "${before}" PARENT_SCOPE)
endfunction()

# render_toy_scene(NAME TEXT): renders the scene file TEXT; the SHA-256 of its picture into NAME.
function(render_toy_scene name text)
  file(WRITE ${WORK}/toy-scenes-drawn/${name}.toml "${text}")
  run(output 0 ${bin}/raylab-reference render ${WORK}/toy-scenes-drawn/${name}.toml --out ${WORK}/toy-scenes-drawn/${name}.png)
  file(SHA256 ${WORK}/toy-scenes-drawn/${name}.png hash)
  set(${name} ${hash} PARENT_SCOPE)
endfunction()

# expect_bad_table(NAME SCENE TABLE PROBLEM): the scene file SCENE then TABLE, whose third line is
# wrong, is refused with PROBLEM after the file's name and that line.
function(expect_bad_table name scene table problem)
  file(WRITE ${WORK}/toy-scenes-drawn/${name}.toml "${scene}${table}")
  string(REGEX MATCHALL "\n" lines "${scene}")
  list(LENGTH lines line)
  math(EXPR line "${line} + 3")
  run(output nonzero ${bin}/raylab-reference render ${WORK}/toy-scenes-drawn/${name}.toml --out ${WORK}/toy-scenes-drawn/${name}.png)
  expect("${output}" "${name}.toml:${line}: ${problem}" "a wrong table is named with its line")
endfunction()

# 3b. The copy's own lab tests pass with lab ${N} added: `ctest -L lab`, as docs/instructors.md asks of
# a new lab (see the top of this file), after building the whole copy, its tests included.
function(step_lab_tests)
  build(all)
  run(output 0 ${CMAKE_CTEST_COMMAND} --test-dir ${build} -L "^lab$" -j 2 --output-on-failure)
  expect("${output}" "100% tests passed" "the copy's lab tests pass")
  expect("${output}" "grading/grade reference" "the copy's lab tests grade the reference")
endfunction()

# 4. Graded: the reference code gets every point, the stub is told to write toyColour.
function(step_grade)
  run(output 0 ${bin}/raylab grade --lab ${N} --agent ${bin}/raylab-agent-reference --report ${WORK}/grade-reference)
  expect("${output}" "PASS  lab${N}  figure ${id}" "the reference's figure passes")
  expect("${output}" "PASS  lab${N}  toyColour: a direction drawn at grading time" "the reference passes lab ${N}'s checks")
  expect("${output}" "lab ${N}: 7 / 7 points" "the reference gets lab ${N}'s points")
  run(output nonzero ${bin}/raylab grade --lab ${N} --report ${WORK}/grade-student)
  expect("${output}" "lab ${N} not done yet: write toyColour" "the stub is not done yet")
  expect("${output}" "lab ${N}: 0 / 7 points" "the stub gets no point")
endfunction()

# 5. Reported: the lab's section with its title, handout number and caption, from its lab.toml.
function(step_report)
  run(output 0 ${bin}/raylab report --impl reference --out ${WORK}/report-reference)
  file(READ ${WORK}/report-reference/report.md report)
  expect("${report}" "## Lab ${N}: A toy lab" "the report has lab ${N}'s section")
  expect("${report}" "### Figure ${N}0 (${id})" "the report numbers lab ${N}'s figure")
  expect("${report}" "1 - (d + 1) / 2" "the report shows lab ${N}'s caption")
  expect("${report}" "![${id}](figures/${id}.png)" "the report shows lab ${N}'s picture")
  run(output 0 ${bin}/raylab report --lang fr --out ${WORK}/report-student)
  file(READ ${WORK}/report-student/report.md report)
  expect("${report}" "## TP ${N} : Un TP jouet" "the French report has lab ${N}'s section")
  # The student build's labs are all stubs: lab ${N}'s figure waits for lab 2's camera first.
  string(FIND "${report}" "## TP ${N} : Un TP jouet" section)
  string(SUBSTRING "${report}" ${section} -1 section)
  expect("${section}" "La direction d de chaque rayon primaire" "the French report shows lab ${N}'s French caption")
  expect("${section}" "TP ${N} : écrivez toyColour dans labs/${id}/ ; cette figure attend d'abord le TP 2 : écrivez PerspectiveCamera::updateViewport"
         "the student's French report names lab ${N}'s function and the earlier lab it waits for")
endfunction()

# 5b. The student writes lab N after the build: `raylab grade` and `raylab lab` rebuild first, and
# grade and draw the code as it is now (written anew, so that it is newer than the build).
function(step_written_after_build)
  file(READ ${TOY}/solutions/toy_colour.cpp written)
  file(WRITE ${tree}/labs/${id}/toy_colour.cpp "${written}")
  run(output nonzero ${bin}/raylab grade --report ${WORK}/grade-written)
  expect("${output}" "labs/${id}/toy_colour.cpp changed since the last build: rebuilding first" "raylab grade rebuilds")
  expect("${output}" "lab ${N}: 7 / 7 points" "the grade follows the code written after the build")
endfunction()

# A lab that does not compile costs that lab: `raylab grade` builds the other labs' grading programs
# all the same, and grades them; the lab's report quotes the compiler.
function(step_does_not_compile)
  file(READ ${TOY}/solutions/toy_colour.cpp written)
  file(WRITE ${tree}/labs/${id}/toy_colour.cpp "${written}\nint unfinished(\n")
  run(output nonzero ${bin}/raylab grade --report ${WORK}/grade-broken)
  expect("${output}" "lab ${N}: 0 / 7 points" "lab ${N} that does not compile gets no point")
  expect("${output}" "the code does not build" "lab ${N} graded as not compiling")
  expect("${output}" "unfinished" "the compiler's words in the grade")
  expect("${output}" "lab 1: 0 / 10 points" "the other labs are graded (lab 1 is a stub)")
  file(WRITE ${tree}/labs/${id}/toy_colour.cpp "${written}")
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
  file(WRITE ${tree}/labs/lab1_first_image/gradient.cpp "#include \"gradient.h\"\nnamespace raylab {\nvoid fillGradient(Texture&) { *static_cast<volatile int*>(nullptr) = 1; }\n}\n")
  run(output 1 ${bin}/raylab figures --out ${WORK}/figures-crash)
  expect("${output}" "lab 1: fillGradient in labs/lab1_first_image/ crashed (" "the crash names lab 1 and fillGradient")
  expect("${output}" "lab2_directions" "the figures after the crash are still drawn")
endfunction()

# A wrong toyColour fails the check with the lab's own English hint, and its French one in French.
function(step_hints)
  file(READ ${TOY}/solutions/toy_colour.cpp written)
  string(REPLACE "Color(1.f) - (ray.direction + 1.f) * 0.5f" "(ray.direction + 1.f) * 0.5f" wrong "${written}")
  if(wrong STREQUAL written)
    message(FATAL_ERROR "toy lab: the solution's formula was not found to make a wrong one")
  endif()
  file(WRITE ${tree}/labs/${id}/toy_colour.cpp "${wrong}")
  run(output nonzero ${bin}/raylab grade --lab ${N} --report ${WORK}/grade-wrong)
  expect("${output}" "toyColour returns 1 - (d + 1) / 2: the direction's colour, inverted" "the check's English hint")
  run(output nonzero ${bin}/raylab grade --lab ${N} --lang fr --report ${WORK}/grade-wrong-fr)
  expect("${output}" "toyColour renvoie 1 - (d + 1) / 2" "the check's French hint")
  expect("${output}" "une direction tirée à la correction" "the check's French title")
  # The instructor rewords the hint in the grading folder: `raylab grade` rebuilds the grader first.
  set(messages ${tree}/framework/grader/labs/${id}/messages.en.toml)
  file(READ ${messages} hints)
  string(REPLACE "the direction's colour, inverted" "the direction's colour, upside down" reworded "${hints}")
  file(WRITE ${messages} "${reworded}")
  run(output nonzero ${bin}/raylab grade --lab ${N} --report ${WORK}/grade-reworded)
  expect("${output}" "framework/grader/labs/${id}/messages.en.toml changed since the last build: rebuilding first"
         "raylab grade rebuilds when the lab's grading folder changed")
  expect("${output}" "toyColour returns 1 - (d + 1) / 2: the direction's colour, upside down" "the reworded hint")
  file(WRITE ${messages} "${hints}")
endfunction()

# The copy's files as copied, each with its SHA256 (${WORK}/copied.sha256), before lab ${N} is added:
# what `tree_changes` compares the copy with later. Not the source itself, which someone may edit
# while the tests run.
function(write_copied_hashes)
  file(GLOB_RECURSE files LIST_DIRECTORIES false RELATIVE ${tree} ${tree}/*)
  set(lines "")
  foreach(file IN LISTS files)
    file(SHA256 ${tree}/${file} hash)
    string(APPEND lines "${hash} ${file}\n")
  endforeach()
  file(WRITE ${WORK}/copied.sha256 "${lines}")
endfunction()

# What differs in the copy, under `prefix` ("" for the whole tree) and the build folder aside, from
# its files as copied, outside the files `allowed` matches: the variable `result` lists them
# ("changed x", "added y", "removed z"), and `added` every file added.
function(tree_changes prefix allowed result)
  file(STRINGS ${WORK}/copied.sha256 lines)
  set(found "")
  set(copied "")
  foreach(line IN LISTS lines)
    string(SUBSTRING "${line}" 65 -1 file)
    if(NOT file MATCHES "^${prefix}")
      continue()
    endif()
    list(APPEND copied ${file})
    string(SUBSTRING "${line}" 0 64 hash)
    if(NOT EXISTS ${tree}/${file})
      list(APPEND found "removed ${file}")
    else()
      file(SHA256 ${tree}/${file} now)
      if(NOT now STREQUAL hash)
        list(APPEND found "changed ${file}")
      endif()
    endif()
  endforeach()
  file(GLOB_RECURSE present LIST_DIRECTORIES false RELATIVE ${tree} ${tree}/${prefix}*)
  list(FILTER present EXCLUDE REGEX "^build/") # (quicker than asking git of its thousands of files)
  set(added ${present})
  list(REMOVE_ITEM added ${copied})
  if(added) # what the build writes beside its folder (compile_commands.json), ignored by git as in the source
    execute_process(COMMAND git -C ${SOURCE} check-ignore --no-index -- ${added} OUTPUT_VARIABLE ignored)
    string(REPLACE "\n" ";" ignored "${ignored}")
    list(REMOVE_ITEM added ${ignored} "")
  endif()
  foreach(file IN LISTS added)
    list(APPEND found "added ${file}")
  endforeach()
  list(FILTER found EXCLUDE REGEX "^[a-z]+ (${allowed})")
  set(${result} ${found} PARENT_SCOPE)
  set(added ${added} PARENT_SCOPE)
endfunction()

# 3b. Adding lab N, its figures and references made, is its three folders and its number in
# course.toml (docs/instructors.md, "Adding a lab"): nothing else in the whole tree differs.
function(step_tree_unchanged)
  tree_changes("" "labs/${id}/|solutions/${id}/|framework/grader/labs/${id}/|course.toml$" outside)
  if(outside)
    string(REPLACE ";" "\n    " listed "${outside}")
    message(FATAL_ERROR "toy lab: adding lab ${N} changed the tree outside its three folders and course.toml:\n    ${listed}")
  endif()
  message(STATUS "toy lab: adding lab ${N} changed its three folders and course.toml, nothing else")
endfunction()

# 6. What the whole test changed under framework/, listed: files added in lab ${N}'s grading folder and
# the references `raylab references` made for it, nothing else added, changed or removed, once the
# lab was graded, reported and its hints reworded (and put back) too.
function(step_framework_unchanged)
  tree_changes("framework/" "framework/grader/labs/${id}/" outside)
  string(REPLACE ";" "\n    " listed "${added}")
  message(STATUS "toy lab: framework/ files added by lab ${N}:\n    ${listed}")
  if(outside)
    string(REPLACE ";" "\n    " listed "${outside}")
    message(FATAL_ERROR "toy lab: adding lab ${N} changed framework/ outside its grading folder:\n    ${listed}")
  endif()
  foreach(file checks.cpp probes.cpp probes.h messages.en.toml messages.fr.toml)
    if(NOT EXISTS ${tree}/framework/grader/labs/${id}/${file})
      message(FATAL_ERROR "toy lab: lab ${N}'s grading folder has no ${file}")
    endif()
  endforeach()
  message(STATUS "toy lab: lab ${N} built, rendered, graded and reported; framework/ changed only in lab ${N}'s grading folder")
endfunction()

run_step()
