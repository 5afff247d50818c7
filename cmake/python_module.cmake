# The Python package grainlab, assembled in build/python/grainlab/: the pure
# Python sources of python/grainlab/ (with the subpackage report/) copied
# there, the compiled extension grainlab._grainlab (src/python/module.cpp)
# beside them. So
#   PYTHONPATH=build/python /usr/bin/python3 -c "import grainlab"
# works with nothing installed. Included by CMakeLists.txt when pybind11 is found.
set(python_package_dir ${CMAKE_BINARY_DIR}/python/grainlab)

file(GLOB_RECURSE python_sources CONFIGURE_DEPENDS RELATIVE ${CMAKE_SOURCE_DIR}/python/grainlab
     ${CMAKE_SOURCE_DIR}/python/grainlab/*.py ${CMAKE_SOURCE_DIR}/python/grainlab/*.pyi
     ${CMAKE_SOURCE_DIR}/python/grainlab/py.typed)
list(FILTER python_sources EXCLUDE REGEX "__pycache__")
set(python_copies)
foreach(name ${python_sources})  # name: relative to python/grainlab (report/cli.py for the subpackage)
  add_custom_command(OUTPUT ${python_package_dir}/${name}
                     COMMAND ${CMAKE_COMMAND} -E copy_if_different ${CMAKE_SOURCE_DIR}/python/grainlab/${name}
                             ${python_package_dir}/${name}
                     DEPENDS ${CMAKE_SOURCE_DIR}/python/grainlab/${name}
                     VERBATIM)
  list(APPEND python_copies ${python_package_dir}/${name})
endforeach()
add_custom_target(python_sources ALL DEPENDS ${python_copies})

# NO_EXTRAS: no link-time optimisation nor stripping (the module only binds;
# the engine's code comes from the static libraries, compiled as for the CLI).
pybind11_add_module(_grainlab MODULE NO_EXTRAS ${CMAKE_SOURCE_DIR}/src/python/module.cpp)
target_link_libraries(_grainlab PRIVATE grainlab_apps)
set_target_properties(_grainlab PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${python_package_dir})
add_dependencies(_grainlab python_sources)

# The Python tests (tests/python, pytest) and the example notebook's run; the
# sweeps on Dask (tests/python/test_sweep*.py: real LocalClusters running this
# build's grainlab) are a test of their own, so ctest -j runs the two side by side.
set(python_test_env "PYTHONPATH=${CMAKE_BINARY_DIR}/python;GRAINLAB=$<TARGET_FILE:grainlab>;GRAINLAB_SOURCE=${CMAKE_SOURCE_DIR};OMP_NUM_THREADS=1;PYTHONDONTWRITEBYTECODE=1")
add_test(NAME python COMMAND ${Python3_EXECUTABLE} -m pytest -q -p no:cacheprovider ${CMAKE_SOURCE_DIR}/tests/python
         -k "not sweep")
add_test(NAME python_sweep COMMAND ${Python3_EXECUTABLE} -m pytest -q -p no:cacheprovider
         ${CMAKE_SOURCE_DIR}/tests/python -k sweep)
set_tests_properties(python python_sweep PROPERTIES ENVIRONMENT "${python_test_env}")
set_tests_properties(python PROPERTIES COST 60)
set_tests_properties(python_sweep PROPERTIES COST 80)
