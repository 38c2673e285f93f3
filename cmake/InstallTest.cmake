# The install as another project sees it (ctest -L install): install this build into a fresh
# prefix, configure and build examples/ on its own with find_package(geartrib), run the examples
# on the installed data, and check that they compiled against the installed headers and that
# linking geartrib::io did not bring Ceres.
#   cmake -DBUILD_DIR=<build> -DSOURCE_DIR=<source> -DWORK_DIR=<scratch> -P cmake/InstallTest.cmake
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "InstallTest.cmake: -D${var}=... is required")
  endif()
endforeach()

set(prefix ${WORK_DIR}/prefix)
set(build ${WORK_DIR}/examples)
file(REMOVE_RECURSE ${WORK_DIR})

execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} OUTPUT_QUIET
                COMMAND_ERROR_IS_FATAL ANY)
foreach(f include/geartrib/gear/spur_pair.hpp include/geartrib/config/case_file.hpp
          share/geartrib/gears/m6z30.toml share/geartrib/materials/steel-45.toml share/geartrib/lubricants/mineral-vg220.toml
          lib/cmake/geartrib/geartribConfig.cmake lib/cmake/geartrib/geartribConfigVersion.cmake bin/geartrib
          lib/geartrib/geartrib-fit.so)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()

execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples -B ${build} -DCMAKE_PREFIX_PATH=${prefix}
                        -DCMAKE_BUILD_TYPE=Release -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
                OUTPUT_QUIET COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND ${CMAKE_COMMAND} --build ${build} --parallel 2 OUTPUT_QUIET COMMAND_ERROR_IS_FATAL ANY)

# Compiled against <prefix>/include/geartrib, not the source tree.
file(READ ${build}/compile_commands.json commands)
string(FIND "${commands}" "${prefix}/include/geartrib" installed_headers)
string(FIND "${commands}" "${SOURCE_DIR}/src" source_headers)
if(installed_headers EQUAL -1 OR NOT source_headers EQUAL -1)
  message(FATAL_ERROR "the examples did not compile against the installed headers:\n${commands}")
endif()
# geartrib::io does not link Ceres (only geartrib::fit does).
file(GLOB link_lines ${build}/CMakeFiles/*.dir/link.txt)
foreach(f ${link_lines})
  file(READ ${f} line)
  if(line MATCHES "ceres")
    message(FATAL_ERROR "${f} links Ceres: ${line}")
  endif()
endforeach()

# Each example runs on the installed data (share/geartrib) and prints its sanity line.
foreach(check "single_asperity:delta_c = 0.0746 nm" "mesh_position:Hertz p0 = 588 MPa" "custom_sweep:1000 +0.80 +120.7 +591 +0.3145 ")
  string(REPLACE ":" ";" check "${check}")
  list(GET check 0 example)
  list(GET check 1 expected)
  execute_process(COMMAND ${build}/${example} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "${expected}")
    message(FATAL_ERROR "${example} (exit ${rc}) did not print '${expected}':\n${out}${err}")
  endif()
  message(STATUS "${example}: ok")
endforeach()

execute_process(COMMAND ${prefix}/bin/geartrib --help OUTPUT_QUIET COMMAND_ERROR_IS_FATAL ANY)
# The fit command's module, loaded from <prefix>/lib/geartrib.
execute_process(COMMAND ${prefix}/bin/geartrib fit --list kogut-etsion OUTPUT_VARIABLE out ERROR_VARIABLE err
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0 OR NOT out MATCHES "load_coefficient_1")
  message(FATAL_ERROR "installed geartrib fit (exit ${rc}):\n${out}${err}")
endif()

# The Python module (when built: -DPYTHON=<interpreter> -DPYTHON_DIR=<its dist-packages under the
# prefix>): imported from the prefix, outside the source tree, it finds the installed default case.
if(PYTHON)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${prefix}/${PYTHON_DIR} ${PYTHON} -c
                          "import geartrib; print(geartrib.__file__); print(geartrib.default_case_file()); print('p0 %.0f MPa' % (geartrib.run(as_dict=True)['hertz_p0_Pa'].max() / 1e6))"
                  WORKING_DIRECTORY ${WORK_DIR} OUTPUT_VARIABLE out ERROR_VARIABLE err RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0 OR NOT out MATCHES "^${prefix}/${PYTHON_DIR}/geartrib/__init__.py\n${prefix}/share/geartrib/gears/m6z30.toml\np0 [0-9]+ MPa")
    message(FATAL_ERROR "installed Python module (exit ${rc}):\n${out}${err}")
  endif()
  message(STATUS "installed Python module: ok (${out})")
endif()
message(STATUS "installed geartrib and examples built against it: ok")
