# The program version recorded in every output: the project version plus the git commit
# (with "-dirty" for uncommitted changes). Recomputed at configure time.
execute_process(COMMAND git rev-parse --short=12 HEAD WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
                OUTPUT_VARIABLE GIB_GIT_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT GIB_GIT_COMMIT)
  set(GIB_GIT_COMMIT "unknown")
endif()
execute_process(COMMAND git status --porcelain --untracked-files=no WORKING_DIRECTORY ${PROJECT_SOURCE_DIR}
                OUTPUT_VARIABLE GIB_GIT_STATUS OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(GIB_GIT_STATUS)
  set(GIB_GIT_DIRTY 1)
  set(GIB_GIT_DIRTY_SUFFIX "-dirty")
else()
  set(GIB_GIT_DIRTY 0)
  set(GIB_GIT_DIRTY_SUFFIX "")
endif()
configure_file(${PROJECT_SOURCE_DIR}/common/version.h.in ${PROJECT_BINARY_DIR}/generated/gib/version.h @ONLY)
