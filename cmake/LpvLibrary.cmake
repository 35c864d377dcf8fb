# lpv_library(NAME [STATIC] SOURCES files... [PUBLIC libs...] [PRIVATE libs...]):
# one of our libraries laid out as STYLE.md asks: the target lpv_NAME and its
# alias lpv::NAME, public headers in include/, internals in src/, and our
# warnings (cmake/Warnings.cmake). Other properties follow the call.
function(lpv_library name)
  cmake_parse_arguments(L "STATIC" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  set(kind "")
  if(L_STATIC)
    set(kind STATIC)
  endif()
  add_library(lpv_${name} ${kind} ${L_SOURCES})
  add_library(lpv::${name} ALIAS lpv_${name})
  target_include_directories(lpv_${name} PUBLIC include PRIVATE src)
  target_link_libraries(lpv_${name} PUBLIC ${L_PUBLIC} PRIVATE ${L_PRIVATE} lpv_warnings)
endfunction()
