# Third-party dependencies, all from Debian 12 packages (scripts/install-deps).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(OpenMP REQUIRED COMPONENTS CXX)
find_package(CLI11 REQUIRED)
find_package(nanoflann REQUIRED PATHS /usr/share/nanoflann/cmake)

# Serial HDF5 on purpose: the MPI build is also installed and must never be mixed in.
set(HDF5_PREFER_PARALLEL OFF)
find_package(HDF5 REQUIRED COMPONENTS C)

if(GSPH_MPI)
  find_package(MPI REQUIRED COMPONENTS CXX)
endif()

# gmsh ships no CMake config.
find_path(GMSH_INCLUDE_DIR gmsh.h REQUIRED)
find_library(GMSH_LIBRARY gmsh REQUIRED)
add_library(gmsh::gmsh UNKNOWN IMPORTED)
set_target_properties(gmsh::gmsh PROPERTIES IMPORTED_LOCATION "${GMSH_LIBRARY}"
                                            INTERFACE_INCLUDE_DIRECTORIES "${GMSH_INCLUDE_DIR}")

if(GSPH_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(GSPH_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
