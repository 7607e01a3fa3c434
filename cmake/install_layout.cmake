# Runs at install time (cmake --install, cpack), from cmake/Packaging.cmake:
# installs the services' configs, the Fast DDS profiles and the systemd units
# for the prefix given then (CMAKE_INSTALL_PREFIX here is the install-time
# prefix). Where things go, the same rule as GNUInstallDirs and
# common/dds/src/installed_paths.cpp:
#   prefix /usr:  /etc/scanfilter, /var/lib/scanfilter
#   prefix P:     P/etc/scanfilter, P/var/lib/scanfilter
# Set by the caller: SCANFILTER_SOURCE_DIR, SCANFILTER_STAGING_DIR,
# SCANFILTER_VERSION and the GNUInstallDirs relative dirs SCANFILTER_BINDIR,
# SCANFILTER_SYSCONFDIR, SCANFILTER_LOCALSTATEDIR, SCANFILTER_DOCDIR.
cmake_policy(PUSH)
cmake_policy(VERSION 3.25)
set(prefix "${CMAKE_INSTALL_PREFIX}")
if(prefix STREQUAL "/usr")
  set(SCANFILTER_CONFDIR "/etc/scanfilter")
  set(SCANFILTER_STATEDIR "/var/lib/scanfilter")
else()
  set(SCANFILTER_CONFDIR "${prefix}/${SCANFILTER_SYSCONFDIR}/scanfilter")
  set(SCANFILTER_STATEDIR "${prefix}/${SCANFILTER_LOCALSTATEDIR}/lib/scanfilter")
endif()
set(SCANFILTER_BINDIR "${prefix}/${SCANFILTER_BINDIR}")
set(SCANFILTER_DOCDIR "${prefix}/${SCANFILTER_DOCDIR}")
# One staging directory per destination: a cpack run and a prefix install
# may run at the same time.
string(MD5 destination_hash "$ENV{DESTDIR}|${prefix}")
set(staging "${SCANFILTER_STAGING_DIR}/${destination_hash}")
file(REMOVE_RECURSE "${staging}")
file(MAKE_DIRECTORY "${staging}/config" "${staging}/systemd")

# In TEXT (read from FILE), OLD must occur exactly once: it becomes NEW. A
# config that changed under this script fails the install loudly instead of
# installing something unintended.
function(replace_once text_var old new file)
  string(FIND "${${text_var}}" "${old}" first)
  string(FIND "${${text_var}}" "${old}" last REVERSE)
  if(first EQUAL -1 OR NOT first EQUAL last)
    message(FATAL_ERROR "${file}: expected \"${old}\" exactly once (cmake/install_layout.cmake rewrites it)")
  endif()
  string(REPLACE "${old}" "${new}" replaced "${${text_var}}")
  set(${text_var} "${replaced}" PARENT_SCOPE)
endfunction()

# The profiles (deploy/*.xml) are installed next to the configs, so a
# config's "../deploy/NAME" becomes "NAME".
file(GLOB profiles RELATIVE "${SCANFILTER_SOURCE_DIR}/deploy" "${SCANFILTER_SOURCE_DIR}/deploy/*.xml")
file(GLOB configs RELATIVE "${SCANFILTER_SOURCE_DIR}/config" "${SCANFILTER_SOURCE_DIR}/config/*.yaml")
foreach(name IN LISTS configs)
  set(source "${SCANFILTER_SOURCE_DIR}/config/${name}")
  file(READ "${source}" text)
  string(REGEX MATCHALL "\\.\\./deploy/[^ \t\r\n#\"']+" references "${text}")
  foreach(reference IN LISTS references)
    string(REPLACE "../deploy/" "" target "${reference}")
    if(NOT target IN_LIST profiles)
      message(FATAL_ERROR "config/${name} refers to ${reference}, which is not installed (only deploy/*.xml is)")
    endif()
  endforeach()
  string(REPLACE "../deploy/" "" text "${text}")
  set(changes "Fast DDS profiles from this directory")
  if(name STREQUAL "map_publisher.yaml")
    # A service's map outlives a restart: saved in its state directory
    # (the units' StateDirectory) and read back on start.
    replace_once(text "save_path: \"\"" "save_path: ${SCANFILTER_STATEDIR}/map" "${source}")
    replace_once(text "load_on_start: false" "load_on_start: true " "${source}")
    string(APPEND changes "; the map saved to and continued from ${SCANFILTER_STATEDIR}/map")
  elseif(name STREQUAL "scan_ingest.yaml")
    # As a system service the source is the robot's driver.
    replace_once(text "kind: simulator  " "kind: live       " "${source}")
    string(APPEND changes "; source.kind live (the robot's driver)")
  endif()
  file(WRITE "${staging}/config/${name}"
       "# Installed by scanfilter ${SCANFILTER_VERSION} from config/${name}; differs from it in:\n"
       "# ${changes}.\n${text}")
endforeach()
list(TRANSFORM profiles PREPEND "${SCANFILTER_SOURCE_DIR}/deploy/")
file(GLOB staged_configs "${staging}/config/*.yaml")
file(INSTALL DESTINATION "${SCANFILTER_CONFDIR}" TYPE FILE FILES ${staged_configs} ${profiles})

# The units (deploy/systemd/*.in) with this prefix's paths.
file(GLOB units "${SCANFILTER_SOURCE_DIR}/deploy/systemd/*.in")
foreach(unit IN LISTS units)
  get_filename_component(name "${unit}" NAME)
  string(REGEX REPLACE "\\.in$" "" name "${name}")
  file(READ "${unit}" text)
  string(CONFIGURE "${text}" text @ONLY)
  file(WRITE "${staging}/systemd/${name}" "${text}")
endforeach()
file(GLOB staged_units "${staging}/systemd/*")
file(INSTALL DESTINATION "${prefix}/lib/systemd/system" TYPE FILE FILES ${staged_units})

# Saved maps, for a prefix install (the .deb's postinst creates its own,
# owned by the service user).
if(NOT prefix STREQUAL "/usr")
  file(MAKE_DIRECTORY "$ENV{DESTDIR}${SCANFILTER_STATEDIR}")
endif()
cmake_policy(POP)
