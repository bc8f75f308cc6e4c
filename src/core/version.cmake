# Writes core/version.h (OUT) from version.h.in (IN): PROJECT_VERSION and `git describe --tags
# --always --dirty` of SOURCE_DIR now ("" when it is not a Git checkout or GIT_EXECUTABLE is
# empty). Run by CMake at configure time (included) and before every build (cmake -P: a commit
# since the configure is then what --version and results.nc say); configure_file leaves OUT
# untouched when its text is the same, so nothing recompiles for it then.
set(CABLEFILM_GIT_DESCRIBE "")
if(GIT_EXECUTABLE)
  execute_process(COMMAND ${GIT_EXECUTABLE} describe --tags --always --dirty
                  WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE git_status
                  OUTPUT_VARIABLE CABLEFILM_GIT_DESCRIBE OUTPUT_STRIP_TRAILING_WHITESPACE
                  ERROR_QUIET)
  if(NOT git_status EQUAL 0)
    set(CABLEFILM_GIT_DESCRIBE "")
  endif()
endif()
configure_file(${IN} ${OUT} @ONLY)
