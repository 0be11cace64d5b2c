# Run at every build (the zcube_build_info target): writes OUT from cmake/build_info.cpp.in with the
# commit of SOURCE_DIR, so a report names the commit its binary was built from even when CMake was
# not re-run since. configure_file rewrites OUT only when its text changes: an unchanged commit
# recompiles nothing. Not a git checkout (a release tarball) or no git: "unknown".
set(ZC_COMMIT "unknown")
find_program(GIT_EXECUTABLE git)
if(GIT_EXECUTABLE AND EXISTS "${SOURCE_DIR}/.git")
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} rev-parse HEAD
                  OUTPUT_VARIABLE head OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET
                  RESULT_VARIABLE rc)
  if(rc EQUAL 0 AND head MATCHES "^[0-9a-f]+$")
    set(ZC_COMMIT ${head})
    # Tracked files edited since that commit: the binary is not the commit's.
    execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} status --porcelain
                            --untracked-files=no
                    OUTPUT_VARIABLE changes ERROR_QUIET RESULT_VARIABLE rc)
    if(rc EQUAL 0 AND NOT changes STREQUAL "")
      string(APPEND ZC_COMMIT "-dirty")
    endif()
  endif()
endif()
configure_file(${SOURCE_DIR}/cmake/build_info.cpp.in ${OUT} @ONLY)
