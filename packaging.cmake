# `cpack` in the build folder makes a .deb of what `cmake --install` puts in place (hdprior, its
# desktop entry and icon). Its Depends: the libraries hdprior links (dpkg-shlibdeps finds their
# packages) and the packages it loads by name, the runtime_packages line of scripts/install-deps.sh
# (the one list of dependencies).
file(STRINGS ${PROJECT_SOURCE_DIR}/scripts/install-deps.sh HDPRIOR_RUNTIME_LINE REGEX "^runtime_packages=\\(")
string(REGEX REPLACE "^runtime_packages=\\((.*)\\).*$" "\\1" HDPRIOR_RUNTIME_PACKAGES "${HDPRIOR_RUNTIME_LINE}")
string(STRIP "${HDPRIOR_RUNTIME_PACKAGES}" HDPRIOR_RUNTIME_PACKAGES)
string(REGEX REPLACE " +" ", " HDPRIOR_RUNTIME_PACKAGES "${HDPRIOR_RUNTIME_PACKAGES}")
if(NOT HDPRIOR_RUNTIME_PACKAGES)
  message(FATAL_ERROR "scripts/install-deps.sh has no runtime_packages=(...) line")
endif()
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/scripts/install-deps.sh)

# Packaging installs hdprior alone, so it should not build the tests and benchmarks of `all` first:
# build the hdprior target, then run cpack.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME hdprior)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "lidar trajectories and maps made consistent by HD-map priors")
set(CPACK_PACKAGE_CONTACT "hdprior developers <hdprior@localhost>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${HDPRIOR_RUNTIME_PACKAGES}")
include(CPack)
