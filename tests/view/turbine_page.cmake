# The NREL 5-MW (tower and rotor, 2 DOFs) as `sim --vtk` writes it and
# `yamsc view` draws it, in headless Chromium: the same checks as the
# pendulum's page, with the share of drawn pixels a turbine gives here
# (about 6.5 % of the view: the rotor's translucent disc, tower and nacelle).
# -DYAMSC -DSOURCE -DOUT -DNODE -DNODE_MODULES -DCHROMIUM
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${YAMSC} sim ${SOURCE}/models/nrel5mw_land_2dof.mbd --tmax 5 --dt 0.01
                        --ic "q=1,psi'=1.2671" --vtk ${OUT}/run
                RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "yamsc sim --vtk failed (${status}): ${err}")
endif()
execute_process(COMMAND ${YAMSC} view ${OUT}/run -o ${OUT}/turbine.html
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "yamsc view failed (${status}): ${err}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env YAMSC_NODE_MODULES=${NODE_MODULES}
                        CHROMIUM=${CHROMIUM}
                        ${NODE} ${SOURCE}/tests/view/browser_test.mjs ${OUT}/turbine.html
                        ${OUT}/screenshot.png 0.02 0.3
                RESULT_VARIABLE status)
if(status EQUAL 77)
  message(STATUS "skipped")
elseif(NOT status EQUAL 0)
  message(FATAL_ERROR "the turbine's page failed in the browser (${status})")
endif()
