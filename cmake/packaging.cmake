# Installing and packaging: the two programs, a desktop entry and icon for the application menu,
# and man pages made from the programs' own --help with help2man. `cpack -G DEB` in the build
# folder then makes armmimic_<version>_<arch>.deb (README: Installing); scripts/package.sh makes
# it and armmimic-models_<version>_all.deb, the pose models.
include(GNUInstallDirs)

install(FILES ${PROJECT_SOURCE_DIR}/packaging/armmimic.desktop
        DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/armmimic.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
# The documentation, with the controller profile it describes (docs/profiles/).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})

# Man pages run the programs at build time, so not in sanitizer or fuzz builds (their runtime
# reports would fail the build) and not for the CLI-only demo configuration.
if(NOT ARMMIMIC_SANITIZE AND NOT ARMMIMIC_BUILD_FUZZ AND NOT ARMMIMIC_CLI_ONLY)
  find_program(ARMMIMIC_HELP2MAN help2man)
  if(NOT ARMMIMIC_HELP2MAN)
    message(WARNING "armmimic: help2man not found, so no man pages (scripts/deps.sh installs it)")
  endif()
endif()

# armmimic_man_page(TARGET <program> NAME <one line> [COMMANDS])
function(armmimic_man_page)
  cmake_parse_arguments(M "COMMANDS" "TARGET;NAME" "" ${ARGN})
  if(NOT ARMMIMIC_HELP2MAN)
    return()
  endif()
  set(out ${CMAKE_BINARY_DIR}/man/${M_TARGET}.1.gz)
  set(include ${PROJECT_SOURCE_DIR}/packaging/${M_TARGET}.h2m)
  add_custom_command(
    OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/man
    COMMAND ${CMAKE_COMMAND} -E env QT_QPA_PLATFORM=offscreen
            ${CMAKE_COMMAND} -D PROGRAM=$<TARGET_FILE:${M_TARGET}> -D HELP2MAN=${ARMMIMIC_HELP2MAN}
            "-D NAME=${M_NAME}" -D COMMANDS=${M_COMMANDS} -D INCLUDE=${include} -D OUTPUT=${out}
            -P ${PROJECT_SOURCE_DIR}/cmake/gen_man.cmake
    DEPENDS ${M_TARGET} ${include} ${PROJECT_SOURCE_DIR}/cmake/gen_man.cmake
    COMMENT "Man page of ${M_TARGET} from its --help"
    VERBATIM)
  add_custom_target(${M_TARGET}-man ALL DEPENDS ${out})
  install(FILES ${out} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endfunction()

armmimic_man_page(TARGET armmimic-cli COMMANDS
                  NAME "make a robot arm mimic a human arm seen on video (command line)")
if(ARMMIMIC_BUILD_GUI)
  armmimic_man_page(TARGET armmimic
                    NAME "make a robot arm mimic a human arm seen on video (desktop application)")
endif()

set(CPACK_PACKAGE_NAME armmimic)
set(CPACK_PACKAGE_VENDOR armmimic)
set(CPACK_PACKAGE_CONTACT "armmimic maintainers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
    "armmimic turns video of a human arm into arm angles with classical vision engines\n"
    "(marker, background subtraction, Lucas-Kanade) or a pose network, and turns those angles\n"
    "into safe VAL II commands for a Unimation PUMA 760, streamed over RS-232 or to the\n"
    "built-in controller emulator. It contains the Qt desktop application armmimic and its\n"
    "command-line twin armmimic-cli.")
string(REPLACE ";" "" CPACK_PACKAGE_DESCRIPTION "${CPACK_PACKAGE_DESCRIPTION}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# Library dependencies come from dpkg-shlibdeps; Qt's platform plugins are loaded at run time,
# so no library names them.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
if(ARMMIMIC_BUILD_GUI)
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins")
endif()
# The pose models, packed by scripts/package.sh from the pinned files (scripts/models.sh).
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "armmimic-models")
include(CPack)
