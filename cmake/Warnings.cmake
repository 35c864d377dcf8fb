# One INTERFACE target carries the warning flags; every target of ours links it.
add_library(lpv_warnings INTERFACE)
target_compile_options(lpv_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wold-style-cast -Wcast-align -Woverloaded-virtual -Wnull-dereference>)
# MSVC (untested here, docs/portability.md): standard conformance and UTF-8 sources.
target_compile_options(lpv_warnings INTERFACE $<$<CXX_COMPILER_ID:MSVC>:/W4 /permissive- /utf-8 /Zc:__cplusplus>)
