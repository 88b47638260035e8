# SPDX-License-Identifier: MIT
# The library's modules are layered: a file of libgsph/MODULE/ may include its own module's
# headers and those of modules on a lower layer, never a module on its own layer or above. The
# build runs this check (libgsph/CMakeLists.txt) whenever a library file changes, so an upward
# include fails the build with one line naming the file, the include and both layers.
#   cmake -DSOURCE_DIR=<libgsph> [-DSTAMP=<file>] -P check_module_layers.cmake
# Files directly in libgsph/ (the composition point, simulation.*) sit on the top layer.
set(GSPH_MODULE_LAYERS
    core=0
    kernel=1
    particles=2  # the reference configuration, its pair list, the state
    neighbors=3 overset=3 io=3
    distributed=4  # the split of a run over processes: needs the blocks and the state
    spaces=4 kinematics=4
    materials=5 reference=5
    failure=6
    forces=7
    boundary=8 contact=8
    integrator=9)
set(top_layer 10)

foreach(entry IN LISTS GSPH_MODULE_LAYERS)
  string(REPLACE "=" ";" pair "${entry}")
  list(GET pair 0 module)
  list(GET pair 1 layer)
  set(layer_of_${module} ${layer})
endforeach()

if(NOT SOURCE_DIR)
  message(FATAL_ERROR "check_module_layers: set -DSOURCE_DIR=<libgsph>")
endif()
get_filename_component(SOURCE_DIR "${SOURCE_DIR}" ABSOLUTE)
file(GLOB_RECURSE files RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/*.hpp ${SOURCE_DIR}/*.cpp
     ${SOURCE_DIR}/*.hpp.in)
set(faults "")
foreach(file IN LISTS files)
  if(file MATCHES "^([a-z_0-9]+)/")
    set(module ${CMAKE_MATCH_1})
    if(NOT DEFINED layer_of_${module})
      string(APPEND faults "libgsph/${file}: module '${module}' has no layer in cmake/check_module_layers.cmake\n")
      continue()
    endif()
    set(own ${layer_of_${module}})
  else()
    set(module "")
    set(own ${top_layer})
  endif()
  file(STRINGS ${SOURCE_DIR}/${file} includes REGEX "^#include \"[a-z_0-9]+/")
  foreach(line IN LISTS includes)
    string(REGEX MATCH "^#include \"([a-z_0-9]+)/([^\"]*)\"" _ "${line}")
    set(target ${CMAKE_MATCH_1})
    if(target STREQUAL module OR NOT DEFINED layer_of_${target})
      continue()  # its own module, or not a library module (a generated header's folder)
    endif()
    if(NOT layer_of_${target} LESS own)
      string(APPEND faults "libgsph/${file}: includes ${target}/${CMAKE_MATCH_2}, a module on layer ${layer_of_${target}}, not below its own (${own}; cmake/check_module_layers.cmake)\n")
    endif()
  endforeach()
endforeach()
if(faults)
  string(STRIP "${faults}" faults)
  message(NOTICE "${faults}")  # one unwrapped line per fault
  message(FATAL_ERROR "libgsph: an include crosses the module layers (above)")
endif()
if(STAMP)
  file(WRITE ${STAMP} "module layers checked\n")
endif()
