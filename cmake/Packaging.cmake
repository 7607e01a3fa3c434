# Installation and the .deb (docs/operations.md, "Install").
#
#   cmake --install BUILD --prefix P     P/bin/scanfilter-*, P/etc/scanfilter/,
#                                        P/lib/systemd/system/, P/share/doc/scanfilter/ (README.md, docs/)
#   cpack --config BUILD/CPackConfig.cmake   scanfilter_<version>_<arch>.deb (prefix /usr,
#                                        configs in /etc/scanfilter, saved maps in /var/lib/scanfilter)
#
# The build tree's binaries (build/services/jump_filter, ...) read the source
# tree's config/ and deploy/ as before. The installed ones are twins linked
# from the same object files with the installed default paths
# (common/dds/src/installed_paths.cpp): they find their configs from where
# they are, so any prefix chosen at install time works, and they carry no
# path of the source tree.
include(GNUInstallDirs)

set(SCANFILTER_INSTALLED_BIN_DIR ${CMAKE_BINARY_DIR}/installed-bin)

# The build-tree programs installed under another name (TARGET:NAME).
set(SCANFILTER_INSTALLED_TWINS)
if(SCANFILTER_BUILD_SERVICES)
  set(SCANFILTER_INSTALLED_TWINS
    scan_ingest:scanfilter-scan-ingest jump_filter:scanfilter-jump-filter
    penetration_filter:scanfilter-penetration-filter map_publisher:scanfilter-map-publisher
    scan_recorder:scanfilter-scan-recorder ros_scan_publisher:scanfilter-ros-scan-publisher)
endif()

# Before anything is copied: every program is built. scripts/demo.sh builds
# only what it runs, and CMake's own "file INSTALL cannot find" names a
# file in the build tree, not what to run.
set(installed_programs $<TARGET_FILE:scanfilter>)
foreach(twin ${SCANFILTER_INSTALLED_TWINS})
  string(REGEX REPLACE "^.*:" "" name ${twin})
  list(APPEND installed_programs $<TARGET_FILE:${name}>)
endforeach()
install(CODE "
  foreach(program ${installed_programs})
    if(NOT EXISTS \"\${program}\")
      message(FATAL_ERROR \"\${program} is not built: run `bash scripts/build.sh` (every program) before installing\")
    endif()
  endforeach()")

# TARGET (a build-tree executable) installed as NAME.
function(scanfilter_installed_twin target name)
  get_target_property(libs ${target} LINK_LIBRARIES)
  add_executable(${name} $<TARGET_OBJECTS:${target}>)
  target_link_libraries(${name} PRIVATE ${libs})
  set_target_properties(${name} PROPERTIES
    SCANFILTER_INSTALLED ON LINKER_LANGUAGE CXX RUNTIME_OUTPUT_DIRECTORY ${SCANFILTER_INSTALLED_BIN_DIR})
  install(TARGETS ${name} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endfunction()

# Installed names: prefixed, so that they cannot collide with other
# packages' programs on a system.
install(TARGETS scanfilter RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(SCANFILTER_BUILD_SERVICES)
  foreach(twin ${SCANFILTER_INSTALLED_TWINS})
    string(REPLACE ":" ";" target_and_name ${twin})
    scanfilter_installed_twin(${target_and_name})
  endforeach()

  # The configs, the Fast DDS profiles and the systemd units, rewritten for
  # the prefix given at install time (cmake/install_layout.cmake).
  install(CODE "
    set(SCANFILTER_SOURCE_DIR \"${PROJECT_SOURCE_DIR}\")
    set(SCANFILTER_STAGING_DIR \"${CMAKE_BINARY_DIR}/install-staging\")
    set(SCANFILTER_VERSION \"${PROJECT_VERSION}\")
    set(SCANFILTER_BINDIR \"${CMAKE_INSTALL_BINDIR}\")
    set(SCANFILTER_SYSCONFDIR \"${CMAKE_INSTALL_SYSCONFDIR}\")
    set(SCANFILTER_LOCALSTATEDIR \"${CMAKE_INSTALL_LOCALSTATEDIR}\")
    set(SCANFILTER_DOCDIR \"${CMAKE_INSTALL_DATADIR}/doc/scanfilter\")
    include(\"${PROJECT_SOURCE_DIR}/cmake/install_layout.cmake\")")
endif()
if(SCANFILTER_BUILD_SERVICES)
  # The keystore maker (docs/operations.md, "DDS Security"), beside the
  # services it makes enclaves for.
  install(PROGRAMS deploy/security/make-keystore.sh DESTINATION ${CMAKE_INSTALL_BINDIR}
          RENAME scanfilter-make-keystore)
endif()
# The README and docs/ side by side, as in the source tree, so that the
# README's links to docs/ and the docs' links to each other and to their
# pictures hold where they are installed.
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/scanfilter)
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/scanfilter/docs)
# The Prometheus scrape config, alert rules and Grafana dashboard, for the
# operator to copy (docs/operations.md, "Monitoring and alerts").
install(DIRECTORY deploy/monitoring/ DESTINATION ${CMAKE_INSTALL_DATADIR}/scanfilter/monitoring)

# The .deb: prefix /usr, so configs go to /etc/scanfilter and saved maps to
# /var/lib/scanfilter (the same rule in install_layout.cmake and
# installed_paths.cpp). Maintainer scripts in deploy/debian/ create the
# service user (postinst) and remove it with the state on purge (postrm).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME scanfilter)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR scanfilter)
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "2D LiDAR scan filter (two-step jump and penetration filter) as Fast DDS services")
set(CPACK_PACKAGE_DESCRIPTION
    "scan_ingest, jump_filter, penetration_filter and map_publisher as systemd services (scanfilter.target), the scanfilter command-line tool, and the scan recorder and publisher.")
# DESTDIR staging with the real prefix: the install scripts see /usr, so the
# configs land in /etc and not /usr/etc.
set(CPACK_SET_DESTDIR ON)
set(CPACK_INSTALL_PREFIX /usr)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "scanfilter developers <scanfilter@localhost>")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# dpkg-shlibdeps finds the shared libraries (Fast DDS, yaml-cpp, ...);
# adduser is what postinst creates the service user with.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "adduser")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "openssl")  # scanfilter-make-keystore
# Every installed config is a conffile: kept on remove, an admin's edits kept
# on upgrade, deleted on purge.
set(SCANFILTER_CONFFILES "")
file(GLOB _configs RELATIVE ${PROJECT_SOURCE_DIR}/config CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/config/*.yaml)
file(GLOB _profiles RELATIVE ${PROJECT_SOURCE_DIR}/deploy CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/deploy/*.xml)
foreach(f IN LISTS _configs _profiles)
  string(APPEND SCANFILTER_CONFFILES "/etc/scanfilter/${f}\n")
endforeach()
file(WRITE ${CMAKE_BINARY_DIR}/debian/conffiles "${SCANFILTER_CONFFILES}")
foreach(script postinst prerm postrm)
  configure_file(${PROJECT_SOURCE_DIR}/deploy/debian/${script} ${CMAKE_BINARY_DIR}/debian/${script} COPYONLY)
endforeach()
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA
    ${CMAKE_BINARY_DIR}/debian/conffiles ${CMAKE_BINARY_DIR}/debian/postinst
    ${CMAKE_BINARY_DIR}/debian/prerm ${CMAKE_BINARY_DIR}/debian/postrm)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
include(CPack)
