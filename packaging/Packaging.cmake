# Installation and the Debian package (docs/architecture.md). Included from the top-level
# CMakeLists.txt after the targets exist. `cmake --install build/release --prefix /usr`
# (or DESTDIR=...) lays out:
#   bin/palpate, bin/palpate-cli
#   share/applications/org.palpate.Palpate.desktop
#   share/icons/hicolor/scalable/apps/org.palpate.Palpate.svg and .../NxN/apps/org.palpate.Palpate.png
#   share/metainfo/org.palpate.Palpate.metainfo.xml
#   lib/udev/rules.d/70-palpate-*.rules        (udev reads these only under /usr/lib or /lib)
#   share/palpate/{meshes,presets,exercises}    (found by findResource via <exe>/../share/palpate)
#   share/doc/palpate/user-guide.md, guide/*.png (Help > User Guide)
# `cpack -G DEB` in the build directory makes palpate_<version>_<arch>.deb.
include(GNUInstallDirs)

set(PALPATE_APP_ID "org.palpate.Palpate")
set(PALPATE_DOCDIR "${CMAKE_INSTALL_DATADIR}/doc/palpate")  # not GNUInstallDirs' doc/Palpate
set(PALPATE_PACKAGING_DIR "${PROJECT_SOURCE_DIR}/packaging")

install(TARGETS palpate-cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET palpate)
  install(TARGETS palpate RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

install(FILES "${PALPATE_PACKAGING_DIR}/${PALPATE_APP_ID}.desktop"
        DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES "${PALPATE_PACKAGING_DIR}/${PALPATE_APP_ID}.metainfo.xml"
        DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
install(FILES "${PROJECT_SOURCE_DIR}/resources/icons/${PALPATE_APP_ID}.svg"
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
foreach(size 16 24 32 48 64 128 256)
  install(FILES "${PROJECT_SOURCE_DIR}/resources/icons/hicolor/${size}x${size}/apps/${PALPATE_APP_ID}.png"
          DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/${size}x${size}/apps)
endforeach()

# The udev rules as the device work ships them (resources/udev/*.rules), in udev's vendor directory.
install(DIRECTORY "${PROJECT_SOURCE_DIR}/resources/udev/" DESTINATION lib/udev/rules.d
        FILES_MATCHING PATTERN "*.rules")
install(FILES "${PROJECT_SOURCE_DIR}/resources/udev/README.md"
        DESTINATION ${PALPATE_DOCDIR} RENAME udev-rules.md)

# The example resources (the shaders are embedded in the binary and not needed here).
install(DIRECTORY "${PROJECT_SOURCE_DIR}/resources/meshes" "${PROJECT_SOURCE_DIR}/resources/presets"
                  "${PROJECT_SOURCE_DIR}/resources/exercises"
        DESTINATION ${CMAKE_INSTALL_DATADIR}/palpate)

# The user guide and its screenshots (Help > User Guide opens the installed copy).
install(FILES "${PROJECT_SOURCE_DIR}/docs/user-guide.md" DESTINATION ${PALPATE_DOCDIR})
# The licence, GPL-3.0-or-later, in Debian's machine-readable copyright format.
install(FILES "${PROJECT_SOURCE_DIR}/packaging/copyright" DESTINATION ${PALPATE_DOCDIR})
install(DIRECTORY "${PROJECT_SOURCE_DIR}/docs/guide" DESTINATION ${PALPATE_DOCDIR})

# --- CPack: the Debian package -------------------------------------------------------------------
set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "palpate")
set(CPACK_PACKAGE_VENDOR "Palpate")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "haptic soft-tissue simulator for palpation training")
set(CPACK_PACKAGE_DESCRIPTION
    "Palpate deforms a soft-tissue mesh under a probe in real time and sends the contact force to a\n\
haptic device (or the mouse in touch mode). Instructors shape the tissue and write exercises;\n\
trainees run them and get a score. Includes palpate (the GUI) and palpate-cli.")
set(CPACK_PACKAGE_CONTACT "Palpate developers <palpate@example.org>")  # placeholder: the real maintainer address
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # palpate_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
# The shared libraries come from dpkg-shlibdeps; the plugins Qt loads at run time (platforms, the
# SQLite driver) and the GL drivers do not show up there, so they are declared by hand.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins, libqt6sql6-sqlite, libgl1-mesa-dri")
# Qt's own German strings (standard buttons, file dialogs; Qt has no Malay translation), and Qt's
# PostgreSQL driver for a class's shared results server (docs/results-store.md; without it a
# workstation keeps its results to itself and says why).
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "xdg-utils, qt6-translations-l10n, libqt6sql6-psql")
set(CPACK_DEBIAN_COMPRESSION_TYPE "gzip")  # fast to build in the test
include(CPack)
