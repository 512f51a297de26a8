# yamsc_add_model(TARGET <name> MODEL <file.mbd> LANGUAGE cpp|c|fmu
#                 [NAME <file base name>] [OPTIONS <yamsc options>...])
#
# Generates the model's code with yamsc at build time into
# ${CMAKE_CURRENT_BINARY_DIR}/yamsc_models/<name>/ (<NAME>.cpp + .hpp, or .c + .h;
# NAME defaults to the target's name) and makes a static library <name> of it whose
# users see the header. yamsc writes a depfile listing the model and every data
# file the model read (SID, ElastoDyn), so editing any of them regenerates the code.
# C++ models link yamsc::runtime (integrators, simulation driver); C models link
# only the math library: generated C is standalone, for controllers.
# LANGUAGE fmu: `yamsc fmu` writes <NAME>.fmu there instead (an FMI unit for other
# tools), built with the target (ALL); its path is the target's YAMSC_FMU property.
# OPTIONS go to yamsc as they are, e.g. OPTIONS --namespace turbine.
include_guard(GLOBAL)

# Policies are recorded when the function is defined. CMP0116: Ninja rewrites the
# depfile's paths relative to the build tree, so absolute paths match its outputs.
cmake_policy(PUSH)
cmake_policy(VERSION 3.20)
function(yamsc_add_model)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "TARGET;MODEL;LANGUAGE;NAME" "OPTIONS")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "yamsc_add_model: unknown arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_TARGET OR NOT arg_MODEL)
    message(FATAL_ERROR "yamsc_add_model: TARGET and MODEL are required")
  endif()
  if(NOT arg_LANGUAGE)
    set(arg_LANGUAGE cpp)
  endif()
  if(arg_LANGUAGE STREQUAL "cpp")
    set(source_ext cpp)
    set(header_ext hpp)
  elseif(arg_LANGUAGE STREQUAL "c")
    set(source_ext c)
    set(header_ext h)
  elseif(NOT arg_LANGUAGE STREQUAL "fmu")
    message(FATAL_ERROR "yamsc_add_model: LANGUAGE must be cpp, c or fmu, not '${arg_LANGUAGE}'")
  endif()
  if(NOT arg_NAME)
    set(arg_NAME ${arg_TARGET})
  endif()
  if(NOT TARGET yamsc::yamsc)
    message(FATAL_ERROR "yamsc_add_model: no yamsc::yamsc target (find_package(yamsc) first)")
  endif()

  get_filename_component(model ${arg_MODEL} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_SOURCE_DIR})
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/yamsc_models/${arg_TARGET})
  if(arg_LANGUAGE STREQUAL "fmu")
    set(unit ${dir}/${arg_NAME}.fmu)
    file(MAKE_DIRECTORY ${dir})
    add_custom_command(
      OUTPUT ${unit}
      COMMAND yamsc::yamsc fmu ${model} -o ${unit} --depfile ${dir}/${arg_NAME}.d ${arg_OPTIONS}
      DEPENDS ${model} yamsc::yamsc
      DEPFILE ${dir}/${arg_NAME}.d
      COMMENT "yamsc: packaging ${arg_NAME}.fmu from ${arg_MODEL}"
      VERBATIM)
    add_custom_target(${arg_TARGET} ALL DEPENDS ${unit})
    set_target_properties(${arg_TARGET} PROPERTIES YAMSC_FMU ${unit})
    return()
  endif()
  set(source ${dir}/${arg_NAME}.${source_ext})
  set(header ${dir}/${arg_NAME}.${header_ext})
  set(depfile ${dir}/${arg_NAME}.d)
  file(MAKE_DIRECTORY ${dir})

  add_custom_command(
    OUTPUT ${source} ${header}
    COMMAND yamsc::yamsc ${model} -o ${source} --header ${header} --lang ${arg_LANGUAGE}
            --depfile ${depfile} ${arg_OPTIONS}
    DEPENDS ${model} yamsc::yamsc
    DEPFILE ${depfile}
    COMMENT "yamsc: generating ${arg_NAME}.${source_ext} from ${arg_MODEL}"
    VERBATIM)

  add_library(${arg_TARGET} STATIC ${source} ${header})
  target_include_directories(${arg_TARGET} PUBLIC ${dir})
  if(arg_LANGUAGE STREQUAL "cpp")
    target_link_libraries(${arg_TARGET} PUBLIC yamsc::runtime)
    target_compile_features(${arg_TARGET} PUBLIC cxx_std_17)
  else()
    target_compile_features(${arg_TARGET} PUBLIC c_std_99)
    if(UNIX)
      target_link_libraries(${arg_TARGET} PUBLIC m)
    endif()
  endif()
endfunction()
cmake_policy(POP)
