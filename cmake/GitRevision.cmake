# Writes OUTPUT from INPUT with @LPV_GIT_REVISION@ set to
# `git describe --always --dirty` of SOURCE_DIR, or "unknown" when SOURCE_DIR
# is not the top of a git checkout (a source tarball, no git installed).
# Run at build time by app/common (cmake -P); configure_file leaves OUTPUT
# untouched when nothing changed.
set(LPV_GIT_REVISION "unknown")
if(GIT_EXECUTABLE)
  # No opportunistic index refresh: a build must not take the index lock a
  # concurrent `git commit` needs.
  set(ENV{GIT_OPTIONAL_LOCKS} 0)
  execute_process(COMMAND "${GIT_EXECUTABLE}" rev-parse --show-toplevel
    WORKING_DIRECTORY "${SOURCE_DIR}" OUTPUT_VARIABLE top RESULT_VARIABLE rc
    OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  # A tarball unpacked inside some other checkout must not report that one's revision.
  if(rc EQUAL 0 AND top)
    file(REAL_PATH "${top}" top)
    file(REAL_PATH "${SOURCE_DIR}" source)
    if(top STREQUAL source)
      execute_process(COMMAND "${GIT_EXECUTABLE}" describe --always --dirty
        WORKING_DIRECTORY "${SOURCE_DIR}" OUTPUT_VARIABLE described RESULT_VARIABLE rc
        OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
      if(rc EQUAL 0 AND described)
        set(LPV_GIT_REVISION "${described}")
      endif()
    endif()
  endif()
endif()
configure_file("${INPUT}" "${OUTPUT}" @ONLY)
