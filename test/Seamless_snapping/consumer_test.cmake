# CTest driver of `package_consumer`: installs the package from the build tree BUILD_DIR into a
# fresh prefix under WORK_DIR, then configures, builds and runs the project in SOURCE_DIR
# (consumer/) against that installation only.
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... [-DGENERATOR=...] [-DCGAL_DIR=...] [-DEigen3_DIR=...] -P consumer_test.cmake
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR)
  if(NOT ${var})
    message(FATAL_ERROR "consumer_test.cmake: ${var} is not set")
  endif()
endforeach()

function(run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${step} failed (${rc}):\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

set(prefix "${WORK_DIR}/prefix")
set(build "${WORK_DIR}/build")
file(REMOVE_RECURSE "${WORK_DIR}")          # from scratch: nothing left from an earlier run
file(MAKE_DIRECTORY "${WORK_DIR}")

run("install" "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
foreach(f include/CGAL/Seamless_snapping/Exact_constraint_projection.h
          share/cmake/Seamless_snapping/Seamless_snappingConfig.cmake
          share/cmake/Seamless_snapping/Seamless_snappingConfigVersion.cmake
          share/cmake/Seamless_snapping/Seamless_snappingTargets.cmake)
  if(NOT EXISTS "${prefix}/${f}")
    message(FATAL_ERROR "not installed: ${prefix}/${f}")
  endif()
endforeach()

set(configure_args -S "${SOURCE_DIR}" -B "${build}" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}")
if(GENERATOR)
  list(APPEND configure_args -G "${GENERATOR}")
endif()
foreach(var CGAL_DIR Eigen3_DIR CMAKE_CXX_COMPILER)
  if(${var})
    list(APPEND configure_args "-D${var}=${${var}}")
  endif()
endforeach()
run("configure" "${CMAKE_COMMAND}" ${configure_args})
string(FIND "${last_output}" "headers in ${prefix}/include" found)
if(found EQUAL -1)
  message(FATAL_ERROR "the consumer did not get the installed headers:\n${last_output}")
endif()
run("build" "${CMAKE_COMMAND}" --build "${build}")
find_program(consumer_exe consumer PATHS "${build}" "${build}/Release" NO_DEFAULT_PATH)
if(NOT consumer_exe)
  message(FATAL_ERROR "no consumer executable in ${build}")
endif()
run("run" "${consumer_exe}")
message("${last_output}")
