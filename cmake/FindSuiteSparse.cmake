# Finds SuiteSparse 5.x as packaged by Debian (libsuitesparse-dev ships no CMake config).
# Defines imported targets SuiteSparse::umfpack, SuiteSparse::cholmod, SuiteSparse::amd.
find_path(SuiteSparse_INCLUDE_DIR umfpack.h PATH_SUFFIXES suitesparse)
set(_ss_libs umfpack cholmod amd colamd camd ccolamd suitesparseconfig)
foreach(_lib IN LISTS _ss_libs)
  find_library(SuiteSparse_${_lib}_LIBRARY ${_lib})
  list(APPEND _ss_required SuiteSparse_${_lib}_LIBRARY)
endforeach()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SuiteSparse REQUIRED_VARS SuiteSparse_INCLUDE_DIR ${_ss_required})
if(SuiteSparse_FOUND)
  foreach(_lib IN LISTS _ss_libs)
    if(NOT TARGET SuiteSparse::${_lib})
      add_library(SuiteSparse::${_lib} UNKNOWN IMPORTED)
      set_target_properties(SuiteSparse::${_lib} PROPERTIES
        IMPORTED_LOCATION "${SuiteSparse_${_lib}_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${SuiteSparse_INCLUDE_DIR}")
    endif()
  endforeach()
  set_property(TARGET SuiteSparse::umfpack APPEND PROPERTY INTERFACE_LINK_LIBRARIES
    SuiteSparse::amd SuiteSparse::cholmod SuiteSparse::suitesparseconfig)
  set_property(TARGET SuiteSparse::cholmod APPEND PROPERTY INTERFACE_LINK_LIBRARIES
    SuiteSparse::amd SuiteSparse::colamd SuiteSparse::camd SuiteSparse::ccolamd SuiteSparse::suitesparseconfig)
endif()
