# Writes generated/gib/version.h: the project version plus the git commit of the source tree
# (with "-dirty" for uncommitted changes to tracked files). Run at configure time and again before
# every build (target gib_version), so that a binary built after `git checkout` or a commit, as
# `git bisect` does, records the commit it was built from. configure_file leaves the header alone
# when nothing changed, so an unchanged tree rebuilds nothing.
# Inputs: GIB_SOURCE_DIR, GIB_BINARY_DIR, GIB_PROJECT_VERSION.
execute_process(COMMAND git rev-parse --short=12 HEAD WORKING_DIRECTORY ${GIB_SOURCE_DIR}
                OUTPUT_VARIABLE GIB_GIT_COMMIT OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT GIB_GIT_COMMIT)
  set(GIB_GIT_COMMIT "unknown")
endif()
execute_process(COMMAND git status --porcelain --untracked-files=no WORKING_DIRECTORY ${GIB_SOURCE_DIR}
                OUTPUT_VARIABLE GIB_GIT_STATUS OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(GIB_GIT_STATUS)
  set(GIB_GIT_DIRTY 1)
  set(GIB_GIT_DIRTY_SUFFIX "-dirty")
else()
  set(GIB_GIT_DIRTY 0)
  set(GIB_GIT_DIRTY_SUFFIX "")
endif()
set(PROJECT_VERSION ${GIB_PROJECT_VERSION})
configure_file(${GIB_SOURCE_DIR}/common/version.h.in ${GIB_BINARY_DIR}/generated/gib/version.h @ONLY)
