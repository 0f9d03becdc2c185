# Finds the Debian bookworm packages that scripts/install-deps.sh installs, and works around
# their known packaging faults (see docs/architecture.md, "Dependencies").

find_package(PkgConfig REQUIRED)
find_package(Threads REQUIRED)
find_package(TBB REQUIRED)
find_package(embree 3.13 REQUIRED)
find_package(fmt REQUIRED)
find_package(glm REQUIRED)
find_package(nlohmann_json REQUIRED)
find_package(CLI11 REQUIRED)
find_package(tomlplusplus REQUIRED)
find_package(tinyobjloader REQUIRED)
find_package(SQLite3 REQUIRED)
# Headless OpenGL through GLVND: libOpenGL (no GLX) and libEGL.
set(OpenGL_GL_PREFERENCE GLVND)
find_package(OpenGL REQUIRED COMPONENTS OpenGL EGL)
pkg_check_modules(XXHASH REQUIRED IMPORTED_TARGET libxxhash)

# OpenImageIO's exported target names /usr/include/opencv4, which Debian does not install unless
# OpenCV is present: drop it from the interface include directories.
find_package(OpenImageIO REQUIRED)
foreach(target OpenImageIO::OpenImageIO OpenImageIO::OpenImageIO_Util)
  if(TARGET ${target})
    foreach(property INTERFACE_INCLUDE_DIRECTORIES INTERFACE_SYSTEM_INCLUDE_DIRECTORIES)
      get_target_property(dirs ${target} ${property})
      if(dirs)
        list(FILTER dirs EXCLUDE REGEX "opencv4")
        set_target_properties(${target} PROPERTIES ${property} "${dirs}")
      endif()
    endforeach()
  endif()
endforeach()

# OpenColorIO's CMake config references targets Debian does not ship: use pkg-config instead.
pkg_check_modules(OCIO REQUIRED IMPORTED_TARGET OpenColorIO>=2.1)
add_library(gib::OpenColorIO ALIAS PkgConfig::OCIO)

if(GIB_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(GIB_BUILD_BENCH)
  # Debian's package warns that the library is a debug build; that does not affect our timings.
  find_package(benchmark REQUIRED)
endif()
