# One INTERFACE target carries the warning flags; every target of ours links it.
add_library(lpv_warnings INTERFACE)
target_compile_options(lpv_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align -Woverloaded-virtual -Wnull-dereference>)
