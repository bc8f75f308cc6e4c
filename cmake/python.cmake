# The Python module `cablefilm` (src/python, pybind11): CABLEFILM_PYTHON is AUTO (the default:
# built when Python 3's headers and pybind11 are found, Debian's python3-dev and pybind11-dev),
# ON (both required) or OFF. Sets CABLEFILM_PYTHON_MODULE when it is built, and
# CABLEFILM_PYTHON_INSTALL_DIR, where `cmake --install` puts it under the prefix.
set(CABLEFILM_PYTHON AUTO CACHE STRING "Build the Python module: AUTO (if found), ON, OFF")
set_property(CACHE CABLEFILM_PYTHON PROPERTY STRINGS AUTO ON OFF)
set(CABLEFILM_PYTHON_MODULE OFF)
if(CABLEFILM_SANITIZE AND CABLEFILM_PYTHON STREQUAL "AUTO")
  # A sanitized module cannot be loaded into an unsanitized Python (the runtime must come
  # first): the sanitizer build tests the libraries, the optimised build the module.
  message(STATUS "cablefilm: no Python module in the sanitizer build")
elseif(NOT CABLEFILM_PYTHON STREQUAL "OFF")
  # The system's Python, whose numpy is Debian's python3-numpy, before another one first on the
  # PATH (pyenv, ...); -DPython3_EXECUTABLE=... chooses another.
  if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3)
  endif()
  if(CABLEFILM_PYTHON STREQUAL "ON")
    find_package(Python3 3.7 REQUIRED COMPONENTS Interpreter Development.Module)
    find_package(pybind11 2.6 CONFIG REQUIRED)
  else()
    find_package(Python3 3.7 COMPONENTS Interpreter Development.Module)
    if(Python3_FOUND)
      find_package(pybind11 2.6 CONFIG QUIET)
    endif()
  endif()
  if(Python3_FOUND AND pybind11_FOUND)
    set(CABLEFILM_PYTHON_MODULE ON)
    # The module links the program's static libraries into a shared object: every library is
    # then position-independent code.
    set(CMAKE_POSITION_INDEPENDENT_CODE ON)
    # lib/python3.11/dist-packages on Debian (its Python's folders are dist-packages): on the
    # sys.path of Debian's Python for the prefixes /usr and /usr/local. site-packages elsewhere.
    set(packages site-packages)
    if(Python3_SITEARCH MATCHES "dist-packages$")
      set(packages dist-packages)
    endif()
    set(python_dir "lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/${packages}")
    set(CABLEFILM_PYTHON_INSTALL_DIR "${python_dir}" CACHE STRING
        "Where the Python module goes, relative to the install prefix")
    message(STATUS "cablefilm: the Python module for ${Python3_EXECUTABLE} "
                   "(${Python3_VERSION}, pybind11 ${pybind11_VERSION}), installed into "
                   "<prefix>/${CABLEFILM_PYTHON_INSTALL_DIR}")
  else()
    message(STATUS "cablefilm: no Python module (needs python3-dev and pybind11-dev; "
                   "CABLEFILM_PYTHON=ON makes them required)")
  endif()
endif()
