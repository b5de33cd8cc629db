# The Debian package (`cpack -G DEB` in the build directory, scripts/package.sh): the command, the
# shared library, the headers, the CMake and pkg-config files, under /usr. Its run-time
# dependencies come from dpkg-shlibdeps; Eigen's headers, which the public headers include, are
# a dependency of their own, and the Python module (built for the python3 of the build) needs
# that python3 and NumPy.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME shapeproc)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "libshapeproc developers <libshapeproc@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "statistical discrete-element texture synthesis: learn an arrangement, make new ones")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libeigen3-dev")
if(SHAPEPROC_BUILD_PYTHON)
  set(python_version ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR})
  math(EXPR python_next "${Python3_VERSION_MINOR} + 1")
  string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS ", python3 (>= ${python_version}), "
         "python3 (<< ${Python3_VERSION_MAJOR}.${python_next}), python3-numpy")
endif()
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
include(CPack)
