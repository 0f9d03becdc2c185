# The program version recorded in every output: the project version plus the git commit (with
# "-dirty" for uncommitted changes). Written at configure time and refreshed before every build by
# the gib_version target (cmake/WriteVersion.cmake says why).
set(GIB_VERSION_ARGS -DGIB_SOURCE_DIR=${PROJECT_SOURCE_DIR} -DGIB_BINARY_DIR=${PROJECT_BINARY_DIR}
                     -DGIB_PROJECT_VERSION=${PROJECT_VERSION})
execute_process(COMMAND ${CMAKE_COMMAND} ${GIB_VERSION_ARGS} -P ${PROJECT_SOURCE_DIR}/cmake/WriteVersion.cmake)
add_custom_target(gib_version
                  COMMAND ${CMAKE_COMMAND} ${GIB_VERSION_ARGS} -P ${PROJECT_SOURCE_DIR}/cmake/WriteVersion.cmake
                  BYPRODUCTS ${PROJECT_BINARY_DIR}/generated/gib/version.h
                  COMMENT "Recording the git commit in gib/version.h")
