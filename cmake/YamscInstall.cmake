# `cmake --install` layout (docs/packaging.md):
#   bin/yamsc                              the compiler
#   include/yamsc/*.hpp, lib/libyamsc_runtime.a   the runtime generated C++ links against
#   lib/cmake/yamsc/                       find_package(yamsc): yamsc::yamsc, yamsc::runtime,
#                                          yamsc_add_model()
#   lib/pkgconfig/yamsc.pc                 the same for builds without CMake
# Every path is relative to the prefix, so an installed tree can be moved.
include(CMakePackageConfigHelpers)

set(YAMSC_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/yamsc)

# yamsc_runtime links yamsc_warnings privately; a static library's private links
# travel with it (as link-only), so the export set must hold that target too. It
# carries only link options (the sanitizers, when YAMSC_SANITIZE is on).
set_target_properties(yamsc_warnings PROPERTIES EXPORT_NAME build_flags)
install(TARGETS yamsc_warnings EXPORT yamscTargets)

install(EXPORT yamscTargets NAMESPACE yamsc:: DESTINATION ${YAMSC_INSTALL_CMAKEDIR})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/yamscConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/yamscConfig.cmake
                              INSTALL_DESTINATION ${YAMSC_INSTALL_CMAKEDIR})
# 0.x: minor versions may break the generated interface.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/yamscConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/yamscConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/yamscConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/YamscAddModel.cmake
        DESTINATION ${YAMSC_INSTALL_CMAKEDIR})

# pkg-config: the prefix is found from the .pc file's own folder (${pcfiledir}).
set(YAMSC_PC_DIR ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
file(RELATIVE_PATH YAMSC_PC_TO_PREFIX /prefix/${YAMSC_PC_DIR} /prefix)
# The SUNDIALS libraries the runtime links, as -L<dir> -l<name>.
set(YAMSC_PC_LIBS "")
set(YAMSC_PC_LIB_DIRS "")
foreach(lib cvode nvecserial sunmatrixdense sunlinsoldense)
  get_target_property(location SUNDIALS::${lib}_shared LOCATION)
  get_filename_component(dir ${location} DIRECTORY)
  list(APPEND YAMSC_PC_LIB_DIRS ${dir})
  string(APPEND YAMSC_PC_LIBS " -lsundials_${lib}")
endforeach()
list(REMOVE_DUPLICATES YAMSC_PC_LIB_DIRS)
list(FILTER YAMSC_PC_LIB_DIRS EXCLUDE REGEX "^(/usr)?/lib(64)?(/${CMAKE_LIBRARY_ARCHITECTURE})?$")
foreach(dir ${YAMSC_PC_LIB_DIRS})
  string(PREPEND YAMSC_PC_LIBS " -L${dir}")
endforeach()
if(CMAKE_DL_LIBS)
  string(APPEND YAMSC_PC_LIBS " -l${CMAKE_DL_LIBS}")
endif()
if(YAMSC_SANITIZE)
  string(APPEND YAMSC_PC_LIBS " -fsanitize=address,undefined")
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/yamsc.pc.in ${CMAKE_CURRENT_BINARY_DIR}/yamsc.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/yamsc.pc DESTINATION ${YAMSC_PC_DIR})
