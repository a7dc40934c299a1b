# The Python module `lenslab` (docs/python.md): the C++ part `_lenslab` (pybind11, src/python/)
# and the package around it (python/lenslab/). Two ways to build it:
#   - this build tree (LENSLAB_PYTHON AUTO or ON): build/python/lenslab/ is an importable package
#     (PYTHONPATH=build/python), which the tests in tests/python/ import;
#   - `pip install .` (pyproject.toml, scikit-build-core, which sets SKBUILD): the same target,
#     installed with the bundled scenes into the wheel's lenslab/ folder.
# pybind11 rather than nanobind: Debian 12 packages it (pybind11-dev), so the build tree needs
# nothing from outside Debian, and its NumPy arrays can own our buffers without a copy.
if(LENSLAB_PYTHON STREQUAL "OFF")
  return()
endif()

# Debian's interpreter, which Debian's NumPy (python3-numpy) goes with, unless one is named.
if(NOT DEFINED Python_EXECUTABLE AND NOT SKBUILD AND EXISTS /usr/bin/python3)
  set(Python_EXECUTABLE /usr/bin/python3)
endif()
set(PYBIND11_FINDPYTHON ON)
if(LENSLAB_PYTHON STREQUAL "ON" OR SKBUILD)
  find_package(Python 3.9 REQUIRED COMPONENTS Interpreter Development.Module)
  find_package(pybind11 2.10 CONFIG REQUIRED)
else()
  find_package(Python 3.9 QUIET COMPONENTS Interpreter Development.Module)
  find_package(pybind11 2.10 CONFIG QUIET)
  if(NOT Python_FOUND OR NOT pybind11_FOUND)
    message(STATUS "Python module: not built (needs pybind11-dev and python3-dev: tools/install-deps.sh)")
    set(LENSLAB_PYTHON_BUILT OFF)
    return()
  endif()
endif()
set(LENSLAB_PYTHON_BUILT ON)
message(STATUS "Python module: built for ${Python_EXECUTABLE} (${Python_VERSION})")

pybind11_add_module(_lenslab
  src/python/Module.cpp
  src/python/SceneBinding.cpp
  src/python/CameraBinding.cpp
  src/python/RendererBinding.cpp
  src/python/FileBinding.cpp
  src/python/SequenceBinding.cpp
)
target_link_libraries(_lenslab PRIVATE lenslab_frame lenslab_render lenslab_raycast lenslab_plan lenslab_io
  lenslab_warnings)

set(LENSLAB_PYTHON_SOURCES __init__.py _camera.py _frame.py _sequence.py)
if(SKBUILD)
  # The wheel: everything under site-packages/lenslab/ (pyproject.toml: wheel.install-dir).
  install(TARGETS _lenslab LIBRARY DESTINATION . COMPONENT python)
  list(TRANSFORM LENSLAB_PYTHON_SOURCES PREPEND python/lenslab/ OUTPUT_VARIABLE python_files)
  install(FILES ${python_files} DESTINATION . COMPONENT python)
  install(DIRECTORY assets/rows assets/occluder assets/grid assets/depth-range
          DESTINATION share/lenslab/assets COMPONENT python)
  install(FILES assets/README.md DESTINATION share/lenslab/assets COMPONENT python)
else()
  # The build tree's package: the module beside copies of the Python sources (configure_file
  # copies again when one changes).
  set(package_dir ${CMAKE_BINARY_DIR}/python/lenslab)
  set_target_properties(_lenslab PROPERTIES LIBRARY_OUTPUT_DIRECTORY ${package_dir})
  foreach(file IN LISTS LENSLAB_PYTHON_SOURCES)
    configure_file(python/lenslab/${file} ${package_dir}/${file} COPYONLY)
  endforeach()
endif()
