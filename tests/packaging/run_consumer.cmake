# cmake -DYAMSC_BUILD_DIR=.. -DCONSUMER_SOURCE_DIR=.. -DWORK_DIR=.. -DGENERATOR=..
#       -DC_COMPILER=.. -DCXX_COMPILER=.. -P run_consumer.cmake
# 1. `cmake --install` the yamsc build into WORK_DIR/prefix.
# 2. Configure, build and run the consumer project (find_package(yamsc)).
# 3. A second build does nothing; touching mast.sid regenerates the mast model
#    (and only it); changing its stiffness changes what the consumer computes.
# 4. Builds the same model without CMake, from pkg-config alone.
# 5. The pendulum packaged as an FMI unit by yamsc_add_model(.. LANGUAGE fmu): the
#    installed yamsc finds the unit's runtime in the prefix; the unit holds its
#    description and binary; it is packaged once.
cmake_minimum_required(VERSION 3.20)

set(prefix ${WORK_DIR}/prefix)
set(source ${WORK_DIR}/src)
set(build ${WORK_DIR}/build)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
# A copy of the project, so the test can edit its SID file.
file(COPY ${CONSUMER_SOURCE_DIR}/ DESTINATION ${source})

# Runs a command; fails the test with its output unless it exits 0. The output
# is left in `<out_var>`.
function(run_step what out_var)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}")
  endif()
  message(STATUS "${what}: ok")
  set(${out_var} "${out}" PARENT_SCOPE)
endfunction()

function(expect_match what text regex)
  if(NOT text MATCHES "${regex}")
    message(FATAL_ERROR "${what}: expected /${regex}/ in:\n${text}")
  endif()
endfunction()

function(expect_no_match what text regex)
  if(text MATCHES "${regex}")
    message(FATAL_ERROR "${what}: did not expect /${regex}/ in:\n${text}")
  endif()
endfunction()

run_step("install into ${prefix}" out ${CMAKE_COMMAND} --install ${YAMSC_BUILD_DIR} --prefix ${prefix})
foreach(f bin/yamsc include/yamsc/rk4.hpp)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "the install has no ${f}")
  endif()
endforeach()

run_step("configure the consumer" out
         ${CMAKE_COMMAND} -S ${source} -B ${build} -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release
         -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_C_COMPILER=${C_COMPILER}
         -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
run_step("build the consumer" out ${CMAKE_COMMAND} --build ${build})
expect_match("first build" "${out}" "yamsc: generating mast_model.cpp")
expect_match("first build" "${out}" "yamsc: generating pendulum.c")
expect_match("first build" "${out}" "yamsc: packaging pendulum.fmu")
set(unit_dir ${WORK_DIR}/unit)
file(MAKE_DIRECTORY ${unit_dir})
run_step("unzip pendulum.fmu" out ${CMAKE_COMMAND} -E chdir ${unit_dir} ${CMAKE_COMMAND} -E tar xf
         ${build}/yamsc_models/pendulum_unit/pendulum.fmu)
file(READ ${unit_dir}/modelDescription.xml description)
expect_match("the unit's description" "${description}" "fmiVersion=\"3.0\" modelName=\"pendulum\"")
expect_match("the unit's description" "${description}" "name=\"theta\"[^>]*unit=\"rad\"")
if(NOT EXISTS ${unit_dir}/binaries/x86_64-linux/pendulum.so)
  message(FATAL_ERROR "the unit has no binaries/x86_64-linux/pendulum.so")
endif()

run_step("run the C++ consumer" out ${build}/consumer)
expect_match("C++ consumer" "${out}" "omega 10.000000\n")
run_step("run the C consumer" out ${build}/consumer_c)
# sqrt(9.81 / 0.5)
expect_match("C consumer" "${out}" "omega 4.429447\n")

run_step("rebuild without changes" out ${CMAKE_COMMAND} --build ${build})
expect_no_match("rebuild without changes" "${out}" "yamsc: generating|yamsc: packaging")

# File times have a resolution of a second on some file systems.
execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)
file(TOUCH ${source}/mast.sid)
run_step("rebuild after touching mast.sid" out ${CMAKE_COMMAND} --build ${build})
expect_match("touched mast.sid" "${out}" "yamsc: generating mast_model.cpp")
expect_no_match("touched mast.sid" "${out}" "yamsc: generating pendulum.c|yamsc: packaging")

execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)
file(READ ${source}/mast.sid sid)
string(REPLACE "= 2500.0" "= 3600.0" sid "${sid}")
file(WRITE ${source}/mast.sid "${sid}")
run_step("rebuild after changing Ke in mast.sid" out ${CMAKE_COMMAND} --build ${build})
expect_match("changed mast.sid" "${out}" "yamsc: generating mast_model.cpp")
run_step("run the rebuilt consumer" out ${build}/consumer)
# sqrt(3600 / 25)
expect_match("rebuilt consumer" "${out}" "omega 12.000000\n")

# Without CMake: the compiler's path and the runtime's flags from pkg-config.
find_program(PKG_CONFIG pkg-config)
if(NOT PKG_CONFIG)
  message(STATUS "pkg-config not found: skipping the pkg-config build")
  return()
endif()
file(GLOB pc_dirs ${prefix}/lib*/pkgconfig ${prefix}/lib/*/pkgconfig)
string(REPLACE ";" ":" pc_path "${pc_dirs}")
set(ENV{PKG_CONFIG_PATH} "${pc_path}")
run_step("pkg-config --variable=yamsc" yamsc ${PKG_CONFIG} --variable=yamsc yamsc)
string(STRIP "${yamsc}" yamsc)
run_step("pkg-config --cflags --libs" flags ${PKG_CONFIG} --cflags --libs yamsc)
string(STRIP "${flags}" flags)
separate_arguments(flags UNIX_COMMAND "${flags}")
set(pc_dir ${WORK_DIR}/pkg-config)
file(MAKE_DIRECTORY ${pc_dir})
run_step("generate with ${yamsc}" out ${yamsc} ${source}/mast.mbd -o ${pc_dir}/mast_model.cpp
         --header ${pc_dir}/mast_model.hpp --namespace mast)
run_step("compile and link with pkg-config's flags" out
         ${CXX_COMPILER} -std=c++17 -O1 -I${pc_dir} ${source}/main.cpp ${pc_dir}/mast_model.cpp
         ${flags} -o ${pc_dir}/consumer)
run_step("run the pkg-config consumer" out ${pc_dir}/consumer)
expect_match("pkg-config consumer" "${out}" "omega 12.000000\n")
