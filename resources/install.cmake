# What `cmake --install` puts beside the programs (each program installs itself in its
# app/<program>.cmake; the presets in core/profile), and the Debian package CPack builds from
# it (scripts/package). Paths follow GNUInstallDirs.

# Serial access for the usual USB-UART chips of ESP32 boards. udev reads /usr/lib/udev/rules.d
# (a prefix of /usr); other prefixes may set the folder (docs/user-guide.md).
set(HATPIC_UDEV_RULES_DIR "lib/udev/rules.d" CACHE STRING
    "Where the udev rule is installed, relative to the prefix or absolute")
install(FILES ${PROJECT_SOURCE_DIR}/resources/udev/60-hatpic-serial.rules
        DESTINATION ${HATPIC_UDEV_RULES_DIR})

# The documentation: README and docs/ (Markdown and the screenshots they show).
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
file(GLOB _hatpic_docs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/*.md
     ${PROJECT_SOURCE_DIR}/docs/*.png)
install(FILES ${_hatpic_docs} DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The Debian package. Its Depends are found by dpkg-shlibdeps from the installed programs'
# shared libraries (Qt 6, QCustomPlot, Cyclone DDS when the bridge is built), so they are
# exactly the Debian 12 runtime packages this build links against (libqt6gui6 also holds the
# xcb platform plugin, so nothing more is needed to open the window).
set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "hatpic-tuner")
set(CPACK_PACKAGE_VENDOR "HATPIC")
# Debian requires a Maintainer ("Name <email>"); whoever publishes a package sets theirs.
set(HATPIC_PACKAGE_MAINTAINER "HATPIC Tuner developers <hatpic@localhost>" CACHE STRING
    "The .deb's Maintainer field")
set(CPACK_PACKAGE_CONTACT "${HATPIC_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_INSTALL_DIRECTORY "/usr")
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_STRIP_FILES ON)
include(CPack)
