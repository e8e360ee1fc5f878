# Optional dependency: SuiteSparse COLAMD (Debian: libsuitesparse-dev), a fill-reducing column
# order for the IRREF of the exact projection (include/.../internal/projection/column_ordering.h).
# Without it the package still builds and works; the IRREF then uses its own pivot rule alone,
# which fills in much more on per-corner seam systems (see the manual, "Performance").
option(SEAMLESS_SNAPPING_USE_COLAMD "Use SuiteSparse COLAMD to order the IRREF's pivots, when found" ON)
function(seamless_snapping_use_colamd target)
  if(NOT SEAMLESS_SNAPPING_USE_COLAMD)
    return()
  endif()
  find_path(SEAMLESS_SNAPPING_COLAMD_INCLUDE_DIR colamd.h PATH_SUFFIXES suitesparse)
  find_library(SEAMLESS_SNAPPING_COLAMD_LIBRARY colamd)
  if(SEAMLESS_SNAPPING_COLAMD_INCLUDE_DIR AND SEAMLESS_SNAPPING_COLAMD_LIBRARY)
    target_include_directories(${target} SYSTEM INTERFACE "${SEAMLESS_SNAPPING_COLAMD_INCLUDE_DIR}")
    target_link_libraries(${target} INTERFACE "${SEAMLESS_SNAPPING_COLAMD_LIBRARY}")
    target_compile_definitions(${target} INTERFACE CGAL_SEAMLESS_SNAPPING_HAS_COLAMD)
    message(STATUS "Seamless_snapping: COLAMD found (${SEAMLESS_SNAPPING_COLAMD_LIBRARY}): fill-reducing IRREF pivot order")
  else()
    message(STATUS "Seamless_snapping: COLAMD not found: IRREF without fill-reducing order (install libsuitesparse-dev)")
  endif()
endfunction()
