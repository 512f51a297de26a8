# cmake -DWORK_DIR=<scratch folder> -P check_paths_self_test.cmake
#
# check_paths.cmake can fail: on small trees (no git, so the walk is used) with one
# forbidden path each it must fail and name the file; on a clean tree, on the
# allowed look-alikes, and on /tmp in code it must pass.
cmake_minimum_required(VERSION 3.20)
set(check ${CMAKE_CURRENT_LIST_DIR}/check_paths.cmake)

# The forbidden strings, assembled so this file does not contain them. (Contents
# below have no `;`: they travel through a CMake list.)
set(up "..")
set(k "k")
set(e "e")
set(p "p")
set(shared_path "${up}/shared/data/x.dat")
set(work_path "/wor${k}/main/build/yamsc")
set(home_path "/hom${e}/someone/data.csv")
set(tmp_path "/tm${p}/yamsc-bench-1/out.cpp")

# run_check(<name> <expect: PASS|FAIL> <file> <content> [<file> <content>]...)
function(run_check name expect)
  set(tree ${WORK_DIR}/${name})
  file(REMOVE_RECURSE ${tree})
  file(MAKE_DIRECTORY ${tree})
  file(WRITE ${tree}/README.md "A clean file.\n")
  # A build folder is never searched, whatever it holds.
  file(WRITE ${tree}/build-x/cache.txt "${work_path}\n")
  set(args ${ARGN})
  while(args)
    list(POP_FRONT args file content)
    file(WRITE ${tree}/${file} "${content}\n")
  endwhile()
  execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${tree} -P ${check}
                  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(expect STREQUAL "FAIL")
    if(status EQUAL 0)
      message(FATAL_ERROR "${name}: the check passed a tree it must reject:\n${out}")
    endif()
    if(NOT out MATCHES "${FILE_NAMED}")
      message(FATAL_ERROR "${name}: the check failed without naming ${FILE_NAMED}:\n${out}")
    endif()
  elseif(NOT status EQUAL 0)
    message(FATAL_ERROR "${name}: the check rejected a clean tree:\n${out}")
  endif()
  message(STATUS "${name}: ${expect} as expected")
endfunction()

set(FILE_NAMED "tests/a_test\\.cpp")
run_check(sibling_folder FAIL tests/a_test.cpp "const char* d = \"${shared_path}\"")
set(FILE_NAMED "bench/results/r\\.json")
run_check(workspace_path FAIL bench/results/r.json "{ \"yamsc\": \"${work_path}\" }")
set(FILE_NAMED "docs/x\\.md")
run_check(home_path FAIL docs/x.md "Data in `${home_path}`.")
set(FILE_NAMED "results\\.json")
run_check(tmp_in_results FAIL results.json "{ \"workdir\": \"${tmp_path}\" }")
run_check(clean PASS
          src/a.cpp "std::string cache = \"${tmp_path}\" // code may name temporary files"
          docs/b.md "Relative paths: `tests/data/nrel5mw/`, `build/work/out`, `\${DIR}/work/x`."
          CMakeLists.txt "set(WORK_DIR \${CMAKE_CURRENT_BINARY_DIR}/work)"
          c.txt "/usr/include/stdio.h, /opt/yamsc, /dev/null are the system's, not a machine's")
