# formats/ stands below the compiler and the runtime: a format includes its own
# headers, those of other formats, compiler/diag (located errors), compiler/text
# (numbers as text; below diag) and libraries,
# never a compiler stage or the runtime. The include paths alone would not stop it
# (yamsc_diag exports compiler/), so the sources are read.
#   cmake -DFORMATS=<source>/formats [-DEXTRA=<a file that must fail>] -P check_formats.cmake
cmake_minimum_required(VERSION 3.20)
file(GLOB folders LIST_DIRECTORIES true ${FORMATS}/*)
set(allowed diag text)
foreach(f ${folders})
  if(IS_DIRECTORY ${f})
    get_filename_component(name ${f} NAME)
    list(APPEND allowed ${name})
  endif()
endforeach()
file(GLOB_RECURSE sources ${FORMATS}/*.cpp ${FORMATS}/*.hpp)
if(EXTRA)
  list(APPEND sources ${EXTRA})
endif()
set(bad "")
foreach(source ${sources})
  file(STRINGS ${source} includes REGEX "^#include \"")
  foreach(line ${includes})
    string(REGEX REPLACE "^#include \"([^\"/]*)/.*" "\\1" root "${line}")
    if(root STREQUAL line OR NOT root IN_LIST allowed)
      string(APPEND bad "\n  ${source}: ${line}")
    endif()
  endforeach()
endforeach()
if(bad)
  message(FATAL_ERROR "formats/ includes what stands above it:${bad}")
endif()
list(LENGTH sources count)
message(STATUS "${count} files of formats/ include only formats/, diag/ and text/")
