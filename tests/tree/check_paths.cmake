# cmake -DSOURCE_DIR=<tree> [-DGIT_EXECUTABLE=<git>] -P check_paths.cmake
#
# The project stands on its own: no file of the tree may name a path outside it.
# Fails, listing file:line and the line, if a file contains
#   - a path up out of the checkout into a sibling `shared` folder (`..` then
#     `/shared`, either slash): data the tests need lives in tests/data/;
#   - an absolute path under /work, /root, /home or /Users (a workspace or a home
#     folder of some machine), where it starts a path: at the start of a line or
#     after a character that cannot be part of a path (blank, quote, `=`, `(`,
#     `:`, ...), so `build/work/x` or `${DIR}/work/x` are not matched;
#   - an absolute path under /tmp in a file that is not code or Markdown (results,
#     data, models, configuration): code and docs may name where temporary files
#     go, a results file naming the temporary folder of one run is a leak.
# /usr, /opt, /dev and the like are not matched: they name the system, not a
# machine's files.
#
# Files: with git, those `git ls-files` lists plus the untracked ones git does
# not ignore (so a new file fails before it is committed); without git (an
# exported tree), every file under SOURCE_DIR except build*/, out/ and .git/.
# The patterns below are written so this file does not match itself.
cmake_minimum_required(VERSION 3.20)
if(NOT SOURCE_DIR OR NOT IS_DIRECTORY "${SOURCE_DIR}")
  message(FATAL_ERROR "check_paths.cmake: -DSOURCE_DIR=<tree> is required")
endif()

set(boundary "(^|[ \t\"'`=(<>,;:|{*[])")
set(pattern_any "[.][.][/\\\\]shared([/\\\\\"'` \t]|$)|${boundary}/(wor[k]|roo[t]|hom[e]|User[s])/")
set(pattern_data "${boundary}/tm[p]/")
# Files where /tmp may appear: code and Markdown.
set(code_file "(\\.(c|h|cpp|hpp|py|sh|cmake|md)|(^|/)CMakeLists\\.txt)$")

set(files "")
set(listed FALSE)
if(GIT_EXECUTABLE AND EXISTS "${SOURCE_DIR}/.git")
  execute_process(COMMAND "${GIT_EXECUTABLE}" -c core.quotepath=off ls-files --cached --others
                          --exclude-standard
                  WORKING_DIRECTORY "${SOURCE_DIR}" RESULT_VARIABLE status OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(status EQUAL 0)
    string(REPLACE ";" "\\;" out "${out}")
    string(REPLACE "\n" ";" files "${out}")
    set(listed TRUE)
    set(how "git ls-files")
  endif()
endif()
if(NOT listed)
  file(GLOB_RECURSE files LIST_DIRECTORIES false RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/*")
  list(FILTER files EXCLUDE REGEX "^(build[^/]*|out|\\.git)/")
  set(how "walk")
endif()

set(found "")
set(count 0)
foreach(f IN LISTS files)
  if(f STREQUAL "" OR NOT EXISTS "${SOURCE_DIR}/${f}" OR IS_DIRECTORY "${SOURCE_DIR}/${f}")
    continue() # deleted in the work tree but still in the index, or a submodule
  endif()
  math(EXPR count "${count} + 1")
  set(pattern "${pattern_any}")
  if(NOT f MATCHES "${code_file}")
    set(pattern "${pattern}|${pattern_data}")
  endif()
  file(STRINGS "${SOURCE_DIR}/${f}" hits REGEX "${pattern}" ENCODING UTF-8)
  foreach(line IN LISTS hits)
    string(SUBSTRING "${line}" 0 160 line)
    string(APPEND found "  ${f}: ${line}\n")
  endforeach()
endforeach()

if(count EQUAL 0)
  message(FATAL_ERROR "check_paths.cmake: no files found under ${SOURCE_DIR} (${how})")
endif()
if(found)
  message(FATAL_ERROR "Paths outside the tree (tests/tree/check_paths.cmake says which are "
                      "forbidden; test data belongs in tests/data/):\n${found}")
endif()
message(STATUS "${count} files (${how}): no path outside the tree")
