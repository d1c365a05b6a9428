# Opens KIT/report.html in headless chromium (CHROMIUM) and reads the marker its own script writes on
# window load: every <img> complete with naturalWidth > 0 and no script error. Then the same page with
# one image made broken must be reported FAILED, so that the check cannot pass by not running.
#   cmake [-DCHROMIUM=/usr/bin/chromium] -DKIT=build/report-kit-test/reference -P check_in_browser.cmake
# Without chromium (looked for when the test runs) it says "skipped: needs chromium (INSTALL)", which
# ctest counts as skipped (tests/CMakeLists.txt).
if(NOT CHROMIUM)
  find_program(CHROMIUM NAMES chromium chromium-browser)
endif()
if(NOT CHROMIUM)
  message("skipped: needs chromium (${INSTALL})")
  return()
endif()

function(dump_dom html out_var)
  string(RANDOM LENGTH 12 suffix)
  set(profile "${KIT}/chromium-profile-${suffix}")
  file(REMOVE_RECURSE "${profile}")
  execute_process(
    COMMAND "${CHROMIUM}" --headless --no-sandbox --disable-gpu --disable-background-networking
            --disable-component-update --disable-sync --no-first-run --user-data-dir=${profile}
            --virtual-time-budget=10000 --dump-dom "file://${html}"
    OUTPUT_VARIABLE dom ERROR_VARIABLE errors RESULT_VARIABLE status TIMEOUT 120)
  file(REMOVE_RECURSE "${profile}")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "chromium failed (${status}) on ${html}:\n${errors}")
  endif()
  # The marker element's text (the script in the page also spells "image check", so not by that alone).
  string(REGEX MATCH "id=\"image-check\"[^>]*>([^<]*)<" found "${dom}")
  set(${out_var} "${CMAKE_MATCH_1}" PARENT_SCOPE)
endfunction()

if(NOT EXISTS "${KIT}/report.html")
  message(FATAL_ERROR "no ${KIT}/report.html: run the report_tests first")
endif()
file(READ "${KIT}/report.html" page)
string(REGEX MATCHALL "<img " tags "${page}")
list(LENGTH tags count)

dump_dom("${KIT}/report.html" marker)
message(STATUS "report.html: ${marker}")
if(NOT marker MATCHES "^image check: ok, ${count} images, broken: \\[\\], errors: \\[\\]$")
  message(FATAL_ERROR "report.html in chromium: expected 'image check: ok, ${count} images', got '${marker}'")
endif()

# The control: one image's file name changed to one that does not exist.
string(FIND "${page}" "<img src=\"" first)
if(first LESS 0)
  message(FATAL_ERROR "report.html has no <img src=...>")
endif()
math(EXPR at "${first} + 10")
string(SUBSTRING "${page}" 0 ${at} head)
string(SUBSTRING "${page}" ${at} -1 tail)
set(broken_page "${KIT}/report.broken-image-test.html")
file(WRITE "${broken_page}" "${head}missing-${tail}")
dump_dom("${broken_page}" broken_marker)
file(REMOVE "${broken_page}")
message(STATUS "with a broken image: ${broken_marker}")
if(NOT broken_marker MATCHES "^image check: FAILED, ${count} images, broken: \\[missing-")
  message(FATAL_ERROR "the check did not see a broken image: '${broken_marker}'")
endif()
